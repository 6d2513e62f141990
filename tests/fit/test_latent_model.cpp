// Closed-form Allan variances of the latent-process terms (errormodels/fit/latent_model.hpp),
// checked against truth from outside the formula: the exact AR Allan variance from the
// autocovariance (fit::arAllanVariance), the continuous IEEE 952 C form, and the average Allan
// variance of records made by the simulator's own effect plug-ins (`sinsim synth`'s loop).
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "../identify/identify_test_util.hpp"
#include "common/constants.hpp"
#include "common/error.hpp"
#include "errormodels/fit/ar_fit.hpp"
#include "errormodels/fit/latent_model.hpp"
#include "fit_test_util.hpp"

using namespace sinsim::errormodels::fit;

TEST_CASE("discrete GM Allan variance equals the AR(1) Allan variance from its autocovariance",
          "[fit][latent]") {
  const double dt = 0.01, s2 = 2.5;
  std::vector<std::size_t> m;
  for (std::size_t k = 1; k <= 65536; k *= 2) m.push_back(k);
  // T/dt from 0.3 (phi = 0.036) to 1e6 (phi = 1 - 1e-6, the series branch for small m u).
  for (double r : {0.3, 1.0, 10.0, 1e3, 1e6}) {
    const double T = r * dt, phi = std::exp(-dt / T);
    const auto ref = arAllanVariance({1.0, -phi}, s2 * (1.0 - phi * phi), m);
    for (std::size_t i = 0; i < m.size(); ++i) {
      INFO("T/dt " << r << ", m " << m[i]);
      // arAllanVariance sums the autocovariance in double: ~1e-9 relative at phi = 1 - 1e-6
      // (its terms ~1e6 times the result); the closed form's series keeps 8 digits (header).
      CHECK(gmDiscreteAllanVariance(s2, T, dt, m[i]) == Approx(ref[i]).epsilon(1e-6));
    }
  }
}

TEST_CASE("discrete GM Allan variance tends to the continuous IEEE 952 form as dt -> 0",
          "[fit][latent]") {
  const double T = 2.0, s2 = 1.0;
  for (double tau : {0.01, 0.5, 2.0, 20.0, 500.0}) {
    const double x = tau / T;
    const double cont = 2.0 * s2 * T / tau * (1.0 - (3.0 - 4.0 * std::exp(-x) + std::exp(-2.0 * x)) / (2.0 * x));
    const double dt = T * 1e-5;
    const auto m = static_cast<std::size_t>(std::llround(tau / dt));
    // The AR(1) differs from the interval-averaged continuous GM by O(dt / T) = 1e-5 relative.
    CHECK(gmDiscreteAllanVariance(s2, T, dt, m) == Approx(cont).epsilon(1e-4));
  }
}

namespace {

/// Autocovariance of the averaged GM's samples at lag k from its definition,
/// (1/dt^2) int_0^dt int_{k dt}^{(k+1) dt} s2 e^{-|t - s| / T} dt ds: with t - s = (k + v) dt, v the
/// difference of two uniform positions in an interval (density 1 - |v| on [-1, 1]), it is
/// s2 int (1 - |v|) e^{-|k + v| dt / T} dv, taken by Gauss-Legendre on [-1, 0] and [0, 1] (smooth on
/// each) - a quadrature, not the closed form it is checked against.
double averagedGmAutocovariance(double s2, double T, double dt, std::size_t k) {
  static const double x8[] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
                              0.1834346424956498,  0.5255324099163290,  0.7966664774136267,  0.9602898564975363};
  static const double w8[] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
                              0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
  const int parts = 16;  // per side: 16 x 8 nodes, exact to ~1e-14 for these exponentials
  double sum = 0.0;
  for (double side : {-1.0, 1.0})
    for (int sub = 0; sub < parts; ++sub)
      for (int i = 0; i < 8; ++i) {
        const double v = side * (sub + 0.5 + 0.5 * x8[i]) / parts;
        sum += w8[i] / (2.0 * parts) * (1.0 - std::fabs(v)) * std::exp(-std::fabs(double(k) + v) * dt / T);
      }
  return s2 * sum;
}

}  // namespace

