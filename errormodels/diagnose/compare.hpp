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

/// The Allan problem's weight and bias (AllanProblem::W, bias) under the model's realisations
/// rounded onto the record's lattice (SeriesStats::roundedAvar), for once the rounding is part of
/// the model: on a lattice coarser than the noise a rounded record's Allan variance scatters
/// otherwise (more where few samples leave their cell) than the unrounded realisations'. Empty
/// (W of size 0) when the realisations were not rounded or a rounded one has zero AVAR.
struct RoundedScatter {
  Eigen::MatrixXd W;
  std::vector<double> bias;
};
RoundedScatter roundedScatter(const std::vector<SeriesStats>& real);

/// Contiguous runs of points outside the band on one side.
std::vector<FailRange> failRanges(const Comparison& c, const std::string& stat);

}  // namespace sinsim::errormodels::diagnose::detail
