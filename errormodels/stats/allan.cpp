// Allan-family estimators (SP1065 eqs. 10, 11, 14, 17, 18) on the phase of a rate record and the
// assembly of an AllanCurve: deviations, then noise type (allan_noise_id.cpp), EDF and chi-square
// bounds (allan_edf.cpp) per tau. Definitions and references: allan.hpp.
#include "errormodels/stats/allan.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "common/error.hpp"
#include "errormodels/stats/allan_internal.hpp"

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

}  // namespace

namespace detail {

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

}  // namespace detail

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

  const std::vector<double> x = detail::phaseOf(y);
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
    } else if (auto id = detail::identifyFromPhase(x, factors[i], d - 1, alpha_min)) {
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
