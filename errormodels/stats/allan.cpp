#include "errormodels/stats/allan.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "common/error.hpp"
#include "errormodels/stats/special.hpp"

namespace sinsim::errormodels {
namespace {

/// Difference order of the variance (2: Allan family, 3: Hadamard).
int orderOf(AllanVariant v) {
  return (v == AllanVariant::Hadamard || v == AllanVariant::OverlappingHadamard) ? 3 : 2;
}

/// Largest m the estimator can use with N rate samples (N_x = N + 1 phase points).
std::size_t maxFactorFor(AllanVariant v, std::size_t n) {
  const std::size_t nx = n + 1;
  switch (v) {
    case AllanVariant::Overlapping: return (nx - 1) / 2;     // N_x - 2m >= 1
    case AllanVariant::NonOverlapping: return n / 2;         // two averages
    case AllanVariant::Modified: return nx / 3;              // N_x - 3m + 1 >= 1
    case AllanVariant::Hadamard: return n / 3;               // three averages
    case AllanVariant::OverlappingHadamard: return (nx - 1) / 3;  // N_x - 3m >= 1
  }
  return 0;
}

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

// ---- helpers for the estimators ----

/// Phase in units of tau0 from the rate with its mean removed: x_0 = 0, x_{i+1} = x_i + y_i - ybar.
std::vector<double> phaseOf(const std::vector<double>& y) {
  long double mean = 0;
  for (double v : y) mean += v;
  mean /= static_cast<long double>(y.size());
  std::vector<double> x(y.size() + 1);
  x[0] = 0.0;
  // Running sum in long double: the phase of a long record is a random walk whose increments
  // must not be rounded against its growing magnitude.
  long double acc = 0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    acc += static_cast<long double>(y[i]) - mean;
    x[i + 1] = static_cast<double>(acc);
  }
  return x;
}

/// Variance (in units of y^2) and the count of terms of one estimator at factor m.
void estimate(AllanVariant v, const std::vector<double>& x, std::size_t m, double& var,
              std::size_t& count) {
  const std::size_t nx = x.size();
  const double* X = x.data();
  const double md = static_cast<double>(m);
  double s = 0.0;
  switch (v) {
    case AllanVariant::Overlapping: {
      const std::size_t n = nx - 2 * m;
      // Four partial sums: independent chains let the compiler keep the FPU busy.
      double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
      std::size_t i = 0;
      for (; i + 4 <= n; i += 4) {
        const double d0 = X[i + 2 * m] - 2.0 * X[i + m] + X[i];
        const double d1 = X[i + 1 + 2 * m] - 2.0 * X[i + 1 + m] + X[i + 1];
        const double d2 = X[i + 2 + 2 * m] - 2.0 * X[i + 2 + m] + X[i + 2];
        const double d3 = X[i + 3 + 2 * m] - 2.0 * X[i + 3 + m] + X[i + 3];
        s0 += d0 * d0;
        s1 += d1 * d1;
        s2 += d2 * d2;
        s3 += d3 * d3;
      }
      for (; i < n; ++i) {
        const double d = X[i + 2 * m] - 2.0 * X[i + m] + X[i];
        s0 += d * d;
      }
      s = (s0 + s1) + (s2 + s3);
      count = n;
      var = s / (2.0 * md * md * static_cast<double>(n));
      return;
    }
    case AllanVariant::NonOverlapping: {
      const std::size_t navg = (nx - 1) / m;  // number of m-sample averages
      for (std::size_t k = 0; k + 2 <= navg; ++k) {
        const double d = X[(k + 2) * m] - 2.0 * X[(k + 1) * m] + X[k * m];
        s += d * d;
      }
      count = navg - 1;
      var = s / (2.0 * md * md * static_cast<double>(count));
      return;
    }
    case AllanVariant::Modified: {
      const std::size_t n = nx - 3 * m + 1;
      // Inner sum over m consecutive second differences, slid one step at a time.
      auto z = [&](std::size_t i) { return X[i + 2 * m] - 2.0 * X[i + m] + X[i]; };
      double inner = 0.0;
      for (std::size_t i = 0; i < m; ++i) inner += z(i);
      for (std::size_t j = 0;; ++j) {
        s += inner * inner;
        if (j + 1 >= n) break;
        inner += z(j + m) - z(j);
      }
      count = n;
      var = s / (2.0 * md * md * md * md * static_cast<double>(n));
      return;
    }
    case AllanVariant::Hadamard: {
      const std::size_t navg = (nx - 1) / m;
      for (std::size_t k = 0; k + 3 <= navg; ++k) {
        const double d = X[(k + 3) * m] - 3.0 * X[(k + 2) * m] + 3.0 * X[(k + 1) * m] - X[k * m];
        s += d * d;
      }
      count = navg - 2;
      var = s / (6.0 * md * md * static_cast<double>(count));
      return;
    }
    case AllanVariant::OverlappingHadamard: {
      const std::size_t n = nx - 3 * m;
      double s0 = 0, s1 = 0;
      std::size_t i = 0;
      for (; i + 2 <= n; i += 2) {
        const double d0 = X[i + 3 * m] - 3.0 * X[i + 2 * m] + 3.0 * X[i + m] - X[i];
        const double d1 = X[i + 1 + 3 * m] - 3.0 * X[i + 1 + 2 * m] + 3.0 * X[i + 1 + m] - X[i + 1];
        s0 += d0 * d0;
        s1 += d1 * d1;
      }
      for (; i < n; ++i) {
        const double d = X[i + 3 * m] - 3.0 * X[i + 2 * m] + 3.0 * X[i + m] - X[i];
        s0 += d * d;
      }
      s = s0 + s1;
      count = n;
      var = s / (6.0 * md * md * static_cast<double>(n));
      return;
    }
  }
}

/// r1 = sum (z_k - zbar)(z_{k+1} - zbar) / sum (z_k - zbar)^2, Riley & Greenhall (2004) eq. (2).
double lag1(const std::vector<double>& z) {
  const std::size_t n = z.size();
  double mean = 0;
  for (double v : z) mean += v;
  mean /= static_cast<double>(n);
  double num = 0, den = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double a = z[k] - mean;
    den += a * a;
    if (k + 1 < n) num += a * (z[k + 1] - mean);
  }
  return den > 0 ? num / den : 0.0;
}

