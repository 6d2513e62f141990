#include "sim/aided/discretize.hpp"

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

}  // namespace sinsim::sim::aided
