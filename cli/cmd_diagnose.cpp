// `sinsim diagnose DATA --model MODEL [--add EFFECT[:AXIS] ...] [--json OUT] [--html OUT]`:
// compares an error model with a measured static record, says where it fails and which effect is
// missing, and with --add (or --edited MODEL2) refits the model with the effect and shows the
// misfit before -> after (errormodels/diagnose).
#include <chrono>
#include <cstdio>
#include <iostream>
#include <optional>

#include "common/limits.hpp"
#include "cli/commands.hpp"
#include "cli/record_options.hpp"
#include "cli/terminal.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/units.hpp"
#include "errormodels/diagnose/diagnose.hpp"
#include "errormodels/model_io.hpp"
#include "errormodels/stats/record.hpp"
#include "sim/diagnose_nav.hpp"
#include "sim/diagnose_report.hpp"
#include "sim/scenario.hpp"

namespace sinsim::cli {
namespace {

namespace dg = errormodels::diagnose;

struct DiagnoseArgs {
  std::string data, model, edited, json, html, output;
  bool nav = false;       // --nav given
  std::string scenario;   // --nav SCENARIO (empty: the README's car)
  std::size_t navRuns = sim::NavVerdictOptions{}.runs;
  std::string navBiasWindow;  // empty: min(60 s, 10 % of the replay)
  std::vector<std::string> add, channels;
  RecordArgs record;
  std::size_t realisations = 32;
  std::uint64_t seed = 20240505;
  unsigned threads = 0;
  double threshold = errormodels::diagnose::DiagnoseOptions{}.threshold;
  double nextThreshold = errormodels::diagnose::DiagnoseOptions{}.nextThreshold;
};

int diagnoseAndWrite(const DiagnoseArgs& a);

// --nav: the verdict of the diagnosed (and improved) model along the scenario (sim/diagnose_nav).
std::optional<sim::NavVerdict> verdict(const DiagnoseArgs& a, const errormodels::Record& record,
                                       const errormodels::ErrorModelSpec& model,
                                       const dg::Improvement* imp) {
  if (!a.nav) return std::nullopt;
  sim::NavVerdictOptions o;
  o.runs = a.navRuns;
  o.termRuns = std::max<std::size_t>(4, a.navRuns / 2);
  o.seed = a.seed;
  o.threads = a.threads;
  if (!a.navBiasWindow.empty()) o.biasWindow = parseDuration(a.navBiasWindow, "--nav-bias-window");
  const sim::Scenario sc = sim::loadScenario(a.scenario.empty() ? "scenarios/car.yaml" : a.scenario);
  return sim::navigationVerdict(record, model, imp ? &imp->model : nullptr, sc, o);
}

std::string defaultOutput(const std::string& model) {
  auto dot = model.rfind('.');
  auto slash = model.rfind('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return model + ".improved.yaml";
  return model.substr(0, dot) + ".improved" + model.substr(dot);
}

int runDiagnose(const DiagnoseArgs& a) {
  // A failure deep inside the statistics names the record (and, below, the channel).
  return withContext(a.data, [&] { return diagnoseAndWrite(a); });
}

int diagnoseAndWrite(const DiagnoseArgs& a) {
  const auto t0 = std::chrono::steady_clock::now();
  const auto record = errormodels::loadRecord(a.data, recordOptions(a.record));
  const auto model = errormodels::loadErrorModel(a.model);
  for (const std::string& w : errormodels::recordWarnings(record)) std::cerr << "diagnose: warning: " << w << "\n";
  dg::DiagnoseOptions o;
  o.channels = a.channels;
  o.realisations = a.realisations;
  o.seed = a.seed;
  o.threads = a.threads;
  o.threshold = a.threshold;
  o.nextThreshold = a.nextThreshold;
  std::vector<dg::AddRequest> adds;
  for (const auto& s : a.add) adds.push_back(dg::AddRequest::parse(s));
  if (!adds.empty() && !a.edited.empty()) throw InputError("give either --add or --edited, not both");
  // Every output before the work: never some written and the next refused.
  const std::string improvedOut = a.output.empty() ? defaultOutput(a.model) : a.output;
  requireWritableTargets({adds.empty() ? std::string() : improvedOut, a.json, a.html});

  DiagnoseCommand command;  // for the page's "what next"
  command.base = "sinsim diagnose " + a.data + recordOptionsText(a.record);
  command.model = a.model;
  if (adds.empty() && a.edited.empty()) {
    const auto d = dg::diagnose(record, model, o);
    const auto nav = verdict(a, record, model, nullptr);
    endProgressLine();
    std::cout << dg::summaryTable(d);
    if (nav) std::cout << sim::navVerdictText(*nav);
    if (!a.json.empty()) writeFileAtomic(a.json, sim::diagnoseJsonWithNav(d, nav ? &*nav : nullptr));
    if (!a.html.empty()) writeDiagnoseReport(a.html, d, nullptr, &command, nav ? &*nav : nullptr);
  } else {
    const auto imp = adds.empty() ? dg::compareModels(record, model, errormodels::loadErrorModel(a.edited), o)
                                  : dg::improve(record, model, adds, o);
    const auto nav = verdict(a, record, model, &imp);
    endProgressLine();
    std::cout << dg::summaryTable(imp);
    if (nav) std::cout << sim::navVerdictText(*nav);
    if (!a.edited.empty()) command.improvedModel = a.edited;
    if (!adds.empty()) {
      errormodels::writeErrorModel(improvedOut, imp.model);
      command.improvedModel = improvedOut;
      std::cout << "wrote the improved model " << improvedOut << "\n";
    }
    if (!a.json.empty()) writeFileAtomic(a.json, sim::diagnoseJsonWithNav(imp, nav ? &*nav : nullptr));
    if (!a.html.empty()) writeDiagnoseReport(a.html, imp.before, &imp, &command, nav ? &*nav : nullptr);
  }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::fprintf(stderr, "diagnose: %.2f s wall\n", s);
  return 0;
}

}  // namespace

void addDiagnoseCommand(CLI::App& app, Action& action) {
  auto a = std::make_shared<DiagnoseArgs>();
  CLI::App* c = app.add_subcommand(
      "diagnose", "compare an error model with a measured record: where it fails, which effect is "
                  "missing; --add EFFECT[:AXIS] refits the model with it");
  c->add_option("DATA", a->data, "record: CSV or CSV.gz (t, gx gy gz, ax ay az, temp)")->required();
  c->add_option("--model", a->model, "error model file (YAML)")->required();
  std::string addable;
  for (const auto& e : dg::detectableEffects()) addable += e + ", ";
  c->add_option("--add", a->add,
                "add an effect (" + addable + "or found = every reported finding), optionally on one channel: ramp:gz")
      ->take_all();
  c->add_option("--edited", a->edited, "compare with a second (user-edited) model file: before -> after");
  c->add_option("-o,--output", a->output, "improved model file (default MODEL.improved.yaml)");
  c->add_option("--json", a->json, "write the diagnosis as JSON");
  c->add_option("--html", a->html, "write a self-contained HTML report");
  c->add_option("--channels", a->channels, "channels to diagnose (gx gy gz ax ay az, by blanks or commas; default all)")
      ->delimiter(',');
  addRecordOptions(c, a->record);
  c->add_option("--realisations", a->realisations, "Monte Carlo realisations of the model (default 32)");
  c->add_option("--seed", a->seed, "seed of the realisations");
  c->add_option("--threads", a->threads, "worker threads (default: all cores)")
      ->check(CLI::Range(0u, sinsim::limits::kMaxThreads));
  auto* nav = c->add_option("--nav", a->scenario,
                            "navigation verdict along a scenario (default scenarios/car.yaml): "
                            "which term and tau band drive its drift, whether the model under- or "
                            "over-predicts the record's own drift, a warning when --add changes "
                            "the predicted drift > 2x (adds a Monte Carlo: tens of seconds)")
                  ->expected(0, 1);
  c->add_option("--nav-runs", a->navRuns, "Monte Carlo runs per model of the verdict (default 32)");
  c->add_option("--nav-bias-window", a->navBiasWindow,
                "initial-bias removal of the verdict's runs and replay, e.g. \"60 s\" (default "
                "min(60 s, 10 % of the replay); 0: none, as mc SCENARIO by default)");
  c->add_option("--threshold", a->threshold, "reporting threshold on the score (default: calibrated on null channels, docs/diagnose.md)");
  c->add_option("--next-threshold", a->nextThreshold,
                "threshold of a further finding on a channel that has one (default: calibrated on one-effect channels; "
                "at most --threshold)");
  c->callback([a, nav, &action] {
    a->nav = nav->count() > 0;
    action = [a] { return runDiagnose(*a); };
  });
}

}  // namespace sinsim::cli
