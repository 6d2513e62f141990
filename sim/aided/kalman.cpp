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
  const Eigen::MatrixXd IKH = Eigen::MatrixXd::Identity(P.rows(), P.cols()) - K * H;
  P = IKH * P * IKH.transpose() + K * R * K.transpose();
  P = 0.5 * (P + P.transpose()).eval();
  return in;
}

}  // namespace sinsim::sim::aided
