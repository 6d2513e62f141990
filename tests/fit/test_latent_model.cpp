// Closed-form Allan variances of the latent-process terms (errormodels/fit/latent_model.hpp),
// checked against truth from outside the formula: the exact AR Allan variance from the
// autocovariance (fit::arAllanVariance), the continuous IEEE 952 C form, and the average Allan
// variance of records made by the simulator's own effect plug-ins (`sinsim synth`'s loop).
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "../identify/identify_test_util.hpp"
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
