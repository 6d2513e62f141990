// Allan-term fit: quantization Q, white noise N, bias instability B, random walk K and ramp R by
// weighted non-negative least squares on the Allan VARIANCE curve (not by reading single points).
//
// Model (IEEE Std 952-1997, Annex C, eq. C.23 etc.; the terms are independent, so variances add):
//   sigma^2(tau) = 3 Q^2 / tau^2 + N^2 / tau + (2 ln 2 / pi) B^2 + K^2 tau / 3 + R^2 tau^2 / 2
// which is linear in theta = (Q^2, N^2, B^2, K^2, R^2) >= 0. B is the flat (flicker) floor: the
// asymptote of the bias-instability term for tau well above its cut-off; the transition region
// is not modelled (IEEE 952 uses the same asymptotes).
//
// Units, for a signal in unit U (e.g. rad/s for a gyro, m/s^2 for an accelerometer):
//   Q [U s], N [U sqrt(s)] (= U/sqrt(Hz)), B [U], K [U / sqrt(s)], R [U / s].
//
// Weights: an Allan-variance estimate with nu equivalent degrees of freedom is distributed as
// sigma^2 chi^2_nu / nu, so var = 2 sigma^4 / nu (Howe, Allan & Barnes 1981; Riley, NIST SP 1065,
// 2008, on chi-squared confidence intervals). The
// fit is iteratively reweighted with sigma^2 from the current model (weights from the noisy
// measurement itself would favour points that happen to fall low). Covariance of the positive
// terms: (X' W X)^-1 over the free set, scaled by max(1, chi^2 / dof) (Birge ratio).
//
// Correlation between points. Overlapping estimates at neighbouring tau are positively correlated
// (at octave spacing, strongly so for random walk); diagonal weights then understate the
// uncertainty (Monte Carlo, white + random walk, 2 h at 100 Hz: pull SD 1.4 for N, 1.8 for K).
// When the record's sample interval and length are given, the fit is generalised least squares
// with the correlation matrix of the overlapping estimates under the current model:
//   Cov(s2_i, s2_j) ~ (2 / L_ij) (1/pi) int_0^pi S(w)^2 |G_i(w)|^2 |G_j(w)|^2 dw,
//   |G_m(w)|^2 = 2 sin^4(m w / 2) / (m^2 sin^2(w / 2))   (the Allan filter of m samples),
// the large-sample covariance of two quadratic forms of a Gaussian process (Isserlis' theorem,
// then Parseval over the lag sum), L_ij = M - 2 min(m_i, m_j): the number of terms of the
// estimate with the *shorter* filter. (The double sum over both estimates' terms is L_j sums of
// the cross-covariance's squares when the longer filter's L_j centres lie inside the shorter's,
// which is 1 / (L_i L_j) x L_j = 1 / L_i.) With max(m_i, m_j) (before 2026-12-04) the
// cross-covariances were L_i / L_j too large, up to 1.11 at the last octave pair of a record's
// m <= M / 10, and the matrix of a random-walk-dominated long-tau end indefinite: Monte Carlo, white
// + random walk, M = 720 000, m = 4096..65536: correlation of the last pair 0.86 (600 records),
// 0.845 now, 0.939 before (eigenvalue -0.004). S the
// model's discrete PSD [U^2 per rad/sample]: Q^2 4 sin^2(w/2) / dt^2 + N^2 / dt + B^2 / w
// + K^2 dt / (4 sin^2(w/2)) (the ramp is deterministic and adds no variance). Each term's S is
// normalised so that (1/pi) int S |G_m|^2 reproduces its Allan-variance term above. Only the
// correlations are taken from this; the variances stay 2 sigma^4 / edf from the given EDF.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Dense>

namespace sinsim::errormodels::fit {

enum class AllanTermKind { Quantization = 0, White = 1, BiasInstability = 2, RandomWalk = 3, Ramp = 4 };
constexpr std::size_t kAllanTermCount = 5;
std::string toString(AllanTermKind kind);  ///< "quantization", "white", ...

struct AllanTerm {
  AllanTermKind kind = AllanTermKind::White;
  bool enabled = true;   ///< part of the fitted model
  double value = 0.0;    ///< coefficient (sqrt of theta) [see units above]; 0 when not fitted
  double stdError = 0.0; ///< delta method sigma_theta / (2 value); 0 when value == 0
  double theta = 0.0;    ///< the variance coefficient (value^2)
  double thetaStdError = 0.0;
  /// One-sided upper bound on value: sqrt(max(theta_free, 0) + 2 sigma_theta_free), from a refit
  /// with this term unconstrained (for terms held at 0) or the fit itself (positive terms).
  double upperBound = 0.0;
  /// value is supported by the data: theta > detectionSigma * thetaStdError.
  bool detected = false;
};

struct AllanFitOptions {
  /// Which terms the model contains, in AllanTermKind order (Q, N, B, K, R).
  std::array<bool, kAllanTermCount> enabled{true, true, true, true, true};
  double tauMin = 0.0;  ///< points with tau outside [tauMin, tauMax] [s] are ignored
  double tauMax = 1e300;
  double detectionSigma = 2.0;
  /// Refit without undetected terms (backward elimination) until every remaining term is
  /// detected; removed terms are reported as 0 with an upper bound. Without it, terms held at
  /// the zero bound bias the terms correlated with them (Monte Carlo, white + random walk with
  /// all five terms: K pull mean -0.6; docs/identify.md, "Allan-term fit").
  bool eliminateUndetected = true;
  int maxReweight = 20;  ///< reweighting iterations (stops earlier at 1e-7 relative change)
  /// Sample interval [s] and length (samples) of the record the curve came from. When both are
  /// set (and every tau is a multiple of dt), points are correlated as described above (GLS);
  /// otherwise they are treated as independent.
  double sampleInterval = 0.0;
  std::size_t recordLength = 0;
};

struct AllanFit {
  std::array<AllanTerm, kAllanTermCount> terms;
  Eigen::MatrixXd thetaCovariance;  ///< 5 x 5 over theta; rows/columns of zero terms are 0
  double chi2 = 0.0;                ///< weighted residual sum of squares
  std::size_t dof = 0;              ///< points used - free terms
  double birgeScale = 1.0;          ///< factor applied to the covariance (>= 1)
  std::size_t pointsUsed = 0;
  bool correlated = false;          ///< GLS with the modelled correlation between points
  std::vector<double> tau;          ///< [s] the points used
  std::vector<double> modelAdev;    ///< [U] fitted model at those tau

