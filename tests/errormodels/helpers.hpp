// Small, deliberately simple statistics for the error-model tests (the production ACF/Allan code
// lives in errormodels/stats and is another helper's; these are written independently of it).
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "errormodels/imu_model.hpp"

namespace sinsim::test {

/// Output RATE samples (increment / dt) of one axis for a static IMU at `rate` [Hz], n samples.
/// sensorAxis: 0..2 gyro x..z, 3..5 accel x..z.
inline std::vector<double> simulateRates(const errormodels::ImuErrorModel& m, double rate,
                                         std::size_t n, std::uint64_t seed, std::uint64_t run,
                                         int sensorAxis = 0) {
  auto c = m.instantiate(rate, {seed, run});
  std::vector<double> out(n);
  ImuSample s;
  s.dt = 1.0 / rate;
  for (std::size_t k = 0; k < n; ++k) {
    s.t = double(k + 1) / rate;
    s.dtheta_b.setZero();
    s.dv_b.setZero();
    c->corrupt(s, NAN);
    out[k] = (sensorAxis < 3 ? s.dtheta_b[sensorAxis] : s.dv_b[sensorAxis - 3]) / s.dt;
  }
  return out;
}

/// Autocovariance estimate with the mean known to be 0: c(k) = (1/N) Σ x[t] x[t+k].
inline std::vector<double> autocov(const std::vector<double>& x, int maxLag) {
  std::vector<double> c(maxLag + 1, 0.0);
  const std::size_t n = x.size();
  for (int k = 0; k <= maxLag; ++k) {
    double s = 0.0;
    for (std::size_t t = 0; t + k < n; ++t) s += x[t] * x[t + k];
    c[k] = s / double(n);
  }
  return c;
}

/// Bartlett's (1946) large-sample variance of the known-mean autocovariance estimate of a
/// Gaussian process with true autocovariance r (r[j] for j ≥ 0, symmetric, r beyond the vector
/// taken as 0): Var c(k) ≈ (1/N) Σ_j [r(j)² + r(j+k) r(j-k)].
inline double bartlettVar(const std::vector<double>& r, int k, std::size_t n) {
  auto R = [&](long j) { j = std::labs(j); return j < long(r.size()) ? r[j] : 0.0; };
  const long L = long(r.size());
  double s = 0.0;
  for (long j = -L; j <= L; ++j) s += R(j) * R(j) + R(j + k) * R(j - k);
  return s / double(n);
}

/// Non-overlapping Allan variance of a rate sequence at cluster size m (τ = m dt), summed over
/// several records (pooled): (1/(2K)) Σ (ȳ[j+1] - ȳ[j])² over all K differences.
inline double allanVar(const std::vector<std::vector<double>>& records, std::size_t m,
                       std::size_t* differences = nullptr) {
  double s = 0.0;
  std::size_t K = 0;
  for (const auto& x : records) {
    const std::size_t blocks = x.size() / m;
    std::vector<double> avg(blocks, 0.0);
    for (std::size_t b = 0; b < blocks; ++b) {
      for (std::size_t i = 0; i < m; ++i) avg[b] += x[b * m + i];
      avg[b] /= double(m);
    }
    for (std::size_t b = 0; b + 1 < blocks; ++b) {
      s += (avg[b + 1] - avg[b]) * (avg[b + 1] - avg[b]);
      ++K;
    }
  }
  if (differences) *differences = K;
  return s / (2.0 * double(K));
}

/// Theory for a stationary sequence with autocovariance r (r(k) for k ≥ 0; 0 beyond): the Allan
/// variance at cluster m and the standard deviation of the non-overlapping estimate from K
/// differences (pooled over independent records of kPerRecord differences each). With
/// g(L) = Cov(ȳ_a, ȳ_{a+L/m}) = (1/m²) Σ_{|k|<m} (m-|k|) r(|L+k|):
///   AVAR = g(0) - g(m),  c_l = Cov(d_0, d_l) = 2 g(lm) - g((l+1)m) - g((l-1)m),
///   Var(AVAR^) = (1/(2 K²)) Σ_{records} [kr c_0² + 2 Σ_{l≥1} (kr - l) c_l²]   (Gaussian: Isserlis)
struct AllanTheory {
  double avar;
  double sd;
};
inline AllanTheory allanFromAcf(const std::vector<double>& r, std::size_t m, std::size_t K,
                                std::size_t kPerRecord) {
  auto R = [&](long j) { j = std::labs(j); return j < long(r.size()) ? r[j] : 0.0; };
  auto g = [&](long L) {
    double s = 0.0;
    for (long k = -long(m) + 1; k < long(m); ++k) s += double(long(m) - std::labs(k)) * R(L + k);
    return s / double(m) / double(m);
  };
  const double avar = g(0) - g(long(m));
  const long lmax = std::min<long>(long(kPerRecord) - 1, long(r.size() / m) + 2);
  double c0 = 2.0 * (g(0) - g(long(m)));
  double sum = double(kPerRecord) * c0 * c0;
  for (long l = 1; l <= lmax; ++l) {
    double cl = 2.0 * g(l * long(m)) - g((l + 1) * long(m)) - g((l - 1) * long(m));
    sum += 2.0 * double(long(kPerRecord) - l) * cl * cl;
  }
  const double records = double(K) / double(kPerRecord);
  const double var = records * sum / (4.0 * double(K) * double(K)) * 2.0;
  return {avar, std::sqrt(var)};
}

/// Autocovariance of an AR model y[n] = -Σ a_i y[n-i] + σ e[n] by its impulse response
/// h (r(k) = σ² Σ_j h_j h_{j+k}), truncated where |h| < 1e-17 of its peak — computed
/// independently of errormodels/ar_model (which solves the Yule-Walker system).
inline std::vector<double> arAcfImpulse(const std::vector<double>& a, double sigma, int maxLag) {
  std::vector<double> h{1.0};
  for (int n = 1; n < 200000; ++n) {
    double v = 0.0;
    for (std::size_t i = 1; i <= a.size() && int(i) <= n; ++i) v -= a[i - 1] * h[n - i];
    h.push_back(v);
    if (n > 50 && std::fabs(v) < 1e-17 && std::fabs(h[n - 1]) < 1e-17) break;
  }
  std::vector<double> r(maxLag + 1, 0.0);
  for (int k = 0; k <= maxLag; ++k)
    for (std::size_t j = 0; j + k < h.size(); ++j) r[k] += sigma * sigma * h[j] * h[j + k];
  return r;
}

/// Autocovariance of a sequence made by averaging m consecutive samples of a sequence with
/// autocovariance r: r_m(k) = (1/m²) Σ_{i,j<m} r(km + i - j).
inline std::vector<double> averagedAcf(const std::vector<double>& r, int m, int maxLag) {
  auto R = [&](long j) { j = std::labs(j); return j < long(r.size()) ? r[j] : 0.0; };
  std::vector<double> out(maxLag + 1, 0.0);
  for (int k = 0; k <= maxLag; ++k) {
    double s = 0.0;
    for (long d = -m + 1; d < m; ++d) s += double(m - std::labs(d)) * R(long(k) * m + d);
    out[k] = s / double(m) / double(m);
  }
  return out;
}

}  // namespace sinsim::test
