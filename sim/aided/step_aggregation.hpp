// The exact effect of a sampled (discrete) sensor-error process on the INS errors over one filter
// step much longer than the process's own sample interval: an AR(p) at 1 kHz seen by a 1 Hz
// filter. The process's samples y[n] = c a[n] are held over their interval h (as the truth
// integrates them into the IMU's increments) and drive the INS errors ẋ = F x + g y(t); over the
// step T = m h, with F constant over the step (the filter's linearisation),
//   x(T) = Φ(T) x(0) + ∫_0^T exp(F (T − s)) g y(s) ds
//        = Φ(T) x(0) + T Σ_k (F T)^k g μ_k,   μ_k = ∫_0^1 (1 − σ)^k / k! y(σ T) dσ,
// so everything the process does to the INS errors over the step is its K + 1 moments μ_k
// (μ_0 is the mean of the step's samples). The moments obey, from one sample to the next
// (σ-step h' = 1/m, μ_k(L) = ∫_0^L (L − σ)^k/k! y dσ, dμ_k/dL = μ_{k−1}),
//   μ_k ← Σ_{d=0}^{k} h'^d/d! μ_{k−d} + h'^{k+1}/(k+1)! y[n],   a ← A a + e[n],
// a linear recursion in (a, μ) that depends on the process and m only, not on F. One pass from
// a[0] = I gives the moments' response to the step's initial state, one pass from the noise
// e[n] = e1 injected after each sample gives their exact covariance with each other and with
// a[m]. The filter then needs only the vectors (F T)^k g, k = 0..K, per step: exact (to the
// truncated series, checked to rounding) at the cost of a few 9-vectors instead of m covariance
// propagations of the joint system. Choice and alternatives: docs/aided.md ("AR blocks").
#pragma once

#include <Eigen/Core>

#include "sim/aided/sensor_states.hpp"

namespace sinsim::sim::aided {

/// A discrete block's statistics over one step of m samples. Moments in units of the process's
/// signal (μ_k is dimensionless time-weight × signal); rows are k = 0..order.
struct StepAggregation {
  int samples = 0;         // m
  int order = 0;           // K
  Eigen::MatrixXd Phi;     // A^m (p × p)
  Eigen::MatrixXd Qd;      // Σ_{l<m} A^l Qs A^lᵀ, the state's noise over the step (p × p)
  Eigen::MatrixXd PhiMu;   // (K+1) × p: μ = PhiMu a[0] + noise part
  Eigen::MatrixXd QdMuA;   // (K+1) × p: E[μ a[m]ᵀ] of the noise part
  Eigen::MatrixXd QdMuMu;  // (K+1) × (K+1): E[μ μᵀ] of the noise part
};

/// The moments series' length: (F T)^k / (k+1)! below rounding by k = 24 for the INS error
/// dynamics at any practical filter step (checked per step by the filter).
constexpr int kAggregationOrder = 24;

/// The aggregation of discrete block b over T [s] (a whole number m ≥ 1 of its periods, else
/// InputError). Cost O(m (K + p)²), once per block and step length.
StepAggregation aggregateBlock(const StateBlock& b, double T, int order = kAggregationOrder);

}  // namespace sinsim::sim::aided