  const AllanTerm& term(AllanTermKind k) const { return terms[static_cast<std::size_t>(k)]; }
};

/// Fits the five-term model to an Allan deviation curve: tau [s] (> 0, increasing), adev [U] (> 0)
/// and the equivalent degrees of freedom edf (> 0) of each point. Throws InputError on bad input
/// (sizes, non-finite, non-positive) or when fewer points than enabled terms remain.
AllanFit fitAllanTerms(const std::vector<double>& tau, const std::vector<double>& adev,
                       const std::vector<double>& edf, const AllanFitOptions& options = {});

/// Correlation matrix of overlapping Allan-variance estimates at averaging factors m (>= 1) of a
/// record of M samples at interval dt [s] under the model theta (see above).
Eigen::MatrixXd allanEstimateCorrelation(const std::array<double, kAllanTermCount>& theta,
                                         const std::vector<std::size_t>& m, double dt,
                                         std::size_t M);
/// The covariance behind it (same arguments) [U^4]: its diagonal gives an EDF 2 s^4 / var.
Eigen::MatrixXd allanEstimateCovariance(const std::array<double, kAllanTermCount>& theta,
                                        const std::vector<std::size_t>& m, double dt,
                                        std::size_t M);
/// The same for any stationary model given by its discrete two-sided PSD psd(w) [U^2 per
/// rad/sample], w in (0, pi], normalised so that (1/pi) int_0^pi psd = the sample variance (a
/// white sequence of variance s^2 has psd = s^2). Used by the latent-process fit (GM terms).
Eigen::MatrixXd allanEstimateCovariance(const std::function<double(double)>& psd,
                                        const std::vector<std::size_t>& m, std::size_t M);
/// The same with psd(w, s) given s = sin(w / 2) as well, which the quadrature has at every node
/// (a PSD written in s, as fit::LatentSpectrum is, need not compute it again).
Eigen::MatrixXd allanEstimateCovariance(const std::function<double(double w, double s)>& psd,
                                        const std::vector<std::size_t>& m, std::size_t M);
/// Correlation matrix of a covariance C, projected onto the positive-definite correlation
/// matrices (eigenvalues floored at 1e-3, unit diagonal restored) when the quadrature made it
/// indefinite (see allanEstimateCorrelation).
Eigen::MatrixXd correlationOfCovariance(const Eigen::MatrixXd& C);
/// The five-term model's discrete PSD [U^2 per rad/sample] at w in (0, pi] (see above).
double allanTermsPsd(const std::array<double, kAllanTermCount>& theta, double dt, double w);
/// The same given s = sin(w / 2).
double allanTermsPsd(const std::array<double, kAllanTermCount>& theta, double dt, double w, double s);

/// Allan deviation [U] of the five-term model theta = (Q^2, N^2, B^2, K^2, R^2) at tau [s].
std::vector<double> allanModelAdev(const std::array<double, kAllanTermCount>& theta,
                                   const std::vector<double>& tau);

/// EDF of a point from its Allan-deviation confidence interval [lo, hi] at two-sided confidence
/// level `confidence` (e.g. 0.683 or 0.95), assuming the chi^2 interval of Stable32 / IEEE 1139:
/// lo = adev sqrt(nu / chi2_{(1+c)/2}), hi = adev sqrt(nu / chi2_{(1-c)/2}); solved for nu with
/// the Wilson-Hilferty approximation of the chi^2 quantiles (accurate to ~1 % for nu >= 2).
double edfFromConfidenceInterval(double lo, double hi, double confidence);

/// Simple approximate EDF of the overlapping Allan variance (Howe, Allan & Barnes 1981; NIST
/// SP 1065 sec. 5.2.x) for M rate samples (M + 1 phase points) at averaging factor m:
///   white rate noise (white FM):   [3 (P-1) / (2m) - 2 (P-2) / P] 4 m^2 / (4 m^2 + 5)
///   random-walk rate (RW FM):      (P-2)/m ((P-1)^2 - 3 m (P-1) + 4 m^2) / (P-3)^2
/// with P = M + 1. Throws InputError unless 1 <= m <= M / 2.
double edfOverlappingWhite(std::size_t M, std::size_t m);
double edfOverlappingRandomWalk(std::size_t M, std::size_t m);

}  // namespace sinsim::errormodels::fit
