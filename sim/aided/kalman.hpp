// The Kalman filter's two covariance steps, in the forms that keep P symmetric and positive
// semi-definite in floating point: prediction P = Φ P Φᵀ + Qd and the Joseph-form update
// (Bucy & Joseph 1968; Grewal & Andrews 2015, eq. 4.39), valid for any gain.
#pragma once

#include <vector>

#include <Eigen/Core>

namespace sinsim::sim::aided {

/// x ← Φ x, P ← Φ P Φᵀ + Qd (symmetrised).
void kalmanPredict(Eigen::VectorXd& x, Eigen::MatrixXd& P, const Eigen::MatrixXd& Phi,
                   const Eigen::MatrixXd& Qd);

/// A transition of the GNSS/INS filter's shape: the 9 navigation rows dense (9 × n), the sensor
/// states block diagonal (Φ_b at offset_b, the blocks tiling states 9 .. n−1; no sensor state is
/// driven by the navigation errors).
struct BlockTransition {
  Eigen::Matrix<double, 9, Eigen::Dynamic> nav;
  std::vector<int> offset;
  std::vector<Eigen::MatrixXd> block;
};

/// The same prediction for a BlockTransition, x ← Φ x, P ← Φ P Φᵀ + Qd (symmetrised), with the
/// products taken by blocks: O(9 n²) for the navigation rows plus the blocks' own, instead of the
/// 2 n³ of the dense products (the same sums of non-zero terms, in another order).
void kalmanPredict(Eigen::VectorXd& x, Eigen::MatrixXd& P, const BlockTransition& Phi,
                   const Eigen::MatrixXd& Qd);

/// What an update saw: the innovation, its covariance and the normalised innovation squared.
struct Innovation {
  Eigen::VectorXd nu;  // z − H x
  Eigen::MatrixXd S;   // H P Hᵀ + R
  double nis = 0.0;    // νᵀ S⁻¹ ν
};

/// Measurement z = H x + v, E[v vᵀ] = R: x ← x + K ν, P ← (I − K H) P (I − K H)ᵀ + K R Kᵀ with
/// K = P Hᵀ S⁻¹, the Joseph form evaluated through the n × m factors in O(n² m):
/// A = (I − K H) P = P − K (P Hᵀ)ᵀ, then A (I − K H)ᵀ + K R Kᵀ = A + (K R − A Hᵀ) Kᵀ; P Hᵀ and
/// A Hᵀ over H's leading non-zero columns only. Throws InputError when S is not positive definite.
Innovation kalmanUpdate(Eigen::VectorXd& x, Eigen::MatrixXd& P, const Eigen::VectorXd& z,
                        const Eigen::MatrixXd& H, const Eigen::MatrixXd& R);

}  // namespace sinsim::sim::aided
