// Simulate, then measure: every stochastic effect at two IMU rates (100 Hz and 1 kHz), its
// variance, autocovariance and Allan deviation against theory computed here, independently of the
// code under test.
//
// Bounds: every statistical check is |estimate - theory| ≤ 5 sd, sd from the estimator's
// large-sample variance for a Gaussian process (Bartlett 1946 for autocovariances; Isserlis'
// theorem for the Allan-difference sums, see helpers.hpp). The suite makes ~150 such checks; at
// 5 sd the chance that any fails for a correct generator is < 1e-4, while a wrong discretisation
// (variance ∝ rate, random walk ∝ dt) is off by factors of 3 to 30 at these rates.
#include <catch2/catch.hpp>

#include <cmath>

#include "errormodels/ar_model.hpp"
#include "errormodels/interval_cache.hpp"
#include "errormodels/random.hpp"
#include "errormodels/imu_model.hpp"
#include "helpers.hpp"

using namespace sinsim;
using namespace sinsim::errormodels;
using namespace sinsim::test;

namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr double kHour = 3600.0;

ImuErrorModel gyroX(const std::string& effect) {
  return ImuErrorModel::fromString("gyro:\n  x: [" + effect + "]\n", "test.yaml");
}

std::string num(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

void checkAcf(const std::vector<double>& x, const std::vector<double>& r, int maxLag) {
  auto c = autocov(x, maxLag);
  for (int k = 0; k <= maxLag; ++k) {
    const double rk = k < int(r.size()) ? r[k] : 0.0;
    const double sd = std::sqrt(bartlettVar(r, k, x.size()));
    INFO("lag " << k << ": estimate " << c[k] << ", theory " << rk << ", sd " << sd);
    CHECK(std::fabs(c[k] - rk) <= 5.0 * sd);
  }
}

void checkAllan(const std::vector<std::vector<double>>& recs, const std::vector<double>& r,
                std::size_t m) {
  std::size_t K = 0;
  const double est = allanVar(recs, m, &K);
  const auto th = allanFromAcf(r, m, K, K / recs.size());
  INFO("m = " << m << ": AVAR estimate " << est << ", theory " << th.avar << ", sd " << th.sd);
  CHECK(std::fabs(est - th.avar) <= 5.0 * th.sd);
}

}  // namespace

TEST_CASE("interval cache: coefficients of the last two interval lengths, computed once each") {
  // IMU intervals k/f − (k−1)/f alternate in their last bits; the cache must return make(dt) for
  // whichever length comes, computing it only for a length that is not one of the last two.
  const double a = (2.0 * 0.01) - (1.0 * 0.01), b = (3.0 * 0.01) - (2.0 * 0.01), c = 0.02;
  REQUIRE(a != b);
  int calls = 0;
  auto make = [&calls](double dt) {
    ++calls;
    return 3.0 * dt;
  };
  errormodels::IntervalCache<double> cache;
  const double seq[] = {a, b, a, b, b, c, a, b, b};
  const int expectedCalls[] = {1, 2, 2, 2, 2, 3, 4, 5, 5};  // c evicts a, a evicts b, b evicts c
  for (int i = 0; i < 9; ++i) {
    CHECK(cache.get(seq[i], make) == 3.0 * seq[i]);
    CHECK(calls == expectedCalls[i]);
  }
}

TEST_CASE("white: rate variance N²/dt, no correlation, ADEV(1 s) = N, at 100 Hz and 1 kHz") {
  const double N = 0.2 * kDeg / std::sqrt(kHour);  // 0.2 deg/sqrt(h) [rad/s/sqrt(Hz)]
  auto m = gyroX("{type: white, density: 0.2 deg/sqrt(h)}");
  for (double rate : {100.0, 1000.0}) {
    INFO("IMU rate " << rate << " Hz");
    const std::size_t n = std::size_t(rate * 2000);  // 2000 s
    auto x = simulateRates(m, rate, n, 11, 0);
    std::vector<double> r{N * N * rate};  // continuous white of density N averaged over 1/rate
    checkAcf(x, r, 5);
    // ADEV(1 s) = N: the density read where IEEE 952 reads it. Also τ = 0.1 and 10 s (slope -1/2).
    for (double tau : {0.1, 1.0, 10.0}) checkAllan({x}, r, std::size_t(tau * rate));
    std::size_t K;
    const double adev1 = std::sqrt(allanVar({x}, std::size_t(rate), &K));
    // sd of ADEV ≈ sd(AVAR)/(2 ADEV); for white noise sd(AVAR)/AVAR = sqrt(3/K) (adjacent
    // differences correlate at -1/2, helpers.hpp), so 5 sd ≈ 5·sqrt(3/K)/2 ≈ 14 % with K = 1999.
    CHECK(adev1 == Approx(N).epsilon(5.0 * std::sqrt(3.0 / double(K)) / 2.0));
  }
}