TEST_CASE("averaged GM: Allan variance from its samples' autocovariance, and its PSD",
          "[fit][latent]") {
  // The Allan variance of means of m samples: Var(mean) - Cov(two adjacent means), each a sum of
  // the samples' autocovariance (from the quadrature above) - against the closed form at T/dt from
  // 0.3 to 1e3 (x = m dt / T down to 1e-3: the series branch below it is checked next).
  const double dt = 0.01, s2 = 2.5;
  for (double r : {0.3, 3.0, 25.0, 1e3}) {
    const double T = r * dt;
    std::vector<double> c(130);
    for (std::size_t k = 0; k < c.size(); ++k) c[k] = averagedGmAutocovariance(s2, T, dt, k);
    for (std::size_t m : {1, 2, 4, 16, 64}) {
      double var = 0.0, cov = 0.0;
      for (std::size_t i = 0; i < m; ++i)
        for (std::size_t j = 0; j < m; ++j) {
          var += c[i > j ? i - j : j - i];
          cov += c[m + j - i];
        }
      const double ref = (var - cov) / double(m * m);
      INFO("T/dt " << r << ", m " << m);
      CHECK(gmAveragedAllanVariance(s2, T, dt, m) == Approx(ref).epsilon(1e-9));
      CHECK(gmAllanVariance({std::sqrt(s2), T, true}, dt, m) == Approx(ref).epsilon(1e-9));
    }
    // The PSD's lag-0 and lag-1 transforms (midpoint rule, exact for these trigonometric sums to
    // rounding at 2^14 nodes) are the samples' autocovariance.
    LatentModel g;
    g.gm.push_back({std::sqrt(s2), T, true});
    const int n = 1 << 14;
    double a0 = 0.0, a1 = 0.0;
    for (int i = 0; i < n; ++i) {
      const double w = (i + 0.5) * sinsim::kPi / n, S = latentPsd(g, dt, w);
      a0 += S / n, a1 += S * std::cos(w) / n;
    }
    CHECK(a0 == Approx(c[0]).epsilon(1e-6));
    CHECK(a1 == Approx(c[1]).epsilon(1e-6));
  }
  // The series branch (x = m dt / T < 0.1) meets the direct form at 0.1 (to 1e-12, the direct
  // form's rounding there), and tends to 2 s2 x / 3 (x -> 0).
  const double T = 1.0;
  CHECK(gmAveragedAllanVariance(s2, T, 0.1 * (1 - 1e-15), 1) == Approx(gmAveragedAllanVariance(s2, T, 0.1, 1)).epsilon(1e-12));
  CHECK(gmAveragedAllanVariance(s2, T, 1e-9, 1) == Approx(s2 * 2e-9 / 3.0).epsilon(1e-8));
  // The sampled AR(1) and the averaged GM part where T is a few samples: at T = 25 dt the
  // averaged one has 2/3 of the AR(1)'s Allan variance at tau = dt (x = 0.04: (2x/3 - x^2/2) / x).
  CHECK(gmAveragedAllanVariance(s2, 0.25, dt, 1) / gmDiscreteAllanVariance(s2, 0.25, dt, 1) ==
        Approx(0.66).margin(0.01));
}

namespace {

/// Mean and standard error over seeds of the overlapping Allan variance of records from `body`.
void averageAvar(const std::string& body, double rate, double duration, int seeds,
                 const std::vector<std::size_t>& m, std::vector<double>& mean, std::vector<double>& se) {
  std::vector<double> s(m.size(), 0.0), s2(m.size(), 0.0);
  for (int k = 0; k < seeds; ++k) {
    const auto r = identify_test::staticRecord(body, rate, duration, 500 + std::uint64_t(k));
    for (std::size_t i = 0; i < m.size(); ++i) {
      const double v = fit_test::overlappingAvar(r.gyro[0], 1.0 / rate, m[i]);
      s[i] += v, s2[i] += v * v;
    }
  }
  mean.resize(m.size()), se.resize(m.size());
  for (std::size_t i = 0; i < m.size(); ++i) {
    mean[i] = s[i] / seeds;
    se[i] = std::sqrt((s2[i] / seeds - mean[i] * mean[i]) / (seeds - 1));
  }
}

}  // namespace

