// The filter's view of an aided Monte Carlo batch (docs/aided.md, "Outputs of mc"), from the
// per-run values after the errors (Reference::runFloats, sim/reference.hpp):
//   outages.csv              per model, run and outage window: the largest horizontal error in
//                            the window and the filter's horizontal 1-sigma at that moment
//   filter_consistency.csv   per model and output epoch: the NEES and NIS averaged over the runs
//                            with their two-sided 99 % chi-square bands
//   summary.json "aided"     per model: each outage's drift (median, 95 %) and predicted sigma;
//                            per epoch class (aiding, outage) the share of epochs whose run-average
//                            lies inside its band.
// The band of the mean of R independent χ²(d) values is [χ²⁻¹(0.005; R d), χ²⁻¹(0.995; R d)] / R
// (Bar-Shalom, Li & Kirubarajan 2001, §5.4.2), exact quantiles (errormodels/stats/special.hpp).
#pragma once

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/constants.hpp"
#include "sim/aided/linearity_limits.hpp"
#include "sim/mc_output.hpp"
#include "sim/output.hpp"

namespace sinsim::sim {

/// Per epoch class (aiding, outage): the epochs with a run-average, how many lie inside their
/// band, and the mean of the run-averages (NaN without epochs).
struct McConsistencyClass {
  std::size_t epochs = 0, inside = 0;
  double meanOfAverages = NAN;
  std::size_t above = 0;  // epochs whose run-average lies above the band (the rest outside: below)
  double fractionInside() const { return epochs ? double(inside) / double(epochs) : NAN; }
};

/// One outage window over the runs whose filter ran in it: the largest horizontal error's median,
/// 95 % and mean, the filter's horizontal 1-sigma then (median, 95 %), and their ratio.
struct McOutageSummary {
  double start = 0.0, end = 0.0;  // [s]
  std::size_t runs = 0;
  double maxP50 = NAN, maxP95 = NAN, maxMean = NAN, sigmaP50 = NAN, sigmaP95 = NAN,
         ratioP50 = NAN, ratioP95 = NAN;
};

/// The filter's consistency and outage drift of one model of an aided batch.
struct McAidedSummary {
  std::string label;
  int neesDof = 9;  // aided::neesDof of the scenario's vertical channel
  std::vector<McOutageSummary> outages;
  McConsistencyClass neesAiding, neesOutage, nisAiding;
  /// The runs' filter epochs (those with a NEES) and how many of them had an attitude error (roll,
  /// pitch or yaw, nav - truth) beyond kSmallAngle, with the largest [rad] (NaN without epochs).
  std::size_t filterEpochs = 0, largeAttitudeEpochs = 0;
  double largestAttitude = NAN;
  /// The runs with a filter epoch, and how many of them passed kSmallAngle at any: a run that went
  /// through large angles early can stay over-confident after they shrink (the states it learned
  /// there), while its epochs beyond are a small share of all (a 5-deg heading prior).
  std::size_t filterRuns = 0, largeAttitudeRuns = 0;
  /// Whether the attitude errors beyond small angles are common enough (5 % of the filter epochs
  /// or of the runs) for the verdict to name the linearisation beside the model.
  bool largeAttitudeNamed() const;
  /// The verdict in words: "consistent", or the class whose NEES lies above (over-confident) or
  /// below (pessimistic) its band at more than 20 % of the epochs, with the numbers.
  std::vector<std::string> sentences() const;
};


/// The summaries of the given models (the first `models` entries) of an aided batch.
std::vector<McAidedSummary> mcAidedSummaries(const McBatch& batch, std::size_t models);

/// Writes outages.csv and filter_consistency.csv into `out` (names appended to files) and returns
/// summary.json's "aided" object. The batch's reference must be aided.
nlohmann::json writeMcAidedOutputs(const McBatch& batch, OutputFiles& out,
                                   std::vector<std::string>& files);

/// The two-sided 99 % band of the mean of `runs` independent χ²(dof) values.
void chiSquareMeanBand99(double dof, std::size_t runs, double& lo, double& hi);

}  // namespace sinsim::sim