TEST_CASE("white given as per-sample sigma at 1 kHz keeps its density in a 100 Hz IMU") {
  // sigma 0.6 deg/s at 1 kHz ⇒ density sigma/sqrt(1 kHz); averaging 10 held samples per 100 Hz
  // interval divides the variance by 10 (not a variance fixed per sample whatever the rate).
  auto m = gyroX("{type: white, sigma: 0.6 deg/s, rate: 1 kHz}");
  const double sigma = 0.6 * kDeg;
  for (double rate : {100.0, 1000.0}) {
    INFO("IMU rate " << rate << " Hz");
    auto x = simulateRates(m, rate, std::size_t(rate * 500), 12, 0);
    std::vector<double> r{sigma * sigma * rate / 1000.0};
    checkAcf(x, r, 3);
    checkAllan({x}, r, std::size_t(rate));
  }
}

TEST_CASE("random_walk: ADEV = K sqrt(τ/3) at 100 Hz and 1 kHz (slope +1/2, sqrt(dt) steps)") {
  const double K = 0.5 * kDeg / kHour / std::sqrt(kHour);  // 0.5 deg/h/sqrt(h)
  for (std::string mode : {"", ", rate: 1 kHz"}) {
    auto m = gyroX("{type: random_walk, K: 0.5 deg/h/sqrt(h)" + mode + "}");
    for (double rate : {100.0, 1000.0}) {
      INFO("IMU rate " << rate << " Hz, " << (mode.empty() ? "continuous" : "discrete 1 kHz"));
      const int runs = 20;
      std::vector<std::vector<double>> recs;
      for (int k = 0; k < runs; ++k) recs.push_back(simulateRates(m, rate, std::size_t(rate * 200), 13, k));
      for (double tau : {1.0, 10.0}) {
        std::size_t Kd;
        const double avar = allanVar(recs, std::size_t(tau * rate), &Kd);
        const double theory = K * K * tau / 3.0;  // IEEE Std 952-1997 Annex C
        // Allan differences of a random walk correlate at lag 1 with ρ = 1/4 (triangle kernels
        // overlapping by half; none beyond), so Var(AVAR^)/AVAR² = (2/K)(1 + 2ρ²) = 2.25/K.
        // (The discrete walk's AVAR differs from K²τ/3 by O((dt/τ)²) ≤ 1e-4, far inside.)
        const double sd = theory * std::sqrt(2.25 / double(Kd));
        INFO("tau " << tau << ": " << avar << " vs " << theory << " ± " << sd);
        CHECK(std::fabs(avar - theory) <= 5.0 * sd);
      }
    }
  }
}

TEST_CASE("gauss_markov discrete: variance σ² and ACF σ² exp(-|k|Δt/τ) at 100 Hz and 1 kHz") {
  const double sigma = 0.01 * kDeg, tau = 0.05;
  for (double rate : {100.0, 1000.0}) {
    INFO("IMU rate " << rate << " Hz");
    auto m = gyroX("{type: gauss_markov, sigma: 0.01 deg/s, tau: 50 ms, rate: " + num(rate) + " Hz}");
    auto x = simulateRates(m, rate, std::size_t(rate * 1000), 14, 0);
    std::vector<double> r;
    for (int k = 0; k < int(40 * tau * rate); ++k) r.push_back(sigma * sigma * std::exp(-k / (tau * rate)));
    checkAcf(x, r, 20);
    for (double t : {0.01, 0.1, 1.0}) checkAllan({x}, r, std::size_t(t * rate));
  }
}

