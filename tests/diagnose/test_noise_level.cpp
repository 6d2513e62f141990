// The noise level over a record (noise_level.hpp) against closed forms, and the diagnosis that
// reports a changing level as unexplained. For white noise of sd s the first differences are
// N(0, 2 s^2) and their mean absolute value is 2 s / sqrt(pi), with relative sd
// sqrt(pi/2 - 1) / sqrt(m) = 0.756 / sqrt(m) over m independent values (neighbouring differences
// correlate at -1/2, which changes that by a few %).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "errormodels/diagnose/diagnose.hpp"
#include "errormodels/diagnose/noise_level.hpp"
#include "errormodels/model_io.hpp"

namespace dg = sinsim::errormodels::diagnose;
using dg::detail::kNoiseLevelBlocks;
using dg::detail::noiseLevelBlocks;

namespace {

constexpr std::size_t kN = 32001;  // 16 blocks of 2000 differences

std::vector<double> white(std::uint64_t seed, double sd, std::size_t n = kN) {
  std::mt19937_64 g(seed);
  std::normal_distribution<double> d(0.0, sd);
  std::vector<double> y(n);
  for (auto& v : y) v = d(g);
  return y;
}

}  // namespace

// 40 seeds of white noise: each block's level is 1 within its relative sd 0.756 / sqrt(2000) =
// 1.7 %; the largest |ln level| of 16 blocks stays below 6 of those sd (0.10) in every seed.
TEST_CASE("noise level: white noise keeps one level in every block", "[diagnose][noise_level]") {
  const double sdBlock = 0.756 / std::sqrt(2000.0);
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const auto b = noiseLevelBlocks(white(seed, 0.3));
    REQUIRE(b.level.size() == kNoiseLevelBlocks);
    CHECK(b.spread < 6 * sdBlock);
    CHECK(b.spread > 0.5 * sdBlock);  // not degenerate: the blocks do differ
  }
}

// The sd doubled in blocks 6 and 7 (samples 12000..16000): their level is 2 (mean |difference|
// scales with the sd), the others 1, to the block's scatter; a burst half a block long is 1.5.
TEST_CASE("noise level: a burst of doubled noise is found at its level and place", "[diagnose][noise_level]") {
  auto y = white(7, 1.0);
  for (std::size_t k = 12001; k < 16001; ++k) y[k] *= 2.0;
  const auto b = noiseLevelBlocks(y);
  REQUIRE(b.level.size() == kNoiseLevelBlocks);
  for (std::size_t i = 0; i < kNoiseLevelBlocks; ++i) {
    INFO("block " << i);
    CHECK(b.level[i] == Approx(i == 6 || i == 7 ? 2.0 : 1.0).epsilon(0.08));
  }
  CHECK(b.spread == Approx(std::log(2.0)).epsilon(0.1));
  // Through noiseLevelChange: the block that departs most is 6 or 7, at 100 Hz 120..140 or 140..160 s.
  const auto c = dg::detail::noiseLevelChange(b, y.size(), 100.0, std::vector<double>(16, 0.04), {});
  REQUIRE(c.has_value());
  CHECK(c->hi == Approx(2.0).epsilon(0.08));
  CHECK(c->lo == Approx(1.0).epsilon(0.08));
  CHECK((c->from == Approx(120.0) || c->from == Approx(140.0)));
  CHECK(c->to - c->from == Approx(20.0));
  // The stretch that departs: blocks 6 and 7 merged, 120..160 s (the others within 8 % of 1, below
  // the change's threshold ln 1.25); a selection judges signals on the record without it.
  REQUIRE(c->stretches.size() == 1);
  CHECK(c->stretches[0].first == Approx(120.0));
  CHECK(c->stretches[0].second == Approx(160.0));
  // Realisations that depart as much as the record: no change reported.
  CHECK_FALSE(dg::detail::noiseLevelChange(b, y.size(), 100.0, std::vector<double>(16, 0.8), {}).has_value());
}

