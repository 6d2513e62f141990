// The value lattice of a recorded series (lattice.hpp).
#include "errormodels/stats/lattice.hpp"

#include "errormodels/stats/allan.hpp"

#include <algorithm>
#include <cmath>

namespace sinsim::errormodels {

double latticeStep(const std::vector<double>& y) {
  const std::size_t n = std::min<std::size_t>(y.size(), 200000);
  double scale = 0;
  for (std::size_t k = 0; k < n; ++k) scale = std::max(scale, std::fabs(y[k]));
  std::vector<double> d;
  d.reserve(n);
  for (std::size_t k = 1; k < n; ++k) {
    const double v = std::fabs(y[k] - y[k - 1]);
    if (v > 1e-12 * scale) d.push_back(v);
  }
  // From 10 differences: among continuous values all 10 within 1 % of integer multiples of the
  // smallest happen with probability ~0.02^9; a channel on which coarse rounding hides nearly all
  // the noise changes value only a few dozen times.
  if (d.size() < 10) return 0.0;
  const double q0 = *std::min_element(d.begin(), d.end());
  // Integer multiples of q0 within 1 % (values printed with a few decimals in a converted unit
  // sit on the lattice to ~1e-3 of a step). Continuous data: only ~2 % of differences do.
  std::size_t on = 0;
  std::vector<double> refined;
  for (double v : d) {
    const double r = v / q0;
    if (r > 1e6) continue;
    const double k = std::nearbyint(r);
    if (std::fabs(r - k) < 0.01) {
      ++on;
      if (k <= 8) refined.push_back(v / k);
    }
  }
  if (double(on) < 0.99 * double(d.size())) return 0.0;
  auto mid = refined.begin() + std::ptrdiff_t(refined.size() / 2);
  std::nth_element(refined.begin(), mid, refined.end());
  return *mid;  // the median step
}

double oneSampleAvarScatter(const std::vector<double>& y) {
  if (y.size() < 3) return 0.0;
  AllanOptions ao;
  ao.factors = {1};
  ao.confidence_intervals = false;
  // AVAR at one sample is half the mean squared difference: the rate given does not enter.
  const auto c = allanDeviation(y, 1.0, AllanVariant::Overlapping, ao);
  return c.dev.empty() ? 0.0 : std::sqrt(3.0 / double(y.size())) * c.dev.front() * c.dev.front();
}

bool latticeVisible(const std::vector<double>& y, double q, bool carried) {
  return q > 0 && q * q / (carried ? 4.0 : 12.0) > oneSampleAvarScatter(y);
}

}  // namespace sinsim::errormodels
