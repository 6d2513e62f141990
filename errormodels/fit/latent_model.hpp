// A composite latent error process of one sensor channel, as GMWM calls it (Guerrier, Skaloud,
// Stebler & Victoria-Feser 2013, "Wavelet-variance-based estimation for composite stochastic
// processes", JASA 108(503)): independent terms whose Allan variances add.
//
// Terms and their Allan variance at tau = m dt (m >= 1, dt the record's sample interval), each
// exact for the process as a static IMU record holds it (rate = increment / dt):
//   quantization Q   3 Q^2 / tau^2        increment rounding with carry: the rate error is
//                                         (e_k - e_{k-1}) / dt, e white of variance Q^2 [(U s)^2]
//                                         (IEEE Std 952-1997 Annex C; exact for white e)
//   white N          N^2 / tau            continuous white noise averaged over each interval
//   flicker B        (2 ln 2 / pi) B^2    two-sided PSD B^2 / (2 pi f): the flat floor (IEEE 952
//                                         C); exact for a 1/f process over the tau it spans
//   random walk K    K^2 tau / 3          continuous Brownian bias averaged over each interval
//   drift R          R^2 tau^2 / 2        deterministic ramp of slope R
// (the five above are fit::allanModelAdev's, their one home), and per Gauss-Markov term (sigma, T)
// the discrete first-order GM, i.e. AR(1) at the record's interval, phi = exp(-dt / T),
// autocovariance sigma^2 phi^|k|. Its Allan variance, from AVAR = Var(mean of m) - Cov(two
// adjacent means of m) summed in closed form:
//   AVAR(m) = sigma^2 [m (1 - phi^2) - phi (1 - phi^m)(3 - phi^m)] / (m^2 (1 - phi)^2)
// (m = 1: sigma^2 (1 - phi); dt -> 0 with m dt = tau: the continuous IEEE 952 C form
// 2 sigma^2 T / tau [1 - T (3 - 4 e^{-tau/T} + e^{-2 tau/T}) / (2 tau)]). The fitted GM is written
// with `rate:` = the record's rate, so the simulator draws exactly this AR(1).
// An **averaged** GM (GmTerm::averaged) is the continuous GM as an integrating or decimating sensor
// outputs it: each sample the mean over its interval. Averages of m such samples are averages over
// tau = m dt of the continuous process, so its Allan variance is the continuous form above at every
// m, exactly; its samples have autocovariance c0 = 2 sigma^2 (u - 1 + e^{-u}) / u^2 (u = dt / T) and
// c_k = sigma^2 (1 - phi)^2 phi^(k-1) / u^2 for k >= 1 (an ARMA(1,1)). Written without `rate:`, it is
// the simulator's continuous GM (errormodels/effects/gm_process.hpp draws exactly these averages).
//
// An AR(p) term (sinsim fit --kind ar+slow, fit/ar_slow_fit.hpp): the polynomial
// A(z) = 1 + a1 z^-1 + ... + ap z^-p of a Burg fit held fixed, its driving variance E a variance
// coefficient like the others; its Allan variance is ar::allanVariance (exact at the record's
// interval), its PSD E / |A(e^{iw})|^2.
//
// Quantization on a value lattice (LatentModel::lattice active, fit/lattice_rounding.hpp): where
// the true integral moves less than the LSB per sample the rounding errors are correlated; the
// quantization term's Allan variance and PSD are then the rounding's exact forms, scaled by
// 12 Q^2 / D^2 (1 at Q = D / sqrt(12), the lattice's own Q).
//
// Units: U is the channel's SI unit (rad/s, m/s^2). Q [U s], N [U sqrt(s)], B [U], K [U/sqrt(s)],
// R [U/s], sigma [U], T [s].
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "errormodels/fit/allan_fit.hpp"
#include "errormodels/fit/lattice_rounding.hpp"

namespace sinsim::errormodels::fit {

/// A first-order Gauss-Markov term.
struct GmTerm {
  double sigma = 0.0;     ///< [U] stationary standard deviation
  double tau = 0.0;       ///< [s] correlation time
  bool averaged = false;  ///< each sample the mean over its interval (else the AR(1) sampled)
};

/// The composite model; a term is absent when its coefficient is 0 (no GM: empty list).
struct LatentModel {
  double quantization = 0.0;  ///< Q [U s]
  double white = 0.0;         ///< N [U sqrt(s)]
  double flicker = 0.0;       ///< B [U]
  double randomWalk = 0.0;    ///< K [U / sqrt(s)]
  double drift = 0.0;         ///< R [U / s]
  std::vector<GmTerm> gm;     ///< first-order GM terms, in increasing tau
  /// AR(p) term: [1, a1..ap] (empty: none) and its driving variance E [U^2] (0: absent).
  std::vector<double> arPolynomial;
  double arVariance = 0.0;
  /// The lattice the quantization rounds to and the true integral's motion (inactive: the
  /// classical white rounding error, 3 Q^2 / tau^2).
  RoundingLattice lattice;