NoiseId noiseIdResult(double rho, int d, int alpha_min) {
  NoiseId id;
  id.d = d;
  id.rho = rho;
  id.alpha_real = -2.0 * (rho + d);
  id.alpha = std::clamp(static_cast<int>(-std::lround(2.0 * rho)) - 2 * d, alpha_min, 2);
  return id;
}

/// Lag-1 noise identification on the block means z_k = (x_{(k+1)m} - x_{km}) / m of the phase:
/// remove the least-squares line (frequency drift), then difference until rho = r1 / (1 + r1)
/// < 0.25 or d = d_max; alpha = -round(2 rho) - 2d (Riley & Greenhall 2004, sec. 3, for
/// frequency data). The undifferenced step runs on the fly (two passes, no copy): it is the
/// common case, and on a 1 M-sample record at m = 1 it is most of the cost.
std::optional<NoiseId> identifyFromPhase(const std::vector<double>& x, std::size_t m, int d_max,
                                         int alpha_min) {
  const std::size_t nb = (x.size() - 1) / m;
  if (nb < 30) return std::nullopt;  // Riley & Greenhall (2004): at least 30 points
  const double inv_m = 1.0 / static_cast<double>(m);
  const double* X = x.data();
  auto zval = [&](std::size_t k) { return (X[(k + 1) * m] - X[k * m]) * inv_m; };
  const double c = 0.5 * static_cast<double>(nb - 1);  // centred abscissa
  // Two interleaved accumulator sets break the add-latency chains (the loops are latency bound).
  double sz0 = 0, stz0 = 0, sz1 = 0, stz1 = 0;
  std::size_t k = 0;
  for (; k + 2 <= nb; k += 2) {
    const double t = static_cast<double>(k) - c;
    const double z0 = zval(k), z1 = zval(k + 1);
    sz0 += z0;
    stz0 += t * z0;
    sz1 += z1;
    stz1 += (t + 1.0) * z1;
  }
  for (; k < nb; ++k) {
    const double z = zval(k);
    sz0 += z;
    stz0 += (static_cast<double>(k) - c) * z;
  }
  const double sz = sz0 + sz1, stz = stz0 + stz1;
  const double nn = static_cast<double>(nb);
  const double stt = nn * (nn * nn - 1.0) / 12.0;  // sum of (k - c)^2, closed form
  const double mean = sz / nn;
  const double slope = stt > 0 ? stz / stt : 0.0;
  auto resid = [&](std::size_t j) { return zval(j) - mean - slope * (static_cast<double>(j) - c); };
  // Residuals of a fit with intercept have zero mean up to rounding; keep the exact formula
  // anyway by accumulating their sum.
  double se0 = 0, see0 = 0, sl0 = 0, se1 = 0, see1 = 0, sl1 = 0;
  double prev = resid(0);
  se0 += prev;
  see0 += prev * prev;
  k = 1;
  for (; k + 2 <= nb; k += 2) {
    const double e0 = resid(k), e1 = resid(k + 1);
    se0 += e0;
    see0 += e0 * e0;
    sl0 += prev * e0;
    se1 += e1;
    see1 += e1 * e1;
    sl1 += e0 * e1;
    prev = e1;
  }
  for (; k < nb; ++k) {
    const double e = resid(k);
    se0 += e;
    see0 += e * e;
    sl0 += prev * e;
    prev = e;
  }
  const double se = se0 + se1, see = see0 + see1, sl = sl0 + sl1;
  const double n = static_cast<double>(nb);
  const double eb = se / n;
  const double e0 = resid(0), el = prev;
  const double den = see - n * eb * eb;
  const double num = sl - eb * (2 * se - e0 - el) + (n - 1) * eb * eb;
  const double r1 = den > 0 ? num / den : 0.0;
  double rho = r1 / (1.0 + r1);
  if (rho < 0.25 || d_max <= 0) return noiseIdResult(rho, 0, alpha_min);
  std::vector<double> z(nb);
  for (std::size_t k = 0; k < nb; ++k) z[k] = resid(k);
  for (int d = 1;; ++d) {
    for (std::size_t k = 0; k + 1 < z.size(); ++k) z[k] = z[k + 1] - z[k];
    z.pop_back();
    const double r = lag1(z);
    rho = r / (1.0 + r);
    if (rho < 0.25 || d >= d_max) return noiseIdResult(rho, d, alpha_min);
  }
}

}  // namespace

