// Quantization of a record on a value lattice when the true signal moves less than the LSB per
// sample: the Allan variance and PSD of the rounding, exact at second order.
//
// An integrating output rounds the true integral theta_k (angle, velocity) to its LSB D and
// differences it: y_k = (R_k - R_{k-1}) / dt, R_k = D round(theta_k / D) = theta_k + e_k. The
// classical quantization noise (3 Q^2 / tau^2, Q = D / sqrt(12); latent_model.hpp) takes e white
// and uniform, true when theta moves several LSB per sample. When it moves less (a quiet sensor,
// a coarse register), successive roundings see nearly the same fractional part and e is
// correlated: at tau = dt the Allan variance of a record whose per-sample motion s is 0.2 D is
// ~25 % below 3 Q^2 / tau^2, and a fit with the classical form fails the short-tau points.
//
// The model (the one our quantization effect realises with carry): theta has a uniformly
// distributed phase on the lattice (any bias or start), per-sample increments of mean mu (the
// record's mean times dt) and independent Gaussian parts of variance s^2 (the white noise: s =
// N sqrt(dt)). With X_k = theta_k - theta_0 ~ N(k mu, k s^2), and the phase uniform, e is
// uncorrelated with every increment of theta (E over the phase of e(phase + x) is 0 for any x),
// so the record's Allan variance is the terms' plus the rounding's:
//   AVAR_e(m) = E[(e_{2m} - 2 e_m + e_0)^2] / (2 m^2 dt^2) = (8 g(m) - 2 g(2m)) / (2 m^2 dt^2),
//   g(k) = E[e_0^2] - E[e_0 e_k] = (D^2 / 2) E[h(frac(X_k / D))], h(f) = f (1 - f)
// (E[e(u) e(u + x)] over the phase is D^2 (1/12 - h(frac(x/D)) / 2): the covariance of two
// roundings a shift x apart). E[h(frac(Z))] for Gaussian Z: by the Fourier series
// h(f) = 1/6 - sum_n cos(2 pi n f) / (pi^2 n^2), E = 1/6 - sum_n cos(2 pi n a) exp(-2 pi^2 n^2 v)
// / (pi^2 n^2) (a, v the mean and variance of Z) where v is not small, else cell by cell from the
// truncated Gaussian moments (both exact; they meet at sd(Z) = 0.3). s >> D: g(k) = D^2/12 for
// k >= 1, the classical 3 Q^2 / tau^2.
//
// The PSD (two-sided, per rad/sample, latentPsd's normalisation): e's autocovariance is
// sum_n D^2/(2 pi^2 n^2) phi_n^|k| cos(beta_n k), phi_n = exp(-2 pi^2 n^2 s^2 / D^2),
// beta_n = 2 pi n mu / D, so
//   S(w) = 4 sin^2(w/2) / dt^2 [D^2/12 + sum_n D^2/(2 pi^2 n^2) (K_n(w) - 1)],
//   K_n(w) = (P_n(w - beta_n) + P_n(w + beta_n)) / 2, P_n(w) = (1 - phi_n^2) / |1 - phi_n e^{iw}|^2,
// the n with phi_n < 1e-9 left out (their K_n is 1 to that level); s below 5e-4 D is taken as
// 5e-4 D there (at most 2000 lines).
//
// Units: U the channel's SI unit; D, s, mu [U s] (increments of the integral per sample).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Dense>

namespace sinsim::errormodels::fit {

/// The lattice a quantization rounds the integral to, and the motion of the true integral.
struct RoundingLattice {
  double step = 0.0;    ///< D [U s]: the increment LSB (the value lattice's step x dt)
  double motion = 0.0;  ///< s [U s]: sd of the true integral's random per-sample increment
  double drift = 0.0;   ///< mu [U s]: its mean per-sample increment (the record's mean x dt)
  /// Whether the rounding is modelled (step > 0 and a motion to correlate it): else the
  /// classical white rounding error.
  bool active() const { return step > 0.0 && motion > 0.0; }
  /// Whether the correlation matters: exp(-2 pi^2 s^2 / D^2) above 1e-9 (s < 1.03 D); above, the
  /// classical form is exact to 1e-9 relative.
  bool correlated() const;
};

/// E[f (1 - f)], f = frac(Z), Z ~ N(mean, sd^2) (sd >= 0).
double expectedFracProduct(double mean, double sd);

/// Allan variance [U^2] at tau = m dt (m >= 1) of the rounding error's rate (e_k - e_{k-1}) / dt
/// on the active lattice L (Q = D / sqrt(12)). Throws InputError for m = 0, dt <= 0 or an
/// inactive lattice.
double latticeQuantizationAllanVariance(const RoundingLattice& L, double dt, std::size_t m);

/// Its two-sided PSD [U^2 per rad/sample] at w in (0, pi] (latentPsd's normalisation).
double latticeQuantizationPsd(const RoundingLattice& L, double dt, double w);

/// Covariance [U^4] of the overlapping Allan-variance estimates at the factors m (increasing,
/// each <= 2^18 / 10) of a record of n samples of white increments of sd L.motion rounded on L
/// (the rate (R_k - R_{k-1}) / dt, R the rounded integral), by Monte Carlo: `realisations` records
/// of min(n, 2^18) samples (seeded, deterministic), the covariance scaled by that length over n.
/// Correlated rounding is far from Gaussian: at 0.13 LSB per sample the estimates at tau = dt
/// scatter 2.7x (in sd) what the Gaussian (Isserlis) covariance of the same PSD says, and those
/// at dt..16 dt move together (docs/fitting-log.md, "Quantization below one LSB per sample").
Eigen::MatrixXd latticeAllanCovariance(const RoundingLattice& L, double dt, std::size_t n,
                                       const std::vector<std::size_t>& m, int realisations,
                                       std::uint64_t seed);

/// The motion s [U s] at which white increments of sd s rounded on the lattice (step D, drift mu
/// of L; its motion ignored) have the Allan variance avar1 [U^2] at tau = dt: the root of
/// s^2 / dt^2 + latticeQuantizationAllanVariance(m = 1) = avar1, increasing in s (bisection in
/// ln s over [1e-6 D, 10 D]). 0 when avar1 is at or below the value at 1e-6 D, 10 D when above
/// the value there (the rounding then uncorrelated). Throws InputError for a step or dt <= 0.
double latticeMotionFromAllan(const RoundingLattice& L, double dt, double avar1);

}  // namespace sinsim::errormodels::fit