TEST_CASE("gauss_markov continuous: exact interval averages at 100 Hz and 1 kHz") {
  // The IMU integrates the continuous process: r(0) = 2σ²τ²/Δ² (Δ/τ - 1 + φ),
  // r(k≥1) = σ²τ²(1-φ)² φ^(k-1) / Δ², φ = e^(-Δ/τ) (double integral of σ² e^(-|t-s|/τ)).
  // With τ = 20 ms the 100 Hz case has Δ/τ = 0.5, where sampling instead of averaging would give a
  // variance 18 % too high.
  const double sigma = 0.01 * kDeg, tau = 0.02;
  auto m = gyroX("{type: gauss_markov, sigma: 0.01 deg/s, tau: 20 ms}");
  for (double rate : {100.0, 1000.0}) {
    INFO("IMU rate " << rate << " Hz");
    const double D = 1.0 / rate, phi = std::exp(-D / tau);
    auto x = simulateRates(m, rate, std::size_t(rate * 1000), 15, 0);
    std::vector<double> r{2 * sigma * sigma * tau * tau / (D * D) * (D / tau - 1 + phi)};
    for (int k = 1; k < int(40 * tau * rate) + 5; ++k)
      r.push_back(sigma * sigma * tau * tau * (1 - phi) * (1 - phi) * std::pow(phi, k - 1) / (D * D));
    checkAcf(x, r, 10);
    for (double t : {0.01, 0.1, 1.0}) checkAllan({x}, r, std::size_t(t * rate));
  }
}

TEST_CASE("ar: the paper's Gx AR(5) at 1 kHz reproduces its theoretical ACF, alone and averaged") {
  const std::vector<double> a{-1.0327, -0.34341, 0.037895, 0.19732, 0.14724};  // pole 0.982
  const double sigmaE = 0.02 * kDeg;
  auto m = gyroX("{type: ar, a: [-1.0327, -0.34341, 0.037895, 0.19732, 0.14724], "
                 "sigma: 0.02 deg/s, rate: 1 kHz}");
  const auto r1k = arAcfImpulse(a, sigmaE, 6000);
  // Independent route check: Yule-Walker linear system (ar_model) vs impulse response, 1e-12
  // relative (both are exact up to rounding; the impulse sum is truncated below 1e-17).
  auto yw = ar::autocovariance(a, sigmaE, 50);
  for (int k = 0; k <= 50; ++k) CHECK(yw[k] == Approx(r1k[k]).epsilon(1e-10).margin(1e-12 * r1k[0]));

  SECTION("1 kHz IMU: ACF and Allan at the model's rate") {
    auto x = simulateRates(m, 1000.0, 1000000, 16, 0);
    checkAcf(x, r1k, 60);
    for (std::size_t mm : {10, 100, 1000}) checkAllan({x}, r1k, mm);
  }
  SECTION("100 Hz IMU: each output is the mean of 10 model samples") {
    auto x = simulateRates(m, 100.0, 200000, 17, 0);
    auto r = averagedAcf(r1k, 10, 500);
    checkAcf(x, r, 10);
    for (std::size_t mm : {1, 10, 100}) checkAllan({x}, r, mm);
  }
}

TEST_CASE("ar: coefficients identified at 100 Hz run in a 100 Hz IMU, output_sigma sets r(0)") {
  // The paper's Ay polynomial (largest pole 0.833), read as a 100 Hz model, scaled to an output
  // standard deviation of 3 mg.
  const std::vector<double> a{-0.46354, -0.078197, -0.077146, -0.020449, -0.062445};
  auto m = ImuErrorModel::fromString(
      "accel:\n  y: [{type: ar, a: [-0.46354, -0.078197, -0.077146, -0.020449, -0.062445], "
      "output_sigma: 3 mg, rate: 100 Hz}]\n", "t.yaml");
  const double out = 3e-3 * 9.80665;
  auto r = arAcfImpulse(a, 1.0, 400);
  const double scale = out * out / r[0];
  for (auto& v : r) v *= scale;
  auto x = simulateRates(m, 100.0, 500000, 18, 0, 4);
  checkAcf(x, r, 20);
  for (std::size_t mm : {1, 10, 100}) checkAllan({x}, r, mm);
}

TEST_CASE("ar: a pole at 0.999 (correlation time ~1000 samples) still starts stationary") {
  // AR(2) with complex poles 0.999 e^{±0.05i}: awkward for any start-up transient. The first
  // samples of many runs must already have the stationary variance r(0): with 400 runs the sample
  // variance has sd r(0)·sqrt(2/400); 5 sd.
  const double rho = 0.999, w = 0.05;
  const std::vector<double> a{-2 * rho * std::cos(w), rho * rho};
  auto m = gyroX("{type: ar, a: [" + num(a[0]) + ", " + num(a[1]) + "], sigma: 1 rad/s, rate: 100 Hz}");
  const double r0 = arAcfImpulse(a, 1.0, 0)[0];
  double s0 = 0, s1 = 0;
  const int runs = 400;
  for (int k = 0; k < runs; ++k) {
    auto x = simulateRates(m, 100.0, 2, 19, k);
    s0 += x[0] * x[0];
    s1 += x[1] * x[1];
  }
  CHECK(std::fabs(s0 / runs - r0) <= 5.0 * r0 * std::sqrt(2.0 / runs));
  CHECK(std::fabs(s1 / runs - r0) <= 5.0 * r0 * std::sqrt(2.0 / runs));
}

