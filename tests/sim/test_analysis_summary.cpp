// `sinsim analyze`'s noise terms read off the Allan curve (sim/analysis_summary.cpp): the white
// density N where the curve has white noise's slope. Truth from the construction: white noise of
// density N, and the same noise through a moving average (a low-pass filter keeps the PSD at low
// frequency, N² there, and removes it near Nyquist, where the shortest tau looks).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "sim/analysis.hpp"

using namespace sinsim;

namespace {

constexpr double kRate = 100.0, kN = 0.01;  // [Hz], [unit·√s]

std::vector<double> whiteNoise(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, kN * std::sqrt(kRate));
  std::vector<double> y(n);
  for (double& v : y) v = g(rng);
  return y;
}

sim::ChannelStats stats(const std::vector<double>& y) {
  errormodels::AllanOptions o;
  o.grid = errormodels::TauGrid::PerDecade;
  sim::ChannelStats c;
  c.name = "gx";
  c.unit_si = "rad/s";
  c.allan = errormodels::allanDeviation(y, kRate, errormodels::AllanVariant::Overlapping, o);
  return c;
}

}  // namespace

TEST_CASE("analyze reads the white density where the Allan curve has white noise's slope", "[analysis]") {
  // White noise: read at the shortest tau, as IEEE 952 reads it; 2e5 samples put that point's
  // ADEV within ~0.3 % (1 sigma), so 2 % is > 6 sigma. No warning.
  const auto white = stats(whiteNoise(200000, 7));
  const sim::NoiseTerms w = sim::readNoiseTerms(white.allan);
  CHECK(w.tauN == white.allan.tau.front());
  CHECK(w.N == Approx(kN).epsilon(0.02));
  CHECK(sim::analysisWarnings({white}).empty());
  // Its curve falls to the longest tau: no floor, and the table shows B as a bound there.
  CHECK(w.bStillFalling);
  CHECK(w.tauB == white.allan.tau.back());
  CHECK_THAT(sim::analysisSummary({white}), Catch::Contains("(still falling)"));

  // The same noise averaged over 8 samples (a low-pass filter, as a sensor's output chain): at
  // one sample the ADEV is ~1/8 of white noise's, so N read there is far too low; beyond a few
  // averaging lengths the curve is white noise's N/sqrt(tau) again (the average keeps the DC
  // density). Within 5 % there, with a warning that names the filter.
  std::vector<double> y = whiteNoise(200008, 8), avg(200000);
  double sum = 0;
  for (std::size_t k = 0; k < 8; ++k) sum += y[k];
  for (std::size_t k = 0; k < avg.size(); ++k) avg[k] = sum / 8.0, sum += y[k + 8] - y[k];
  const auto filtered = stats(avg);
  CHECK(filtered.allan.dev.front() * std::sqrt(filtered.allan.tau.front()) < 0.5 * kN);  // the old reading
  const sim::NoiseTerms f = sim::readNoiseTerms(filtered.allan);
  CHECK(f.tauN > 4 * filtered.allan.tau.front());
  CHECK(f.N == Approx(kN).epsilon(0.05));
  const auto warnings = sim::analysisWarnings({filtered});
  REQUIRE(warnings.size() == 1);
  CHECK_THAT(warnings[0], Catch::Contains("a low-pass filter in the sensor (or a correlated noise) under-reads the white noise"));
}

// White noise plus a random walk whose Allan minimum, sqrt(3) N / K, is at 10 s of a 2000-s
// record: the minimum is inside the curve (its Allan deviation rises sqrt(tau) beyond it, 4.5x at
// the longest tau of ~200 s), B is read there, and the table says nothing of a falling curve.
TEST_CASE("analyze reads B at an Allan minimum inside the curve, and says when there is none", "[analysis]") {
  const double K = std::sqrt(3.0) * kN / 10.0;  // [unit/√s]: minimum at 10 s
  std::vector<double> y = whiteNoise(200000, 9);
  std::mt19937_64 rng(10);
  std::normal_distribution<double> g(0.0, K / std::sqrt(kRate));
  double b = 0;
  for (double& v : y) v += (b += g(rng));
  const auto walk = stats(y);
  const sim::NoiseTerms t = sim::readNoiseTerms(walk.allan);
  CHECK_FALSE(t.bStillFalling);
  CHECK(t.tauB > 2.0);
  CHECK(t.tauB < 50.0);
  CHECK_THAT(sim::analysisSummary({walk}), !Catch::Contains("still falling"));
}