TEST_CASE("composite closed form matches the simulated Allan variance (white + GM + RW + quantization + ramp)",
          "[fit][latent]") {
  // 100 Hz, 300 s, 48 seeds. Each term dominates some of m = 1..2048 (checked by the design:
  // quantization at m = 1, white 2..16, GM (tau 0.5 s) around 64, RW and ramp at the end).
  const double rate = 100.0, dt = 0.01, N = 1e-3, sigma = 3e-3, T = 0.5, K = 1e-3, R = 2e-6;
  const double lsb = N * std::sqrt(dt);  // increment LSB = per-sample noise: uniform white rounding
  const std::string body =
      "gyro:\n  x:\n"
      "    - {type: white, density: 1e-3 rad/sqrt(s)}\n"
      "    - {type: gauss_markov, sigma: 3e-3 rad/s, tau: 0.5 s, rate: 100 Hz}\n"
      "    - {type: random_walk, K: 1e-3 rad/s/sqrt(s)}\n"
      "    - {type: ramp, slope: 2e-6 rad/s/s}\n"
      "    - {type: quantization, lsb: 1e-4 rad}\n";
  REQUIRE(lsb == Approx(1e-4));
  LatentModel model;
  model.white = N, model.randomWalk = K, model.drift = R, model.quantization = lsb / std::sqrt(12.0);
  model.gm.push_back({sigma, T});
  std::vector<std::size_t> m;
  for (std::size_t k = 1; k <= 2048; k *= 2) m.push_back(k);
  std::vector<double> mean, se;
  averageAvar(body, rate, 300.0, 48, m, mean, se);
  const auto avar = latentAllanVariance(model, dt, m);
  for (std::size_t i = 0; i < m.size(); ++i) {
    INFO("m " << m[i] << ": simulated " << mean[i] << " +- " << se[i] << ", closed form " << avar[i]);
    // 4 standard errors of the seed mean: the mean of 48 independent estimates is near normal;
    // 12 points at 4 sigma give a false alarm rate < 1e-3.
    CHECK(std::fabs(mean[i] - avar[i]) <= 4.0 * se[i]);
  }
}

TEST_CASE("sampled flicker: Allan variance against closed forms and an independent quadrature",
          "[fit][latent]") {
  // (B^2/pi) I(m), I(m) = int_0^{1/2} 2 sin^4(pi m x) / (m^2 x sin^2(pi x)) dx. I(1) = Cin(pi) and
  // I(2) = -Cin(pi)/4 + Cin(2 pi)/2 + Cin(3 pi)/4, Cin(z) = gamma + ln z - Ci(z) (expanding sin^2
  // cos^4 in cosines); I(4), I(64) by adaptive quadrature. Numbers from SciPy 1.x:
  //   from scipy.special import sici; from scipy.integrate import quad; import numpy as np
  //   Cin = lambda z: np.euler_gamma + np.log(z) - sici(z)[1]
  //   quad(lambda x: 2*np.sin(np.pi*m*x)**4/(m*m*x*np.sin(np.pi*x)**2), 0, 0.5, limit=2000)
  const double B2 = 2.0, floor = 2.0 * std::log(2.0) / sinsim::kPi * B2;
  CHECK(flickerSampledAllanVariance(B2, 1) == Approx(B2 / sinsim::kPi * 1.6482776387045073).epsilon(1e-12));
  CHECK(flickerSampledAllanVariance(B2, 2) == Approx(B2 / sinsim::kPi * 1.5092416959659334).epsilon(1e-12));
  CHECK(flickerSampledAllanVariance(B2, 4) == Approx(B2 / sinsim::kPi * 1.4269810614832248).epsilon(1e-12));
  CHECK(flickerSampledAllanVariance(B2, 64) == Approx(B2 / sinsim::kPi * 1.3866210021618093).epsilon(1e-11));
  // 1.19x the averaged flicker's floor at m = 1, tending to it; the floor itself beyond m = 4096
  CHECK(flickerSampledAllanVariance(B2, 1) / floor == Approx(1.18898).epsilon(1e-5));
  CHECK(flickerSampledAllanVariance(B2, 4096) == Approx(floor).epsilon(1e-6));
  CHECK(flickerSampledAllanVariance(B2, 4097) == floor);
  CHECK_THROWS_AS(flickerSampledAllanVariance(B2, 0), sinsim::InputError);
}

