// sinsim run [SCENARIO] [-o DIR] [--seed N] [--model FILE|none] [--bias-window T] [--html FILE]
#include <filesystem>
#include <iostream>
#include <optional>

#include "cli/commands.hpp"
#include "cli/terminal.hpp"
#include "common/error.hpp"
#include "common/units.hpp"
#include "sim/run.hpp"
#include "sim/scenario.hpp"

namespace sinsim::cli {
namespace {

namespace fs = std::filesystem;

// The default scenario, looked up where a user or CI would have it: relative to the current
// folder (`build/sinsim run` from the checkout), beside the executable's source tree (the
// build-time SINSIM_SOURCE_DIR), or next to the executable (build/ inside the checkout).
std::string defaultScenario() {
  const fs::path rel = fs::path("scenarios") / "car.yaml";
  std::vector<fs::path> candidates{rel};
#ifdef SINSIM_SOURCE_DIR
  candidates.push_back(fs::path(SINSIM_SOURCE_DIR) / rel);
#endif
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    candidates.push_back(exe.parent_path().parent_path() / rel);
    candidates.push_back(exe.parent_path() / rel);
  }
  for (const auto& c : candidates)
    if (fs::is_regular_file(c, ec)) return c.lexically_normal().string();
  throw InputError("no scenario given and the default scenario scenarios/car.yaml was not found "
                   "(run from the sinsim checkout or name a scenario file)");
}

}  // namespace

void addRunCommand(CLI::App& app, Action& action) {
  struct Args {
    std::string scenario;
    std::string outDir;
    std::optional<std::uint64_t> seed;
    std::string model;
    std::string biasWindow;  // "30 s"; empty: none
    bool imu = false;
    std::string html;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "run", "Simulate a scenario: ideal IMU, sensor errors, strapdown, errors vs truth");
  cmd->add_option("scenario", args->scenario,
                  "Scenario YAML file (default: scenarios/car.yaml)");
  cmd->add_option("-o,--output", args->outDir,
                  "Output folder for truth.csv, nav.csv, errors.csv, summary.json (filter.csv with a filter, imu.csv with --imu) "
                  "(default: out/<scenario name>)");
  cmd->add_option("--seed", args->seed, "Seed of the sensor error realisation (overrides the "
                                        "scenario's seed:)");
  cmd->add_option("--model", args->model,
                  "Sensor error model file, or none for a perfect IMU (overrides errors:)");
  cmd->add_option("--bias-window", args->biasWindow,
                  "Remove the mean sensor error of the first T seconds [s] (as a user does with a "
                  "static start; default 0: none)");
  cmd->add_flag("--imu", args->imu,
                "Also write imu.csv: ideal and measured IMU as rates and increments (one row per "
                "IMU interval)");
  cmd->add_option("--html", args->html,
                  "Also write a report: track of truth and navigation, errors against time");
  cmd->callback([&action, args]() {
    action = [args]() {
      const std::string file = args->scenario.empty() ? defaultScenario() : args->scenario;
      const sim::Scenario sc = sim::loadScenario(file);
      sim::RunOptions opt;
      opt.outDir = args->outDir.empty() ? (fs::path("out") / sc.folderName()).string() : args->outDir;
      opt.seed = args->seed;
      if (!args->biasWindow.empty())
        opt.biasWindow = parseDuration(args->biasWindow, "--bias-window");
      if (!args->model.empty()) opt.model = args->model;
      opt.writeImu = args->imu;
      opt.htmlPath = args->html;
      const sim::RunSummary s = [&] {
        try {
          return sim::run(sc, opt);
        } catch (const NumericalError& e) {  // "the navigation state became non-finite": say where
          throw NumericalError(file + (opt.model ? " with model " + *opt.model : "") + ": " +
                               e.text());
        } catch (const MotionError& e) {
          throw InputError(file + ": " + e.text());
        }
      }();
      endProgressLine();
      std::string files;
      for (const std::string& f : s.files) files += (files.empty() ? "" : ", ") + f;
      std::cout << "sinsim run: " << file << " -> " << s.outDir << " (" << files << ") in "
                << s.wallTime << " s\n"
                << sim::summaryLine(s) << "\n";
      if (!s.filter.empty()) std::cout << s.filter << "\n";
      if (!s.report.empty()) std::cout << "report: " << s.report << "\n";
      for (const std::string& w : s.warnings) std::cerr << "sinsim run: warning: " << w << "\n";
      return 0;
    };
  });
}

}  // namespace sinsim::cli