std::string toString(AllanVariant v) {
  switch (v) {
    case AllanVariant::Overlapping: return "oadev";
    case AllanVariant::NonOverlapping: return "adev";
    case AllanVariant::Modified: return "mdev";
    case AllanVariant::Hadamard: return "hdev";
    case AllanVariant::OverlappingHadamard: return "ohdev";
  }
  return "?";
}

std::vector<std::size_t> tauFactors(TauGrid grid, std::size_t max_factor, int points_per_decade) {
  std::vector<std::size_t> m;
  if (max_factor == 0) return m;
  switch (grid) {
    case TauGrid::Octave:
      for (std::size_t f = 1; f <= max_factor; f *= 2) {
        m.push_back(f);
        if (f > max_factor / 2) break;
      }
      break;
    case TauGrid::All:
      for (std::size_t f = 1; f <= max_factor; ++f) m.push_back(f);
      break;
    case TauGrid::PerDecade: {
      if (points_per_decade < 1) throw InputError("Allan tau grid: points per decade must be >= 1");
      const double step = std::pow(10.0, 1.0 / points_per_decade);
      for (double f = 1.0; f <= static_cast<double>(max_factor) + 0.5; f *= step) {
        const std::size_t k = static_cast<std::size_t>(std::llround(f));
        if (k <= max_factor && (m.empty() || k > m.back())) m.push_back(k);
      }
      break;
    }
  }
  return m;
}

