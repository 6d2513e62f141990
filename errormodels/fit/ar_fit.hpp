// Autoregressive model fitting: Burg (Burg 1975) and Yule-Walker (Levinson-Durbin), with the
// asymptotic covariance of the coefficients.
//
// Convention (MATLAB/Octave `arburg`, the seed paper's eq. (1)):
//     A(z) = 1 + a1 z^-1 + ... + ap z^-p,      x[n] = -a1 x[n-1] - ... - ap x[n-p] + e[n],
//     var(e) = E (the "driving-noise variance", what arburg returns second).
// statsmodels returns rho = -a[1..p] and, for Burg, a different variance (see residualVariance).
//
// Pure numerics over plain vectors: no I/O, no randomness. Units: x in any unit U; E in U^2.
#pragma once

#include <complex>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

namespace sinsim::errormodels::fit {

enum class ArMethod { Burg, YuleWalker };
std::string toString(ArMethod method);

/// How Burg's reflection coefficients are evaluated. All give the same numbers up to rounding:
///  - Fast: from the lagged products of x and O(p^4) boundary corrections (the idea of Vos 2013,
///    "A fast implementation of Burg's method"): one pass over the data. The quadratic forms
///    cancel: its relative error is about kappa = eps * (r0 / E_p) * (sum |a_i|)^2 (prediction
///    gain times coefficient mass), measured within 3x of that on the fixtures.
///  - Direct: the lattice recursion over stored forward/backward errors (Burg 1975; the loop of
///    Octave arburg), p passes over the data; no cancellation.
///  - Auto (default): Fast, then Direct again when kappa > 1e-11 (near-unit-circle poles, large
///    undemeaned offsets), so the result carries ~10 correct digits or more.
enum class BurgAlgorithm { Auto, Fast, Direct };

struct ArOptions {
  /// Subtract the sample mean before fitting (statsmodels' default). Octave arburg/aryule do NOT:
  /// set false to reproduce them. A sensor bias is a constant, not part of the AR process, so the
  /// default is true.
  bool demean = true;
  BurgAlgorithm burgAlgorithm = BurgAlgorithm::Auto;
};

/// A fitted AR(p) model with its uncertainties.
struct ArFit {
  ArMethod method = ArMethod::Burg;
  std::size_t order = 0;  ///< p
  std::size_t n = 0;      ///< samples used
  double mean = 0.0;      ///< mean removed before fitting [U] (0 when demean = false)
  /// [1, a1, ..., ap] (arburg convention; size p + 1).
  std::vector<double> a;
  /// Reflection coefficients k1..kp (arburg sign: k_m = a_m of the order-m model).
  std::vector<double> reflection;
  /// E [U^2]: driving-noise variance as arburg / aryule return it, E = r0 prod(1 - k_m^2) with
  /// r0 = x'x / N.  This is the variance to drive the simulation filter with.
  double drivingVariance = 0.0;
  /// E_m for m = 0..p (the nested lower-order fits' driving variances; used for order selection).
  std::vector<double> drivingVariancePath;
  /// Burg: mean square of the order-p forward and backward prediction errors over their valid
  /// samples, sum(f_p^2 + b_p^2) / (2 (N - p)) — what statsmodels `burg` returns as sigma2
  /// (Brockwell & Davis 2016, sec. 5.1.2). Yule-Walker: equal to drivingVariance.
  double residualVariance = 0.0;
  /// Asymptotic covariance of (a1..ap), p x p: sigma^2 Gamma_p^{-1} / N (Brockwell & Davis 1991,
  /// Theorem 8.1.1 for Yule-Walker; Burg has the same limit law), evaluated at the fitted
  /// coefficients with the Gohberg-Semencul form sigma^2 Gamma_p^{-1} = L L' - U U'.
  Eigen::MatrixXd covariance;
  std::vector<double> stdError;  ///< sqrt(diag(covariance)), for a1..ap
  /// Asymptotic standard error of E, sqrt(2/N) E (Gaussian driving noise).
  double drivingVarianceStdError = 0.0;
};

/// Burg AR(p) fit of x. order >= 1 and order < x.size() - 2 (arburg's limit); x finite and not
/// constant. Throws InputError otherwise.
ArFit burg(const std::vector<double>& x, std::size_t order, const ArOptions& options = {});

/// Yule-Walker AR(p) fit: biased autocovariance r_k = (1/N) sum x[n] x[n+k], Levinson-Durbin.
/// Equal to Octave aryule (demean = false) and statsmodels yule_walker(method="mle").
ArFit yuleWalker(const std::vector<double>& x, std::size_t order, const ArOptions& options = {});

/// Yule-Walker from a given biased autocovariance r[0..] (r.size() > order) of a record of n
/// samples (n only sets the uncertainties). Lets the caller supply an FFT-based ACF.
ArFit yuleWalkerFromAutocovariance(const std::vector<double>& r, std::size_t order, std::size_t n);

/// Biased autocovariance r_k = (1/N) sum_{n=0}^{N-1-k} x[n] x[n+k], k = 0..maxLag, by direct
/// summation (O(N maxLag); meant for the small lags of AR fitting). No mean removal.
std::vector<double> biasedAutocovariance(const std::vector<double>& x, std::size_t maxLag);

/// Levinson-Durbin recursion on autocovariance r[0..order] (Levinson 1947, Durbin 1960).
struct LevinsonResult {
  std::vector<double> a;           ///< [1, a1..ap]
  std::vector<double> reflection;  ///< k1..kp
  std::vector<double> variancePath;  ///< E_0..E_p
};
LevinsonResult levinsonDurbin(const std::vector<double>& r, std::size_t order);

/// sigma^2 Gamma_p^{-1} / n for the AR polynomial a = [1, a1..ap] (Gohberg-Semencul:
/// sigma^2 Gamma_p^{-1} = L L' - U U', L lower-triangular Toeplitz with first column
/// (1, a1, ..., a_{p-1}), U lower-triangular Toeplitz with first column (ap, ..., a1)).
Eigen::MatrixXd arCoefficientCovariance(const std::vector<double>& a, std::size_t n);

// The AR polynomial math lives once, in errormodels/ar_model.hpp (coefficients a1..ap). These
// adapters take the polynomial as ArFit holds it, [1, a1..ap], and throw InputError otherwise.

/// a1..ap of a = [1, a1, ..., ap] (p >= 1).
std::vector<double> arCoefficients(const std::vector<double>& a);
/// ar::poles of [1, a1..ap].
std::vector<std::complex<double>> arPoles(const std::vector<double>& a);
/// ar::largestPoleMagnitude of [1, a1..ap] (< 1 for a stable, stationary model).
double arMaxPoleMagnitude(const std::vector<double>& a);
/// ar::longRunVariance of [1, a1..ap] [U^2].
double arLongRunVariance(const std::vector<double>& a, double drivingVariance);
/// ar::autocovarianceOfVariance of [1, a1..ap]: gamma_0..gamma_maxLag [U^2].
std::vector<double> arAutocovariance(const std::vector<double>& a, double drivingVariance,
                                     std::size_t maxLag);
/// The AR(p) [1, a1'..ap'] and driving variance whose autocovariance at lags 0..p is that of
/// ([1, a1..ap], drivingVariance) less independent white noise of `whiteVariance` [U^2] per sample
/// (lag 0 lowered by it; Levinson-Durbin at the same order): the process a record's AR fit saw
/// with that noise (a rounding's q^2 / 12) taken out of its spectrum rather than out of the
/// driving noise, which would scale the whole spectrum down. Empty where the lowered
/// autocovariance is not positive definite (the noise exceeds the spectrum somewhere).
struct ArLessWhite {
  std::vector<double> a;  ///< [1, a1'..ap']
  double drivingVariance = 0.0;
};
std::optional<ArLessWhite> arLessWhite(const std::vector<double>& a, double drivingVariance, double whiteVariance);
/// ar::allanVariance of [1, a1..ap] [U^2] at tau = m dt.
std::vector<double> arAllanVariance(const std::vector<double>& a, double drivingVariance,
                                    const std::vector<std::size_t>& m);

}  // namespace sinsim::errormodels::fit
