// Window and block means, median, least squares (series_tools.hpp).
#include "errormodels/diagnose/series_tools.hpp"

#include <algorithm>
#include <cmath>

namespace sinsim::errormodels::diagnose::detail {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  auto mid = v.begin() + std::ptrdiff_t(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

double robustSd(const std::vector<double>& v) {
  const double med = median(v);
  std::vector<double> dev(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) dev[i] = std::fabs(v[i] - med);
  return kSdPerMad * median(dev);
}

double leastSquares(const Eigen::MatrixXd& X, const Eigen::VectorXd& y, Eigen::VectorXd& beta) {
  beta = X.colPivHouseholderQr().solve(y);
  return (y - X * beta).squaredNorm();
}

BlockMeans blockMeans(const std::vector<double>& y, double dt, std::size_t blocks) {
  BlockMeans out;
  const std::size_t b = std::max<std::size_t>(1, y.size() / blocks);
  const std::size_t nb = y.size() / b;
  out.size = b;
  out.t.resize(nb);
  out.m.resize(nb);
  for (std::size_t j = 0; j < nb; ++j) {
    double s = 0;
    for (std::size_t k = j * b; k < (j + 1) * b; ++k) s += y[k];
    out.m[j] = s / double(b);
    out.t[j] = (double(j * b) + 0.5 * double(b)) * dt;
  }
  return out;
}

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

std::vector<double> windowMeans(const std::vector<double>& y, std::size_t m) {
  std::vector<double> out(y.size() / m);
  for (std::size_t j = 0; j < out.size(); ++j) {
    double s = 0;
    for (std::size_t k = j * m; k < (j + 1) * m; ++k) s += y[k];
    out[j] = s / double(m);
  }
  return out;
}

}  // namespace sinsim::errormodels::diagnose::detail
