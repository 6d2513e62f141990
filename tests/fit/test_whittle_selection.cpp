// The Whittle term-set selection (errormodels/fit/whittle_selection.hpp): its model of the
// expected tapered, detrended periodogram against the mean periodogram of simulated records over
// many seeds (the records are made here with the standard library's generator, not by sinsim's
// effects), and the fit's choice on records whose Allan variance alone is ambiguous.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "common/error.hpp"
#include "errormodels/fit/whittle_selection.hpp"

using namespace sinsim::errormodels::fit;

namespace {

constexpr std::size_t kN = 4096;  // 2^12: taperedPeriodogram uses every sample
constexpr double kDt = 0.01;      // [s]

/// Mean over `seeds` records of each bin's level, from records made by `make(rng)`.
template <class Make>
std::vector<double> meanLevels(int seeds, Make make) {
  std::vector<double> mean;
  std::mt19937_64 rng(20261124);
  for (int s = 0; s < seeds; ++s) {
    const WhittleBins b = whittleBins(make(rng), kDt);
    if (mean.empty()) mean.assign(b.level.size(), 0.0);
    for (std::size_t i = 0; i < b.level.size(); ++i) mean[i] += b.level[i] / seeds;
  }
  return mean;
}

}  // namespace

TEST_CASE("Whittle: the model's expected periodogram equals the simulated mean", "[fit][whittle]") {
  const int seeds = 600;
  std::normal_distribution<double> normal;
  const WhittleBins ref = whittleBins(std::vector<double>(kN, 0.0) /* shape only */, kDt);
  // Each of the lowest 16 bins is one ordinate, ~ f chi^2_2 / 2 (sd = mean) times the taper's
  // variance inflation: the mean of 600 has relative sd sqrt(1.06 / 600) = 4.2 %. 4.5 sd (18.9 %)
  // over 3 x 16 checks: a false failure has probability ~ 48 x 7e-6 = 3e-4. Above the lowest 16,
  // bins average >= 2 ordinates and are checked the same way with their own count.
  auto check = [&](const std::vector<double>& mean, const std::vector<double>& model, const char* what) {
    int off = 0;
    for (std::size_t i = 0; i < mean.size(); ++i) {
      const double sd = model[i] * std::sqrt(ref.count[i] > 0 ? 1.0 / (ref.count[i] * seeds) : 1.0);
      INFO(what << " bin " << i << " (w " << ref.wHigh[i] << "): simulated " << mean[i] << ", model " << model[i]);
      if (std::fabs(mean[i] - model[i]) > 4.5 * sd) ++off;
      if (i < kExactOrdinates) CHECK(std::fabs(mean[i] - model[i]) <= 4.5 * sd);
    }
    // Above the exact ordinates: the bin mean of the PSD is an approximation (leakage, curvature
    // within a bin); all but a few of the ~60 bins within 4.5 sd.
    CHECK(off <= 3);
  };

  SECTION("white noise: N^2 = 1e-6 (variance per sample N^2 / dt)") {
    const double N2 = 1e-6;
    const auto mean = meanLevels(seeds, [&](std::mt19937_64& rng) {
      std::vector<double> x(kN);
      for (double& v : x) v = std::sqrt(N2 / kDt) * normal(rng);
      return x;
    });
    std::vector<double> model(ref.white);
    for (double& v : model) v *= N2;
    check(mean, model, "white");
  }
  SECTION("random walk: K^2 = 1e-6, increments K sqrt(dt) normal") {
    const double K2 = 1e-6;
    const auto mean = meanLevels(seeds, [&](std::mt19937_64& rng) {
      std::vector<double> x(kN);
      double b = 0.0;
      for (double& v : x) v = (b += std::sqrt(K2 * kDt) * normal(rng));
      return x;
    });
    std::vector<double> model(ref.randomWalk);
    for (double& v : model) v *= K2;
    // The line removal and the taper matter here: at the lowest ordinate the plain PSD
    // dt / (4 sin^2(w/2)) is far from the exact column (the reason for the exact columns).
    CHECK(std::fabs(ref.randomWalk[0] * 4.0 * std::pow(std::sin(0.5 * ref.wHigh[0]), 2) / kDt - 1.0) > 0.3);
    check(mean, model, "random walk");
  }
  SECTION("quantization: the angle of white noise rounded with carry, LSB = the increment sd") {
    const double N2 = 1e-6, lsb = std::sqrt(N2 * kDt);
    const auto mean = meanLevels(seeds, [&](std::mt19937_64& rng) {
      std::vector<double> x(kN);
      double angle = 0.0, prev = 0.0;
      for (double& v : x) {
        angle += std::sqrt(N2 / kDt) * normal(rng) * kDt;
        const double q = std::round(angle / lsb) * lsb;
        v = (q - prev) / kDt;
        prev = q;
      }
      return x;
    });
    std::vector<double> model(ref.white);
    for (std::size_t i = 0; i < model.size(); ++i) model[i] = N2 * ref.white[i] + lsb * lsb / 12.0 * ref.quantization[i];
    check(mean, model, "quantization + white");
  }
}

