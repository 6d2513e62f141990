// Gaussian-equivalent z of p-values and t statistics (significance.hpp).
#include "errormodels/diagnose/significance.hpp"

#include <algorithm>
#include <cmath>

#include "errormodels/diagnose/series_tools.hpp"
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

double jumpZ(const std::vector<double>& y, const std::vector<std::size_t>& factors) {
  double pMin = 1;
  std::size_t tested = 0;
  for (auto m : factors) {
    const auto wm = windowMeans(y, m);
    if (wm.size() < 33 || wm.size() > 4097) continue;
    std::vector<double> d(wm.size() - 1);
    for (std::size_t j = 0; j < d.size(); ++j) d[j] = wm[j + 1] - wm[j];
    const double med = median(d);
    std::vector<double> dev(d.size());
    for (std::size_t j = 0; j < d.size(); ++j) dev[j] = std::fabs(d[j] - med);
    const double scale = 1.482602218505602 * median(dev);
    tested += d.size();
    if (!(scale > 0)) continue;
    const double zMax = *std::max_element(dev.begin(), dev.end()) / scale;
    pMin = std::min(pMin, std::erfc(zMax / std::sqrt(2.0)));
  }
  return tested ? zFromTwoSidedP(double(tested) * pMin) : 0.0;
}

}  // namespace sinsim::errormodels::diagnose::detail