TEST_CASE("bias_instability: Allan floor 0.664 B over tau_range, at 100 Hz and 1 kHz") {
  // Design check (deterministic, outside the code): the documented construction — GM components
  // 2 per decade at the centres of half-decade cells over tau_range widened by 10^1.5 each side,
  // each of variance B² ln10/(2π) — has, by the closed-form GM Allan variance
  //   σ²(T) = (s² τ²/T²)(2T/τ - 3 + 4e^(-T/τ) - e^(-2T/τ)),
  // a floor within -2.5 %/+1 % of sqrt(2 ln2/π) B over tau_range (IEEE Std 952-1997 Annex C).
  const double B = 10 * kDeg / kHour;
  const double floor = std::sqrt(2 * std::log(2.0) / M_PI) * B;
  const double lo = 1.0, hi = 100.0;
  std::vector<double> taus;
  for (int j = 0; j < 2 * 5; ++j) taus.push_back(lo * std::pow(10.0, -1.5 + (j + 0.5) / 2));
  const double s2 = B * B * std::log(10.0) / (2 * M_PI);
  for (double T = lo; T <= hi * 1.0001; T *= std::pow(10.0, 0.1)) {
    double av = 0;
    for (double t : taus) {
      double x = T / t;
      av += s2 * t * t / (T * T) * (2 * x - 3 + 4 * std::exp(-x) - std::exp(-2 * x));
    }
    INFO("T = " << T);
    CHECK(std::sqrt(av) / floor >= 0.975);
    CHECK(std::sqrt(av) / floor <= 1.01);
  }
  // Simulation check: the generated process has the ACF of the sum of exactly integrated GMs
  // (continuous-GM interval averages, as in the gauss_markov test), hence its Allan variance.
  auto m = gyroX("{type: bias_instability, B: 10 deg/h, tau_range: [1 s, 100 s]}");
  for (double rate : {100.0, 1000.0}) {
    INFO("IMU rate " << rate << " Hz");
    const double D = 1.0 / rate;
    const int runs = rate > 500 ? 6 : 30;
    std::vector<std::vector<double>> recs;
    for (int k = 0; k < runs; ++k) recs.push_back(simulateRates(m, rate, std::size_t(rate * 1000), 20, k));
    std::vector<double> r(std::size_t(rate * 400), 0.0);  // to 400 s: beyond, |r| < 1 % of r(0)
    for (double t : taus) {
      const double phi = std::exp(-D / t);
      r[0] += 2 * s2 * t * t / (D * D) * (D / t - 1 + phi);
      double c = s2 * t * t * (1 - phi) * (1 - phi) / (D * D);
      for (std::size_t k = 1; k < r.size(); ++k, c *= phi) r[k] += c;
    }
    for (double T : {1.0, 10.0, 100.0}) checkAllan(recs, r, std::size_t(T * rate));
  }
}

TEST_CASE("bias_jumps steps: P(no jump) = exp(-rate T), final level variance rate T size^2") {
  // A compound Poisson process (Poisson arrivals of rate lambda, N(0, s^2) jumps): over T the
  // number of jumps is Poisson(mu = lambda T), so P(none) = e^-mu, and the level L_T given N
  // jumps is N(0, N s^2), so E L_T^2 = mu s^2 and Var L_T^2 = s^4 (3 E N^2 - mu^2) = s^4
  // (3 mu + 2 mu^2). Both bounds are exact (binomial; the mean of R independent L_T^2), not
  // Gaussian-process approximations. At most one jump per interval: P(two) ~ (lambda dt)^2 / 2
  // per interval, 2.5e-5 of the runs here.
  const double s = 0.1 * kDeg, lambda = 0.02, T = 100.0, mu = lambda * T;
  auto m = gyroX("{type: bias_jumps, rate: 0.02 Hz, size: 0.1 deg/s}");
  for (double rate : {100.0, 1000.0}) {
    INFO("IMU rate " << rate << " Hz");
    const int runs = rate > 500 ? 600 : 3000;
    int none = 0;
    double sumL2 = 0;
    for (int k = 0; k < runs; ++k) {
      const auto x = simulateRates(m, rate, std::size_t(rate * T), 21, std::uint64_t(k));
      bool flat = true;
      for (double v : x) flat = flat && v == 0.0;
      none += flat;
      sumL2 += x.back() * x.back();
    }
    const double p0 = std::exp(-mu), sdP = std::sqrt(p0 * (1 - p0) / runs);
    INFO("no jump in " << none << " of " << runs << " runs, expected " << p0 * runs);
    CHECK(std::fabs(double(none) / runs - p0) <= 5 * sdP);
    const double meanL2 = sumL2 / runs, sdL2 = s * s * std::sqrt((3 * mu + 2 * mu * mu) / runs);
    INFO("E L_T^2 " << meanL2 << " vs " << mu * s * s << " +- " << sdL2);
    CHECK(std::fabs(meanL2 - mu * s * s) <= 5 * sdL2);
  }
}

