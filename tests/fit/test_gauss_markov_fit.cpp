// First-order Gauss-Markov fit: exact on a closed-form ACF, and on simulated records at two
// sample rates the recovered (sigma, tau) fall within the stated (Bartlett) uncertainty, whose
// size is checked against the Monte Carlo spread.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "common/error.hpp"
#include "errormodels/fit/ar_fit.hpp"
#include "errormodels/fit/gauss_markov_fit.hpp"

using namespace sinsim::errormodels::fit;

namespace {

// Exact discretisation of the GM process: x[n] = phi x[n-1] + sigma sqrt(1 - phi^2) w[n].
std::vector<double> simulateGm(double sigma, double tau, double dt, std::size_t n,
                               std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> w;
  const double phi = std::exp(-dt / tau), q = sigma * std::sqrt(1 - phi * phi);
  std::vector<double> x(n);
  double v = sigma * w(rng);  // stationary start
  for (auto& xi : x) {
    v = phi * v + q * w(rng);
    xi = v;
  }
  return x;
}

std::vector<double> demeanedAcf(std::vector<double> x, std::size_t maxLag) {
  double mean = 0;
  for (double v : x) mean += v;
  mean /= static_cast<double>(x.size());
  for (double& v : x) v -= mean;
  return biasedAutocovariance(x, maxLag);
}

}  // namespace

TEST_CASE("GM fit is exact on a closed-form autocovariance", "[fit][gm]") {
  const double sigma = 0.02, tau = 0.305, dt = 0.01;  // [U], [s], [s]
  std::vector<double> acf(120);
  for (std::size_t k = 0; k < acf.size(); ++k)
    acf[k] = sigma * sigma * std::exp(-double(k) * dt / tau);
  // Noise-free data: the only error is the Gauss-Newton stopping rule (1e-13 relative steps).
  const auto fit = fitGaussMarkov(acf, dt);
  CHECK(fit.sigma == Approx(sigma).epsilon(1e-10));
  CHECK(fit.tau == Approx(tau).epsilon(1e-10));
  CHECK(fit.lastLag == 92);  // first k with k dt / tau >= 3 (91.5)
  CHECK_FALSE(fit.bartlettCovariance);
  // White noise of variance 3 sigma^2 added: it only raises lag 0; skipping lag 0 is still exact.
  auto withWhite = acf;
  withWhite[0] += 3 * sigma * sigma;
  GaussMarkovFitOptions skip;
  skip.skipLagZero = true;
  const auto fit2 = fitGaussMarkov(withWhite, dt, skip);
  CHECK(fit2.sigma == Approx(sigma).epsilon(1e-10));
  CHECK(fit2.tau == Approx(tau).epsilon(1e-10));
}

TEST_CASE("GM fit round trip at two sample rates with calibrated uncertainty", "[fit][gm]") {
  // sigma = 0.05 U, tau = 0.5 s; 300 s records at 100 Hz and 500 Hz. For each rate, 60 seeded
  // records: every estimate within 4 stated sigma of the truth (4 sigma: 120 two-sided checks per
  // rate, P(any > 4 sigma) ~ 0.8 %; tau on a log scale, see below), and the Monte Carlo SD of tau_hat within [0.7, 1.4] of the
  // mean stated SD (the SD of 60 draws has ~9 % standard error, plus the O(tau/T) bias of the
  // sample ACF and the asymptotic nature of Bartlett's formula).
  const double sigma = 0.05, tau = 0.5, T = 300.0;
  for (double dt : {0.01, 0.002}) {
    INFO("dt = " << dt);
    const auto n = static_cast<std::size_t>(T / dt);
    const auto maxLag = static_cast<std::size_t>(4 * tau / dt);
    double sumTau = 0, sumTau2 = 0, sumStated = 0, sumSig = 0, sumSig2 = 0, sumSigStated = 0;
    const int runs = 60;
    for (int r = 0; r < runs; ++r) {
      const auto x = simulateGm(sigma, tau, dt, n, 100 + r + static_cast<int>(1 / dt));
      GaussMarkovFitOptions opt;
      opt.recordLength = n;
      const auto fit = fitGaussMarkov(demeanedAcf(x, maxLag), dt, opt);
      REQUIRE(fit.bartlettCovariance);
      // tau_hat is right-skewed (its relative SD is ~12 % here and the stated SD scales with
      // tau_hat^1.5), so the check is made on ln tau, where the delta-method SD is
      // tauStdError / tau_hat and the distribution is close to symmetric.
      CHECK(std::abs(std::log(fit.tau / tau)) <= 4 * fit.tauStdError / fit.tau);
      CHECK(std::abs(fit.sigma - sigma) <= 4 * fit.sigmaStdError);
      sumTau += fit.tau; sumTau2 += fit.tau * fit.tau; sumStated += fit.tauStdError;
      sumSig += fit.sigma; sumSig2 += fit.sigma * fit.sigma; sumSigStated += fit.sigmaStdError;
    }
    const double sdTau = std::sqrt(sumTau2 / runs - std::pow(sumTau / runs, 2));
    const double sdSig = std::sqrt(sumSig2 / runs - std::pow(sumSig / runs, 2));
    INFO("tau: MC sd " << sdTau << " stated " << sumStated / runs << "; sigma: MC sd " << sdSig
                       << " stated " << sumSigStated / runs);
    CHECK(sdTau / (sumStated / runs) >= 0.7);
    CHECK(sdTau / (sumStated / runs) <= 1.4);
    CHECK(sdSig / (sumSigStated / runs) >= 0.7);
    CHECK(sdSig / (sumSigStated / runs) <= 1.4);
  }
}

