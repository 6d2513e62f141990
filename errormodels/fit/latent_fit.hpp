// Composite latent-process fit (GMWM-style): white + quantization + one or two first-order
// Gauss-Markov + random walk + flicker + drift, fitted jointly to the overlapping Allan variance
// of a record over all octave tau, with the terms chosen by an information criterion.
//
// Method (Guerrier et al. 2013, JASA 108(503), "GMWM"; the Haar wavelet variance is half the
// Allan variance, so the two criteria are the same up to a factor):
//  1. Allan variance nu_i at tau_i = m_i dt, m = 1, 2, 4, ... <= N / 10 (beyond, < ~10 EDF and
//     the modelled covariance below is unreliable, see identify_terms.hpp usablePoints).
//  2. For a term set, minimise the GLS criterion (nu - nu(theta))' Omega^-1 (nu - nu(theta)).
//     nu(theta) is latent_model.hpp's closed form. It is linear in the variance coefficients
//     (Q^2, N^2, sigma_j^2, B^2, K^2, R^2) and non-linear only in the GM correlation times, so
//     the fit is by variable projection (Golub & Pereyra 1973): the variances by non-negative
//     least squares (Lawson-Hanson) for given T_j, the T_j (log scale) by a grid of starts
//     (factor sqrt 2 over [dt / 2, tau_max] for one GM, tau_max the largest tau used; factor 2, T_2 >= 2 T_1, for two) refined
//     by golden-section search (coordinate-wise for two GMs). This finds the global minimum over
//     T that a Gauss-Newton/LM run from a few slope-read starts may miss (the GM hump can hide
//     under white noise or a random walk).
//  3. Omega: the covariance of the overlapping Allan-variance estimates under a model, from its
//     PSD (fit::allanEstimateCovariance: Isserlis + Parseval, large-sample). Pass 1 selects a
//     preliminary model with diagonal weights 2 nu(theta)^2 / edf (model-based levels, white-noise
//     EDF); Omega is then computed from that model and held FIXED while every candidate set is
//     fitted (pass 2), so their criteria are comparable (GMWM keeps Omega fixed likewise).
//     Finally Omega is recomputed from the winner and the winner refitted once.
//  4. Selection: score = chi^2 + penalty, a term of k parameters (k = 2 for a GM: sigma and T,
//     else 1) costing the 1 % point of the boundary mixture (chi^2_0 + chi^2_k) / 2: 5.41 for
//     k = 1, 7.82 for k = 2 (Self & Liang 1987: a variance on the boundary; a GM's T is a second
//     free parameter). Written as 3.00 per term + 2.41 per parameter (exact at k = 1, 2). A term
//     enters only when it lowers the GLS chi^2 by more than its cost. One flat 5.41 per term (GM
//     included) took white + 2 GM for white + GM + RW in 15/40 seeds (bench/latent_study: the
//     second GM's free T mimics a random walk); 5.41 per parameter took white + GM + flicker for
//     white + 2 GM in 20/40 (docs/fitting.md). A set whose fit puts a variance at the zero bound
//     is not a candidate (it is a smaller set). The runner-up is reported. (In the Whittle and
//     block choices of steps 7-8, a set whose slowest GM beats the same set with that GM replaced
//     by a random walk, its T -> inf limit, by less than a one-parameter term's cost, 5.41, is taken
//     to be that walk set: latent_fit.cpp withoutWalkLikeGms.)
//  5. Uncertainty: p = log of every parameter (variance coefficients and T_j); the Gauss-Newton
//     covariance (J' Omega^-1 J)^-1 of p at the optimum, scaled by max(1, chi^2 / dof) (Birge
//     ratio); 1-sigma of an amplitude A = sqrt(theta) is A sd(p) / 2, of T it is T sd(p).
//     It is conditional on the chosen set.
//  6. Selection-aware parameters (LatentAveragedParameter): every set within 20 of the best score
//     refitted under the final Omega, weighted exp(-delta score / 2), each with its 1-sigma
//     under Omega from its own model; averaged per parameter (Buckland et al. 1997).
//  7. With the record (fitLatentModel(x, ...)) and LatentFitOptions::whittleSelection, the set is
//     chosen by the Whittle likelihood of the record's tapered, detrended periodogram instead
//     (whittle_selection.hpp; every Fourier frequency down to 1 / (N dt) instead of 2-3 Allan
//     points where a random walk lives): the best Whittle score among the sets without drift,
//     started from their Allan fits; drift is added when the slope of the line the periodogram
//     removed is significant under that set's Whittle model (chi^2_1 at 1 %). The parameters and
//     1-sigma are the Allan fit's of the chosen set (steps 2-5); step 6 still weighs the sets by
//     their Allan scores.
//  8. With LatentFitOptions::blockSelection (default), the drift-free sets within 15 of the best
//     Whittle score are rescored by the exact Gaussian likelihood of the record's block means (a
//     Kalman filter; the periodogram above the blocks' band) and the set, with or without drift,
//     chosen by that score (block_likelihood.hpp). Parameters and 1-sigma stay the Allan fit's,
//     but where that likelihood rejects the Allan optimum (beyond the chi^2_k 0.1 % point over its
//     own fit of the set: a GLS parameterisation below every long-tau point), the Allan fit under
//     Omega from the likelihood's model, nearest its optimum, is written instead.
//  Goodness of fit: chi^2, dof = n - k and its p-value over the whole range used.
#pragma once

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "errormodels/fit/latent_model.hpp"

