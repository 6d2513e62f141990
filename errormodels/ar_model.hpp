// Autoregressive polynomial math, the one home: poles and stationarity, autocovariance, variance
// gain and Allan variance of an AR(p) process. Used by the `ar` effect, the fits (fit/ar_fit.hpp
// adapts ArFit's [1, a1..ap] to it), the presets' derivations, the aided filter and the tests.
//
// Convention (MATLAB arburg, the seed paper's eq. 1-2):
//   A(z) = 1 + a1 z^-1 + ... + ap z^-p,    y[n] = -a1 y[n-1] - ... - ap y[n-p] + e[n]
// with e white, var(e) = E = sigma_e² (the driving-noise variance arburg returns). Every function
// here takes the coefficients a1..ap WITHOUT the leading 1. Units: y in any unit U, E in U².
// Errors: an unstable polynomial or a bad variance is an InputError (the polynomial comes from a
// user's file or a fit).
#pragma once

#include <complex>
#include <cstddef>
#include <vector>

namespace sinsim::errormodels::ar {

/// Poles of 1/A(z): the roots of z^p + a1 z^(p-1) + ... + ap, computed as the eigenvalues of the
/// companion matrix (Golub & Van Loan 2013, §7.4.6). Empty for p = 0.
std::vector<std::complex<double>> poles(const std::vector<double>& a);
/// max |pole|; the model is stable (stationary) iff this is < 1. 0 for p = 0.
double largestPoleMagnitude(const std::vector<double>& a);
/// The long-run variance E / A(1)^2 [U²] (A(1) = 1 + a1 + ... + ap): the sum of the stationary
/// process's autocovariances over every lag, i.e. m times the variance of a mean of m samples for
/// m much longer than its correlation time.
double longRunVariance(const std::vector<double>& a, double drivingVariance);

/// Autocovariance r(0..maxLag) [U²] of the stationary process with driving variance E [U²], from
/// the Yule-Walker equations
///   r(k) + sum_i a_i r(|k-i|) = E δ(k),  k = 0..p
/// solved as one (p+1)×(p+1) linear system for r(0..p), then r(k) = -sum_i a_i r(k-i) for k > p
/// (Box, Jenkins & Reinsel 2008, §3.2.2, eq. 3.2.4). Throws InputError for an unstable polynomial
/// (a pole on or outside the unit circle) or E not finite and >= 0.
std::vector<double> autocovarianceOfVariance(const std::vector<double>& a, double drivingVariance,
                                             std::size_t maxLag);
/// The same with the driving-noise standard deviation sigma_e [U] (E = sigma_e²); maxLag < 0 is 0.
std::vector<double> autocovariance(const std::vector<double>& a, double sigmaE, int maxLag);

/// Variance gain r(0)/sigma_e² of the stationary process [-].
double varianceGain(const std::vector<double>& a);

/// Allan variance [U²] of the process sampled at interval dt, at tau = m dt for each m in `m`
/// (m >= 1), from its autocovariance: AVAR(m) = Var(ybar) - Cov(ybar_k, ybar_{k+1}) with m-sample
/// averages ybar (IEEE Std 952-1997 Annex C definition, exact for a stationary process).
std::vector<double> allanVariance(const std::vector<double>& a, double drivingVariance,
                                  const std::vector<std::size_t>& m);

}  // namespace sinsim::errormodels::ar