TEST_CASE("bias_jumps telegraph: two levels +-size/2 and the ACF of a GM of tau 1/(2 rate)") {
  // A random telegraph between +-a switching at rate lambda has E x(t) x(t+h) = a^2 e^(-2 lambda
  // |h|): the continuous Gauss-Markov's with sigma = a, tau = 1/(2 lambda), so its interval
  // averages have the continuous-GM ACF of the gauss_markov test. The bounds are Bartlett's for a
  // Gaussian process; a two-level process has a negative fourth cumulant, which only lowers the
  // variance of the autocovariance estimates. Intervals without a switch hold exactly +-a.
  const double a = 0.05 * kDeg, lambda = 0.5, tau = 1.0 / (2 * lambda);
  auto m = gyroX("{type: bias_jumps, rate: 0.5 Hz, size: 0.1 deg/s, telegraph: yes}");
  for (double rate : {100.0, 1000.0}) {
    INFO("IMU rate " << rate << " Hz");
    const double D = 1.0 / rate, phi = std::exp(-D / tau);
    auto x = simulateRates(m, rate, std::size_t(rate * 2000), 22, 0);
    std::size_t onLevel = 0;
    for (double v : x) onLevel += std::fabs(std::fabs(v) - a) <= 1e-12 * a;
    // a switch moves one interval off the levels: Poisson(lambda 2000 s = 1000) of them, sd 32;
    // 5 sd is 16 %
    CHECK(double(x.size() - onLevel) == Approx(lambda * 2000).epsilon(0.16));
    std::vector<double> r{2 * a * a * tau * tau / (D * D) * (D / tau - 1 + phi)};
    for (int k = 1; k < int(40 * tau * rate) + 5; ++k)
      r.push_back(a * a * tau * tau * (1 - phi) * (1 - phi) * std::pow(phi, k - 1) / (D * D));
    checkAcf(x, r, 10);
    for (double t : {0.1, 1.0, 10.0}) checkAllan({x}, r, std::size_t(t * rate));
  }
}

TEST_CASE("streams: different runs are independent, and random access matches sequential") {
  auto m = gyroX("{type: white, density: 1 rad/s/sqrt(Hz)}");
  const std::size_t n = 200000;
  auto x0 = simulateRates(m, 100.0, n, 21, 0);
  auto x1 = simulateRates(m, 100.0, n, 21, 1);
  auto y0 = simulateRates(m, 100.0, n, 22, 0);
  auto corr = [&](const std::vector<double>& a, const std::vector<double>& b) {
    double sab = 0, saa = 0, sbb = 0;
    for (std::size_t i = 0; i < n; ++i) sab += a[i] * b[i], saa += a[i] * a[i], sbb += b[i] * b[i];
    return sab / std::sqrt(saa * sbb);
  };
  // Independent N(0,1) pairs: the sample correlation has sd 1/sqrt(n); 5 sd.
  CHECK(std::fabs(corr(x0, x1)) <= 5.0 / std::sqrt(double(n)));
  CHECK(std::fabs(corr(x0, y0)) <= 5.0 / std::sqrt(double(n)));
  // Lagged cross-correlation too (a stream offset by a block would show up here).
  std::vector<double> x1s(x1.begin() + 64, x1.end());
  x1s.resize(n, 0.0);
  CHECK(std::fabs(corr(x0, x1s)) <= 5.0 / std::sqrt(double(n)));
  // Regenerating normal #123457 of a stream alone gives the number the sequential stream gave.
  NormalStream s(5, 6, 7);
  double v = 0;
  for (int i = 0; i <= 123457; ++i) v = s.next();
  CHECK(NormalStream::at(5, 6, 7, 123457) == v);
}