namespace sinsim::errormodels::fit {

/// The terms of a candidate model.
struct LatentTermSet {
  bool quantization = false;
  bool white = true;
  int gm = 0;  ///< 0, 1 or 2 first-order GM terms
  bool flicker = false;
  bool randomWalk = false;
  bool drift = false;
  /// AR(p) term with the polynomial LatentFitOptions::arPolynomial held fixed and its driving
  /// variance fitted (counts 1 parameter; fit/ar_slow_fit.hpp).
  bool ar = false;

  std::size_t parameterCount() const;  ///< GM counts 2
  std::size_t termCount() const;       ///< GM counts 1
  std::string name() const;            ///< "white + gm + random_walk"
  bool operator==(const LatentTermSet& o) const;
};

/// Every set of the terms allowed: white always; quantization, flicker, random walk, drift each
/// on or off; 0..maxGm GM terms (48 sets with everything allowed).
std::vector<LatentTermSet> latentCandidateSets(bool quantization, int maxGm, bool flicker,
                                               bool randomWalk, bool drift);

struct LatentFitOptions {
  double sampleInterval = 0.0;  ///< dt [s] (required)
  /// Candidate term sets; empty: latentCandidateSets(true, 2, true, true, true).
  std::vector<LatentTermSet> candidates;
  double tauMin = 0.0;  ///< [s] Allan points outside [tauMin, tauMax] are not used
  double tauMax = std::numeric_limits<double>::infinity();
  /// [1, a1..ap] of the AR term of sets with `ar` (required by them): the shape is fixed, the
  /// driving variance is fitted with the other variance coefficients.
  std::vector<double> arPolynomial;
  /// Upper bound of that AR's driving variance [U^2] (0: none). The AR + slow fit passes Burg's:
  /// the one-step prediction error of AR + slow terms is at least the AR's own driving variance,
  /// so a joint fit that raises it above Burg's reads the record's mid-tau excess as short-tau
  /// power (fit/ar_slow_fit.hpp).
  double arVarianceMax = 0.0;
  /// Shortest GM correlation time searched, in sample intervals (`sinsim fit --kind gm` uses 2:
  /// a GM faster than that is white noise to a navigation filter at this rate).
  double minGmTauSamples = 0.5;
  /// Start-of-range scan: when the fit over all points is inconsistent (p-value < 0.001), move
  /// the first Allan point up one octave at a time (keeping >= 6 points) and take the first
  /// consistent start, else the one with the smallest chi^2 / dof. Real sensors show features at
  /// short tau no term carries (an internal filter's hump); `sinsim fit` turns this on.
  bool scanStart = false;
  /// Penalty per term in the score (a GM is one term) and per parameter (a GM has two); the
  /// score adds both (latentPenalty). The defaults make a term of k parameters cost the 1 %
  /// point of the boundary mixture (chi^2_0 + chi^2_k) / 2: 5.41 for k = 1, 7.82 for k = 2.
  double penaltyPerTerm = 3.0;
  double penaltyPerParameter = 2.41;
  /// Choose the term set by the Whittle likelihood of the differenced record's periodogram
  /// (whittle_selection.hpp) instead of the Allan GLS score; the parameters and their 1-sigma stay
  /// the Allan fit's. Only the record overload fitLatentModel(x, ...) has a periodogram.
  bool whittleSelection = true;
  /// With whittleSelection: the sets near the Whittle's best are rescored by the exact Gaussian
  /// likelihood of the record's block means with the periodogram above them (block_likelihood.hpp),
  /// and the set chosen by that score.
  bool blockSelection = true;
  /// With blockSelection: the chosen set's Allan parameters are checked against the block
  /// likelihood's own fit of the set, and where the likelihood rejects them (beyond the chi^2_k
  /// 0.1 % point) the Allan fit nearest the likelihood's is written (LatentFit::parameterNote).
  bool likelihoodCheckedParameters = true;
  /// The record's value lattice for a quantization term (fit/lattice_rounding.hpp): step D = the
  /// lattice step x dt, drift = the record's mean x dt. Active (a motion set): the quantization
  /// column is the lattice rounding's exact Allan variance. Step set without a motion: the record
  /// overload fitLatentModel(x, ...) takes s from the record's Allan variance at tau = dt
  /// (fit::latticeMotionFromAllan) and uses the lattice where that s correlates the rounding
  /// (below ~1 LSB per sample). Not used otherwise.
  RoundingLattice lattice;
  /// Whether lattice.motion was read from the record's Allan variance at tau = dt (set by the
  /// record overload): its estimation error then enters the covariance of the rounding's points.
  bool latticeMotionRead = false;
};

/// The score's penalty of a term set: penaltyPerTerm * terms + penaltyPerParameter * parameters.
double latentPenalty(const LatentTermSet& set, const LatentFitOptions& options);
/// The cost a slow GM must beat its walk partner (the GM replaced by a random walk, one parameter
/// fewer) by to stay a GM: one term's and one parameter's penalty (latent_fit.cpp
/// withoutWalkLikeGms).
inline double walkForGmCost(const LatentFitOptions& options) {
  return options.penaltyPerTerm + options.penaltyPerParameter;
}

/// One parameter of the fitted model with its 1-sigma uncertainty (SI of the channel, see
/// latent_model.hpp for the units).
struct LatentParameter {
  std::string name;  ///< "white", "quantization", "gm1.sigma", "gm1.tau", "random_walk", ...
  double value = 0.0;
  /// the delta method's 1-sigma (Gauss-Newton covariance of the log parameters), with the
  /// discretisation shifts below in quadrature
  double stdError = 0.0;
  /// Every parameter also has an interval in ln(value). A GM tau's is the profile likelihood: the
  /// Allan chi^2 minimised over every other parameter rises by the Birge scale (Delta chi^2 = 1,
  /// one parameter) at logCenter - logLower and logCenter + logUpper. An amplitude's is the delta
  /// method's in the space its covariance is computed in (ln of the variance coefficient, halved:
  /// logLower = logUpper = sd(ln theta) / 2). The k-sigma interval is the union of value +-
  /// k stdError and logCenter + [-k logLower, k logUpper]: neither first-order interval is
  /// calibrated at these record lengths, and each missed on one side where the other did not -- a
  /// slow GM's T and a weak walk beside a GM come out low (the ln interval's longer upper side),
  /// the faster of two GMs' T high (docs/fitting-log.md, "Profile-likelihood intervals for the GM
  /// taus", "The amplitudes' interval in ln").
  bool logScale = false;
  double logCenter = 0.0;                 ///< ln(value)
  double logLower = 0.0, logUpper = 0.0;  ///< 1-sigma distances below and above logCenter
  /// The same set fitted with its GMs averaged over each sample interval (GmTerm::averaged, the
  /// continuous GM an integrating sensor outputs) instead of sampled: this parameter's value there
  /// minus `value` (0 without a GM). To first order the two differ at short tau by a 1/tau term,
  /// the shape of white noise, so they fit equally well and the record cannot tell which it holds:
  /// the shift is a 1-sigma of its own, in stdError and in the ln interval (each side; shift /
  /// value there), in quadrature.
  double gmConventionShift = 0.0;
  /// Likewise with the flicker sampled at each instant (digital 1/f noise up to Nyquist,
  /// flickerSampledAllanVariance: 1.19x the floor at tau = dt, decaying within a few samples)
  /// instead of averaged (the fit's floor): this parameter's value there minus `value` (0 without
  /// a flicker term); in stdError and the ln interval the same way (both shifts in quadrature).
  double flickerConventionShift = 0.0;
  /// Whether `truth` lies inside the k-sigma interval (for a tau the union above).
  bool covers(double truth, double k) const;
};

/// A parameter with the uncertainty of the term-set choice included (model averaging: Buckland,
/// Burnham & Augustin 1997, Biometrics 53; Burnham & Anderson 2002, sec. 4.3). Each valid set i
/// gets the weight w_i = exp(-(score_i - score_best) / 2) / sum, the score being a penalised
/// -2 log-likelihood (chi^2 + penalty). Over the sets that have the parameter (weights
/// renormalised to sum 1 among them): value = sum w_i v_i, and the unconditional 1-sigma
/// sum w_i sqrt(se_i^2 + (v_i - value)^2), se_i the set's own 1-sigma (LatentFit::parameters'
/// rule). GM terms are labelled by increasing tau in each set (gm1 the fastest).
struct LatentAveragedParameter {
  std::string name;
  double inclusion = 0.0;  ///< sum of the weights of the sets that have the parameter, in (0, 1]
  double value = 0.0;      ///< its value if the term is present
  double stdError = 0.0;   ///< its 1-sigma, including the spread between sets
  /// The ln-space interval (LatentParameter::logScale) averaged in ln: logCenter = sum w_i ln v_i,
  /// logLower and logUpper = sum w_i sqrt(l_i^2 + (ln v_i - logCenter)^2) with l_i the set's own
  /// (Buckland's eq. 9 on ln v, each side).
  bool logScale = false;
  double logCenter = 0.0, logLower = 0.0, logUpper = 0.0;
  bool covers(double truth, double k) const;  ///< as LatentParameter::covers
};

/// A fitted candidate set and its score.
struct LatentCandidate {
  LatentTermSet terms;
  LatentModel model;
  double chi2 = 0.0;
  double score = 0.0;  ///< chi2 + latentPenalty(terms, options)
  bool valid = false;  ///< every variance strictly positive
  /// -2 log L (Whittle) + latentPenalty, NaN where not scored (drift, AR, no record, invalid).
  double whittleScore = std::numeric_limits<double>::quiet_NaN();
  LatentModel whittleModel;  ///< the Whittle fit behind whittleScore
  /// -2 log L (block means + periodogram above them) + latentPenalty, NaN where not scored.
  double blockScore = std::numeric_limits<double>::quiet_NaN();
  /// The block likelihood's own fit of this set (without drift), where blockScore is finite: the
  /// written parameters are checked against it (Estimator, "Parameters the likelihood rejects").
  LatentModel blockModel;
  /// Chosen by a likelihood as this set + drift, whose own Allan fit put the drift at zero (the
  /// Allan variance sees a ramp through its last octaves alone): the drift is added from the
  /// record's trend (LatentFit::trendDrift).
  bool trendDrift = false;
};

/// How far (as an ADEV ratio, either way) a scanned fit's model may be off the record below its
/// start before fit warns and `--kind auto` prefers whole-range terms to its AR branch.
inline constexpr double kBelowStartTolerance = 1.25;

struct LatentFit {
  LatentTermSet terms;
  LatentModel model;
  std::vector<LatentParameter> parameters;
  Eigen::MatrixXd logCovariance;  ///< of p = log(parameters) in `parameters` order (variances, T)
  double chi2 = 0.0;
  std::size_t dof = 0;
  double pValue = 0.0;     ///< P(chi^2_dof >= chi2)
  bool consistent = true;  ///< pValue >= 0.001 (with scanStart: at the chosen start)
  double birgeScale = 1.0; ///< applied to logCovariance
  double sampleInterval = 0.0;  ///< [s]
  std::size_t samples = 0;      ///< N
  std::vector<std::size_t> m;   ///< averaging factors used
  std::vector<double> tau, avar, modelAvar;  ///< [s], [U^2], [U^2]
  /// Pass-2 fits, the chosen set first. Allan selection: by score (valid first). Whittle
  /// selection: the chosen, then the sets with a Whittle score by it, then the rest by score.
  std::vector<LatentCandidate> candidates;
  bool whittleSelected = false;  ///< the set was chosen by the Whittle score
  bool blockSelected = false;    ///< ... rescored by the block likelihood (then the order is by blockScore)
  /// Every parameter of the valid sets averaged over them (LatentAveragedParameter): the
  /// selection-aware statement, also for terms the chosen set lacks.
  std::vector<LatentAveragedParameter> averaged;
  /// Sanity findings (GM tau < 2 dt or > duration / 3, uncertainty above the value).
  std::vector<std::string> warnings;
  /// With a scanned start above the record's first Allan point: the model's ADEV over the
  /// record's at the point below the start where they differ most (1: no point below, or not
  /// scanned). Warned beyond kBelowStartTolerance either way (offBelowStart).
  double belowStartRatio = 1.0;
  /// [U/s] With a drift fitted from a record: the signed GLS slope of its block means under the
  /// other terms, which set the drift's size and 1-sigma (drift_gls.hpp); NaN where the size is
  /// the Allan fit's.
  double driftSlope = std::numeric_limits<double>::quiet_NaN();
  /// The likelihood's choice was this set + drift, but its Allan fit held no drift (put it at
  /// zero): the drift is the record's trend's alone, added by drift_gls.hpp (with a record).
  bool trendDrift = false;
  /// With a drift fitted from a record's trend (driftSlope finite): the same trend as a random
  /// walk instead (driftWalkAlternative, drift_gls.hpp): the walk's -2 log L of the block means
  /// above the ramp's, and its K [U / sqrt(s)] (the whole walk, the set's own included); NaN
  /// where not computed. Warned where the gap is below kDriftSlopeChi2.
  double driftWalkGap = std::numeric_limits<double>::quiet_NaN();
  double driftWalkK = std::numeric_limits<double>::quiet_NaN();
  /// Where the block likelihood rejected the Allan fit's optimum of the chosen set and the
  /// parameters written are the Allan fit nearest the likelihood's (likelihoodCheckedFit): what
  /// was done, for the model file; empty otherwise.
  std::string parameterNote;

