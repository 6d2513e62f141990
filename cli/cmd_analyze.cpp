// sinsim analyze DATA [--json OUT] [--html OUT]: per-axis statistics of a measured record (ACF,
// Welch PSD, Allan deviation with confidence bounds) as JSON for scripting and as an HTML report.
#include <cmath>
#include <iostream>
#include <string>

#include "cli/commands.hpp"
#include "cli/record_options.hpp"
#include "cli/terminal.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/limits.hpp"
#include "errormodels/stats/record.hpp"
#include "sim/analysis.hpp"

namespace sinsim::cli {
namespace {

struct AnalyzeArgs {
  std::string data;
  std::string json_out;
  std::string html_out;
  RecordArgs record;
  double max_lag_s = 0;  // 0: default
  long long segment = 0;  // 0: default
  std::string tau = "octave";
  double confidence = 0.683;
  std::string denoise = "none";
  bool fullJson = false;
};

int runAnalyze(const AnalyzeArgs& a) {
  const errormodels::RecordOptions ro = recordOptions(a.record);
  if (a.denoise != "none" && a.denoise != "db5")
    throw InputError("--denoise: expected db5 or none, got \"" + a.denoise + "\"");
  if (a.tau != "octave" && a.tau != "decade")
    throw InputError("--tau: expected octave or decade, got \"" + a.tau + "\"");
  if (a.segment < 0) throw InputError("--segment: expected a positive number of samples");
  sim::AnalysisOptions opt;
  opt.max_lag_s = a.max_lag_s;
  opt.segment = static_cast<std::size_t>(a.segment);
  opt.tauPerDecade = a.tau == "decade";
  opt.confidence = a.confidence;
  opt.denoise = a.denoise == "db5";
  opt.fullJson = a.fullJson;
  sim::checkAnalysisOptions(opt);  // before the record is read
  const errormodels::Record rec = errormodels::loadRecord(a.data, ro);
  // Both outputs before the work: never the JSON written and the HTML refused.
  requireWritableTargets({a.json_out, a.html_out});
  if (a.segment > 0 && static_cast<std::size_t>(a.segment) > rec.size())
    throw InputError("--segment: " + std::to_string(a.segment) + " samples, longer than the " +
                     std::to_string(rec.size()) + "-sample record " + a.data);
  const std::vector<sim::ChannelStats> stats = sim::analyzeRecord(rec, opt);
  sim::writeAnalysis(rec, stats, opt, a.json_out, a.html_out);
  endProgressLine();
  std::cout << "analyze: " << rec.size() << " samples at " << rec.rate_hz << " Hz, "
            << stats.size() << " channel(s)";
  if (!a.json_out.empty() || !a.html_out.empty())
    std::cout << " ->" << (a.json_out.empty() ? "" : " " + a.json_out)
              << (a.html_out.empty() ? "" : " " + a.html_out);
  std::cout << "\n" << sim::analysisSummary(stats);
  for (const std::string& w : sim::analysisWarnings(stats)) std::cerr << "analyze: warning: " << w << "\n";
  for (const std::string& w : errormodels::recordWarnings(rec)) std::cerr << "analyze: warning: " << w << "\n";
  return 0;
}

}  // namespace

void addAnalyzeCommand(CLI::App& app, Action& action) {
  auto args = std::make_shared<AnalyzeArgs>();
  CLI::App* cmd = app.add_subcommand(
      "analyze",
      "Per-axis statistics of a measured record (ACF, Welch PSD, Allan with bounds) as JSON/HTML");
  cmd->add_option("DATA", args->data, "record: CSV or CSV.gz with header (t, gx gy gz, ax ay az, temp)")
      ->required();
  cmd->add_option("--json", args->json_out, "output JSON file (SI units)");
  cmd->add_option("--html", args->html_out,
                  "output HTML report: Allan deviation with bounds, PSD and ACF per axis");
  addRecordOptions(cmd, args->record);
  cmd->add_option("--max-lag", args->max_lag_s, "largest ACF lag [s] (default min(duration/10, 1000 s))");
  cmd->add_option("--segment", args->segment, "Welch segment length [samples] (default: power of 2 <= N/8)");
  cmd->add_option("--tau", args->tau, "Allan tau grid: octave | decade (10 per decade)");
  cmd->add_option("--confidence", args->confidence, "two-sided level of the Allan bounds (default 0.683)");
  cmd->add_option("--denoise", args->denoise, "db5 | none: denoise before ACF and PSD (Allan uses raw data)");
  cmd->add_flag("--json-full", args->fullJson,
                "every ACF lag and PSD bin in the JSON (default: all below index 64, then ~32 per decade)");
  cmd->callback([args, &action] { action = [args] { return runAnalyze(*args); }; });
}

}  // namespace sinsim::cli
