// Exact discretisation of a linear time-invariant stochastic system over one step (Van Loan 1978,
// "Computing integrals involving the matrix exponential", IEEE TAC 23(3); Brown & Hwang 2012,
// §3.9): for ẋ = F x + w, E[w(t) w(s)ᵀ] = Qc δ(t − s), held constant over T,
//   exp([[−F, Qc], [0, Fᵀ]] T) = [[·, Φ⁻¹ Qd], [0, Φᵀ]]   ⇒   Φ = exp(F T), Qd = Φ (Φ⁻¹ Qd).
#pragma once

#include <Eigen/Core>

namespace sinsim::sim::aided {

struct DiscreteSystem {
  Eigen::MatrixXd Phi;  // state transition over T
  Eigen::MatrixXd Qd;   // ∫_0^T exp(F s) Qc exp(F s)ᵀ ds, symmetric
};

/// Φ and Qd of (F, Qc) over T [s] > 0 (Qc symmetric, same size as F). Qd is symmetrised.
DiscreteSystem vanLoan(const Eigen::MatrixXd& F, const Eigen::MatrixXd& Qc, double T);

}  // namespace sinsim::sim::aided
