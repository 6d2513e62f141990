// Sensor-error states of the GNSS/INS filter, one block per error process of one sensor axis, each
// with its exact discretisation (Brown & Hwang 2012, §3.9 and §4.6; Box, Jenkins & Reinsel 2008,
// §3.2 for AR):
//   bias (constant)      1 state   ẋ = 0                          P0 = sigma²
//   random_walk K        1 state   ẋ = K w                        Qc = K²
//   gauss_markov σ, τ    1 state   ẋ = −x/τ + sqrt(2σ²/τ) w       Qc = 2σ²/τ, P0 = σ²
//     with a rate f      1 state   the held discrete GM, an AR(1) at f (below)
//   ar a1..ap, σ_e, f    p states  companion form at its own rate f (below), held between samples
//   white (density N)    no state: enters the INS errors directly with spectral density N²
//   scale_factor σ       1 state   ẋ = 0, P0 = σ²; the sensor error is x times the axis's measured
//                                  signal (δω = ω_i s, δf = f_i s): its input column changes with
//                                  the motion (error_state_filter.hpp, ScaleInput)
// The AR(p) companion state is x[n] = (y[n], y[n−1], …, y[n−p+1]):
//   x[n+1] = A x[n] + e[n],  A = [[−a1 … −ap], [I_{p−1} 0]],  E[e eᵀ] = σ_e² e1 e1ᵀ,
// so over m samples Φ = A^m and Qd = Σ_{j<m} A^j Q A^jᵀ (exact); P0 is the stationary Toeplitz
// autocovariance r(|i−j|) (errormodels/ar_model.hpp). Over a filter step of many samples the
// INS errors see the step's samples through their time-weighted sums (step_aggregation.hpp).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "sim/aided/discretize.hpp"

namespace sinsim::sim::aided {

/// The states of one error process. The sensor error it adds is c x.
struct StateBlock {
  std::string name;  // "gauss_markov", "ar", ... (for state listings)
  int size = 0;
  // continuous-time process (discrete == false): ẋ = F x + w, E[w wᵀ] = Qc δ
  Eigen::MatrixXd F, Qc;
  // discrete-time process (discrete == true) at `period` [s]: x[n+1] = A x[n] + e, E[e eᵀ] = Qs
  bool discrete = false;
  double period = 0.0;
  Eigen::MatrixXd A, Qs;
  Eigen::RowVectorXd c;  // sensor error = c x
  Eigen::MatrixXd P0;    // initial covariance (stationary where the process has one)
  Eigen::VectorXd x0;    // prior mean (zero unless the model states a known value)
  // A scale-factor block: the sensor error is (c x) times the axis's measured signal [rad/s or
  // m/s^2], c x dimensionless; otherwise c x is the sensor error itself.
  bool scale = false;
};

/// Constant bias with turn-on standard deviation sigma [signal] (>= 0; 0: a known value).
StateBlock biasState(double sigma);
/// Random walk b' = K w, K [signal/sqrt(s)] > 0, starting at 0 with standard deviation sigma0.
StateBlock randomWalkState(double K, double sigma0 = 0.0);
/// Constant scale-factor error of one axis with turn-on standard deviation sigma [-] (>= 0).
StateBlock scaleFactorState(double sigma);
/// First-order Gauss-Markov, stationary sigma [signal] > 0, correlation time tau [s] > 0.
StateBlock gaussMarkovState(double sigma, double tau);
/// A Gauss-Markov sampled at `rate` [Hz] and held (the model's `rate:`): exactly the AR(1)
/// x[n+1] = φ x[n] + σ sqrt(1 − φ²) e[n], φ = exp(−1/(rate τ)), as the truth generates it; a
/// discrete block named "gauss_markov".
StateBlock sampledGaussMarkovState(double sigma, double tau, double rate);
/// AR(p) in the arburg convention (errormodels/ar_model.hpp): coefficients a1..ap (stable),
/// driving-noise standard deviation sigmaE [signal], rate [Hz].
StateBlock arState(const std::vector<double>& a, double sigmaE, double rate);

/// Φ and Qd of one block over T [s]: Van Loan for a continuous block; A^m and Σ A^j Qs A^jᵀ for a
/// discrete one, where T must be a whole number m ≥ 1 of its periods (InputError otherwise).
DiscreteSystem discretizeBlock(const StateBlock& b, double T);

/// Number m of periods of a discrete block in T; throws InputError unless T/period is a whole
/// number ≥ 1 (to 1e-9 relative).
int samplesPerStep(const StateBlock& b, double T);

}  // namespace sinsim::sim::aided
