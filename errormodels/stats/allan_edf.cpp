// Equivalent degrees of freedom of the Allan-family variances (C. A. Greenhall & W. J. Riley,
// "Uncertainty of stability variances based on finite differences", Proc. 35th PTTI, 2003; the
// algorithm IEEE Std 1139-2008 refers to) and the chi-square confidence bounds built on them
// (NIST SP1065 eq. 45).
#include <cmath>
#include <string>

#include "common/error.hpp"
#include "errormodels/stats/allan.hpp"
#include "errormodels/stats/special.hpp"

namespace sinsim::errormodels {
namespace {

// ---- Greenhall & Riley (2003) EDF. Equation numbers are those of the paper. ----

/// sw(t), eq. (7): the generalized autocovariance kernel of power-law noise with exponent alpha.
double sw(double t, int alpha) {
  const double a = std::abs(t);
  switch (alpha) {
    case 2: return -a;
    case 1: return t == 0 ? 0.0 : t * t * std::log(a);
    case 0: return a * a * a;
    case -1: return t == 0 ? 0.0 : std::pow(t, 4) * std::log(a);
    case -2: return std::pow(a, 5);
    case -3: return t == 0 ? 0.0 : std::pow(t, 6) * std::log(a);
    case -4: return std::pow(a, 7);
    default: break;
  }
  throw InputError("Allan EDF: noise type alpha = " + std::to_string(alpha) + " outside [-4, 2]");
}

/// sx(t), eq. (8); F = +inf is the limit sw(t, alpha + 2).
double sx(double t, double F, int alpha) {
  if (std::isinf(F)) return sw(t, alpha + 2);
  return F * F * (2.0 * sw(t, alpha) - sw(t - 1.0 / F, alpha) - sw(t + 1.0 / F, alpha));
}

/// sz(t), eq. (9): binomial d-th difference of sx.
double sz(double t, double F, int alpha, int d) {
  switch (d) {
    case 1: return 2 * sx(t, F, alpha) - sx(t - 1, F, alpha) - sx(t + 1, F, alpha);
    case 2:
      return 6 * sx(t, F, alpha) - 4 * sx(t - 1, F, alpha) - 4 * sx(t + 1, F, alpha) +
             sx(t - 2, F, alpha) + sx(t + 2, F, alpha);
    case 3:
      return 20 * sx(t, F, alpha) - 15 * sx(t - 1, F, alpha) - 15 * sx(t + 1, F, alpha) +
             6 * sx(t - 2, F, alpha) + 6 * sx(t + 2, F, alpha) - sx(t - 3, F, alpha) -
             sx(t + 3, F, alpha);
    default: break;
  }
  throw InputError("Allan EDF: difference order must be 1, 2 or 3");
}

/// BasicSum, eq. (10).
double basicSum(double J, double M, double S, double F, int alpha, int d) {
  const double s0 = sz(0, F, alpha, d);
  double sum = s0 * s0;
  const double sj = sz(J / S, F, alpha, d);
  sum += (1.0 - J / M) * sj * sj;
  for (long j = 1; j < static_cast<long>(J); ++j) {
    const double s = sz(j / S, F, alpha, d);
    sum += 2.0 * (1.0 - j / M) * s * s;
  }
  return sum;
}

struct A01 {
  double a0, a1;
};

/// Table 1 (modified variances, F = 1): rows alpha = 2 .. -4, columns d = 1, 2, 3.
A01 table1(int alpha, int d) {
  static const A01 t[7][3] = {
      {{2.0 / 3, 1.0 / 3}, {7.0 / 9, 1.0 / 2}, {22.0 / 25, 2.0 / 3}},
      {{0.840, 0.345}, {0.997, 0.616}, {1.141, 0.843}},
      {{1.079, 0.368}, {1.033, 0.607}, {1.184, 0.848}},
      {{-1, -1}, {1.048, 0.534}, {1.180, 0.816}},
      {{-1, -1}, {1.302, 0.535}, {1.175, 0.777}},
      {{-1, -1}, {-1, -1}, {1.194, 0.703}},
      {{-1, -1}, {-1, -1}, {1.489, 0.702}},
  };
  return t[2 - alpha][d - 1];
}

/// Table 2 (unmodified variances, F = m).
A01 table2(int alpha, int d) {
  static const A01 t[7][3] = {
      {{3.0 / 2, 1.0 / 2}, {35.0 / 18, 1.0}, {231.0 / 100, 3.0 / 2}},
      {{78.6, 25.2}, {790.0, 410.0}, {9950.0, 6520.0}},
      {{2.0 / 3, 1.0 / 6}, {2.0 / 3, 1.0 / 3}, {7.0 / 9, 1.0 / 2}},
      {{-1, -1}, {0.852, 0.375}, {0.997, 0.617}},
      {{-1, -1}, {1.079, 0.368}, {1.033, 0.607}},
      {{-1, -1}, {-1, -1}, {1.053, 0.553}},
      {{-1, -1}, {-1, -1}, {1.302, 0.535}},
  };
  return t[2 - alpha][d - 1];
}

/// Table 3 (alpha = 1, unmodified): b0, b1 of the log(m) correction.
A01 table3(int d) {
  static const A01 t[3] = {{6.0, 4.0}, {15.23, 12.0}, {47.8, 40.0}};
  return t[d - 1];
}

double binomial(int n, int k) {
  double r = 1.0;
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}

}  // namespace

double greenhallEdf(int alpha, int d, double m, double n_phase, bool overlapping, bool modified) {
  if (d < 1 || d > 3) throw InputError("Allan EDF: difference order d must be 1, 2 or 3");
  if (!(alpha + 2 * d > 1) || alpha > 2 || alpha < -4) {
    throw InputError("Allan EDF: noise type alpha = " + std::to_string(alpha) +
                     " is not estimable with difference order " + std::to_string(d) +
                     " (need alpha + 2d > 1, alpha <= 2)");
  }
  const double F = modified ? 1.0 : m;  // filter factor
  const double S = overlapping ? m : 1.0;  // stride factor
  const double L = m / F + m * d;  // filter length on the phase, eq. (5)
  if (n_phase < L + 1) throw InputError("Allan EDF: record too short for this averaging factor");
  const double M = 1.0 + std::floor(S * (n_phase - L) / m);  // number of summands
  const double J = std::min(M, (d + 1) * S);
  constexpr double Jmax = 100.0;
  const double r = M / S;
  double inv = 0.0;
  if (modified) {
    // Case 1: modified variances, all alpha.
    if (J <= Jmax) {
      const double s0 = sz(0, 1.0, alpha, d);
      inv = basicSum(J, M, S, 1.0, alpha, d) / (s0 * s0 * M);
    } else if (r > d + 1) {
      const A01 a = table1(alpha, d);
      inv = (a.a0 - a.a1 / r) / r;
    } else {
      const double mp = Jmax / r;
      const double s0 = sz(0, 1.0, alpha, d);
      inv = basicSum(Jmax, Jmax, mp, 1.0, alpha, d) / (s0 * s0 * Jmax);
    }
  } else if (alpha <= 0) {
    // Case 2: unmodified variances, alpha <= 0.
    if (J <= Jmax) {
      const double Fp = m * (d + 1) <= Jmax ? m : std::numeric_limits<double>::infinity();
      const double s0 = sz(0, Fp, alpha, d);
      inv = basicSum(J, M, S, Fp, alpha, d) / (s0 * s0 * M);
    } else if (r > d + 1) {
      const A01 a = table2(alpha, d);
      inv = (a.a0 - a.a1 / r) / r;
    } else {
      const double mp = Jmax / r;
      const double inf = std::numeric_limits<double>::infinity();
      const double s0 = sz(0, inf, alpha, d);
      inv = basicSum(Jmax, Jmax, mp, inf, alpha, d) / (s0 * s0 * Jmax);
    }
  } else if (alpha == 1) {
    // Case 3: unmodified variances, flicker PM.
    if (J <= Jmax) {
      const double s0 = sz(0, m, 1, d);
      inv = basicSum(J, M, S, m, 1, d) / (s0 * s0 * M);
    } else if (r > d + 1) {
      const A01 a = table2(1, d);
      const A01 b = table3(d);
      const double c = b.a0 + b.a1 * std::log(m);
      inv = (a.a0 - a.a1 / r) / (c * c * r);
    } else {
      const double mp = Jmax / r;
      const A01 b = table3(d);
      const double c = b.a0 + b.a1 * std::log(m);
      inv = basicSum(Jmax, Jmax, mp, mp, 1, d) / (c * c * Jmax);
    }
  } else {
    // Case 4: unmodified variances, white PM (alpha = 2).
    const double K = std::ceil(r);
    if (K <= d) {
      // Few summands: the exact basic sum (eq. 10, all J = M correlation lags) is cheap here.
      const double s0 = sz(0, m, 2, d);
      inv = basicSum(M, M, S, m, 2, d) / (s0 * s0 * M);
    } else {
      const double a0 = binomial(4 * d, 2 * d) / std::pow(binomial(2 * d, d), 2);
      const double a1 = d / 2.0;
      inv = (a0 - a1 / r) / M;
    }
  }
  if (!(inv > 0) || !std::isfinite(inv)) {
    throw NumericalError("Allan EDF: non-positive 1/edf for alpha = " + std::to_string(alpha) +
                         ", m = " + std::to_string(m));
  }
  return 1.0 / inv;
}

void chiSquareBounds(double dev, double edf, double confidence, double& lo, double& hi) {
  if (!(confidence > 0 && confidence < 1)) throw InputError("confidence level must be in (0, 1)");
  const double pl = 0.5 * (1.0 - confidence);
  const double ph = 1.0 - pl;
  lo = dev * std::sqrt(edf / chiSquareQuantile(ph, edf));
  hi = dev * std::sqrt(edf / chiSquareQuantile(pl, edf));
}
}  // namespace sinsim::errormodels
