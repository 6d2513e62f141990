#include "errormodels/ar_model.hpp"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

#include "common/error.hpp"

namespace sinsim::errormodels::ar {

std::vector<std::complex<double>> poles(const std::vector<double>& a) {
  const int p = int(a.size());
  if (p == 0) return {};
  // Companion matrix of z^p + a1 z^(p-1) + ... + ap: first row -a, ones on the sub-diagonal.
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(p, p);
  for (int i = 0; i < p; ++i) C(0, i) = -a[i];
  for (int i = 1; i < p; ++i) C(i, i - 1) = 1.0;
  Eigen::EigenSolver<Eigen::MatrixXd> es(C, false);
  std::vector<std::complex<double>> out;
  for (int i = 0; i < p; ++i) out.push_back(es.eigenvalues()[i]);
  return out;
}

double largestPoleMagnitude(const std::vector<double>& a) {
  double m = 0.0;
  for (const auto& z : poles(a)) m = std::max(m, std::abs(z));
  return m;
}

double longRunVariance(const std::vector<double>& a, double drivingVariance) {
  double A1 = 1.0;
  for (double v : a) A1 += v;
  return drivingVariance / (A1 * A1);
}

std::vector<double> autocovarianceOfVariance(const std::vector<double>& a, double drivingVariance,
                                             std::size_t maxLag) {
  if (!(largestPoleMagnitude(a) < 1.0))
    throw InputError("AR autocovariance: the polynomial is not stable (a pole on or outside the "
                     "unit circle)");
  if (!(std::isfinite(drivingVariance) && drivingVariance >= 0.0))
    throw InputError("AR autocovariance: driving variance must be finite and >= 0");
  const int p = int(a.size());
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(p + 1, p + 1);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(p + 1);
  for (int k = 0; k <= p; ++k) {
    M(k, k) += 1.0;
    for (int i = 1; i <= p; ++i) M(k, std::abs(k - i)) += a[i - 1];
  }
  rhs(0) = drivingVariance;
  Eigen::VectorXd r0 = M.fullPivLu().solve(rhs);
  std::vector<double> r(std::max(maxLag, std::size_t(p)) + 1);
  for (int k = 0; k <= p; ++k) r[k] = r0(k);
  for (std::size_t k = p + 1; k < r.size(); ++k) {
    double s = 0.0;
    for (int i = 1; i <= p; ++i) s -= a[i - 1] * r[k - i];
    r[k] = s;
  }
  r.resize(maxLag + 1);
  return r;
}

std::vector<double> autocovariance(const std::vector<double>& a, double sigmaE, int maxLag) {
  return autocovarianceOfVariance(a, sigmaE * sigmaE, std::size_t(std::max(maxLag, 0)));
}

double varianceGain(const std::vector<double>& a) { return autocovarianceOfVariance(a, 1.0, 0)[0]; }

std::vector<double> allanVariance(const std::vector<double>& a, double drivingVariance,
                                  const std::vector<std::size_t>& m) {
  std::size_t mMax = 0;
  for (std::size_t v : m) {
    if (v == 0) throw InputError("AR Allan variance: averaging factors must be >= 1");
    mMax = std::max(mMax, v);
  }
  const std::vector<double> g = autocovarianceOfVariance(a, drivingVariance, 2 * mMax);
  std::vector<double> out;
  out.reserve(m.size());
  for (std::size_t mm : m) {
    const double md = static_cast<double>(mm);
    // Var(ybar) = (1/m^2) sum_{|j|<m} (m - |j|) gamma_j
    double var = md * g[0];
    for (std::size_t j = 1; j < mm; ++j) var += 2.0 * (md - static_cast<double>(j)) * g[j];
    // Cov(ybar_k, ybar_{k+1}) = (1/m^2) sum_{|j|<m} (m - |j|) gamma_{m+j}
    double cov = md * g[mm];
    for (std::size_t j = 1; j < mm; ++j)
      cov += (md - static_cast<double>(j)) * (g[mm + j] + g[mm - j]);
    out.push_back((var - cov) / (md * md));
  }
  return out;
}

}  // namespace sinsim::errormodels::ar
