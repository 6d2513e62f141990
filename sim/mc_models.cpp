#include "sim/mc_models.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/error.hpp"

namespace sinsim::sim {
namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void addUnique(std::vector<McModel>& models, McModel m) {
  const std::string base = m.label;
  for (int k = 2;; ++k) {
    bool clash = false;
    for (const auto& o : models) clash = clash || o.label == m.label;
    if (!clash) break;
    m.label = base + "-" + std::to_string(k);
  }
  models.push_back(std::move(m));
}

}  // namespace

std::vector<McModel> loadMcModels(const std::vector<std::string>& files, const Scenario& sc,
                                  const std::string& scenarioIdentity) {
  std::vector<McModel> models;
  if (files.empty()) addUnique(models, {"scenario-errors", sc.errors, "inline/scenario:" + scenarioIdentity});
  for (const auto& f : files) {
    if (f == "none") {
      addUnique(models, {"none", errormodels::ImuErrorModel::none(), "none"});
      continue;
    }
    McModel m{std::filesystem::path(f).stem().string(), errormodels::ImuErrorModel::load(f),
              slurp(f)};
    requireTemperatureFor(sc, m.model, f);
    addUnique(models, std::move(m));
  }
  for (const auto& m : models)  // refuse a model that cannot run at the IMU rate, before any file
    if (!m.model.empty()) m.model.instantiate(sc.imuRate, {0, 0});
  return models;
}

}  // namespace sinsim::sim
