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

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/mc_output.hpp"
#include "sim/output.hpp"

namespace sinsim::sim {

/// Writes outages.csv and filter_consistency.csv into `out` (names appended to files) and returns
/// summary.json's "aided" object. The batch's reference must be aided.
nlohmann::json writeMcAidedOutputs(const McBatch& batch, OutputFiles& out,
                                   std::vector<std::string>& files);

/// The two-sided 99 % band of the mean of `runs` independent χ²(dof) values.
void chiSquareMeanBand99(double dof, std::size_t runs, double& lo, double& hi);

}  // namespace sinsim::sim
