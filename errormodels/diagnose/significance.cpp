// Gaussian-equivalent z of p-values and t statistics (significance.hpp).
#include "errormodels/diagnose/significance.hpp"

#include <algorithm>
#include <cmath>

#include "errormodels/stats/special.hpp"

namespace sinsim::errormodels::diagnose::detail {

double zFromTwoSidedP(double p) {
  if (!(p > 0)) return kMaxScore;
  if (p >= 1) return 0.0;
  return std::min(kMaxScore, normalTwoSidedCritical(p));
}

double zFromStudentT(double t, double nu) {
  if (!(nu > 0)) return 0.0;
  return std::sqrt(nu * std::log1p(t * t / nu)) * (8 * nu + 1) / (8 * nu + 3);
}

}  // namespace sinsim::errormodels::diagnose::detail
