// Least-squares trend and its exact scatter (trend.hpp).
#include "errormodels/stats/trend.hpp"

namespace sinsim::errormodels {

double trendSlope(const std::vector<double>& y, double dt) {
  const std::size_t N = y.size();
  double st = 0, sy = 0, stt = 0, sty = 0;
  for (std::size_t k = 0; k < N; ++k) {
    const double t = (double(k) + 0.5) * dt;
    st += t, sy += y[k], stt += t * t, sty += t * y[k];
  }
  return (double(N) * sty - st * sy) / (double(N) * stt - st * st);
}

double trendVarianceFromAcov(const std::vector<double>& acov, std::size_t n, double dt) {
  // slope = sum_i (i - c) y_i / (dt S), c = (N - 1) / 2, S = sum (i - c)^2 = N (N^2 - 1) / 12;
  // Var = (acov_0 S + 2 sum_{h >= 1} acov_h P(h)) / (dt S)^2 with
  // P(h) = sum_{i < N - h} (i - c)(i + h - c) in closed form over the M = N - h terms.
  const double N = double(n);
  if (n < 2 || acov.empty() || !(dt > 0)) return 0.0;
  const double c = 0.5 * (N - 1), S = N * (N * N - 1) / 12;
  double sum = acov[0] * S;
  for (std::size_t h = 1; h < acov.size() && h < n; ++h) {
    const double M = N - double(h);
    const double si = M * (M - 1) / 2, sii = (M - 1) * M * (2 * M - 1) / 6;
    const double su = si - M * c, suu = sii - 2 * c * si + M * c * c;  // sums of u = i - c, u^2
    sum += 2 * acov[h] * (suu + double(h) * su);
  }
  return sum / (dt * dt * S * S);
}

}  // namespace sinsim::errormodels
