// Window and block means, median, least squares (series_tools.hpp).
#include "errormodels/diagnose/series_tools.hpp"

#include <algorithm>
#include <cmath>

namespace sinsim::errormodels::diagnose::detail {

Moments moments(const std::vector<double>& v) {
  Moments m;
  for (double x : v) m.mean += x;
  m.mean /= double(v.size());
  for (double x : v) m.var += (x - m.mean) * (x - m.mean);
  m.var /= double(v.size() - 1);
  return m;
}

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
