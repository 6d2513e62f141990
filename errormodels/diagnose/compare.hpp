// Step 1 of the diagnosis: one channel of the measurement against the model's Monte Carlo
// realisations (diagnose.hpp, "band", "misfit", "chi2"): ADEV, PSD and ACF curves with their
// bands, the misfit, the Allan chi-square and the ranges where the measurement leaves the band.
#pragma once

#include <string>
#include <vector>

#include "errormodels/diagnose/allan_chi2.hpp"
#include "errormodels/diagnose/series_stats.hpp"

namespace sinsim::errormodels::diagnose::detail {

/// Fills d.adev, d.psd, d.acf, d.misfit*, d.fractionOutside, d.chi2, d.fails and the Allan
/// chi-square problem of the channel (prob) from the measurement's statistics and the R
/// realisations' (real).
void compareChannel(const SeriesStats& meas, const std::vector<SeriesStats>& real,
                    const Setup& setup, double bandLevel, AxisDiagnosis& d, AllanProblem& prob);

/// Contiguous runs of points outside the band on one side.
std::vector<FailRange> failRanges(const Comparison& c, const std::string& stat);

}  // namespace sinsim::errormodels::diagnose::detail
