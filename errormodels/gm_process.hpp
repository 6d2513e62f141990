// First-order Gauss-Markov (Ornstein-Uhlenbeck) process x' = -x/tau + sqrt(2 sigma²/tau) w(t),
// stationary variance sigma², integrated EXACTLY over intervals of any length: the state x and its
// integral I = ∫ x dt over an interval Δ are jointly Gaussian given the state at the start
// (Van Loan 1978 discretisation, written out):
//   x1 = φ x0 + e1,            I = tau (1-φ) x0 + e2,            φ = exp(-Δ/tau)
//   Var e1 = sigma² (1-φ²)
//   Var e2 = q tau² [Δ - 2 tau (1-φ) + tau (1-φ²)/2]
//   Cov    = q tau² (1-φ)² / 2,          q = 2 sigma²/tau (driving-noise intensity)
// So the integral over an IMU interval is right whatever Δ/tau is (no "tau must be ≫ dt").
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "errormodels/interval_cache.hpp"
#include "errormodels/random.hpp"

namespace sinsim::errormodels {

/// Allan variance [unit²] of a first-order GM process with variance s2 [unit²] and correlation
/// time T [s] at averaging time tau [s] (IEEE Std 952-1997 Annex C, C.2.4 with q_c = 2 s2 / T):
///   AVAR = (q_c T² / tau) [1 - (T / 2 tau)(3 - 4 e^{-tau/T} + e^{-2 tau/T})].
/// With x = tau/T the bracket loses ~1e-16 / x³ relative to cancellation, so below x = 0.1 its
/// Taylor series is used: AVAR / s2 = sum_{n>=3} (4 (-1)^n - (-2)^n) / n! x^(n-2)
/// = 2x/3 - x²/2 + 7x³/30 - ..., to n = 18 (the next term < 1e-17 relative). Peak of the
/// deviation: 0.618 sqrt(s2) at tau = 1.89 T; AVAR -> 2 s2 T / tau for tau >> T.
inline double gaussMarkovAllanVariance(double s2, double T, double tau) {
  const double x = tau / T;
  if (x < 0.1) {
    double sum = 0.0, fact = 2.0, xp = 1.0;  // fact = n!, xp = x^(n-2)
    for (int n = 3; n <= 18; ++n) {
      fact *= n, xp *= x;
      const double sign = n % 2 ? -1.0 : 1.0;  // (-1)^n
      sum += (4.0 * sign - sign * std::ldexp(1.0, n)) / fact * xp;
    }
    return s2 * sum;
  }
  const double e1 = std::exp(-x);
  return s2 * 2.0 / x * (1.0 - (3.0 - 4.0 * e1 + e1 * e1) / (2.0 * x));
}

/// Autocovariance [unit²] at lags 0..maxLag of the interval averages over dt [s] of a GM process
/// (variance s2, time T): lag 0 (2 s2 T²/dt²)(dt/T - 1 + e^(-dt/T)), lag k >= 1
/// (s2 T²/dt²)(1 - e^(-dt/T))² e^(-(k-1) dt/T). Added into r (size maxLag + 1).
/// (x - 1 + e^-x = x²/2 - x³/6 + x⁴/24 - ... cancels below x = 1e-4: its series there.)
inline void addGaussMarkovIntervalAcov(double s2, double T, double dt, std::vector<double>& r) {
  const double x = dt / T, c2 = s2 / (x * x);
  const double om = -std::expm1(-x);
  r[0] += x < 1e-4 ? s2 * (1.0 - x / 3.0 + x * x / 12.0) : 2.0 * c2 * (x - om);
  const double step = std::exp(-x);
  double decay = 1.0;
  for (std::size_t k = 1; k < r.size(); ++k) {
    r[k] += c2 * om * om * decay;
    decay *= step;
  }
}

class ExactGaussMarkov {
 public:
  ExactGaussMarkov(double sigma, double tau, NormalStream s) : sigma_(sigma), tau_(tau), s_(s) {
    x_ = sigma_ * s_.next();  // stationary start
  }

  /// ∫ x dt over the next interval of length dt [s]; advances the state.
  double integral(double dt) {
    const Step& k = steps_.get(dt, [this](double h) { return step(h); });
    const double w1 = s_.next(), w2 = s_.next();
    const double e1 = k.l11 * w1;
    const double e2 = k.l21 * w1 + k.l22 * w2;
    const double I = k.c * x_ + e2;
    x_ = k.phi * x_ + e1;
    return I;
  }
  /// integral() over n <= kMaxChunk intervals of lengths dtOf(0), dtOf(1), ... into I[0..n): the
  /// same draws and operations, the draws taken at once.
  template <class DtOf>
  void integrals(std::size_t n, DtOf&& dtOf, double* I) {
    double w[2 * kMaxChunk];
    s_.fill(w, 2 * n);
    double x = x_;
    for (std::size_t i = 0; i < n; ++i) {
      const Step& k = steps_.get(dtOf(i), [this](double h) { return step(h); });
      const double w1 = w[2 * i], w2 = w[2 * i + 1];
      const double e1 = k.l11 * w1;
      const double e2 = k.l21 * w1 + k.l22 * w2;
      I[i] = k.c * x + e2;
      x = k.phi * x + e1;
    }
    x_ = x;
  }
  static constexpr std::size_t kMaxChunk = 64;
  double state() const { return x_; }

 private:
  struct Step {  // the discretisation over one interval length
    double phi = 0.0, c = 0.0, l11 = 0.0, l21 = 0.0, l22 = 0.0;
  };

  Step step(double dt) const {
    Step k;
    const double r = dt / tau_;
    k.phi = std::exp(-r);
    const double om = -std::expm1(-r);         // 1 - φ, accurate for small r
    const double om2 = -std::expm1(-2.0 * r);  // 1 - φ²
    const double q = 2.0 * sigma_ * sigma_ / tau_;
    const double v1 = sigma_ * sigma_ * om2;
    // dt - 2 tau (1-φ) + tau (1-φ²)/2 loses digits for r ≪ 1; use its series r³/3 - r⁴/4 + ...
    double bracket;
    if (r < 1e-3) {
      bracket = tau_ * (r * r * r / 3.0 - r * r * r * r / 4.0 + r * r * r * r * r * 7.0 / 60.0);
    } else {
      bracket = dt - 2.0 * tau_ * om + 0.5 * tau_ * om2;
    }
    const double v2 = q * tau_ * tau_ * bracket;
    const double cv = q * tau_ * tau_ * om * om / 2.0;
    k.c = tau_ * om;
    k.l11 = std::sqrt(v1);
    k.l21 = k.l11 > 0 ? cv / k.l11 : 0.0;
    k.l22 = std::sqrt(std::max(0.0, v2 - k.l21 * k.l21));
    return k;
  }

  double sigma_, tau_;
  NormalStream s_;
  double x_ = 0.0;
  IntervalCache<Step> steps_;
};

}  // namespace sinsim::errormodels