TEST_CASE("GM fit refuses unusable autocovariances", "[fit][gm][input]") {
  CHECK_THROWS_AS(fitGaussMarkov({1.0, 0.5}, 0.01), sinsim::InputError);
  CHECK_THROWS_AS(fitGaussMarkov({1.0, 0.5, 0.25}, 0.0), sinsim::InputError);
  CHECK_THROWS_AS(fitGaussMarkov({-1.0, 0.5, 0.25}, 0.01), sinsim::InputError);
  CHECK_THROWS_AS(fitGaussMarkov({1.0, 1.2, 1.5, 1.9}, 0.01), sinsim::InputError);  // no decay
  CHECK_THROWS_WITH(fitGaussMarkov({1.0, std::nan(""), 0.2}, 0.01), Catch::Contains("lag 1"));
}

// The Bartlett sandwich is computed without forming its m x m covariance (gauss_markov_fit.cpp,
// bartlettMiddle): it must equal the dense (J'J)^-1 J' C J (J'J)^-1 built here from the header's
// formula, on a fit whose lags start at 0 and at 1. And a fit over 10^5 lags -- an ACF that never
// decays, as a random walk's over the 100 s of lags `fit --kind gm` computes at 1 kHz -- runs: the
// dense C was 80 GB (std::bad_alloc, found by a blind round trip of `fit`, bench/fit_blind/).
TEST_CASE("GM fit: the Bartlett covariance equals the dense sandwich and 10^5 lags run", "[fit][gm]") {
  const double sigma = 0.05, tau = 0.5, dt = 0.01;
  const std::size_t n = 30000;
  const auto x = simulateGm(sigma, tau, dt, n, 77);
  for (const bool skip : {false, true}) {
    GaussMarkovFitOptions opt;
    opt.recordLength = n;
    opt.skipLagZero = skip;
    const auto fit = fitGaussMarkov(demeanedAcf(x, 400), dt, opt);
    REQUIRE(fit.bartlettCovariance);
    const double s2 = fit.sigma * fit.sigma, phi = std::exp(-dt / fit.tau);
    const double kappa = (1 + phi * phi) / (1 - phi * phi);
    const auto m = Eigen::Index(fit.lastLag - fit.firstLag + 1);
    Eigen::MatrixXd J(m, 2), C(m, m);
    for (Eigen::Index i = 0; i < m; ++i) {
      const double h = double(fit.firstLag) + double(i), e = std::exp(-h * dt / fit.tau);
      J(i, 0) = e;
      J(i, 1) = s2 * e * h * dt / (fit.tau * fit.tau);
      for (Eigen::Index j = 0; j < m; ++j) {
        const double k = double(fit.firstLag) + double(j), d = std::abs(h - k);
        C(i, j) = s2 * s2 / double(n) * (std::pow(phi, d) * (kappa + d) + std::pow(phi, h + k) * (kappa + h + k));
      }
    }
    const Eigen::Matrix2d A = (J.transpose() * J).inverse();
    Eigen::Matrix2d cov = A * (J.transpose() * C * J) * A;
    Eigen::Matrix2d G = Eigen::Matrix2d::Identity();
    G(0, 0) = 0.5 / fit.sigma;
    cov = G * cov * G.transpose();
    INFO("skip lag 0: " << skip << ", lags " << fit.firstLag << ".." << fit.lastLag);
    for (int r = 0; r < 2; ++r)
      for (int c = 0; c < 2; ++c) CHECK(fit.covariance(r, c) == Approx(cov(r, c)).epsilon(1e-9));
  }
  // An ACF that never falls to e^-3 over 10^5 lags, as a random walk's sample ACF (1 - k / (2 L)):
  // every lag is used.
  std::vector<double> slow(100001);
  for (std::size_t k = 0; k < slow.size(); ++k) slow[k] = 1.0 - double(k) / (2.0 * double(slow.size()));
  GaussMarkovFitOptions opt;
  opt.recordLength = 1000000;
  const auto fit = fitGaussMarkov(slow, 1e-3, opt);
  CHECK(fit.lastLag == 100000);
  CHECK(std::isfinite(fit.tauStdError));
}