std::optional<NoiseId> identifyNoise(const std::vector<double>& y, std::size_t m, int d_max,
                                     int alpha_min) {
  if (m == 0) throw InputError("noise identification: averaging factor must be >= 1");
  return identifyFromPhase(phaseOf(y), m, d_max, alpha_min);
}

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

AllanCurve allanDeviation(const std::vector<double>& y, double rate_hz, AllanVariant variant,
                          const AllanOptions& options) {
  if (!(std::isfinite(rate_hz) && rate_hz > 0))
    throw InputError("Allan deviation: sample rate must be a positive number of Hz");
  const std::size_t n = y.size();
  if (n < 3) throw InputError("Allan deviation: need at least 3 samples, got " + std::to_string(n));
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(y[i]))
      throw InputError("Allan deviation: sample " + std::to_string(i) + " is not finite");
  }
  const int d = orderOf(variant);
  const std::size_t m_limit = maxFactorFor(variant, n);
  std::vector<std::size_t> factors = options.factors;
  if (factors.empty()) {
    std::size_t mmax = options.max_factor ? options.max_factor : n / 4;
    mmax = std::max<std::size_t>(1, std::min(mmax, m_limit));
    factors = tauFactors(options.grid, mmax, options.points_per_decade);
  } else {
    for (std::size_t i = 0; i < factors.size(); ++i) {
      if (factors[i] == 0 || factors[i] > m_limit || (i > 0 && factors[i] <= factors[i - 1])) {
        std::ostringstream os;
        os << "Allan deviation: averaging factors must increase and lie in [1, " << m_limit
           << "] for " << toString(variant) << " of " << n << " samples; got " << factors[i];
        throw InputError(os.str());
      }
    }
  }
  if (options.alpha) {
    const int a = *options.alpha;
    if (a > 2 || a + 2 * d <= 1)
      throw InputError("Allan deviation: noise type alpha = " + std::to_string(a) +
                       " is not estimable by " + toString(variant));
  }

  const std::vector<double> x = phaseOf(y);
  AllanCurve c;
  c.variant = variant;
  c.tau0 = 1.0 / rate_hz;
  c.samples = n;
  c.confidence = options.confidence;
  const std::size_t k = factors.size();
  c.m = factors;
  c.tau.resize(k);
  c.dev.resize(k);
  c.count.resize(k);
  for (std::size_t i = 0; i < k; ++i) {
    double var = 0;
    estimate(variant, x, factors[i], var, c.count[i]);
    c.tau[i] = static_cast<double>(factors[i]) * c.tau0;
    c.dev[i] = std::sqrt(var);
  }
  if (!options.confidence_intervals) return c;

  const bool overlapping = variant != AllanVariant::NonOverlapping && variant != AllanVariant::Hadamard;
  const bool modified = variant == AllanVariant::Modified;
  const int alpha_min = 2 - 2 * d;  // alpha + 2d > 1
  c.alpha.resize(k);
  c.alpha_measured.resize(k);
  c.edf.resize(k);
  c.lo.resize(k);
  c.hi.resize(k);
  std::optional<int> last;
  for (std::size_t i = 0; i < k; ++i) {
    int alpha;
    bool measured = false;
    if (options.alpha) {
      alpha = *options.alpha;
    } else if (auto id = identifyFromPhase(x, factors[i], d - 1, alpha_min)) {
      alpha = id->alpha;
      measured = true;
      last = alpha;
    } else {
      alpha = last ? *last : 0;  // too few averages at this tau: keep the last identified type
    }
    c.alpha[i] = alpha;
    c.alpha_measured[i] = measured;
    c.edf[i] = greenhallEdf(alpha, d, static_cast<double>(factors[i]), static_cast<double>(n + 1),
                            overlapping, modified);
    chiSquareBounds(c.dev[i], c.edf[i], options.confidence, c.lo[i], c.hi[i]);
  }
  return c;
}

}  // namespace sinsim::errormodels
