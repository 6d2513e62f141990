// The Kalman filter's two covariance steps, in the forms that keep P symmetric and positive
// semi-definite in floating point: prediction P = Φ P Φᵀ + Qd and the Joseph-form update
// (Bucy & Joseph 1968; Grewal & Andrews 2015, eq. 4.39), valid for any gain.
#pragma once

#include <Eigen/Core>

namespace sinsim::sim::aided {

/// x ← Φ x, P ← Φ P Φᵀ + Qd (symmetrised).
void kalmanPredict(Eigen::VectorXd& x, Eigen::MatrixXd& P, const Eigen::MatrixXd& Phi,
                   const Eigen::MatrixXd& Qd);

/// What an update saw: the innovation, its covariance and the normalised innovation squared.
struct Innovation {
  Eigen::VectorXd nu;  // z − H x
  Eigen::MatrixXd S;   // H P Hᵀ + R
  double nis = 0.0;    // νᵀ S⁻¹ ν
};

/// Measurement z = H x + v, E[v vᵀ] = R: x ← x + K ν, P ← (I − K H) P (I − K H)ᵀ + K R Kᵀ with
/// K = P Hᵀ S⁻¹. Throws InputError when S is not positive definite.
Innovation kalmanUpdate(Eigen::VectorXd& x, Eigen::MatrixXd& P, const Eigen::VectorXd& z,
                        const Eigen::MatrixXd& H, const Eigen::MatrixXd& R);

}  // namespace sinsim::sim::aided
