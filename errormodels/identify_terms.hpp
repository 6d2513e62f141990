// The Allan-term fit of the identify pipeline (identify.cpp): which Allan points are usable, which
// of the IEEE 952 terms Q, N, B, K, R the data support (BIC over subsets), and from which tau on
// the term model is consistent with the curve. Internal to errormodels/identify*.cpp.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "errormodels/fit/allan_fit.hpp"
#include "errormodels/stats/allan.hpp"

namespace sinsim::errormodels::detail {

/// Points of an Allan curve usable by the term fit: finite, positive dev and EDF, and
/// m <= N / 10. Beyond N / 10 a point has fewer than ~10 EDF and the modelled correlation between
/// points (the quadrature behind fit::allanEstimateCorrelation) is no longer reliable: with them
/// the correlated fit of white + random walk records (100 Hz, 2 h) lost K in 7 of 12 records.
struct CurvePoints {
  std::vector<double> tau, dev, edf;  ///< [s], [U], [-]
};
CurvePoints usablePoints(const AllanCurve& c);

/// Number of points at tau >= tauMin [s].
std::size_t pointsAtOrAbove(const CurvePoints& p, double tauMin);

/// The fit range: the first Allan point at or above tauStart [s] from which the term model is
/// consistent with the points, chi^2 <= its 0.999 quantile for the fit's dof (real sensors show
/// features at short tau no term model carries: an internal filter's hump, a vibration line).
/// The start moves up one point at a time while at least minPoints remain; when no start passes,
/// the one with the smallest chi^2 / dof is kept. `consistent` says which case it was. The scan
/// uses independent-point fits (cheap); the chosen range is then refitted with the correlated
/// GLS, whose values and uncertainties are the ones reported. dt [s]: sample interval; n: samples.
struct RangedFit {
  fit::AllanFit fit;
  double tauMin = 0.0;  ///< [s]
  bool consistent = false;
};
RangedFit fitTermsFrom(const CurvePoints& p, double dt, std::size_t n,
                       std::array<bool, fit::kAllanTermCount> enabled, double tauStart,
                       std::size_t minPoints);

/// "tau >= 0.5 s (12 points, chi2 9.1 / 8 dof)", for the model file's comments.
std::string describeRange(const RangedFit& r);
/// "white detected, random_walk not detected, ...".
std::string describeAllan(const fit::AllanFit& f);

}  // namespace sinsim::errormodels::detail
