#include "sim/aided/step_aggregation.hpp"

#include <vector>

#include <Eigen/Eigenvalues>

#include "common/error.hpp"

namespace sinsim::sim::aided {
namespace {

// One sample of the joint recursion (a, μ) for every column: μ from y = c a held over the
// sample, then a ← A a. coef[d] = h'^d / d!, d = 0..K+1.
void sampleStep(const StateBlock& b, const std::vector<double>& coef, Eigen::MatrixXd& a,
                Eigen::MatrixXd& mu) {
  const Eigen::RowVectorXd y = b.c * a;
  const int K = static_cast<int>(mu.rows()) - 1;
  for (int k = K; k >= 0; --k) {  // descending: μ_{k−d}, d ≥ 1, are still the old values
    Eigen::RowVectorXd v = coef[k + 1] * y;
    for (int d = 1; d <= k; ++d) v += coef[d] * mu.row(k - d);
    mu.row(k) += v;  // coef[0] = 1
  }
  a = (b.A * a).eval();
}

}  // namespace

StepAggregation aggregateBlock(const StateBlock& b, double T, int order) {
  if (!b.discrete) throw InputError("step aggregation: only a discrete (sampled) block has one");
  if (order < 0) throw InputError("step aggregation: negative series order");
  const int m = samplesPerStep(b, T);
  const int p = b.size;
  std::vector<double> coef(order + 2);
  coef[0] = 1.0;
  for (int d = 1; d <= order + 1; ++d) coef[d] = coef[d - 1] / (double(m) * d);

  StepAggregation g;
  g.samples = m;
  g.order = order;
  // Response to the step's initial state a[0].
  Eigen::MatrixXd a = Eigen::MatrixXd::Identity(p, p);
  Eigen::MatrixXd mu = Eigen::MatrixXd::Zero(order + 1, p);
  for (int n = 0; n < m; ++n) sampleStep(b, coef, a, mu);
  g.Phi = a;
  g.PhiMu = mu;

  // The noise e[n] (covariance Qs = S Sᵀ) enters a[n+1]; l = m − 1 − n samples of the step remain
  // after it. Its contribution after those l samples is (A^l S, μ(l)); summed over l = 0..m−1.
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(b.Qs);
  const Eigen::MatrixXd S =
      es.eigenvectors() * es.eigenvalues().cwiseMax(0.0).cwiseSqrt().asDiagonal();
  a = S;
  mu = Eigen::MatrixXd::Zero(order + 1, p);
  g.Qd = Eigen::MatrixXd::Zero(p, p);
  g.QdMuA = Eigen::MatrixXd::Zero(order + 1, p);
  g.QdMuMu = Eigen::MatrixXd::Zero(order + 1, order + 1);
  for (int l = 0; l < m; ++l) {
    g.Qd.noalias() += a * a.transpose();
    g.QdMuA.noalias() += mu * a.transpose();
    g.QdMuMu.noalias() += mu * mu.transpose();
    sampleStep(b, coef, a, mu);
  }
  g.Qd = 0.5 * (g.Qd + g.Qd.transpose()).eval();
  g.QdMuMu = 0.5 * (g.QdMuMu + g.QdMuMu.transpose()).eval();
  return g;
}

}  // namespace sinsim::sim::aided
