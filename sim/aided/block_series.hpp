// The filter's Φ and Qd over one step from their series, block by block: the navigation rows only.
// The error-state model has the shape
//   F = [[A, B], [0, F_s]],  Qc = [[Q_n, 0], [0, Q_s]],  B = [g_1 c_1, g_2 c_2, ...],
// F_s = diag(F_1, F_2, ...), Q_s = diag(Qc_1, Qc_2, ...): 9 INS error states driven by sensor
// blocks b (each enters through one input column g_b times its output row c_b). The sensor blocks'
// own Φ_b, Qd_b do not depend on the navigation and are constant for a given step (the filter
// caches them), so only the 9 navigation rows of Φ and Qd change from step to step. Their series
// (discretize.hpp: Φ = Σ (F T)^k/k!, Qd = Σ M_k T^(k+1)/(k+1)!, M_{k+1} = F M_k + M_k Fᵀ) taken by
// blocks, with M_ss = diag(M_b) block diagonal at every k:
//   Φ_k:  [n]  ← A T Φ_n,                  [b] ← A T Φ_b' + T g_b c_b (F_b T)^(k−1)/(k−1)!
//   M_k:  [nn] ← X + Xᵀ, X = A M_nn + Σ_b g_b c_b M_bn,
//         [nb] ← A M_nb + g_b c_b M_bb + M_nb F_bᵀ,   M_bb ← F_b M_bb + M_bb F_bᵀ
// (scaled by T/k and T/(k+1) as in discretize). Cost per term: the non-zeros of A times (9 + q)
// plus O(9 q) for the blocks, instead of the non-zeros of F times (9 + q) twice over the whole
// matrix; the same terms, so the same sums to rounding.
#pragma once

#include <vector>

#include <Eigen/Core>

namespace sinsim::sim::aided {

/// One sensor block of the continuous model as the navigation rows see it.
struct InputBlock {
  int column = 0;                 // first column of the block in the navigation rows (>= 9)
  Eigen::Matrix<double, 9, 1> g;  // input column into the INS errors
  Eigen::RowVectorXd c;           // sensor error = c x_b
  Eigen::MatrixXd F, Qc;          // the block's own continuous dynamics and noise
};

/// The navigation rows [Φ_nn Φ_ns] and [Qd_nn Qd_ns] (9 × n, n = 9 + the blocks' states, columns
/// the blocks' `column`s; columns of no block are left zero) of the model (A, Q_n, blocks) over
/// T [s]. Returns false (outputs unspecified) when a process is too fast for one series step
/// (|F_ii| T > 1, on A's or a block's diagonal) or the series does not reach its tolerance (a term
/// below 2^-40 of the largest entry) within 40 terms: the caller then discretises the whole system with discretize().
bool navigationRowSeries(const Eigen::Matrix<double, 9, 9>& A, const Eigen::Matrix<double, 9, 9>& Qn,
                         const std::vector<InputBlock>& blocks, int n, double T,
                         Eigen::Matrix<double, 9, Eigen::Dynamic>& PhiN,
                         Eigen::Matrix<double, 9, Eigen::Dynamic>& QdN);

}  // namespace sinsim::sim::aided
