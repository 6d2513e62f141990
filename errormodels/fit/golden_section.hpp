// Golden-section search for a correlation time on a log scale: the one bracket-shrinking loop of
// the latent fit's Allan chi2 and of the Whittle likelihood (both minimise over log T_k with the
// other parameters profiled out).
#pragma once

#include <cmath>

namespace sinsim::errormodels::fit {

/// The better of the last two interior points of `iterations` golden-section steps over
/// u = log T in [log lo, log hi]: at(u) fits at T = e^u and returns a fit, cost(fit) its criterion.
template <class At, class Cost>
auto goldenSectionLog(double lo, double hi, int iterations, At at, Cost cost) {
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double a = std::log(lo), b = std::log(hi);
  double c = b - g * (b - a), d = a + g * (b - a);
  auto fc = at(c), fd = at(d);
  for (int it = 0; it < iterations; ++it) {
    if (cost(fc) <= cost(fd)) {
      b = d, d = c, fd = fc;
      c = b - g * (b - a), fc = at(c);
    } else {
      a = c, c = d, fc = fd;
      d = a + g * (b - a), fd = at(d);
    }
  }
  return cost(fc) <= cost(fd) ? fc : fd;
}

}  // namespace sinsim::errormodels::fit