TEST_CASE("averaged GM: closed form matches the simulator's continuous GM (no rate)", "[fit][latent]") {
  // The simulator draws the continuous GM's exact mean over each IMU interval (gm_process.hpp), an
  // implementation independent of this closed form. 100 Hz, 120 s, tau 0.2 s = 20 samples, where
  // the sampled AR(1)'s Allan variance at tau = dt is 1.5x the averaged one.
  const double rate = 100.0, dt = 0.01;
  const std::string body = "gyro:\n  x:\n    - {type: gauss_markov, sigma: 2e-3 rad/s, tau: 0.2 s}\n";
  std::vector<std::size_t> m;
  for (std::size_t k = 1; k <= 1024; k *= 2) m.push_back(k);
  std::vector<double> mean, se;
  averageAvar(body, rate, 120.0, 48, m, mean, se);
  LatentModel model;
  model.gm.push_back({2e-3, 0.2, true});
  const auto avar = latentAllanVariance(model, dt, m);
  for (std::size_t i = 0; i < m.size(); ++i) {
    INFO("m " << m[i] << ": simulated " << mean[i] << " +- " << se[i] << ", closed form " << avar[i]);
    CHECK(std::fabs(mean[i] - avar[i]) <= 4.0 * se[i]);
  }
  // ... and the sampled AR(1)'s form is far outside at tau = dt (the test can fail)
  CHECK(std::fabs(mean[0] - gmDiscreteAllanVariance(4e-6, 0.2, dt, 1)) > 10.0 * se[0]);
}

TEST_CASE("flicker floor: closed form within the simulated effect's stated flatness", "[fit][latent]") {
  // bias_instability is a sum of GMs whose Allan floor stays within -2.5 %/+1 % of
  // (2 ln 2 / pi) B^2 over tau_range (errormodels/effects/bias_instability.cpp).
  const double rate = 100.0, dt = 0.01, B = 2e-3;
  const std::string body = "gyro:\n  x:\n    - {type: bias_instability, B: 2e-3 rad/s, tau_range: [0.01 s, 300 s]}\n";
  LatentModel model;
  model.flicker = B;
  std::vector<std::size_t> m;
  for (std::size_t k = 1; k <= 2048; k *= 2) m.push_back(k);
  std::vector<double> mean, se;
  averageAvar(body, rate, 300.0, 32, m, mean, se);
  const auto avar = latentAllanVariance(model, dt, m);
  for (std::size_t i = 0; i < m.size(); ++i) {
    INFO("m " << m[i] << ": simulated " << mean[i] << " +- " << se[i] << ", closed form " << avar[i]);
    // 5 % ADEV-floor flatness budget (~5 % in AVAR covers -2.5 %/+1 % of the deviation twice)
    // plus 4 standard errors of the seed mean.
    CHECK(std::fabs(mean[i] - avar[i]) <= 0.05 * avar[i] + 4.0 * se[i]);
  }
}

TEST_CASE("AR term of the composite model: AR(1) equals the discrete GM, in Allan variance and PSD",
          "[fit][latent][ar]") {
  // Two closed forms from different derivations: ar::allanVariance (autocovariance sum) for the
  // AR term and the GM's own closed form; an AR(1) with E = sigma^2 (1 - phi^2) is that GM.
  const double dt = 0.01, s2 = 4e-8, T = 0.3, phi = std::exp(-dt / T);
  LatentModel ar;
  ar.arPolynomial = {1.0, -phi};
  ar.arVariance = s2 * (1.0 - phi * phi);
  LatentModel gm;
  gm.gm = {{std::sqrt(s2), T}};
  std::vector<std::size_t> m;
  for (std::size_t k = 1; k <= 4096; k *= 2) m.push_back(k);
  const auto a = latentAllanVariance(ar, dt, m), g = latentAllanVariance(gm, dt, m);
  // double-precision sums of ~T/dt = 30 terms: 1e-12 relative is far above their round-off
  for (std::size_t i = 0; i < m.size(); ++i) CHECK(a[i] == Approx(g[i]).epsilon(1e-12));
  for (double w : {1e-4, 0.1, 1.0, 3.0}) CHECK(latentPsd(ar, dt, w) == Approx(latentPsd(gm, dt, w)).epsilon(1e-12));
  CHECK(ar.termNames() == "ar");
}

