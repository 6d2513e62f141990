#include "sim/aided/kalman.hpp"

#include <Eigen/Cholesky>

#include "common/error.hpp"

namespace sinsim::sim::aided {

void kalmanPredict(Eigen::VectorXd& x, Eigen::MatrixXd& P, const Eigen::MatrixXd& Phi,
                   const Eigen::MatrixXd& Qd) {
  x = Phi * x;
  P = Phi * P * Phi.transpose() + Qd;
  P = 0.5 * (P + P.transpose()).eval();
}

void kalmanPredict(Eigen::VectorXd& x, Eigen::MatrixXd& P, const BlockTransition& Phi,
                   const Eigen::MatrixXd& Qd) {
  const Eigen::Index n = P.rows();
  Eigen::VectorXd xn(n);
  xn.head<9>().noalias() = Phi.nav * x;
  Eigen::MatrixXd Y(n, n);  // Φ P
  Y.topRows<9>().noalias() = Phi.nav * P;
  for (std::size_t b = 0; b < Phi.block.size(); ++b) {
    const Eigen::Index o = Phi.offset[b], s = Phi.block[b].rows();
    if (s == 1) {  // one-state blocks (most): a scale, without a product's dispatch
      const double f = Phi.block[b](0, 0);
      xn[o] = f * x[o];
      Y.row(o) = f * P.row(o);
      continue;
    }
    xn.segment(o, s).noalias() = Phi.block[b] * x.segment(o, s);
    Y.middleRows(o, s).noalias() = Phi.block[b] * P.middleRows(o, s);
  }
  x = xn;
  P.leftCols<9>().noalias() = Y * Phi.nav.transpose();  // (Φ P Φᵀ) by column blocks
  for (std::size_t b = 0; b < Phi.block.size(); ++b) {
    const Eigen::Index o = Phi.offset[b], s = Phi.block[b].rows();
    if (s == 1)
      P.col(o) = Phi.block[b](0, 0) * Y.col(o);
    else
      P.middleCols(o, s).noalias() = Y.middleCols(o, s) * Phi.block[b].transpose();
  }
  P += Qd;
  P = 0.5 * (P + P.transpose()).eval();
}

Innovation kalmanUpdate(Eigen::VectorXd& x, Eigen::MatrixXd& P, const Eigen::VectorXd& z,
                        const Eigen::MatrixXd& H, const Eigen::MatrixXd& R) {
  Innovation in;
  in.nu = z - H * x;
  const Eigen::MatrixXd PHt = P * H.transpose();
  in.S = H * PHt + R;
  const Eigen::LLT<Eigen::MatrixXd> llt(in.S);
  if (llt.info() != Eigen::Success)
    throw InputError("Kalman update: innovation covariance is not positive definite");
  const Eigen::MatrixXd K = llt.solve(PHt.transpose()).transpose();  // P Hᵀ S⁻¹
  in.nis = in.nu.dot(llt.solve(in.nu));
  x += K * in.nu;
  const Eigen::MatrixXd A = P - K * PHt.transpose();  // (I − K H) P
  P = A - (A * H.transpose()) * K.transpose() + K * R * K.transpose();
  P = 0.5 * (P + P.transpose()).eval();
  return in;
}

}  // namespace sinsim::sim::aided
