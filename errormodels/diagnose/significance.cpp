// Gaussian-equivalent z of p-values and t statistics (significance.hpp).
#include "errormodels/diagnose/significance.hpp"

#include <cmath>

namespace sinsim::errormodels::diagnose::detail {

double zFromTwoSidedP(double p) {
  if (!(p > 0)) return kMaxScore;
  if (p >= 1) return 0.0;
  double lo = 0, hi = kMaxScore;
  for (int i = 0; i < 200 && hi - lo > 1e-12; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (std::erfc(mid / std::sqrt(2.0)) > p) lo = mid;
    else hi = mid;
  }
  return 0.5 * (lo + hi);
}

double zUpperBisect(double p) {
  double lo = 0, hi = 40;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (std::erfc(mid / std::sqrt(2.0)) > p) lo = mid;
    else hi = mid;
  }
  return hi;
}

double zFromStudentT(double t, double nu) {
  if (!(nu > 0)) return 0.0;
  return std::sqrt(nu * std::log1p(t * t / nu)) * (8 * nu + 1) / (8 * nu + 3);
}

}  // namespace sinsim::errormodels::diagnose::detail
