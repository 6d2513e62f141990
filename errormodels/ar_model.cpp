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

std::vector<double> autocovariance(const std::vector<double>& a, double sigmaE, int maxLag) {
  const int p = int(a.size());
  if (!(largestPoleMagnitude(a) < 1.0))
    throw NumericalError("AR autocovariance of a non-stationary polynomial");
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(p + 1, p + 1);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(p + 1);
  for (int k = 0; k <= p; ++k) {
    M(k, k) += 1.0;
    for (int i = 1; i <= p; ++i) M(k, std::abs(k - i)) += a[i - 1];
  }
  rhs(0) = sigmaE * sigmaE;
  Eigen::VectorXd r0 = M.fullPivLu().solve(rhs);
  std::vector<double> r(std::max(maxLag, p) + 1);
  for (int k = 0; k <= p; ++k) r[k] = r0(k);
  for (int k = p + 1; k < int(r.size()); ++k) {
    double s = 0.0;
    for (int i = 1; i <= p; ++i) s -= a[i - 1] * r[k - i];
    r[k] = s;
  }
  r.resize(std::max(maxLag, 0) + 1);
  return r;
}

double varianceGain(const std::vector<double>& a) { return autocovariance(a, 1.0, 0)[0]; }

}  // namespace sinsim::errormodels::ar
