#include "sim/aided/sensor_states.hpp"

#include <cmath>
#include <string>

#include "common/error.hpp"
#include "errormodels/ar_model.hpp"

namespace sinsim::sim::aided {
namespace {

StateBlock scalarBlock(std::string name, double F, double Qc, double P0) {
  StateBlock b;
  b.name = std::move(name);
  b.size = 1;
  b.F = Eigen::MatrixXd::Constant(1, 1, F);
  b.Qc = Eigen::MatrixXd::Constant(1, 1, Qc);
  b.c = Eigen::RowVectorXd::Ones(1);
  b.P0 = Eigen::MatrixXd::Constant(1, 1, P0);
  b.x0 = Eigen::VectorXd::Zero(1);
  return b;
}

void requirePositive(double v, const char* what) {
  if (!(std::isfinite(v) && v > 0.0))
    throw InputError(std::string("filter sensor state: ") + what + " must be positive and finite");
}

}  // namespace

StateBlock biasState(double sigma) {
  if (!(std::isfinite(sigma) && sigma >= 0.0))
    throw InputError("filter sensor state: bias sigma must be >= 0");
  return scalarBlock("bias", 0.0, 0.0, sigma * sigma);
}

StateBlock scaleFactorState(double sigma) {
  if (!(std::isfinite(sigma) && sigma >= 0.0))
    throw InputError("filter sensor state: scale-factor sigma must be >= 0");
  StateBlock b = scalarBlock("scale_factor", 0.0, 0.0, sigma * sigma);
  b.scale = true;
  return b;
}

StateBlock randomWalkState(double K, double sigma0) {
  requirePositive(K, "random-walk coefficient K");
  if (!(std::isfinite(sigma0) && sigma0 >= 0.0))
    throw InputError("filter sensor state: random-walk initial sigma must be >= 0");
  return scalarBlock("random_walk", 0.0, K * K, sigma0 * sigma0);
}

StateBlock gaussMarkovState(double sigma, double tau) {
  requirePositive(sigma, "Gauss-Markov sigma");
  requirePositive(tau, "Gauss-Markov tau");
  return scalarBlock("gauss_markov", -1.0 / tau, 2.0 * sigma * sigma / tau, sigma * sigma);
}

StateBlock arState(const std::vector<double>& a, double sigmaE, double rate) {
  requirePositive(sigmaE, "AR driving-noise sigma");
  requirePositive(rate, "AR rate");
  const int p = static_cast<int>(a.size());
  if (p < 1) throw InputError("filter sensor state: AR needs at least one coefficient");
  if (!(errormodels::ar::largestPoleMagnitude(a) < 1.0))
    throw InputError("filter sensor state: unstable AR polynomial");
  StateBlock b;
  b.name = "ar";
  b.size = p;
  b.discrete = true;
  b.period = 1.0 / rate;
  b.A = Eigen::MatrixXd::Zero(p, p);
  for (int i = 0; i < p; ++i) b.A(0, i) = -a[i];
  if (p > 1) b.A.bottomLeftCorner(p - 1, p - 1).setIdentity();
  b.Qs = Eigen::MatrixXd::Zero(p, p);
  b.Qs(0, 0) = sigmaE * sigmaE;
  b.c = Eigen::RowVectorXd::Zero(p);
  b.c(0) = 1.0;
  const std::vector<double> r = errormodels::ar::autocovariance(a, sigmaE, p);
  b.P0.resize(p, p);
  for (int i = 0; i < p; ++i)
    for (int j = 0; j < p; ++j) b.P0(i, j) = r[std::abs(i - j)];
  b.x0 = Eigen::VectorXd::Zero(p);
  return b;
}

StateBlock sampledGaussMarkovState(double sigma, double tau, double rate) {
  requirePositive(sigma, "Gauss-Markov sigma");
  requirePositive(tau, "Gauss-Markov tau");
  requirePositive(rate, "Gauss-Markov rate");
  const double phi = std::exp(-1.0 / (rate * tau));
  StateBlock b = arState({-phi}, sigma * std::sqrt(-std::expm1(-2.0 / (rate * tau))), rate);
  b.name = "gauss_markov";
  b.P0(0, 0) = sigma * sigma;  // the stationary variance, exactly (not through Yule-Walker)
  return b;
}

int samplesPerStep(const StateBlock& b, double T) {
  const double m = T / b.period;
  const double mr = std::round(m);
  if (!(mr >= 1.0 && std::abs(m - mr) <= 1e-9 * mr))
    throw InputError("filter sensor state: the filter step " + std::to_string(T) +
                     " s is not a whole number of the " + b.name + " process's periods (" +
                     std::to_string(b.period) + " s)");
  return static_cast<int>(mr);
}

DiscreteSystem discretizeBlock(const StateBlock& b, double T) {
  if (!b.discrete) return vanLoan(b.F, b.Qc, T);
  const int m = samplesPerStep(b, T);
  DiscreteSystem d;
  d.Phi = Eigen::MatrixXd::Identity(b.size, b.size);
  d.Qd = Eigen::MatrixXd::Zero(b.size, b.size);
  for (int j = 0; j < m; ++j) {  // after j steps: Φ = A^j, Qd = Σ_{i<j} A^i Qs A^iᵀ
    d.Qd = b.A * d.Qd * b.A.transpose() + b.Qs;
    d.Phi = b.A * d.Phi;
  }
  return d;
}

}  // namespace sinsim::sim::aided
