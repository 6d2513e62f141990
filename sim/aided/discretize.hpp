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
/// The series is summed over a step h with every |F_ii| h <= 1 (no fast decay whose alternating
/// series would cancel): h = T for the slow processes of a navigation filter, else T / 2^s and s
/// doublings Φ(2h) = Φ(h)², Qd(2h) = Φ(h) Qd(h) Φ(h)ᵀ + Qd(h) — where vanLoan's exp(−F T) block
/// overflows (a Gauss-Markov τ of 3 ms over T = 1 s is e^300). vanLoan is the fallback when the
/// series does not reach half an ulp within 40 terms.
DiscreteSystem discretize(const Eigen::MatrixXd& F, const Eigen::MatrixXd& Qc, double T);

}  // namespace sinsim::sim::aided
