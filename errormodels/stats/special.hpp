// Special functions for confidence intervals and tests: the standard normal distribution and its
// quantiles, regularized incomplete gamma and its inverse, chi-square distribution function and
// quantiles (any real degrees of freedom > 0). The one home of these formulas in the tree.
#pragma once

namespace sinsim::errormodels {

/// Standard normal distribution function Φ(z) = erfc(-z/√2) / 2 (accurate in both tails).
double normalCdf(double z);
/// Φ⁻¹(p): z with Φ(z) = p, for 0 <= p <= 1 (0 and 1 give -inf and +inf). Relative accuracy
/// ~1e-15 in both tails (bisection on erfc, whose own accuracy is the limit).
/// Throws InputError for p outside [0, 1] or NaN.
double normalQuantile(double p);
/// Two-sided standard normal quantile z >= 0 with P(|Z| <= z) = confidence, 0 < confidence < 1
/// (0.683 gives 1.0, 0.95 gives 1.96). Throws InputError outside (0, 1).
double normalQuantileTwoSided(double confidence);
/// The z >= 0 whose two-sided tail is p: P(|Z| > z) = p, 0 <= p <= 1 (p = 0 gives +inf). Exact
/// in the far tail (p = 1e-300 gives 37.0), where 1 - p would round to 1. Throws InputError
/// outside [0, 1].
double normalTwoSidedCritical(double p);

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
