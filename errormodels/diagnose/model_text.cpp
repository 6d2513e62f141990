// Reading effect types and the AR base from a model file's text, and editing it (model_text.hpp).
#include "errormodels/diagnose/model_text.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "common/error.hpp"
#include "common/units.hpp"
#include "errormodels/diagnose/channels.hpp"
#include "errormodels/diagnose/diagnose.hpp"
#include "errormodels/model_io.hpp"

namespace sinsim::errormodels::diagnose {

ModelText ModelText::load(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read model file " + path);
  std::ostringstream s;
  s << in.rdbuf();
  return {s.str(), path};
}

namespace detail {

std::vector<std::string> modelEffectTypes(const std::string& modelText, int channel) {
  // Through the one model reader, so `enabled: no / false / off` means what it means to the
  // simulator (effectTypesOn counts enabled effects only).
  const ErrorModelSpec spec = errorModelFromString(modelText, "model");
  return effectTypesOn(spec, isGyro(channel) ? Sensor::gyro : Sensor::accel, channel % 3);
}

std::optional<std::vector<double>> arOfChannel(const std::string& text, int channel, double rate) {
  YAML::Node root = YAML::Load(text);
  YAML::Node sensor = root[sensorName(channel)];
  if (!sensor || !sensor.IsMap()) return std::nullopt;
  std::optional<std::vector<double>> found;
  int count = 0;
  for (const char* list : {"all", axisName(channel)}) {
    YAML::Node l = sensor[list];
    if (!l || !l.IsSequence()) continue;
    for (const auto& e : l) {
      if (!e.IsMap() || !e["type"] || e["type"].as<std::string>() != "ar") continue;
      ++count;
      try {
        const double r = parseQuantityAs(e["rate"].as<std::string>(), Dimension::frequency());
        if (std::fabs(r - rate) > 1e-6 * rate) continue;
        std::vector<double> a{1.0};
        for (const auto& v : e["a"]) a.push_back(v.as<double>());
        found = a;
      } catch (const std::exception&) {
      }
    }
  }
  if (count != 1) return std::nullopt;
  return found;
}

namespace {

/// The keys holding a stochastic effect's noise level (scaled by sqrt of the variance factor).
std::vector<std::string> noiseKeys(const std::string& type) {
  if (type == "ar") return {"sigma", "output_sigma"};
  if (type == "white") return {"density", "sigma"};
  if (type == "gauss_markov") return {"sigma"};
  if (type == "random_walk") return {"K"};
  if (type == "bias_instability") return {"B", "floor"};
  return {};
}

bool scalable(const YAML::Node& e) {
  return e.IsMap() && e["type"] && !noiseKeys(e["type"].as<std::string>()).empty();
}

void scaleEffect(YAML::Node e, double factor) {
  for (const auto& key : noiseKeys(e["type"].as<std::string>())) {
    if (!e[key] || !e[key].IsScalar()) continue;
    const std::string text = e[key].as<std::string>();
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (end == text.c_str()) continue;
    e[key] = num(v * factor, 9) + std::string(end);
  }
}

void flowStyle(YAML::Node n) {
  if (n.IsSequence())
    for (auto e : n)
      if (e.IsMap()) e.SetStyle(YAML::EmitterStyle::Flow);
}

/// A copy of effect e of channel c: an `ar` with the coefficients and sigma of rep (when given),
/// a scalable effect with its noise scaled by f.
YAML::Node editedEffect(const YAML::Node& e, int c, const std::vector<double>& rep, double f) {
  YAML::Node copy = YAML::Clone(e);
  const bool isAr = copy.IsMap() && copy["type"] && copy["type"].as<std::string>() == "ar";
  if (isAr && !rep.empty()) {
    YAML::Node a(YAML::NodeType::Sequence);
    for (std::size_t i = 0; i + 1 < rep.size(); ++i) a.push_back(num(rep[i], 10));
    a.SetStyle(YAML::EmitterStyle::Flow);
    copy["a"] = a;
    copy.remove("output_sigma");
    copy["sigma"] = quantity(rep.back(), unitsFor(c).level);
  } else if (scalable(copy) && f != 1.0) {
    scaleEffect(copy, f);
  }
  return copy;
}

/// Scalable effects of `all` move to the axis lists when the axes are scaled differently.
std::vector<YAML::Node> takeScalableFromAll(YAML::Node s) {
  std::vector<YAML::Node> moved;
  if (!(s["all"] && s["all"].IsSequence())) return moved;
  YAML::Node keep(YAML::NodeType::Sequence);
  for (const auto& e : s["all"]) {
    if (scalable(e)) moved.push_back(YAML::Clone(e));
    else keep.push_back(e);
  }
  if (keep.size() == 0) s.remove("all");
  else s["all"] = keep;
  return moved;
}

void editSensor(YAML::Node& root, int sensor, const std::array<std::vector<std::string>, 6>& addYaml,
                const std::array<double, 6>& varianceScale,
                const std::array<std::vector<double>, 6>& arReplace) {
  const char* sname = sensor == 0 ? "gyro" : "accel";
  bool any = false, differs = false;
  for (int a = 0; a < 3; ++a) {
    const auto c = std::size_t(sensor * 3 + a);
    any = any || !addYaml[c].empty() || varianceScale[c] != 1.0 || !arReplace[c].empty();
    differs = differs || varianceScale[c] != 1.0 || !arReplace[c].empty();
  }
  if (!any) return;
  YAML::Node s = root[sname];
  if (!s || !s.IsMap()) {
    root[sname] = YAML::Node(YAML::NodeType::Map);
    s = root[sname];
  }
  std::vector<YAML::Node> moved;
  if (differs) moved = takeScalableFromAll(s);
  for (int a = 0; a < 3; ++a) {
    const int c = sensor * 3 + a;
    const double f = std::sqrt(varianceScale[std::size_t(c)]);
    const auto& rep = arReplace[std::size_t(c)];
    YAML::Node list(YAML::NodeType::Sequence);
    for (const auto& e : moved) list.push_back(editedEffect(e, c, rep, f));
    const char* an = axisName(c);
    if (s[an] && s[an].IsSequence())
      for (const auto& e : s[an]) list.push_back(editedEffect(e, c, rep, f));
    for (const auto& y : addYaml[std::size_t(c)]) list.push_back(YAML::Load(y));
    if (list.size() > 0 || (s[an] && s[an].IsDefined())) s[an] = list;
  }
}

}  // namespace

std::string editModel(const std::string& modelText,
                      const std::array<std::vector<std::string>, 6>& addYaml,
                      const std::array<double, 6>& varianceScale, const std::string& header,
                      const std::array<std::vector<double>, 6>& arReplace) {
  YAML::Node root = YAML::Load(modelText);
  if (!root.IsMap()) root = YAML::Node(YAML::NodeType::Map);
  for (int sensor = 0; sensor < 2; ++sensor) editSensor(root, sensor, addYaml, varianceScale, arReplace);
  for (auto kv : root)
    if (kv.second.IsMap())
      for (auto l : kv.second) flowStyle(l.second);
  YAML::Emitter out;
  out << root;
  std::string text;
  std::istringstream hs(header);
  std::string line;
  while (std::getline(hs, line)) text += "# " + line + "\n";
  return text + out.c_str() + "\n";
}

}  // namespace detail

}  // namespace sinsim::errormodels::diagnose