TEST_CASE("one-step prediction variance of the terms: white, GM, white + GM (ARMA(1,1)), AR(5)",
          "[fit][latent][innovation]") {
  // Closed forms from outside the quadrature: white noise predicts nothing (N^2 / dt); an AR(1)
  // (the discrete GM) leaves sigma^2 (1 - phi^2); an AR polynomial driven by E leaves E
  // (minimum phase); white + GM is an ARMA(1,1) whose innovation variance v solves
  // a (1 + phi^2) + b = v (1 + theta^2), a phi = v theta (a = N^2 / dt, b = sigma^2 (1 - phi^2):
  // the spectral factorisation of a |1 - phi z|^2 + b), theta the root inside the unit circle.
  const double dt = 0.01, N = 1e-3, s = 2e-3, T = 0.05, phi = std::exp(-dt / T);
  const double a = N * N / dt, b = s * s * (1.0 - phi * phi);
  LatentModel white;
  white.white = N;
  CHECK(latentInnovationVariance(white, dt) == Approx(a).epsilon(1e-9));
  LatentModel gm;
  gm.gm = {{s, T}};
  CHECK(latentInnovationVariance(gm, dt) == Approx(b).epsilon(1e-6));
  LatentModel both = white;
  both.gm = gm.gm;
  const double c = a * phi / (a * (1.0 + phi * phi) + b);  // theta / (1 + theta^2)
  const double theta = (1.0 - std::sqrt(1.0 - 4.0 * c * c)) / (2.0 * c);
  CHECK(latentInnovationVariance(both, dt) == Approx(a * phi / theta).epsilon(1e-6));
  LatentModel ar;  // the paper's Gx AR(5) (poles up to 0.982)
  ar.arPolynomial = {1.0, -1.0327, -0.34341, 0.037895, 0.19732, 0.14724};
  ar.arVariance = 4e-6;
  CHECK(latentInnovationVariance(ar, dt) == Approx(4e-6).epsilon(1e-6));
  // A walk beside white noise: above the white part's innovation (an independent process added
  // never makes the next sample more predictable).
  LatentModel walk = white;
  walk.randomWalk = 1e-3;
  CHECK(latentInnovationVariance(walk, dt) > a);
  CHECK_THROWS_AS(latentInnovationVariance(LatentModel{}, dt), sinsim::InputError);
}

TEST_CASE("a slow GM's spectrum at its lowest frequencies keeps its digits", "[fit][latent]") {
  // T = 1e6 dt: |1 - phi e^{-iw}|^2 is ~1e-12 at w -> 0, where 1 - 2 phi cos w + phi^2 keeps only
  // ~4 digits. Truth from the autocovariance sums: the sampled GM's sum_k sigma^2 phi^|k| =
  // sigma^2 coth(u/2), the averaged samples' the continuous PSD at 0 over dt, 2 sigma^2 / u
  // (u = dt / T); at w = 1e-12 the frequency's own term is 1e-12 of these.
  const double dt = 0.01, T = 1e4, sigma = 2.0, u = dt / T, w = 1e-12;
  LatentModel sampled, averaged;
  sampled.gm = {{sigma, T}};
  averaged.gm = {{sigma, T, true}};
  CHECK(LatentSpectrum(sampled, dt)(w) == Approx(sigma * sigma / std::tanh(0.5 * u)).epsilon(1e-10));
  CHECK(LatentSpectrum(averaged, dt)(w) == Approx(2.0 * sigma * sigma / u).epsilon(1e-10));
  CHECK(latentPsd(sampled, dt, w) == LatentSpectrum(sampled, dt)(w, std::sin(0.5 * w)));
}