  const LatentParameter& parameter(const std::string& name) const;  ///< InputError if absent
  const LatentCandidate* runnerUp() const;  ///< second valid candidate, nullptr if none
};

/// The octave overlapping Allan variance the fit uses (m = 1, 2, 4, ... <= N / 10).
struct LatentAllanPoints {
  std::vector<std::size_t> m;
  std::vector<double> tau, avar, dev;  ///< [s], [U^2], [U]
};
/// Throws InputError for dt <= 0, fewer than 40 samples or non-finite samples.
LatentAllanPoints latentAllanPoints(const std::vector<double>& x, double sampleInterval);

/// Whether the model is off the record below a scanned start beyond kBelowStartTolerance.
bool offBelowStart(const LatentFit& fit);
/// How far the model's ADEV is from the record's at its worst point, fitted or below a scanned
/// start: the largest |ln(model / record)| (0 for a perfect fit).
double worstAdevLogRatio(const LatentFit& fit);
/// How far the model is from the record at its worst octave point, every point of `record` (the
/// whole range, fitted or not), in standard errors of the record's Allan variance: the largest
/// |ln(model avar / record avar)| / sqrt(2 / edf), edf the Greenhall EDF of white noise (the most
/// precise of the usual types at short tau, where N samples pin the estimate down; at long tau,
/// where slower noise leaves fewer degrees of freedom, the deviation is overstated, not hidden).
/// Two models of one record compare by it on the same points.
double worstAllanZ(const LatentModel& model, const LatentAllanPoints& record, std::size_t samples, double dt);
/// The sanity warning of a parameter whose 1-sigma exceeds its value, and its opening words.
std::string uncertaintyWarning(const LatentParameter& p);
std::string uncertaintyWarningLead(const std::string& name);

/// Fits the record x [U] (any mean; sampled at options.sampleInterval). Throws InputError for bad
/// options, non-finite samples, or too few Allan points for the smallest candidate.
LatentFit fitLatentModel(const std::vector<double>& x, const LatentFitOptions& options);

/// The same from a precomputed overlapping Allan variance: avar[i] at m[i] (octave or any
/// increasing factors) of a record of `samples` samples.
LatentFit fitLatentModel(const std::vector<std::size_t>& m, const std::vector<double>& avar,
                         std::size_t samples, const LatentFitOptions& options);

}  // namespace sinsim::errormodels::fit
