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

/// The same Φ and Qd, from their Taylor series summed to rounding with sparse products when that
/// is safe, else vanLoan. The series (Van Loan 1978, §2; Brown & Hwang 2012, §3.9):
///   Φ = Σ_k (F T)^k / k!,   Qd = Σ_k M_k T^(k+1)/(k+1)!,   M_0 = Qc, M_{k+1} = F M_k + M_k Fᵀ.
/// Used for the GNSS/INS error dynamics, whose F is sparse (≈ 4 non-zeros a row) and nearly
/// nilpotent (the large terms, f_n × ψ and the sensor couplings, form a chain; the eigenvalues
/// are Schuler, Earth rate and the processes' 1/τ): the terms then fall off without
/// cancellation, and each costs a sparse product instead of the dense 2n × 2n Padé products.
/// Safe means: every |F_ii| T <= 1 (no fast decay whose alternating series would cancel) and the
/// terms below 1e-17 of the sum within 40 terms; otherwise the result is vanLoan's.
DiscreteSystem discretize(const Eigen::MatrixXd& F, const Eigen::MatrixXd& Qc, double T);

}  // namespace sinsim::sim::aided
