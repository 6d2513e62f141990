#include "sim/aided/discretize.hpp"

#include <Eigen/SparseCore>
#include <unsupported/Eigen/MatrixFunctions>

namespace sinsim::sim::aided {

DiscreteSystem vanLoan(const Eigen::MatrixXd& F, const Eigen::MatrixXd& Qc, double T) {
  const Eigen::Index n = F.rows();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  A.topLeftCorner(n, n) = -F * T;
  A.topRightCorner(n, n) = Qc * T;
  A.bottomRightCorner(n, n) = F.transpose() * T;
  const Eigen::MatrixXd B = A.exp();  // Padé with scaling and squaring (Higham 2005)
  DiscreteSystem d;
  d.Phi = B.bottomRightCorner(n, n).transpose();
  d.Qd = d.Phi * B.topRightCorner(n, n);
  d.Qd = 0.5 * (d.Qd + d.Qd.transpose()).eval();
  return d;
}

DiscreteSystem discretize(const Eigen::MatrixXd& F, const Eigen::MatrixXd& Qc, double T) {
  const Eigen::Index n = F.rows();
  if (!((F.diagonal().cwiseAbs() * T).maxCoeff() <= 1.0)) return vanLoan(F, Qc, T);
  const Eigen::SparseMatrix<double> FT = (F * T).sparseView();
  DiscreteSystem d;
  d.Phi = Eigen::MatrixXd::Identity(n, n);
  d.Qd = Qc * T;
  Eigen::MatrixXd P = d.Phi;   // (F T)^k / k!
  Eigen::MatrixXd M = d.Qd;    // M_k T^(k+1) / (k+1)!
  constexpr int kMaxTerms = 40;
  constexpr double kTol = 1e-17;  // below rounding of the sum: the series is summed out
  for (int k = 1; k <= kMaxTerms; ++k) {
    P = (FT * P) / double(k);
    Eigen::MatrixXd FM = FT * M;
    M = (FM + FM.transpose()) / double(k + 1);
    d.Phi += P;
    d.Qd += M;
    const double pn = P.lpNorm<Eigen::Infinity>(), mn = M.lpNorm<Eigen::Infinity>();
    if (pn <= kTol * d.Phi.lpNorm<Eigen::Infinity>() &&
        mn <= kTol * d.Qd.lpNorm<Eigen::Infinity>())
      return d;
  }
  return vanLoan(F, Qc, T);
}

}  // namespace sinsim::sim::aided
