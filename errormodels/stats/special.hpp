// Special functions for confidence intervals: regularized incomplete gamma and its inverse,
// chi-square distribution function and quantiles (any real degrees of freedom > 0).
#pragma once

namespace sinsim::errormodels {

/// Regularized lower incomplete gamma P(a, x) = gamma(a, x) / Gamma(a); a > 0, x >= 0.
/// Series for x < a + 1, Legendre continued fraction otherwise (Numerical Recipes 3rd ed. 6.2),
/// prefactor x^a e^-x / Gamma(a) formed without cancellation for large a (Stirling series).
/// Relative accuracy ~1e-14 for a up to 1e7. Throws NumericalError outside the domain.
double regularizedGammaP(double a, double x);
/// Regularized upper incomplete gamma Q(a, x) = 1 - P(a, x), accurate in the upper tail.
double regularizedGammaQ(double a, double x);
/// x with P(a, x) = p, 0 <= p <= 1 (p = 1 gives +inf). Halley iteration on P or Q (whichever is
/// smaller, to keep tail accuracy) from the NR 6.2.1 starting point; relative accuracy ~1e-13.
double inverseRegularizedGammaP(double a, double p);

/// Chi-square distribution function with nu > 0 degrees of freedom: P(nu/2, x/2).
double chiSquareCdf(double x, double nu);
/// Chi-square quantile: x with chiSquareCdf(x, nu) = p.
double chiSquareQuantile(double p, double nu);

}  // namespace sinsim::errormodels
