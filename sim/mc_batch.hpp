// `sinsim mc` as one library call: the reference (a scenario file, or the static scenario of a
// measured record, navigated once as the batch's measured participant), the models, the batch
// (sim/montecarlo.hpp) and the headline numbers. The CLI parses options into an McRequest, calls
// runMcBatch and prints the McCommandResult.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sim/mc_headlines.hpp"
#include "sim/mc_models.hpp"
#include "sim/measured.hpp"
#include "sim/montecarlo.hpp"
#include "sim/scenario.hpp"

namespace sinsim::sim {

struct McRequest {
  std::string scenarioPath;                 ///< a scenario file; empty with `measured`
  std::optional<MeasuredOptions> measured;  ///< a static record instead of a scenario
  std::vector<std::string> models;          ///< model files ("none": perfect IMU); empty: the scenario's errors:
  std::optional<std::uint64_t> seed;        ///< unset: the scenario's seed (else 0)
  /// runs, threads, times, budget, navigate (bias window of a scenario batch), resume, outDir
  /// (empty: out/mc-<scenario name>), interrupt, progress, partition. seed, scenarioIdentity and
  /// measured are filled by runMcBatch.
  McOptions options;
};

struct McCommandResult {
  std::string scenarioName;
  std::size_t modelCount = 0;
  McOptions options;       ///< as run (seed, outDir and bias window resolved)
  std::size_t samples = 0; ///< IMU samples per run
  McResult result;
  McHeadlines headlines;  ///< empty unless the batch is complete
  std::vector<std::string> warnings;  ///< about every run (aided: aided::startWarnings)
};

/// The warnings about every run of a batch of scenario sc along its reference: a duration of no
/// whole number of IMU intervals (Scenario::durationWarning), an aided filter's start
/// (aided::startWarnings). `sinsim mc` and Python's `mc` print them.
std::vector<std::string> batchWarnings(const Scenario& sc, const Reference& ref);

/// For each model fitted on a record shorter than the scenario's `duration` [s]
/// (ImuErrorModel::recordDuration): a warning that its drift beyond the record is extrapolated.
std::vector<std::string> extrapolationWarnings(const std::vector<McModel>& models, double duration);

/// Runs (or resumes) the batch. Throws InputError for a scenario and a record together, neither,
/// a record without a model to compare with, and whatever the scenario, record, models and batch
/// options refuse.
McCommandResult runMcBatch(const McRequest& request);

}  // namespace sinsim::sim