// Spikes of 100 sd on 20 samples, and a level step of 50 sd: capped at 8x the median |difference|
// they move a block's mean |difference| by at most 2 x 8 x 1.13 / 2000 = 1 %; the spread stays
// that of white noise. And a lattice 3x coarser than the noise (most differences 0 or +-1 LSB).
TEST_CASE("noise level: outliers, a level step and a coarse lattice are no change of level",
          "[diagnose][noise_level]") {
  const double sdBlock = 0.756 / std::sqrt(2000.0);
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    auto y = white(100 + seed, 1.0);
    for (std::size_t k = 500; k < kN; k += 1600) y[k] += (k % 3200 == 500 ? 100.0 : -100.0);
    for (std::size_t k = kN / 2; k < kN; ++k) y[k] += 50.0;
    CHECK(noiseLevelBlocks(y).spread < 7 * sdBlock);
    auto q = white(200 + seed, 1.0);
    for (auto& v : q) v = 3.0 * std::nearbyint(v / 3.0);
    // On the lattice the differences flip less often; a block's mean |difference| has a larger
    // relative scatter (~2x): 12 of white noise's sd.
    CHECK(noiseLevelBlocks(q).spread < 12 * sdBlock);
  }
  CHECK(noiseLevelBlocks(white(1, 1.0, 1000)).level.empty());  // < 64 samples a block: no test
  CHECK(noiseLevelBlocks(std::vector<double>(kN, 2.0)).level.empty());  // constant
}

// The diagnosis: a white-noise gyro whose noise triples for the middle fifth of the record,
// against its true (stationary) model, is reported as a change of level, unexplained, and the
// channel does not fit; the same record without the burst (three seeds) is not.
TEST_CASE("noise level: diagnose reports a noise that changes with time as unexplained",
          "[diagnose][noise_level]") {
  const auto model = sinsim::errormodels::errorModelFromString(
      "gyro:\n  x: [{type: white, density: 0.5 deg/sqrt(h)}]\n", "white.yaml");
  dg::DiagnoseOptions o;
  o.channels = {"gx"};
  o.realisations = 16;
  o.seed = 3;
  for (std::uint64_t seed : {41, 42, 43}) {
    auto r = dg::simulateRecord(model, 100.0, 60000, seed, 0, {0, 0, 0, 0, 0, 0});
    const auto clean = dg::diagnose(r, model, o).axis("gx");
    CHECK_FALSE(clean.noiseLevelChange.has_value());
    for (std::size_t k = 24000; k < 36000; ++k) r.gyro[0][k] *= 3.0;
    const auto burst = dg::diagnose(r, model, o).axis("gx");
    REQUIRE(burst.noiseLevelChange.has_value());
    CHECK(burst.noiseLevelChange->hi == Approx(3.0).epsilon(0.1));
    CHECK(burst.noiseLevelChange->from >= 240.0 - 1e-9);
    CHECK(burst.noiseLevelChange->to <= 360.0 + 1e-9);
    CHECK_FALSE(burst.fits());
    const auto sentences = dg::unexplainedSentences(burst);
    CHECK(std::any_of(sentences.begin(), sentences.end(), [](const std::string& s) {
      return s.find("the noise level changes over the record") != std::string::npos;
    }));
    // The burst's own samples are no outliers (an outlier stands out against the noise around
    // it): 4.3 % of them are beyond 6 sd of the calm noise, which made hundreds "isolated".
    auto named = [](const dg::AxisDiagnosis& a, const std::string& e) {
      return std::any_of(a.findings.begin(), a.findings.end(),
                         [&](const dg::Finding& f) { return f.reported && f.effect == e; });
    };
    CHECK_FALSE(named(burst, "outliers"));
    // Spikes of 12 sd in the calm stretches beside it still are: all 20 and no more.
    for (std::size_t k = 1000; k < 20000; k += 1000) r.gyro[0][k] += (k % 2000 ? 12.0 : -12.0) * 0.5 * M_PI / 180.0 / 60.0 * 10.0;
    for (std::size_t k = 40000; k < 41000; k += 1000) r.gyro[0][k] += 12.0 * 0.5 * M_PI / 180.0 / 60.0 * 10.0;
    const auto spikes = dg::diagnose(r, model, o).axis("gx");
    REQUIRE(named(spikes, "outliers"));
    for (const auto& f : spikes.findings)
      if (f.effect == "outliers") CHECK_THAT(f.evidence, Catch::StartsWith("20 isolated samples"));
  }
}

// White noise of sd 0.3 LSB rounded onto its lattice while its level drifts by one LSB: the
// values flip between neighbours often where the level sits near a cell's edge and seldom at its
// middle, so the blocks' mean |difference| swings (the statistic alone sees a "change"); the
// diagnosis does not judge the noise level on a lattice coarser than the noise.
TEST_CASE("noise level: a coarse lattice's flip rate is not judged", "[diagnose][noise_level]") {
  const auto model = sinsim::errormodels::errorModelFromString(
      "gyro:\n  x: [{type: white, density: 0.5 deg/sqrt(h)}]\n", "white.yaml");
  auto r = dg::simulateRecord(model, 100.0, 60000, 51, 0, {0, 0, 0, 0, 0, 0});
  const double sd = 0.5 * M_PI / 180.0 / 60.0 * std::sqrt(100.0);  // the density at 100 Hz [rad/s]
  const double q = sd / 0.3;
  for (std::size_t k = 0; k < r.gyro[0].size(); ++k) {
    const double level = q * double(k) / double(r.gyro[0].size());
    r.gyro[0][k] = q * std::nearbyint((r.gyro[0][k] + level) / q);
  }
  REQUIRE(noiseLevelBlocks(r.gyro[0]).spread > std::log(1.25));
  dg::DiagnoseOptions o;
  o.channels = {"gx"};
  o.realisations = 16;
  CHECK_FALSE(dg::diagnose(r, model, o).axis("gx").noiseLevelChange.has_value());
}