TEST_CASE("Whittle: a set's fit recovers the variances of a long record", "[fit][whittle]") {
  // One record of 2^20 samples of white + random walk: the fitted variances within 4 of their
  // large-sample sd (Fisher information of the binned likelihood, here ~1 % for N^2 and ~5 % for
  // K^2 from the 2 c_b weights; 20 % is > 4 sd for both).
  const std::size_t n = std::size_t(1) << 20;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal;
  const double N = 1e-3, K = 1e-5;
  std::vector<double> x(n);
  double b = 0.0;
  for (double& v : x) v = N / std::sqrt(kDt) * normal(rng) + (b += K * std::sqrt(kDt) * normal(rng));
  const WhittleBins bins = whittleBins(x, kDt);
  LatentModel start;
  start.white = 2.0 * N, start.randomWalk = 0.5 * K;
  const WhittleSetFit f = whittleFitSet(bins, 4.0, {false, true, 0, false, true, false}, start, kDt, 100.0);
  REQUIRE(f.valid);
  CHECK(f.model.white == Approx(N).epsilon(0.2));
  CHECK(f.model.randomWalk == Approx(K).epsilon(0.2));
  // The white-only set is far worse: the walk's likelihood-ratio statistic is huge here.
  const WhittleSetFit w = whittleFitSet(bins, 4.0, {false, true, 0, false, false, false}, start, kDt, 100.0);
  CHECK(w.m2LogLik - f.m2LogLik > 100.0);
  CHECK_THROWS_AS(whittleBins(std::vector<double>(10, 0.0), kDt), sinsim::InputError);
  CHECK_THROWS_AS(whittleFitSet(bins, 4.0, {false, true, 0, false, false, true}, start, kDt, 100.0),
                  sinsim::InputError);
}

TEST_CASE("Whittle: the drift slope's variance equals the simulated one", "[fit][whittle]") {
  // white + random walk + a GM (T = 0.5 s = 50 samples), 800 records of 4096 samples from the
  // standard library's generator: the sample variance of the removed line's slope has relative sd
  // sqrt(2 / 800) = 5 %; 4.5 sd = 22.5 % (a false failure ~ 7e-6).
  const int seeds = 800;
  const double N = 1e-3, K = 2e-4, sigma = 2e-3, T = 0.5;
  std::mt19937_64 rng(11);
  std::normal_distribution<double> normal;
  const double phi = std::exp(-kDt / T);
  double s2 = 0.0;
  WhittleBins last;
  for (int s = 0; s < seeds; ++s) {
    std::vector<double> x(kN);
    double b = 0.0, g = sigma * normal(rng);
    for (double& v : x) {
      g = phi * g + sigma * std::sqrt(1.0 - phi * phi) * normal(rng);
      v = N / std::sqrt(kDt) * normal(rng) + (b += K * std::sqrt(kDt) * normal(rng)) + g;
    }
    last = whittleBins(x, kDt);
    s2 += last.slope * last.slope / seeds;  // the slope's mean is 0
  }
  LatentModel m;
  m.white = N, m.randomWalk = K, m.gm = {{sigma, T}};
  const double v = whittleSlopeVariance(last, m);
  CHECK(s2 == Approx(v).epsilon(0.225));
  // Each term matters at this size (else the check would not test the sum): none is > 90 %.
  for (int t = 0; t < 3; ++t) {
    LatentModel one;
    if (t == 0) one.white = N;
    if (t == 1) one.randomWalk = K;
    if (t == 2) one.gm = m.gm;
    CHECK(whittleSlopeVariance(last, one) < 0.9 * v);
  }
}
