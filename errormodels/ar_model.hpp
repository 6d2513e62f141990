// Autoregressive model math shared by the `ar` effect, the presets' derivations and the tests.
// Convention (MATLAB arburg, the seed paper's eq. 1-2):
//   A(z) = 1 + a1 z^-1 + ... + ap z^-p,    y[n] = -a1 y[n-1] - ... - ap y[n-p] + sigma_e w[n]
// with w unit white noise and sigma_e the driving-noise standard deviation.
#pragma once

#include <complex>
#include <vector>

namespace sinsim::errormodels::ar {

/// Poles of 1/A(z): the roots of z^p + a1 z^(p-1) + ... + ap, computed as the eigenvalues of the
/// companion matrix (Golub & Van Loan 2013, §7.4.6). Empty for p = 0.
std::vector<std::complex<double>> poles(const std::vector<double>& a);
/// max |pole|; the model is stable (stationary) iff this is < 1. 0 for p = 0.
double largestPoleMagnitude(const std::vector<double>& a);

/// Autocovariance r(0..maxLag) of the stationary process, from the Yule-Walker equations
///   r(k) + sum_i a_i r(|k-i|) = sigma_e² δ(k),  k = 0..p
/// solved as one (p+1)×(p+1) linear system for r(0..p), then r(k) = -sum_i a_i r(k-i) for k > p
/// (Box, Jenkins & Reinsel 2008, §3.2.2). Requires a stable polynomial.
std::vector<double> autocovariance(const std::vector<double>& a, double sigmaE, int maxLag);

/// Variance gain r(0)/sigma_e² of the stationary process.
double varianceGain(const std::vector<double>& a);

}  // namespace sinsim::errormodels::ar