// A burst of noise is no stationary white noise: against a white + Gauss-Markov gyro model, a
// record of that model with a white noise of twice the base's sd added for a fifth of it
// (the sum: x2.2 the level there) has its quiet blocks at the
// model's level (quiet = 1: the median block's mean |difference| scales with the white sd, and the
// GM's differences add 2 sigma^2 / (tau rate) = 1e-5 of the white's variance), and neither white
// nor a quantization's rounding noise is named, though white is tried and would pass the
// threshold: sized to the whole record it would add 0.2 x 4 = 0.8 of the model's Allan variance
// at the shortest tau, where the quiet stretches add none. With the white density doubled in the
// record the quiet blocks are x2 the model's (to their 1 % scatter): 4x in variance, beyond the
// factor 1.5 to which a model's stated level is taken to be known, and white is named beside the
// change.
TEST_CASE("noise level: a burst is not named white, a white the quiet stretches lack is",
          "[diagnose][noise_level]") {
  const std::string gm = "    - {type: gauss_markov, sigma: 0.02 deg/s, tau: 10 s}\n";
  const double kWhiteSd = 0.5 * M_PI / 180.0 / 60.0 * std::sqrt(100.0);  // 0.5 deg/sqrt(h) at 100 Hz [rad/s]
  const auto model = sinsim::errormodels::errorModelFromString(
      "gyro:\n  x:\n    - {type: white, density: 0.5 deg/sqrt(h)}\n" + gm, "white-gm.yaml");
  const auto noisier = sinsim::errormodels::errorModelFromString(
      "gyro:\n  x:\n    - {type: white, density: 1.0 deg/sqrt(h)}\n" + gm, "white2-gm.yaml");
  dg::DiagnoseOptions o;
  o.channels = {"gx"};
  o.realisations = 16;
  o.seed = 5;
  auto finding = [](const dg::AxisDiagnosis& a, const std::string& e) -> const dg::Finding* {
    for (const auto& f : a.findings)
      if (f.effect == e) return &f;
    return nullptr;
  };
  for (std::uint64_t seed : {61, 62, 63}) {
    INFO("seed " << seed);
    auto r = dg::simulateRecord(model, 100.0, 240000, seed, 0, {0, 0, 0, 0, 0, 0});
    auto r2 = dg::simulateRecord(noisier, 100.0, 240000, seed, 0, {0, 0, 0, 0, 0, 0});
    const auto burst2 = white(seed, 2.0 * kWhiteSd, 48000);  // the burst: a white noise of 2x the base's sd
    for (std::size_t k = 0; k < burst2.size(); ++k) r.gyro[0][96000 + k] += burst2[k], r2.gyro[0][96000 + k] += burst2[k];
    const auto burst = dg::diagnose(r, model, o).axis("gx");
    REQUIRE(burst.noiseLevelChange.has_value());
    CHECK(burst.noiseLevelChange->quiet == Approx(1.0).margin(0.03));
    const auto& averaged = burst.noiseLevelChange->averaged;
    CHECK(std::find(averaged.begin(), averaged.end(), "white") != averaged.end());
    const dg::Finding* white = finding(burst, "white");
    REQUIRE(white != nullptr);
    CHECK_FALSE(white->reported);
    CHECK(white->score >= o.threshold);  // it would have been named
    const dg::Finding* q = finding(burst, "quantization");
    CHECK((q == nullptr || !q->reported));
    const auto sentences = dg::unexplainedSentences(burst);
    CHECK(std::any_of(sentences.begin(), sentences.end(), [](const std::string& s) {
      return s.find("a stationary noise that would mostly average the change, not named") != std::string::npos;
    }));

    const auto both = dg::diagnose(r2, model, o).axis("gx");
    REQUIRE(both.noiseLevelChange.has_value());
    CHECK(both.noiseLevelChange->quiet == Approx(2.0).epsilon(0.03));
    CHECK(both.noiseLevelChange->averaged.empty());
    const dg::Finding* white2 = finding(both, "white");
    REQUIRE(white2 != nullptr);
    CHECK(white2->reported);
  }
}
