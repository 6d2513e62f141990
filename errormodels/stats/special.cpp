#include "errormodels/stats/special.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "common/error.hpp"

namespace sinsim::errormodels {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kLn2Pi = 1.8378770664093454836;  // ln(2 pi)

/// lgamma(a) - [(a - 1/2) ln a - a + ln(2 pi)/2], the Stirling remainder. For a >= 10 from its
/// asymptotic series (Abramowitz & Stegun 6.1.41; error < 1e-16 there), else by subtraction.
double stirlingRemainder(double a) {
  if (a >= 10.0) {
    const double r = 1.0 / a;
    const double r2 = r * r;
    return r * (1.0 / 12 - r2 * (1.0 / 360 - r2 * (1.0 / 1260 - r2 * (1.0 / 1680))));
  }
  return std::lgamma(a) - ((a - 0.5) * std::log(a) - a + 0.5 * kLn2Pi);
}

/// ln(x^a e^-x / Gamma(a)) written as a (ln(1 + u) - u) + ln(a / 2 pi) / 2 - remainder with
/// x = a (1 + u): the two large terms a ln x and lgamma(a) never meet, so no digits are lost
/// for large a.
double logPrefactor(double a, double x) {
  const double u = (x - a) / a;
  // log1p(u) keeps its digits near u = 0; far from it (x << a) 1 + u would lose them.
  const double lg = std::abs(u) < 0.5 ? std::log1p(u) : std::log(x / a);
  return a * (lg - u) + 0.5 * (std::log(a) - kLn2Pi) - stirlingRemainder(a);
}

/// Series for P (NR3 eq. 6.2.5): P = prefactor * sum_{n>=0} x^n / (a (a+1) ... (a+n)).
double seriesP(double a, double x) {
  double ap = a;
  double del = 1.0 / a;
  double sum = del;
  for (int n = 0; n < 100000000; ++n) {
    ap += 1.0;
    del *= x / ap;
    sum += del;
    if (std::abs(del) < std::abs(sum) * kEps) return sum * std::exp(logPrefactor(a, x));
  }
  throw NumericalError("regularizedGammaP: series did not converge");
}

/// Continued fraction for Q (NR3 eq. 6.2.7), modified Lentz.
double continuedFractionQ(double a, double x) {
  constexpr double tiny = std::numeric_limits<double>::min() / kEps;
  double b = x + 1.0 - a;
  double c = 1.0 / tiny;
  double d = 1.0 / b;
  double h = d;
  for (int i = 1; i < 100000000; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1.0 / d;
    const double del = d * c;
    h *= del;
    if (std::abs(del - 1.0) <= kEps) return h * std::exp(logPrefactor(a, x));
  }
  throw NumericalError("regularizedGammaQ: continued fraction did not converge");
}

void checkDomain(double a, double x, const char* who) {
  if (!(std::isfinite(a) && a > 0) || !(x >= 0)) {
    throw NumericalError(std::string(who) + ": need a > 0 and x >= 0, got a = " +
                         std::to_string(a) + ", x = " + std::to_string(x));
  }
}

/// z with Q(z) = erfc(z/√2) / 2 = q, 0 < q < 1, by bisection on [-40, 40] (Q(40) underflows
/// below the smallest double, so the root is inside). 200 halvings shrink the bracket below
/// 1e-58, so erfc's own ~1 ulp accuracy is the limit: the upper tail is evaluated directly, never
/// as 1 - Φ, which keeps full relative accuracy for tiny q.
double upperTailQuantile(double q) {
  double lo = -40.0, hi = 40.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (0.5 * std::erfc(mid / std::sqrt(2.0)) > q ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

double normalCdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

double normalQuantile(double p) {
  if (!(p >= 0.0 && p <= 1.0)) throw InputError("normal quantile: probability must be in [0, 1]");
  if (p == 0.0) return -std::numeric_limits<double>::infinity();
  if (p == 1.0) return std::numeric_limits<double>::infinity();
  return -upperTailQuantile(p);  // Φ(z) = Q(-z)
}

double normalQuantileTwoSided(double confidence) {
  if (!(confidence > 0.0 && confidence < 1.0))
    throw InputError("confidence level must be in (0, 1)");
  return upperTailQuantile(0.5 * (1.0 - confidence));
}

double normalTwoSidedCritical(double p) {
  if (!(p >= 0.0 && p <= 1.0))
    throw InputError("two-sided normal critical value: probability must be in [0, 1]");
  if (p == 0.0) return std::numeric_limits<double>::infinity();
  return std::max(0.0, upperTailQuantile(0.5 * p));
}

double regularizedGammaP(double a, double x) {
  checkDomain(a, x, "regularizedGammaP");
  if (x == 0.0) return 0.0;
  if (std::isinf(x)) return 1.0;
  return x < a + 1.0 ? seriesP(a, x) : 1.0 - continuedFractionQ(a, x);
}

double regularizedGammaQ(double a, double x) {
  checkDomain(a, x, "regularizedGammaQ");
  if (x == 0.0) return 1.0;
  if (std::isinf(x)) return 0.0;
  return x < a + 1.0 ? 1.0 - seriesP(a, x) : continuedFractionQ(a, x);
}

double inverseRegularizedGammaP(double a, double p) {
  if (!(std::isfinite(a) && a > 0) || !(p >= 0 && p <= 1)) {
    throw NumericalError("inverseRegularizedGammaP: need a > 0 and 0 <= p <= 1, got a = " +
                         std::to_string(a) + ", p = " + std::to_string(p));
  }
  if (p == 0.0) return 0.0;
  if (p == 1.0) return std::numeric_limits<double>::infinity();
  const double q = 1.0 - p;  // exact enough for the start; the iteration uses p or q below
  const bool upper = p > 0.5;
  // Starting point: NR3 6.2.1 (Wilson-Hilferty for a > 1, power/exponential tails otherwise).
  double x;
  if (a > 1.0) {
    const double pp = upper ? q : p;
    const double t = std::sqrt(-2.0 * std::log(pp));
    double z = (2.30753 + t * 0.27061) / (1.0 + t * (0.99229 + t * 0.04481)) - t;
    if (p < 0.5) z = -z;
    const double w = 1.0 - 1.0 / (9.0 * a) - z / (3.0 * std::sqrt(a));
    x = std::max(1e-3, a * w * w * w);
  } else {
    const double t = 1.0 - a * (0.253 + a * 0.12);
    x = p < t ? std::pow(p / t, 1.0 / a) : 1.0 - std::log(1.0 - (p - t) / (1.0 - t));
  }
  for (int it = 0; it < 100; ++it) {
    if (x <= 0.0) return 0.0;
    // err = P(a,x) - p, computed from Q in the upper half so that 1 - p keeps its digits.
    const double err = upper ? q - regularizedGammaQ(a, x) : regularizedGammaP(a, x) - p;
    const double pdf = std::exp(logPrefactor(a, x)) / x;  // dP/dx
    if (pdf == 0.0) break;
    const double u = err / pdf;
    // Halley step (NR3 6.2.1): d2P/dx2 / (dP/dx) = (a - 1) / x - 1.
    const double step = u / (1.0 - 0.5 * std::min(1.0, u * ((a - 1.0) / x - 1.0)));
    x -= step;
    if (x <= 0.0) x = 0.5 * (x + step);
    if (std::abs(step) < 1e-15 * x) break;
  }
  return x;
}

double chiSquareCdf(double x, double nu) { return regularizedGammaP(0.5 * nu, 0.5 * x); }

double chiSquareQuantile(double p, double nu) {
  return 2.0 * inverseRegularizedGammaP(0.5 * nu, p);
}

}  // namespace sinsim::errormodels
