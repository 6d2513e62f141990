// Flicker (bias instability) as a sum of first-order Gauss-Markov processes, two per decade of
// correlation time, each of variance B² ln 10 / (2π) (effects/bias_instability.cpp explains the
// construction): the one recipe the effect, its detector and the block-mean likelihood share.
#pragma once

#include <cmath>
#include <vector>

#include "common/constants.hpp"

namespace sinsim::errormodels {

inline constexpr int kFlickerGmsPerDecade = 2;

/// Variance of each component per unit B² [-].
inline double flickerGmVariance() { return std::log(10.0) / (kPi * kFlickerGmsPerDecade); }

/// Correlation time [s] of component j counted from lo [s]: the centre of its half decade.
inline double flickerGmTau(double lo, int j) {
  return lo * std::pow(10.0, (j + 0.5) / kFlickerGmsPerDecade);
}

/// The components' correlation times covering [lo, hi] [s] (0 < lo < hi, at most a few dozen
/// decades apart: the caller checks).
inline std::vector<double> flickerGmTaus(double lo, double hi) {
  const double decades = std::log10(hi) - std::log10(lo);  // hi / lo may overflow
  const int n = int(std::ceil(kFlickerGmsPerDecade * decades - 1e-9));
  std::vector<double> taus;
  for (int j = 0; j < n; ++j) taus.push_back(flickerGmTau(lo, j));
  return taus;
}

/// The widest tau_range a bias_instability may span [decades] (with the widening, 54 components
/// an axis, each drawn at every IMU interval).
inline constexpr double kFlickerMaxDecades = 24.0;

/// Decades the components reach beyond a bias_instability's tau_range on each side: what keeps
/// its Allan floor flat up to the range's ends (effects/bias_instability.cpp).
inline constexpr double kFlickerWidenDecades = 1.5;

/// The Gauss-Markov components of a bias_instability: each of standard deviation sigma.
struct FlickerGms {
  double sigma = 0.0;        ///< [signal]
  std::vector<double> taus;  ///< correlation times [s]
};

/// The components of a bias_instability of coefficient B [signal] over tau_range [lo, hi] [s].
inline FlickerGms biasInstabilityGms(double B, double lo, double hi) {
  FlickerGms g;
  g.taus = flickerGmTaus(lo * std::pow(10.0, -kFlickerWidenDecades),
                         hi * std::pow(10.0, kFlickerWidenDecades));
  g.sigma = B * std::sqrt(flickerGmVariance());
  return g;
}

}  // namespace sinsim::errormodels