  /// "ar + gm + random_walk": the terms present, in the order quantization, white, ar, gm,
  /// flicker, random_walk, drift.
  std::string termNames() const;
};

/// Allan variance [U^2] of the discrete GM (AR(1)) with variance s2 [U^2], correlation time T [s],
/// sampled at dt [s], at tau = m dt. Throws InputError for m = 0 or non-positive T, dt.
double gmDiscreteAllanVariance(double s2, double T, double dt, std::size_t m);

/// Allan variance [U^2] of the averaged GM (GmTerm::averaged): the continuous GM of variance s2
/// [U^2] and correlation time T [s] averaged over tau = m dt. Throws InputError for m = 0 or
/// non-positive T, dt.
double gmAveragedAllanVariance(double s2, double T, double dt, std::size_t m);

/// The GM term's Allan variance at tau = m dt in its convention (discrete or averaged).
double gmAllanVariance(const GmTerm& g, double dt, std::size_t m);

/// Allan variance [U^2] of flicker noise **sampled** at each instant rather than averaged over
/// the interval: the digital 1/f noise of spectral synthesis, one-sided PSD B^2 / (pi f) up to the
/// Nyquist frequency, whose means of m samples see the discrete Allan filter:
///   AVAR(m) = (B^2 / pi) int_0^{1/2} 2 sin^4(pi m x) / (m^2 x sin^2(pi x)) dx     (x = f dt)
/// (Gauss-Legendre on panels of 1/(8m); 1.189 x the floor at m = 1, i.e. (gamma + ln pi - Ci(pi))
/// / (2 ln 2); the floor (2 ln 2 / pi) B^2 beyond m = 4096, where the two differ by < 1e-7).
/// The fit's flicker term is the floor at every m (the averaged process); this one is the other
/// discretisation its 1-sigma allows for (LatentParameter::flickerConventionShift). Throws
/// InputError for m = 0.
double flickerSampledAllanVariance(double B2, std::size_t m);

/// Allan variance [U^2] of the composite model at tau = m dt for each m (>= 1).
std::vector<double> latentAllanVariance(const LatentModel& model, double dt,
                                        const std::vector<std::size_t>& m);

/// Discrete two-sided PSD of the model's random terms [U^2 per rad/sample] at w in (0, pi]
/// (normalised so that (1/pi) int_0^pi = the sample variance); the drift is deterministic and
/// adds nothing. For the covariance of Allan-variance estimates (fit::allanEstimateCovariance).
double latentPsd(const LatentModel& model, double dt, double w);

/// latentPsd as a function of w alone, with what does not depend on w (the five terms'
/// coefficients, the lattice's scale, each GM's phi and lag covariances) computed once: for the
/// thousands of frequencies of a covariance or a Whittle column. Written in s = sin(w/2), which
/// a quadrature may already have (the second form): a GM's |1 - phi e^{-iw}|^2 is
/// (1 - phi)^2 + 4 phi s^2, free of the cancellation of 1 - 2 phi cos w + phi^2 at a slow GM's
/// low frequencies (phi -> 1, w -> 0).
class LatentSpectrum {
 public:
  LatentSpectrum(const LatentModel& model, double dt);
  double operator()(double w) const;
  double operator()(double w, double s) const;  ///< s = sin(w / 2)

 private:
  struct Gm {
    bool averaged;
    double omPhi;      // 1 - phi, phi = e^{-dt/T}
    double omPhi2;     // (1 - phi)^2
    double fourPhi;    // 4 phi
    double num;        // sampled: sigma^2 (1 - phi^2)
    double c0, twoC1;  // averaged: c0, 2 c1
  };
  double dt_;
  std::array<double, kAllanTermCount> theta_;  // fit::allanTermsPsd's (the ramp's 0)
  bool anyAllanTerm_;
  double latticeScale_;
  RoundingLattice lattice_;
  std::vector<Gm> gm_;
  std::vector<double> arPolynomial_;
  double arVariance_;
};

/// One-step prediction error variance [U^2] of the model's random terms sampled at dt: the
/// variance left when the whole past predicts the next sample (Kolmogorov-Szego:
/// exp((1/pi) int_0^pi ln latentPsd dw); midpoint rule on 2^15 frequencies, whose error at the
/// log singularities of a walk, flicker or quantization at w = 0 is < 1e-4 relative). What a
/// Burg AR of the record should reach if these terms are all its correlation. Throws InputError
/// when the model has no random term.
double latentInnovationVariance(const LatentModel& model, double dt);

}  // namespace sinsim::errormodels::fit
