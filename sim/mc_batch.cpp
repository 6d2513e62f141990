// `sinsim mc` as one library call (mc_batch.hpp).
#include "sim/mc_batch.hpp"

#include <filesystem>

#include "common/error.hpp"
#include "common/limits.hpp"
#include "common/number_text.hpp"
#include "common/read_file.hpp"
#include "errormodels/stats/record.hpp"
#include "sim/aided/aided_navigation.hpp"
#include "sim/nav_loop.hpp"
#include "sim/reference.hpp"
#include "sim/scenario.hpp"

namespace sinsim::sim {

std::vector<std::string> batchWarnings(const Scenario& sc, const Reference& ref) {
  std::vector<std::string> w;
  if (std::string d = sc.durationWarning(); !d.empty()) w.push_back(std::move(d));
  if (!ref.aiding.inert())
    for (std::string& s : aided::startWarnings(sharedEarth(), ref.aiding, ref.strapdown, ref.initial))
      w.push_back(std::move(s));
  return w;
}

std::vector<std::string> extrapolationWarnings(const std::vector<McModel>& models, double duration) {
  std::vector<std::string> w;
  for (const McModel& m : models)
    if (const auto record = m.model.recordDuration(); record && duration > *record)
      w.push_back("model " + m.label + " was fitted on a " + durationText(*record) + " record and the scenario runs " +
                  durationText(duration) + ": its drift beyond " + durationText(*record) +
                  " is extrapolated (a GM slower than the record, a walk or a ramp the record could not "
                  "resolve there)");
  return w;
}

McCommandResult runMcBatch(const McRequest& request) {
  // ---- the reference: a scenario, or a static one matching a measured record ------------------
  Scenario sc;
  std::string scenarioIdentity;
  std::optional<MeasuredSetup> measuredSetup;
  McOptions opt = request.options;
  if (request.measured) {
    if (!request.scenarioPath.empty())
      throw InputError("give either a scenario or --measured (the measured record defines a "
                       "static scenario), not both");
    if (request.models.empty())
      throw InputError("--measured needs at least one --model to compare with");
    measuredSetup = prepareMeasured(*request.measured);
    sc = measuredSetup->scenario;
    scenarioIdentity = measuredSetup->identity;
    opt.navigate.biasWindow = measuredSetup->biasWindow;
  } else {
    if (request.scenarioPath.empty())
      throw InputError("name a scenario file (or give --measured DATA.csv)");
    sc = loadScenario(request.scenarioPath);
    scenarioIdentity = readRegularFile(request.scenarioPath, limits::kMaxYamlBytes, "YAML file");
  }
  const std::vector<McModel> models = loadMcModels(request.models, sc, scenarioIdentity);
  requireReference(models, opt.reference);  // before a measured record is navigated

  opt.seed = request.seed ? *request.seed : sc.seed.value_or(0);
  if (opt.outDir.empty()) opt.outDir = (std::filesystem::path("out") / sc.folderName("mc-")).string();
  opt.scenarioIdentity = scenarioIdentity;

  const Reference ref = buildReference(sc);
  McMeasured measured;
  if (measuredSetup) {
    measured = navigateMeasured(*measuredSetup, ref, opt.navigate);
    opt.measured = &measured;
  }

  McCommandResult batch;
  batch.result = runMonteCarlo(ref, models, opt);
  opt.measured = nullptr;  // points into this frame
  batch.scenarioName = sc.name;
  batch.modelCount = models.size();
  batch.options = opt;
  batch.samples = ref.samples.size();
  batch.warnings = batchWarnings(sc, ref);
  for (std::string& w : extrapolationWarnings(models, sc.duration())) batch.warnings.push_back(std::move(w));
  if (measuredSetup)  // a record in g or deg/s read as SI navigates as nonsense, silently
    for (std::string& w : errormodels::recordWarnings(measuredSetup->record)) batch.warnings.push_back(std::move(w));
  if (opt.budget)
    for (const McModel& m : models)
      if (budgetEffects(m).empty())
        batch.warnings.push_back("--budget: model " + m.label +
                                 (m.model.empty() || m.model.effectNames().empty()
                                      ? " has no effect"
                                      : " has one effect, which is all its drift") +
                                 ": nothing to switch off");
  if (batch.result.complete && opt.partition.rank == 0)
    batch.headlines =
        mcHeadlines(ref, batch.result, models.size(), opt.times, measuredSetup ? &measured : nullptr, opt.reference);
  return batch;
}

}  // namespace sinsim::sim
