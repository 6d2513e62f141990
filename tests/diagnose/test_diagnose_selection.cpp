// Selection cases issue 12's challenge exposed (docs/diagnose.md, "Challenge benchmark"): spikes
// under an oscillatory AR base, a bias step (outside the catalogue), a small effect beside a large
// deterministic one, and channels on worker threads. The model given is the exact base (as in the
// challenge: the judge knows the base, the diagnosis must find what was added).
#include <catch2/catch.hpp>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "errormodels/diagnose/detector.hpp"
#include "errormodels/diagnose/diagnose.hpp"
#include "errormodels/diagnose/significance.hpp"
#include "errormodels/model_io.hpp"

namespace dg = sinsim::errormodels::diagnose;
using sinsim::errormodels::errorModelFromString;
using sinsim::errormodels::Record;

namespace {

constexpr double kRate = 100.0;  // [Hz]

dg::DiagnoseOptions gxOnly(std::uint64_t seed) {
  dg::DiagnoseOptions o;
  o.channels = {"gx"};
  o.realisations = 16;
  o.seed = seed;
  return o;
}

Record simulate(const std::string& model, std::size_t n, std::uint64_t seed) {
  return dg::simulateRecord(errorModelFromString(model, "truth.yaml"), kRate, n, seed, 0,
                            {0, 0, 0, 0, 0, 0});
}

std::string reportedList(const dg::AxisDiagnosis& a) {
  std::string s;
  for (const auto& f : a.findings)
    if (f.reported) s += f.effect + " ";
  return s;
}

}  // namespace

// A spike s at sample k enters the AR residuals as s (1, a1, a2): with a2 = 0.848 > |a1| = 0.626
// the residual has a second local peak two samples later, and the old per-residual test dropped
// both as "not isolated" (challenge record r0000 of seed 7: 5 spikes at 10x named white). The
// additive-outlier estimate has its peak at k alone. 20 spikes of 1 deg/s against a base of
// sd ~0.05 deg/s: > 20 sigma each, far beyond the 5.4 sigma Bonferroni limit of 10^5 samples.
TEST_CASE("spikes under an oscillatory AR base are found as outliers", "[diagnose][selection]") {
  const std::string base = "gyro:\n  x:\n    - {type: ar, a: [-0.626, 0.848], sigma: 0.02 deg/s, rate: 100 Hz}\n";
  for (std::uint64_t seed : {1, 2, 3}) {
    const auto r = simulate(base + "    - {type: outliers, rate: 0.02 Hz, amplitude: 1 deg/s}\n", 100000, seed);
    const auto d = dg::diagnose(r, errorModelFromString(base, "base.yaml"), gxOnly(seed)).axis("gx");
    INFO("seed " << seed << ": reported " << reportedList(d));
    REQUIRE_FALSE(d.findings.empty());
    CHECK(d.findings[0].effect == "outliers");
    CHECK(d.findings[0].reported);
    CHECK(d.findings[0].params.at("amplitude") == Approx(1.0 * M_PI / 180).epsilon(0.05));
  }
}

// On a lattice coarser than the noise (sd q/5 about a cell's centre: 1 % of the samples leave
// it) the one-step residuals are mostly 0 and their MAD is 0: the outlier test had no scale and
// proposed nothing (here a line or nothing was reported first; challenge record r0145: five
// spikes of 40 LSB beside quantization, reported as quantization alone). The residual scale is
// at least the rounding's q/sqrt(12): a spike of 40 q is ~100 of it, a one-level flip stays below
// the test's 4 LSB. Each spike's estimate is off by about the noise's q/5 and the rounding's,
// under 1 % of 40 q: their RMS amplitude within 5 %.
TEST_CASE("spikes on a lattice coarser than the noise are found as outliers", "[diagnose][selection]") {
  const double q = 0.05 * M_PI / 180;  // 0.05 deg/s; the white sd is 0.01 deg/s per sample
  const std::string base = "gyro:\n  x:\n    - {type: white, density: 0.001 deg/s/sqrt(Hz)}\n"
                           "    - {type: quantization, lsb: 0.05 deg/s}\n";
  for (std::uint64_t seed : {31, 32, 33}) {
    auto r = simulate("gyro:\n  x:\n    - {type: white, density: 0.001 deg/s/sqrt(Hz)}\n", 30000, seed);
    for (std::size_t k = 2500; k < r.rows; k += 5000) r.gyro[0][k] += (k % 2 ? 40 : -40) * q;
    for (auto& v : r.gyro[0]) v = q * std::round(v / q);  // a level at a cell centre: 1 % flip
    const auto d = dg::diagnose(r, errorModelFromString(base, "base.yaml"), gxOnly(seed)).axis("gx");
    INFO("seed " << seed << ": reported " << reportedList(d));
    REQUIRE_FALSE(d.findings.empty());
    CHECK(d.findings[0].reported);
    CHECK(d.findings[0].effect == "outliers");
    CHECK(d.findings[0].params.at("amplitude") == Approx(40 * q).epsilon(0.05));
  }
}

// A correlated noise rounded on a lattice coarser than it (challenge records r0160 of seed 1 and
// r0456, r0222 of seed 2: an AR base rounded at 3-5 one-sample sd, named `white` first). The
// rounding of a slowly varying input is no white noise (the error follows the input), and where
// the level sits near a cell's centre it removes variance: the white term q^2/12 (or the variance
// the record says rounding added) is a poor proxy, and a free white level fitted better than the
// fixed-size quantization. Now the quantization's Allan term is what rounding makes of the
// model's own realisations, put at the level whose rounded mean is the record's. Base: a
// Gauss-Markov of 0.1 deg/s, tau 1 s, beside white of 0.02 deg/s per sample, 300 s at 100 Hz, the
// truth given as the model; rounded at 0.5 deg/s with the level at 0, 0.3 or 0.5 of a cell from a
// lattice point. Before: `white` first in 4 of these 10 (the cell's centre), and a Gauss-Markov
// reported on all 10. Now quantization first in >= 9 of 10 (10 measured). Another finding beside
// it: 3 of 10 while the later trials were weighed with the unrounded realisations' Allan scatter
// (all at the cell's centre, where the rounded record flips on ~1 % of samples and its Allan
// variance scatters more than theirs); none since the rounded realisations' scatter is the
// problem's once the quantization is accepted (ChannelWork::rounded).
TEST_CASE("a correlated noise on a coarse lattice is named quantization and not white", "[diagnose][selection]") {
  const double q = 0.5 * M_PI / 180;
  const std::string base = "gyro:\n  x:\n    - {type: white, density: 0.002 deg/s/sqrt(Hz)}\n"
                           "    - {type: gauss_markov, sigma: 0.1 deg/s, tau: 1 s}\n";
  int first = 0, others = 0;
  for (std::uint64_t seed = 1800; seed < 1810; ++seed) {
    auto r = simulate(base, 30000, seed);
    const double level = q * 0.1 * double((seed % 3) * 3 + (seed % 3 == 2 ? -1 : 0));  // 0, 0.3, 0.5 q
    double mean = 0;
    for (double v : r.gyro[0]) mean += v / double(r.rows);
    for (auto& v : r.gyro[0]) v = q * std::round((v - mean + level) / q);
    const auto d = dg::diagnose(r, errorModelFromString(base, "base.yaml"), gxOnly(seed)).axis("gx");
    INFO("seed " << seed << ": reported " << reportedList(d));
    first += !d.findings.empty() && d.findings[0].reported && d.findings[0].effect == "quantization";
    others += reportedList(d) != "quantization ";
  }
  CHECK(first >= 9);
  CHECK(others <= 1);
}

// A single bias step has the Allan variance of a random walk (one large increment), and the
// Gaussian noise candidates would absorb it. Its window-mean increments show one far beyond the
// rest, and on the record with that step taken out no Gaussian noise explains anything, so none
// may be reported: the step is left unexplained (or named by a signal candidate, ramp or
// warm-up) — issue 12's "physical equivalent or unexplained".
TEST_CASE("a bias step is not named a Gaussian noise", "[diagnose][selection]") {
  const std::string base = "gyro:\n  x:\n    - {type: white, density: 0.01 deg/s/sqrt(Hz)}\n";
  for (std::uint64_t seed : {4, 5, 6}) {
    auto r = simulate(base, 60000, seed);
    for (std::size_t k = 36000; k < r.rows; ++k) r.gyro[0][k] += 0.05 * M_PI / 180;  // 0.05 deg/s
    const auto d = dg::diagnose(r, errorModelFromString(base, "base.yaml"), gxOnly(seed)).axis("gx");
    INFO("seed " << seed << ": reported " << reportedList(d));
    for (const auto& f : d.findings) {
      if (!f.reported) continue;
      CHECK(f.effect != "random_walk");
      CHECK(f.effect != "bias_instability");
      CHECK(f.effect != "gauss_markov");
      CHECK(f.effect != "white");
    }
    const bool named = !d.findings.empty() && d.findings[0].reported;
    CHECK((named || d.unexplained.has_value()));
  }
}

// The same step as above is a catalogue effect since the twenty-fifth session: `bias_jumps`, the
// steps the record shows taken out as a signal (two parameters each). It is named first, stated
// as one jump in the record's 600 s (rate 1/600 Hz) of the step's size, and adding it -- a model
// whose bias jumps at random instants by that much -- at least halves the misfit. The step is
// 0.05 deg/s under a white noise of 0.1 deg/s per sample: the size from ~24000 samples either
// side has a standard error of ~0.001 deg/s, so 10 % is > 5 sigma.
TEST_CASE("a bias step is named bias_jumps and adding it halves the misfit", "[diagnose][selection]") {
  const std::string base = "gyro:\n  x:\n    - {type: white, density: 0.01 deg/s/sqrt(Hz)}\n";
  for (std::uint64_t seed : {4, 5, 6}) {
    auto r = simulate(base, 60000, seed);
    for (std::size_t k = 36000; k < r.rows; ++k) r.gyro[0][k] += 0.05 * M_PI / 180;  // 0.05 deg/s
    const auto imp = dg::improve(r, errorModelFromString(base, "base.yaml"), {dg::AddRequest::parse("bias_jumps:gx")},
                                 gxOnly(seed));
    const auto& d = imp.before.axis("gx");
    INFO("seed " << seed << ": reported " << reportedList(d) << ", misfit " << d.misfit << " -> "
                 << imp.after.axis("gx").misfit);
    REQUIRE_FALSE(d.findings.empty());
    CHECK(d.findings[0].reported);
    REQUIRE(d.findings[0].effect == "bias_jumps");
    CHECK(d.findings[0].params.at("rate") == Approx(1.0 / 600.0).epsilon(1e-9));
    CHECK(d.findings[0].params.at("size") == Approx(0.05 * M_PI / 180).epsilon(0.1));
    CHECK(d.unexplainedSteps.empty());
    CHECK(imp.after.axis("gx").misfit <= 0.5 * d.misfit);
  }
}

// The window-mean jump test against its law: on Gaussian white noise and random walk its
// corrected z exceeds the 0.999 limit (3.29) in about 0.1 % of records; one step of 10 sd of the
// increments at the coarsest window puts it far beyond.
TEST_CASE("the jump test is quiet on Gaussian noise and sees a step", "[diagnose][selection]") {
  using dg::detail::jumpZ;
  const std::vector<std::size_t> factors = {16, 32, 64, 128, 256};
  int loud = 0;
  for (std::uint64_t seed = 10; seed < 30; ++seed) {
    const auto r = simulate("gyro:\n  x:\n    - {type: white, density: 0.01 deg/s/sqrt(Hz)}\n"
                            "    - {type: random_walk, K: 0.001 deg/s/sqrt(s)}\n", 40000, seed);
    loud += jumpZ(r.gyro[0], factors) > 3.29;
  }
  // P(>= 2 of 20 above) ~ 2e-4 at the nominal 0.1 %; 1 allowed for the MAD's scatter.
  CHECK(loud <= 1);
  std::vector<double> y(40000, 0.0);
  for (std::size_t k = 0; k < y.size(); ++k) y[k] = std::sin(0.7 * double(k)) * 1e-3 + (k > 20000 ? 1.0 : 0.0);
  CHECK(jumpZ(y, factors) > 10.0);
}

// The steps behind the jumps (levelSteps): one bias step of 0.2 in white noise of sd 0.05 (90 sd
// of a 1024-sample window increment) is located to within its window and sized from up to 8
// windows either side: the size's standard error is then <= 0.05 sqrt(2/1024) = 0.0022 (the
// narrowest span the locator can pick is one window: 0.05 sqrt(2/m) for m >= 64 is <= 0.009), so
// 0.03 is > 3 sigma. Spikes move one window mean and back: no step. Gaussian noise gives none but
// in about 0.1 % of records (the jump test's level).
TEST_CASE("level steps are located and sized while spikes and Gaussian noise give none",
          "[diagnose][selection]") {
  using dg::detail::levelSteps;
  const std::vector<std::size_t> factors = {16, 32, 64, 128, 256, 512, 1024};
  const double zLimit = 3.29;  // two-sided 0.999
  int quiet = 0;
  for (std::uint64_t seed = 30; seed < 40; ++seed) {
    // sd 0.005 sqrt(100 Hz) = 0.05 rad/s per sample
    const auto y = simulate("gyro:\n  x:\n    - {type: white, density: 0.005 rad/s/sqrt(Hz)}\n", 65536, seed).gyro[0];
    quiet += levelSteps(y, factors, zLimit).empty();
    auto stepped = y;
    for (std::size_t k = 40000; k < stepped.size(); ++k) stepped[k] += 0.2;
    const auto steps = levelSteps(stepped, factors, zLimit);
    REQUIRE(steps.size() == y.size());
    CHECK(steps[39000] == Approx(0.0).margin(0.03));
    CHECK(steps[41000] == Approx(0.2).margin(0.03));
    auto spiky = y;
    for (std::size_t k = 5000; k < spiky.size(); k += 9000) spiky[k] += 40.0;  // 800 sd
    CHECK(levelSteps(spiky, factors, zLimit).empty());
  }
  CHECK(quiet >= 9);  // P(>= 2 of 10 above) ~ 5e-5 at the nominal 0.1 %
}

// On a value lattice of step q a slow drift under noise below q/2 (no dither) crosses one level at
// a time: a staircase of exact single-LSB steps, which the jump test sees at long windows. They
// are rounding, not jumps: with the lattice given no step is kept; a step of 4 q on the same record
// is, and sized: it stands out most at the longest windows (its z grows as sqrt(m)), where the size
// from 8 windows either side has a standard error below 0.01 q (noise sd 0.2 q); 0.5 q leaves room
// for the staircase levels inside the spans (their drift is removed as a mean, exact on average).
TEST_CASE("single-LSB steps of a quantized drift are rounding and no jumps", "[diagnose][selection]") {
  using dg::detail::levelSteps;
  const std::vector<std::size_t> factors = {16, 32, 64, 128, 256, 512, 1024};
  const double q = 1.0;
  for (std::uint64_t seed : {41, 42, 43}) {
    // noise sd 0.02 sqrt(100 Hz) = 0.2 q, plus a ramp of 12 q, rounded to the lattice
    auto y = simulate("gyro:\n  x:\n    - {type: white, density: 0.02 rad/s/sqrt(Hz)}\n", 65536, seed).gyro[0];
    for (std::size_t k = 0; k < y.size(); ++k) y[k] = std::round((y[k] + 12.0 * double(k) / double(y.size())) / q) * q;
    CHECK_FALSE(levelSteps(y, factors, 3.29, 0.0).empty());  // without the lattice: "jumps"
    CHECK(levelSteps(y, factors, 3.29, q).empty());
    for (std::size_t k = 40000; k < y.size(); ++k) y[k] += 4 * q;
    const auto steps = levelSteps(y, factors, 3.29, q);
    REQUIRE(steps.size() == y.size());
    CHECK(steps.back() - steps.front() == Approx(4 * q).margin(0.5 * q));
  }
}

// The ADIS16405 accelerometers (docs/diagnose.md, walkthrough): a random walk with a few
// disturbances of the test stand. The jumps once kept every Gaussian noise out (a bias step has a
// random walk's Allan shape), and the walk's large excess was left "unexplained". Now a candidate
// is credited with what it explains on the record with the steps taken out too: the steps' share
// goes, the walk's stays. Walk K = 0.002 deg/s/sqrt(s): 9x the white ADEV at tau = 75 s; three
// steps of 0.1 deg/s, 13 sd of the 1875-sample window increments (white + walk).
TEST_CASE("a random walk with bias jumps is still named", "[diagnose][selection]") {
  const std::string base = "gyro:\n  x:\n    - {type: white, density: 0.01 deg/s/sqrt(Hz)}\n";
  for (std::uint64_t seed : {7, 8, 9}) {
    auto r = simulate(base + "    - {type: random_walk, K: 0.002 deg/s/sqrt(s)}\n", 60000, seed);
    for (std::size_t at : {15000, 30000, 45000})
      for (std::size_t k = at; k < r.rows; ++k) r.gyro[0][k] += (at == 30000 ? -0.1 : 0.1) * M_PI / 180;
    const auto o = gxOnly(seed);
    REQUIRE(dg::detail::jumpZ(r.gyro[0], {15, 30, 60, 120, 240, 480, 960, 1875}) > 3.29);
    const auto d = dg::diagnose(r, errorModelFromString(base, "base.yaml"), o).axis("gx");
    INFO("seed " << seed << ": reported " << reportedList(d));
    CHECK(reportedList(d).find("random_walk") != std::string::npos);
  }
}

// A random telegraph (bias switching between +A and -A at rate lambda, "popcorn noise") has the
// autocorrelation A^2 exp(-2 lambda |t|): a Gauss-Markov's with sigma = A and tau = 1 / (2 lambda)
// -- its physical equivalent in the catalogue (issue 12). With A the white noise's per-sample sd
// each switch is a step of 2 sd, ~14 sd of a 100-sample window increment, and the step test finds
// them; every noise was then credited only with what the record without them holds: here a GM
// of tau 0.9-1.8 s that the imperfectly located switches leave (on the challenge's records r0104
// and r0238 a flat floor: bias instability first). Switches that go back and forth are the GM's
// realisation: it is credited on the record with them. lambda = 1/15 Hz: ~40 switches in 600 s,
// tau = 7.5 s; the estimate from 40 switches scatters by ~1/sqrt(40), the GM grid's step is
// sqrt(2): tau within a factor 2.
TEST_CASE("a telegraph with many switches is named a Gauss-Markov", "[diagnose][selection]") {
  const std::string base = "gyro:\n  x:\n    - {type: white, density: 0.01 deg/s/sqrt(Hz)}\n";
  const double A = 0.1 * M_PI / 180, lambda = 1.0 / 15.0;
  for (std::uint64_t seed : {21, 22, 23}) {
    auto r = simulate(base, 60000, seed);
    std::mt19937_64 gen(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    double level = A;
    for (std::size_t k = 0; k < r.rows; ++k) {
      if (u(gen) < lambda / kRate) level = -level;
      r.gyro[0][k] += level;
    }
    const auto d = dg::diagnose(r, errorModelFromString(base, "base.yaml"), gxOnly(seed)).axis("gx");
    INFO("seed " << seed << ": reported " << reportedList(d));
    REQUIRE_FALSE(d.findings.empty());
    CHECK(d.findings[0].reported);
    REQUIRE(d.findings[0].effect == "gauss_markov");
    CHECK(d.findings[0].params.at("tau") > 0.5 / (2 * lambda));
    CHECK(d.findings[0].params.at("tau") < 2.0 / (2 * lambda));
    // the switches found are the GM's realisation, listed as such and not as unexplained
    CHECK(d.unexplainedSteps.empty());
    CHECK(d.switchingSteps.size() >= 10);
    CHECK(dg::switchingSentence(d).find("go back and forth") != std::string::npos);
  }
}

// Six channels on worker threads: each channel's result in its own slot, so the JSON is the
// same byte for byte with one thread or two (realisation r is StreamKey (seed, r) wherever it runs).
TEST_CASE("channels on worker threads give the same diagnosis as one thread", "[diagnose][selection]") {
  std::string model = "gyro:\n";
  for (const char* ax : {"x", "y", "z"})
    model += std::string("  ") + ax + ":\n    - {type: ar, a: [-0.9], sigma: 0.01 deg/s, rate: 100 Hz}\n";
  model += "accel:\n";
  for (const char* ax : {"x", "y", "z"})
    model += std::string("  ") + ax + ":\n    - {type: white, density: 0.1 mg/sqrt(Hz)}\n";
  auto r = simulate(model + "", 20000, 9);
  for (std::size_t k = 0; k < r.rows; ++k) r.accel[1][k] += 2e-3 * std::sin(0.37 * double(k));
  const auto spec = errorModelFromString(model, "base.yaml");
  dg::DiagnoseOptions o1;
  o1.realisations = 8;
  o1.threads = 1;
  auto o2 = o1;
  o2.threads = 2;
  const auto one = dg::diagnose(r, spec, o1), two = dg::diagnose(r, spec, o2);
  CHECK(one.axes.size() == 6);
  CHECK(dg::toJson(one) == dg::toJson(two));
}

// The ramp's trend test given the model (detectors/ramp.cpp, ModelNow): after a Gauss-Markov
// noise (sigma 0.05 deg/s, tau 1 s) is accepted, a ramp of R = 8e-4 deg/s^2 over 300 s at 100 Hz
// stands against the trend scatter the white base and the GM predict: the GM acts at long tau as
// white noise of density sqrt(2 sigma^2 tau) = 0.071 deg/s/sqrt(Hz), so the least-squares trend's
// sd is sqrt(12 (0.01^2 + 0.071^2) / T^3) = 4.8e-5 deg/s^2 (the GM's share exact from its
// autocovariance, TrendScatter::exactLine; 5.3e-5 with the 12/pi^2 margin of the cosine bound it
// had before): t = 16.7, beyond the 5.5 threshold in each seed but for the scatter of the
// realised trend (z scatter +-1) and of the white share's 16 realisations. Its Allan excess alone
// is 1.8x the model's ADEV at the last tau (37.5 s) only, and the one-sign test is weak on a
// white-like base: without the trend test the ramp was missed in all five seeds. At least 4 of 5
// required (P(<= 3 of 5) < 0.03 at a per-seed miss rate of 0.2).
TEST_CASE("a ramp beside a Gauss-Markov noise is found by its trend against the model", "[diagnose][selection]") {
  const std::string base = "gyro:\n  x:\n    - {type: white, density: 0.01 deg/s/sqrt(Hz)}\n";
  const std::string gm = "    - {type: gauss_markov, sigma: 0.05 deg/s, tau: 1 s}\n";
  int found = 0;
  for (std::uint64_t seed : {31, 32, 33, 34, 35}) {
    const auto r = simulate(base + gm + "    - {type: ramp, slope: 0.0008 deg/s/s}\n", 30000, seed);
    const auto d = dg::diagnose(r, errorModelFromString(base, "base.yaml"), gxOnly(seed)).axis("gx");
    INFO("seed " << seed << ": reported " << reportedList(d));
    found += reportedList(d).find("ramp") != std::string::npos;
  }
  CHECK(found >= 4);
}

// The ramp's conditional test against its law, with the model's trend variance given in closed
// form (least squares on white noise of sd s: Var(slope) = s^2 / sum (t_k - tbar)^2, sum =
// dt^2 N (N^2 - 1) / 12) and dof so large that the Student-t is Gaussian: on white noise z = |t| is
// half-normal, P(z > 2.576) = 1 % and P(z > 1) = 31.7 %; with a ramp of 6 trend sd's, z ~ |N(6, 1)|.
// 200 seeds: beyond 2.576 at most 6 (P(>= 7) = 0.5 % for Binomial(200, 0.01)); beyond 1 within
// 63.4 +- 21 (3.2 sd of the binomial count); the ramp's mean z within 6 +- 0.3 (4 sd of a mean
// of 200 unit-variance values). A test that compared the trend with the wrong scatter (the
// increments' own, a factor sqrt(N/m) off) or took the wrong slope fails one of the three.
TEST_CASE("the ramp's trend test given the model is Gaussian on white noise", "[diagnose][selection]") {
  namespace d = dg::detail;
  constexpr std::size_t N = 4096;
  const double sd = 0.01 * std::sqrt(kRate) * M_PI / 180;  // [rad/s] of 0.01 deg/s/sqrt(Hz)
  const double dt = 1.0 / kRate;
  const double trendSd = sd / std::sqrt(dt * dt * double(N) * (double(N) * double(N) - 1) / 12);
  const d::Setup setup = d::makeSetup(kRate, N, dg::DiagnoseOptions{});
  std::vector<double> tau, avar;
  for (auto m : setup.factors) tau.push_back(double(m) * dt), avar.push_back(sd * sd / double(m));
  const d::ModelNow now{avar, trendSd * trendSd, 1e12, nullptr};
  auto zOf = [&](const Record& r, const std::vector<double>& y) {
    for (const auto& c : d::buildCandidates(r, 0, y, 0.0, tau, setup, {"white"}))
      if (c.effect == "ramp") return c.zConditional(now);
    return -1.0;
  };
  int over2576 = 0, over1 = 0;
  double rampMean = 0;
  for (std::uint64_t seed = 100; seed < 300; ++seed) {
    auto r = simulate("gyro:\n  x:\n    - {type: white, density: 0.01 deg/s/sqrt(Hz)}\n", N, seed);
    const double z = zOf(r, r.gyro[0]);
    over2576 += z > 2.576, over1 += z > 1.0;
    for (std::size_t k = 0; k < N; ++k) r.gyro[0][k] += 6.0 * trendSd * (double(k) + 0.5) * dt;
    rampMean += zOf(r, r.gyro[0]) / 200.0;
  }
  CHECK(over2576 <= 6);
  CHECK(over1 >= 43);
  CHECK(over1 <= 84);
  CHECK(rampMean == Approx(6.0).margin(0.3));
}

// On records the model describes exactly (white + GM, the model of the first ramp test) no ramp is
// reported: the trend's t with 16 realisations passes the 5.5 threshold alone with probability
// ~ 1e-8, and with the Allan terms (calibrated on null channels) the rate is the threshold's.
TEST_CASE("the ramp's trend test reports no ramp on null records", "[diagnose][selection]") {
  const std::string model = "gyro:\n  x:\n    - {type: white, density: 0.01 deg/s/sqrt(Hz)}\n"
                            "    - {type: gauss_markov, sigma: 0.05 deg/s, tau: 1 s}\n";
  for (std::uint64_t seed : {41, 42, 43, 44, 45}) {
    const auto d = dg::diagnose(simulate(model, 30000, seed), errorModelFromString(model, "base.yaml"),
                                gxOnly(seed)).axis("gx");
    INFO("seed " << seed << ": reported " << reportedList(d));
    CHECK(reportedList(d).find("ramp") == std::string::npos);
  }
}

namespace {

/// The sinusoid candidate's own z (the Welch line test, confirmed on the whole record's
/// periodogram) and its refined frequency [Hz] on gx of r; {0, 0} when the detector proposes none.
std::pair<double, double> lineZ(const Record& r) {
  namespace d = dg::detail;
  const d::Setup setup = d::makeSetup(kRate, r.rows, dg::DiagnoseOptions{});
  std::vector<double> tau;
  for (auto m : setup.factors) tau.push_back(double(m) / kRate);
  for (const auto& c : d::buildCandidates(r, 0, r.gyro[0], 0.0, tau, setup, {"white"}))
    if (c.effect == "sinusoid") {
      sinsim::errormodels::diagnose::Finding f;
      c.describe(1.0, f);
      return {c.zSpecial, f.params.at("frequency")};
    }
  return {0.0, 0.0};
}

// 30000 samples at 100 Hz: Welch segments of 2048 (bin 0.0488 Hz, nu = 2 x 28 / 1.056 = 53),
// T / L = 14.6 whole-record ordinates per Welch bin.
constexpr std::size_t kLineN = 30000;
const std::string kWhite = "gyro:\n  x:\n    - {type: white, density: 0.01 deg/s/sqrt(Hz)}\n";

}  // namespace

// A red continuum is no line. White + a Gauss-Markov of sigma 0.05 deg/s, tau 4 s (corner
// 0.040 Hz, below the first Welch bin): the spectrum falls as f^-2 over the lowest bins, 13x the
// white floor at bin 3. There the Welch test's neighbourhood is one-sided (bins 6..15 only), so
// bin 3 stands ~6x above its "neighbours" and the Welch test alone gives z = 40 on every seed (a
// false line was named first, before the Gauss-Markov, on 8 of the benchmark's telegraph
// channels). Confirmed on the record's periodogram, the continuum has no peak: over the search
// window (1.5..4.5 Welch bins) S(edge) / S(median) <= 4 for f^-2, so the peak ordinate over the
// median is ~4 E with E the largest of a few Exp(1) ordinates, and z > 5.5 needs 4 E > 21.6
// (2 M e^-x < 3.8e-8, M ~ 44): P(E > 5.4) ~ 5 e^-5.4 = 2 % per seed. 40 seeds: at most 3 beyond
// the 5.5 threshold (P(>= 4) = 0.9 % for Binomial(40, 0.02)).
TEST_CASE("a red continuum at the lowest Welch bins is no line", "[diagnose][selection]") {
  int beyond = 0;
  for (std::uint64_t seed = 500; seed < 540; ++seed) {
    const auto r = simulate(kWhite + "    - {type: gauss_markov, sigma: 0.05 deg/s, tau: 4 s}\n", kLineN, seed);
    beyond += lineZ(r).first > 5.5;
  }
  CHECK(beyond <= 3);
}

// A real line at the lowest bins stays a line: 0.1 Hz (2.05 Welch bins, 30 cycles in 300 s),
// A = 0.02 deg/s on the white floor. Its whole-record ordinate is A^2 against the continuum's
// mean 4 s^2 / N = 1.3e-6 (deg/s)^2 (s^2 = 0.01 (deg/s)^2 the white variance): x ~ 300, z = 40;
// at Welch bin 3 it leaks -6 dB, ~7x the floor: far beyond the Bonferroni limit. Every seed of
// ten must give z > 5.5 and the frequency within 0.5 / T = 1.7 mHz (the peak of the whole
// record's periodogram; its sd from noise is ~ sqrt(6) / (pi T sqrt(x)) = 1.5e-4 Hz).
TEST_CASE("a line at the lowest Welch bins is still a line", "[diagnose][selection]") {
  for (std::uint64_t seed = 600; seed < 610; ++seed) {
    auto r = simulate(kWhite, kLineN, seed);
    for (std::size_t k = 0; k < r.rows; ++k)
      r.gyro[0][k] += 0.02 * M_PI / 180 * std::sin(2 * M_PI * 0.1 * (double(k) + 0.5) / kRate + 0.3 * double(seed));
    const auto [z, f] = lineZ(r);
    INFO("seed " << seed << ": z " << z << ", f " << f);
    CHECK(z > 5.5);
    CHECK(std::fabs(f - 0.1) < 0.5 / (double(kLineN) / kRate));
  }
}

// A line below the Welch bins (stats/spectral_lines.hpp, lowLineTest; detectors/sinusoid.cpp): 25 cycles in 300 s
// (0.0833 Hz, 1.7 Welch bins: the Welch test, bins >= 3, cannot see it; before the whole-record
// scan no sinusoid candidate was proposed on any of these seeds), A = 0.01 deg/s on the white
// floor: its ordinate over the continuum's mean is A^2 N / (4 s^2) = 75 (s^2 = 0.01 (deg/s)^2),
// P ~ 36 e^-75: z ~ 11 against the Bonferroni limit. Every seed of ten must give z > 5.5 and the
// frequency within 0.5 / T (the periodogram peak's sd from noise: sqrt(6) / (pi T sqrt(75)) = 3e-4 Hz).
TEST_CASE("a line below the Welch bins is found on the whole record's periodogram", "[diagnose][selection]") {
  const double f0 = 25.0 / (double(kLineN) / kRate);
  for (std::uint64_t seed = 1300; seed < 1310; ++seed) {
    auto r = simulate(kWhite, kLineN, seed);
    for (std::size_t k = 0; k < r.rows; ++k)
      r.gyro[0][k] += 0.01 * M_PI / 180 * std::sin(2 * M_PI * f0 * (double(k) + 0.5) / kRate + 0.7 * double(seed));
    const auto [z, f] = lineZ(r);
    INFO("seed " << seed << ": z " << z << ", f " << f);
    CHECK(z > 5.5);
    CHECK(std::fabs(f - f0) < 0.5 / (double(kLineN) / kRate));
  }
}

// Red continua below the Welch bins are no line: the scan compares each ordinate with a line in
// log-log through its neighbours, so a continuum's slope (f^-2 of a walk, the bend of a
// Gauss-Markov whose corner, 1 / (2 pi 2 s) = 0.08 Hz, lies in the scanned band, f^-1 of
// flicker) is followed, not taken for a peak. 40 seeds of each of the three: the scan's z beyond
// 5.5 (a Bonferroni-corrected tail of 4e-8) on at most 1 of the 120.
TEST_CASE("red continua below the Welch bins make no line", "[diagnose][selection]") {
  const std::vector<std::string> reds = {
      kWhite + "    - {type: random_walk, K: 20 deg/h/sqrt(s)}\n",
      kWhite + "    - {type: gauss_markov, sigma: 0.1 deg/s, tau: 2 s}\n",
      kWhite + "    - {type: bias_instability, B: 0.05 deg/s, tau_range: [0.01 s, 300 s]}\n"};
  int beyond = 0;
  double worst = 0;
  for (const auto& model : reds)
    for (std::uint64_t seed = 1400; seed < 1440; ++seed) {
      const double z = lineZ(simulate(model, kLineN, seed)).first;
      beyond += z > 5.5, worst = std::max(worst, z);
    }
  INFO("largest z " << worst);
  CHECK(beyond <= 1);
}

namespace {

/// A sensor warming up over the record: 25 degC + 15 (1 - exp(-t / (T / 4))) [K].
std::vector<double> warmingTemperature(std::size_t n) {
  std::vector<double> TK(n);
  const double T = double(n) / kRate;
  for (std::size_t k = 0; k < n; ++k) TK[k] = 298.15 + 15 * (1 - std::exp(-(double(k) + 0.5) / kRate / (T / 4)));
  return TK;
}

Record simulateWarming(const std::string& model, std::size_t n, std::uint64_t seed) {
  return dg::simulateRecord(errorModelFromString(model, "truth.yaml"), kRate, n, seed, 0, {0, 0, 0, 0, 0, 0},
                            warmingTemperature(n));
}

}  // namespace

// A weak thermal drift is found by its coefficient against the model (detectors/temperature.cpp):
// white 0.01 deg/s/sqrt(Hz) (sample sd 0.1 deg/s) over 300 s at 100 Hz, c1 = 1.5e-3 deg/s/degC on
// the warming profile (Var T = 225 ((1 - e^-8) / 8 - ((1 - e^-4) / 4)^2) = 14.6 degC^2). The
// coefficient's sd under the model is 0.1 / sqrt(30000 x 14.6) = 1.5e-4 deg/s/degC: t = 9.9, a
// Gaussian-equivalent z ~ 5.5 with 16 realisations as dof, which with the drift's Allan drop
// passes the threshold. Without the test the drift's Allan term alone was below it and the
// record's trend was named `ramp` in 5 of these 10 seeds and nothing in 5 (0 of 10 temperature);
// with it 9 of 10. At least 6 of 10 required (P(<= 5 of 10) = 0.2 % at the measured 0.9).
TEST_CASE("a weak thermal drift is found by its coefficient against the model", "[diagnose][selection]") {
  int found = 0;
  for (std::uint64_t seed = 800; seed < 810; ++seed) {
    const auto r = simulateWarming(kWhite + "    - {type: temperature, T0: 25 degC, coefficients: [1.5e-3 deg/s/degC]}\n",
                                   kLineN, seed);
    const auto d = dg::diagnose(r, errorModelFromString(kWhite, "base.yaml"), gxOnly(seed)).axis("gx");
    INFO("seed " << seed << ": reported " << reportedList(d));
    found += !d.findings.empty() && d.findings[0].reported && d.findings[0].effect == "temperature";
  }
  CHECK(found >= 6);
}

// A bias step under a warming (found by a blind probe): the temperature's polynomial in the
// warming profile takes part of a step out of the block means and passes the threshold, and as
// the temperature was tried first in every round it was taken before the step, which the step
// tests then no longer saw (the rest went to a walk). A step is no shape a thermal drift takes
// (selection.cpp, thermalShape): where it explains more it is taken first. White 0.01
// deg/s/sqrt(Hz) (sample sd 0.1 deg/s) over 300 s at 100 Hz, a step of 0.03 deg/s at 40 % of the
// record (1 s means: 3 sd). At least 8 of 10 with bias_jumps first, at most 1 with the
// temperature reported (the code before fails both). And on the warming profile (a quadratic in
// time holds 99.9 % of it) a reported temperature says that a drift in time would fit alike.
TEST_CASE("a bias step under a warming is named bias_jumps, not temperature", "[diagnose][selection]") {
  int steps = 0, temps = 0;
  for (std::uint64_t seed = 1400; seed < 1410; ++seed) {
    Record r = simulateWarming(kWhite, kLineN, seed);
    for (std::size_t k = kLineN * 2 / 5; k < kLineN; ++k) r.gyro[0][k] += 0.03 * M_PI / 180.0;
    const auto d = dg::diagnose(r, errorModelFromString(kWhite, "base.yaml"), gxOnly(seed)).axis("gx");
    INFO("seed " << seed << ": reported " << reportedList(d));
    steps += !d.findings.empty() && d.findings[0].reported && d.findings[0].effect == "bias_jumps";
    temps += reportedList(d).find("temperature") != std::string::npos;
  }
  CHECK(steps >= 8);
  CHECK(temps <= 1);
  const auto r = simulateWarming(kWhite + "    - {type: temperature, T0: 25 degC, coefficients: [4e-3 deg/s/degC]}\n",
                                 kLineN, 1410);
  const auto d = dg::diagnose(r, errorModelFromString(kWhite, "base.yaml"), gxOnly(1410)).axis("gx");
  REQUIRE(!d.findings.empty());
  CHECK(d.findings[0].effect == "temperature");
  CHECK_THAT(d.findings[0].evidence, Catch::Contains("a drift in time (a ramp or a warm-up) would fit alike"));
}

// A temperature column is no thermal drift: on records the model describes exactly (white + GM,
// the sensor warming by 15 degC) the coefficient's test is a Student-t whose variance is, if
// anything, overstated (temperature.cpp), so alone it passes 5.5 with probability < 1e-7; with the
// Allan terms the rate is the calibrated threshold's (~1 % per channel at most). At most 1 of 10
// (P(>= 2 of 10) = 0.4 % at 1 %).
TEST_CASE("a temperature column alone makes no temperature finding", "[diagnose][selection]") {
  const std::string model = kWhite + "    - {type: gauss_markov, sigma: 0.05 deg/s, tau: 1 s}\n";
  int reported = 0;
  for (std::uint64_t seed = 900; seed < 910; ++seed) {
    const auto d = dg::diagnose(simulateWarming(model, kLineN, seed), errorModelFromString(model, "base.yaml"),
                                gxOnly(seed)).axis("gx");
    INFO("seed " << seed << ": reported " << reportedList(d));
    reported += reportedList(d).find("temperature") != std::string::npos;
  }
  CHECK(reported <= 1);
}

// A temperature column no drift follows, beside a walk the model lacks: the walk's realised drift
// over the record is much like the warming profile (any monotone wander is), so the temperature's
// polynomial fitted to the block means takes a share of the walk out of the record and passes the
// threshold alone. It only imitates the walk (selection.cpp, temperatureImitates): with the walk
// taken the temperature's test given the model no longer passes, while the walk still does with
// the temperature taken, so the walk is taken first and the temperature is tried beside it.
// White 0.01 deg/s/sqrt(Hz) and a walk of K = 0.003 deg/s/sqrt(s) (its Allan deviation 6.5x the
// white's at tau = 37.5 s, N/8) over 300 s at 100 Hz. Measured on these 10 seeds: the temperature
// reported in 7 of 10 before and the walk first in 3; with the test 0 of 10 and 9 of 10. At most
// 2 of 10 with a temperature, at least 8 of 10 with the walk first (both fail the code before).
TEST_CASE("a temperature column no drift follows is not named for a walk the model lacks", "[diagnose][selection]") {
  int temps = 0, walks = 0;
  for (std::uint64_t seed = 1300; seed < 1310; ++seed) {
    const auto r = simulateWarming(kWhite + "    - {type: random_walk, K: 0.003 deg/s/sqrt(s)}\n", kLineN, seed);
    const auto d = dg::diagnose(r, errorModelFromString(kWhite, "base.yaml"), gxOnly(seed)).axis("gx");
    INFO("seed " << seed << ": reported " << reportedList(d));
    temps += reportedList(d).find("temperature") != std::string::npos;
    walks += !d.findings.empty() && d.findings[0].reported && d.findings[0].effect == "random_walk";
  }
  CHECK(temps <= 2);
  CHECK(walks >= 8);
}

// A ramp beside a thermal drift whose temperature settles over the record: the temperature is
// regressed first (issue 12), and a line is much like the warming profile -- of the line's
// variance only 19 % lies outside {1, d} and 5.9 % outside {1, d, d^2}, d = T - T0 (computed
// here). Judged on the record without the drift, the ramp kept only that share of its trend and a
// z of ~rho z_full; fitted beside the drift (DetectorContext::apart, Frisch-Waugh-Lovell) its
// coefficient is the joint fit's with z = sqrt(rho) z_full. White 0.01 deg/s/sqrt(Hz), 300 s at
// 100 Hz, c1 = 4e-3 deg/s/degC, R = 2000 deg/h^2 = 1.54e-4 deg/s^2: z_full = R N^1.5 dt /
// (sqrt(12) sigma) = 23 (sigma = 0.1 deg/s per sample), so 10.2 (degree 1) or 5.6 (degree 2)
// beside the drift, 4.5 or 1.4 before (t values: the test takes the trend's scatter from 64
// realisations). Measured on these 10 seeds: ramp reported in 0 of 10 before, 10 of 10 with the
// joint fit. At least 8 of 10 required (P(<= 7 of 10) = 7 % even at a rate of 0.9); the slope
// within 4 of its joint-fit sd (computed here by least squares on the samples: sigma^2 (X'X)^-1
// with X = [1, d, d^2, t]) wherever it is reported, and the temperature's c1 beside it (degree
// 1) within 4 of its sd from X = [1, d, t]: the drift's size restated from the joint fit (alone
// it took the ramp's likeness, c1 ~ 7e-3 instead of 4e-3 deg/s/degC: 10 of these checks fail
// without restateSignals); on seed 1100 --add found halves the misfit (0.163 -> 0.047).
TEST_CASE("a ramp beside a thermal drift of nearly its shape is fitted jointly with it", "[diagnose][selection]") {
  const double R = 2000.0 * (M_PI / 180.0) / 3600.0 / 3600.0;  // [rad/s^2]
  const auto TK = warmingTemperature(kLineN);
  Eigen::MatrixXd X(Eigen::Index(kLineN), 4);
  for (std::size_t k = 0; k < kLineN; ++k) {
    const double d = TK[k] - TK[0];
    X.row(Eigen::Index(k)) << 1.0, d, d * d, (double(k) + 0.5) / kRate;
  }
  const double sigma = 0.01 * M_PI / 180.0 * std::sqrt(kRate);  // per sample [rad/s]
  const double sdR = sigma * std::sqrt((X.transpose() * X).inverse()(3, 3));
  // The temperature's c1 reported beside the ramp (degree 1): the joint fit's, sd from X = [1, d, t].
  Eigen::MatrixXd X1(Eigen::Index(kLineN), 3);
  X1 << X.col(0), X.col(1), X.col(3);
  const double c1 = 4e-3 * M_PI / 180.0, sdC1 = sigma * std::sqrt((X1.transpose() * X1).inverse()(1, 1));
  int found = 0;
  for (std::uint64_t seed = 1100; seed < 1110; ++seed) {
    const auto r = simulateWarming(kWhite + "    - {type: temperature, T0: 25 degC, coefficients: [4e-3 deg/s/degC]}\n"
                                            "    - {type: ramp, slope: 2000 deg/h^2}\n",
                                   kLineN, seed);
    auto o = gxOnly(seed);
    o.realisations = 64;  // the trend's scatter to 64 dof: t = 10 is a z of ~8 (~5.6 with 16)
    const auto d = dg::diagnose(r, errorModelFromString(kWhite, "base.yaml"), o).axis("gx");
    INFO("seed " << seed << ": reported " << reportedList(d));
    for (const auto& f : d.findings)
      if (f.reported && f.effect == "ramp") {
        ++found;
        INFO("slope " << f.params.at("slope") << " rad/s^2, truth " << R << ", joint sd " << sdR);
        CHECK(std::fabs(f.params.at("slope") - R) < 4 * sdR);
        for (const auto& t : d.findings)
          if (t.reported && t.effect == "temperature" && !t.params.count("c2")) {
            INFO("c1 " << t.params.at("c1") << " rad/s/K, truth " << c1 << ", joint sd " << sdC1);
            CHECK(std::fabs(t.params.at("c1") - c1) < 4 * sdC1);
            // The earlier signal's size was restated from the joint fit, and its evidence (the
            // record's alone) says so with the size it had alone.
            CHECK((t.evidence.find("sized jointly with the other signals found (alone: c") != std::string::npos ||
                   f.evidence.find("sized jointly with the other signals found (alone: R = ") != std::string::npos));
          }
      }
    if (seed == 1100) {  // the joint sizes as --add writes them: the misfit at least halved
      const auto imp = dg::improve(r, errorModelFromString(kWhite, "base.yaml"), {dg::AddRequest::parse("found:gx")}, o);
      CHECK(imp.after.axis("gx").misfit <= 0.5 * imp.before.axis("gx").misfit);
    }
  }
  CHECK(found >= 8);
}

// The same drift without a ramp: the line beside it is tested with its variance inflated by
// 1 / rho (the coefficient's on the line apart from the drift), so no ramp is reported beside a
// pure thermal drift more often than the threshold allows: at most 1 of 10 (P(>= 2) = 0.4 % at 1 %).
TEST_CASE("no ramp is reported beside a pure thermal drift", "[diagnose][selection]") {
  int ramps = 0, temps = 0;
  for (std::uint64_t seed = 1200; seed < 1210; ++seed) {
    const auto r = simulateWarming(kWhite + "    - {type: temperature, T0: 25 degC, coefficients: [4e-3 deg/s/degC]}\n",
                                   kLineN, seed);
    const auto d = dg::diagnose(r, errorModelFromString(kWhite, "base.yaml"), gxOnly(seed)).axis("gx");
    INFO("seed " << seed << ": reported " << reportedList(d));
    ramps += reportedList(d).find("ramp") != std::string::npos;
    temps += reportedList(d).find("temperature") != std::string::npos;
  }
  CHECK(temps == 10);
  CHECK(ramps <= 1);
}

// A thermal drift with curvature is no warm-up beside a linear one: white 0.01 deg/s/sqrt(Hz),
// 300 s at 100 Hz, c1 = 4e-3 deg/s/degC, c2 = 4.5e-4 deg/s/degC^2 on the warming profile (the
// curvature's t is 11 beside the temperature, 6.1 beside it and a line: least squares, computed
// with NumPy). The Allan terms hardly tell degree 2 from degree 1 (their drops differ by about
// one parameter's penalty), and a curvature left over is what a warm-up fitted beside the linear
// drift takes (challenge r0063). Degree 2 is now credited with its curvature's own test
// (detectors/temperature.cpp). Measured on these 10 seeds: degree 2 in 5 of 10 before, 10 of 10
// now, no warm-up in either. At least 8 of 10 (P(<= 7 of 10) = 7 % even at a rate of 0.9), and
// at most 1 of 10 may report a warm-up.
TEST_CASE("a thermal drift with curvature is not split into a linear drift and a warm-up", "[diagnose][selection]") {
  int warmups = 0, degree2 = 0;
  for (std::uint64_t seed = 1500; seed < 1510; ++seed) {
    const auto r = simulateWarming(
        kWhite + "    - {type: temperature, T0: 25 degC, coefficients: [4e-3 deg/s/degC, 4.5e-4 deg/s/degC^2]}\n",
        kLineN, seed);
    const auto d = dg::diagnose(r, errorModelFromString(kWhite, "base.yaml"), gxOnly(seed)).axis("gx");
    INFO("seed " << seed << ": reported " << reportedList(d));
    warmups += reportedList(d).find("warmup") != std::string::npos;
    for (const auto& f : d.findings)
      if (f.reported && f.effect == "temperature") degree2 += f.params.count("c2") > 0;
  }
  INFO("degree 2 in " << degree2 << " of 10");
  CHECK(warmups <= 1);
  CHECK(degree2 >= 8);
}

// A weak warm-up is found by its settling against the model (detectors/warmup.cpp): white
// 0.01 deg/s/sqrt(Hz) (sample sd 0.1 deg/s), 300 s at 100 Hz, a warm-up of 0.035 deg/s decaying
// with 30 s (~1.4x the white's Allan deviation at its tau). On x = exp(-t / 30 s) (Var x = 0.04
// over the record) the coefficient's sd under the model is 0.1 / sqrt(30000 x 0.04) = 2.9e-3:
// t = 12, with 16 realisations as dof and Bonferroni over the ~7 octaves of tau_w searched a z of
// ~5.7, so with the Allan drop it passes the threshold in most seeds. The start test alone (first
// window-mean step against the later ones) gives t ~ 3.6 at best: without the test given the model
// nothing was reported in any of these 10 seeds (best candidate `ramp` in 7, scores 2.6-5.2); with
// it the warm-up comes first and reported in 8 of 10. At least 5 of 10 required (P(<= 4 of 10) = 0.6 % at the measured 0.8).
TEST_CASE("a weak warm-up is found by its settling against the model", "[diagnose][selection]") {
  int found = 0;
  for (std::uint64_t seed = 1000; seed < 1010; ++seed) {
    const auto r = simulate(kWhite + "    - {type: warmup, amplitude: 0.035 deg/s, tau: 30 s}\n", kLineN, seed);
    const auto d = dg::diagnose(r, errorModelFromString(kWhite, "base.yaml"), gxOnly(seed)).axis("gx");
    INFO("seed " << seed << ": reported " << reportedList(d));
    found += !d.findings.empty() && d.findings[0].reported && d.findings[0].effect == "warmup";
  }
  CHECK(found >= 5);
}

// The slow coefficients' likelihood (low_frequency.hpp) enters every candidate's drop; on records
// the model describes exactly it must not make findings: 10 seeds each of white noise and of
// white + a Gauss-Markov of tau = T/30 (its slow coefficients well above white's), the model the
// truth. The threshold keeps the false-alarm rate per channel near 0.3 % (8/2623 on the
// benchmark's clean channels), so at most 1 of 20 (P(>= 2) = 1.7 % at a rate of 1 %).
TEST_CASE("the longest scales make no finding on records the model describes", "[diagnose][selection]") {
  const std::string gm = kWhite + "    - {type: gauss_markov, sigma: 0.02 deg/s, tau: 10 s}\n";
  int findings = 0;
  for (std::uint64_t seed = 1100; seed < 1110; ++seed)
    for (const auto& model : {kWhite, gm}) {
      const auto d = dg::diagnose(simulate(model, 30000, seed), errorModelFromString(model, "base.yaml"),
                                  gxOnly(seed)).axis("gx");
      INFO("seed " << seed << ": reported " << reportedList(d));
      findings += !reportedList(d).empty();
    }
  CHECK(findings <= 1);
}

namespace {

/// The outliers candidate's isolated samples on gx of r (empty: none proposed).
std::vector<std::size_t> outlierSamples(const Record& r) {
  namespace d = dg::detail;
  const d::Setup setup = d::makeSetup(kRate, r.rows, dg::DiagnoseOptions{});
  std::vector<double> tau;
  for (auto m : setup.factors) tau.push_back(double(m) / kRate);
  std::vector<std::size_t> at;
  for (const auto& c : d::buildCandidates(r, 0, r.gyro[0], 0.0, tau, setup, {"ar"}))
    if (c.effect == "outliers")
      for (std::size_t k = 0; k < c.signal.size(); ++k)
        if (c.signal[k] != 0.0) at.push_back(k);
  return at;
}

}  // namespace

// A bias step under a nearly integrated base is a level shift, not an outlier (Chen & Liu 1993:
// of an additive outlier and a level shift the larger lambda decides). Base: AR(1) y_t = 0.99
// y_t-1 + w_t, sd(w) = 1, N = 20000. Its whitening AR(4) is ~(1, -0.99, 0, 0, 0), so a step h at k
// enters the residuals as h (1, 0.01, 0.01, ...): the spike estimate there is h (1 - 0.0099) /
// |a|^2 = 0.50 h with lambda_A = 0.70 h / sigma = 10.5 for h = 15, beyond the spike test's 5.45
// (2 N Phi(-z) = 1e-3), so the spike test alone flags it (challenge record r0473: a 3x bias step
// under an AR(5) with A(1) = 0.05, named `outliers`). The shift's |u_k|^2 = 1 + 1e-4 k (N - k) / N
// (1.5 at k = 9000) gives lambda_L = 1.22 h / sigma = 18 > 10.5: none of 10 seeds may propose the
// step as an outlier (with lambda_L taken at the flagged sample alone, the step's twin peak one
// sample earlier stayed an outlier in 4 of 10). Control: a spike of 10 in the same base (lambda_A
// = 10 |a| = 14) is a step up and one down a sample later, where the shift test may place a shift
// of lambda_L ~ 0.81 x 10 = 8; the spike is found at its sample on every seed.
TEST_CASE("a step under a nearly integrated base is no outlier, a spike still is", "[diagnose][selection]") {
  constexpr std::size_t N = 20000;
  std::mt19937_64 g(1200);
  std::normal_distribution<double> n01(0.0, 1.0);
  for (int seed = 0; seed < 10; ++seed) {
    auto r = simulate(kWhite, N, 1200 + std::uint64_t(seed));
    double y = 0;
    for (auto& v : r.gyro[0]) v = (y = 0.99 * y + n01(g));
    auto stepped = r;
    for (std::size_t k = 9000; k < N; ++k) stepped.gyro[0][k] += 15.0;
    INFO("seed " << seed);
    CHECK(outlierSamples(stepped).empty());
    auto spiked = r;
    spiked.gyro[0][9000] += 10.0;
    const auto at = outlierSamples(spiked);
    CHECK(std::find(at.begin(), at.end(), std::size_t(9000)) != at.end());
  }
}

// A warm-up beside a drift through the record (challenge records r0205, r0277 of seed 2: a
// warm-up and a ramp, each 6-10x the base, named `random_walk` or `gauss_markov`). Fitted alone
// to block means, exp(-t / tau_w) takes part of the line and its time constant moves (4.9 s for
// a 0.34 s settling on a 15 s record); on a large settling the transient the wrong time constant
// leaves loses the trial to a Gauss-Markov hump. The variant fitted beside a straight trend keeps
// the settling's own time constant. White sd 0.1 deg/s, 300 s at 100 Hz; a settling of 3 deg/s
// with tau 5 s and a ramp of 0.6 deg/s over the record. Before: a spurious `gauss_markov` beside
// them in 7 of these 10 seeds (on two records of `sinsim synth` it came alone, with `unexplained`).
// Now warm-up and ramp in >= 9 of 10 (10 measured), a Gauss-Markov in <= 1 (0), tau within 10 %
// in >= 9 (10).
TEST_CASE("a warm-up beside a ramp keeps its own time constant", "[diagnose][selection]") {
  int both = 0, gm = 0, tauOk = 0;
  for (std::uint64_t seed = 1700; seed < 1710; ++seed) {
    const auto r = simulate(kWhite + "    - {type: warmup, amplitude: 3 deg/s, tau: 5 s}\n"
                                     "    - {type: ramp, slope: 0.002 deg/s/s}\n",
                            kLineN, seed);
    const auto d = dg::diagnose(r, errorModelFromString(kWhite, "base.yaml"), gxOnly(seed)).axis("gx");
    const std::string rep = reportedList(d);
    INFO("seed " << seed << ": reported " << rep);
    both += rep.find("warmup") != std::string::npos && rep.find("ramp") != std::string::npos;
    gm += rep.find("gauss_markov") != std::string::npos;
    for (const auto& f : d.findings)
      if (f.reported && f.effect == "warmup") tauOk += std::fabs(f.params.at("tau") / 5.0 - 1.0) < 0.1;
  }
  CHECK(both >= 9);
  CHECK(gm <= 1);
  CHECK(tauOk >= 9);
}

// A line far above the noise (1 deg/s at 1.0178 Hz beside white of 0.07 deg/s per sample; the
// ADIS16405 run-2 injection of a 10x line on gy): on its Welch main lobe several bins test with
// p = 0 (underflow), and they were taken lowest frequency first: the refinement window (+-1.5
// bins) around the lobe's flank missed the peak, the line was fitted 0.018 Hz off with 6 % of
// its amplitude, and a Gauss-Markov hump took the rest (3 of 3 seeds: `gauss_markov` first).
// Equal p are now ordered by the bin's ratio to its neighbourhood: the lobe's peak first.
// Frequency resolution 1/T = 0.0033 Hz; the amplitude's sd is ~0.07 sqrt(2/N) = 0.06 % of it.
TEST_CASE("a line far above the noise is fitted at its own frequency", "[diagnose][selection]") {
  for (std::uint64_t seed : {1900, 1901, 1902}) {
    const auto r = simulate(kWhite + "    - {type: sinusoid, amplitude: 1 deg/s, frequency: 1.0178 Hz, phase: 0 deg}\n",
                            kLineN, seed);
    const auto d = dg::diagnose(r, errorModelFromString(kWhite, "base.yaml"), gxOnly(seed)).axis("gx");
    INFO("seed " << seed << ": reported " << reportedList(d));
    REQUIRE_FALSE(d.findings.empty());
    CHECK(reportedList(d) == "sinusoid ");
    CHECK(d.findings[0].params.at("frequency") == Approx(1.0178).margin(1e-3));
    CHECK(d.findings[0].params.at("amplitude") == Approx(M_PI / 180).epsilon(0.01));
  }
}

/// The reported lines of a channel, lowest frequency first: (frequency [Hz], amplitude [deg/s]).
std::vector<std::pair<double, double>> linesReported(const dg::AxisDiagnosis& d) {
  std::vector<std::pair<double, double>> found;
  for (const auto& f : d.findings)
    if (f.reported && f.effect == "sinusoid")
      found.push_back({f.params.at("frequency"), f.params.at("amplitude") * 180 / M_PI});
  std::sort(found.begin(), found.end());
  return found;
}

// Two lines on one channel (issue 12: "sinusoid (any number of lines)"): once a line is accepted
// and taken out of the record, the next is proposed on what is left (Candidate::maxAccepted).
// Before, a channel had at most one sinusoid finding and the second line stayed `unexplained`
// (0.03 deg/s at 7.7 Hz beside 0.05 deg/s at 1.3 Hz, white sd 0.07 deg/s per sample: 3 of 3
// seeds). Each amplitude's sd is ~0.07 sqrt(2/N) = 0.0006 deg/s: within 10 % is > 5 sd. `--add
// found` writes both lines.
TEST_CASE("two lines on one channel are both found and both added", "[diagnose][selection]") {
  const std::string lines = "    - {type: sinusoid, amplitude: 0.05 deg/s, frequency: 1.3 Hz, phase: 0 deg}\n"
                            "    - {type: sinusoid, amplitude: 0.03 deg/s, frequency: 7.7 Hz, phase: 10 deg}\n";
  for (std::uint64_t seed : {1910, 1911, 1912}) {
    const auto r = simulate(kWhite + lines, kLineN, seed);
    const auto imp = dg::improve(r, errorModelFromString(kWhite, "base.yaml"), {dg::AddRequest::parse("found:gx")},
                                 gxOnly(seed));
    const auto& d = imp.before.axis("gx");
    INFO("seed " << seed << ": reported " << reportedList(d));
    CHECK(reportedList(d) == "sinusoid sinusoid ");
    const auto found = linesReported(d);
    REQUIRE(found.size() == 2);
    CHECK(found[0].first == Approx(1.3).margin(1e-3));
    CHECK(found[0].second == Approx(0.05).epsilon(0.1));
    CHECK(found[1].first == Approx(7.7).margin(1e-3));
    CHECK(found[1].second == Approx(0.03).epsilon(0.1));
    REQUIRE(imp.changes.size() == 1);
    CHECK(std::count_if(imp.changes[0].added.begin(), imp.changes[0].added.end(),
                        [](const auto& e) { return e.type == "sinusoid"; }) == 2);
    CHECK(imp.after.axis("gx").misfit <= 0.5 * d.misfit);
  }
}

// A line the model already has is the model's own, whatever its phase (the model's realisations
// carry it; the Allan variance does not see a phase): only the line it lacks is reported, or one
// the model has far too weak (more than 2x in amplitude: detectors/sinusoid.cpp). Before,
// the sinusoid detector proposed every line of the record, and a model improved by `--add
// sinusoid` was told to add the same line again when diagnosed anew (ADIS16405 run 1: all three
// accelerometers' 0.564 Hz line, the model's A within 0.1 % of it).
TEST_CASE("a line the model has is not reported again, the one it lacks is", "[diagnose][selection]") {
  const std::string lines = "    - {type: sinusoid, amplitude: 0.05 deg/s, frequency: 1.3 Hz, phase: 0 deg}\n"
                            "    - {type: sinusoid, amplitude: 0.03 deg/s, frequency: 7.7 Hz, phase: 10 deg}\n";
  const std::string withOne = kWhite + "    - {type: sinusoid, amplitude: 0.05 deg/s, frequency: 1.3 Hz, phase: 90 deg}\n";
  for (std::uint64_t seed : {1915, 1916, 1917}) {
    const auto r = simulate(kWhite + lines, kLineN, seed);
    const auto d = dg::diagnose(r, errorModelFromString(withOne, "one-line.yaml"), gxOnly(seed)).axis("gx");
    INFO("seed " << seed << ": reported " << reportedList(d));
    CHECK(reportedList(d) == "sinusoid ");
    const auto found = linesReported(d);
    REQUIRE(found.size() == 1);
    CHECK(found[0].first == Approx(7.7).margin(1e-3));
    const auto both = dg::diagnose(r, errorModelFromString(kWhite + lines, "both.yaml"), gxOnly(seed)).axis("gx");
    INFO("with both lines in the model: reported " << reportedList(both));
    CHECK(linesReported(both).empty());
    // A model line 5x weaker than the record's (its power 1/25) does not explain it: proposed whole.
    const std::string weak = kWhite + "    - {type: sinusoid, amplitude: 0.01 deg/s, frequency: 1.3 Hz}\n" +
                             "    - {type: sinusoid, amplitude: 0.03 deg/s, frequency: 7.7 Hz, phase: 10 deg}\n";
    const auto under = dg::diagnose(r, errorModelFromString(weak, "weak.yaml"), gxOnly(seed)).axis("gx");
    INFO("with the 1.3 Hz line 5x too weak in the model: reported " << reportedList(under));
    const auto more = linesReported(under);
    REQUIRE(more.size() == 1);
    CHECK(more[0].first == Approx(1.3).margin(1e-3));
  }
}

// Two lines closer than the Welch test's separation (3 bins: 0.146 Hz at 100 Hz with 2048-sample
// segments, 44 / T on this 300-s record) but 18 / T apart, so that the whole record's periodogram
// resolves them: 0.05 deg/s at 1.30 Hz and 0.03 deg/s at 1.36 Hz beside white of sd 0.1 deg/s per
// sample. Before, what was left after the first line was taken as that line's own width: the second
// stayed unproposed (the independent generator's seed 2 r0007: two lines 1.2 Welch bins apart on a
// 75-s record read as one line and a Gauss-Markov). Now both, each amplitude within 10 % (> 5 sd of
// its estimate, 0.1 sqrt(2 / N) = 0.0008 deg/s), on 3 of 3 seeds.
TEST_CASE("two lines the whole record resolves inside one Welch separation are both found",
          "[diagnose][selection]") {
  const std::string lines = "    - {type: sinusoid, amplitude: 0.05 deg/s, frequency: 1.30 Hz, phase: 0 deg}\n"
                            "    - {type: sinusoid, amplitude: 0.03 deg/s, frequency: 1.36 Hz, phase: 40 deg}\n";
  for (std::uint64_t seed : {1930, 1931, 1932}) {
    const auto r = simulate(kWhite + lines, kLineN, seed);
    const auto d = dg::diagnose(r, errorModelFromString(kWhite, "base.yaml"), gxOnly(seed)).axis("gx");
    INFO("seed " << seed << ": reported " << reportedList(d));
    CHECK(reportedList(d) == "sinusoid sinusoid ");
    const auto found = linesReported(d);
    REQUIRE(found.size() == 2);
    CHECK(found[0].first == Approx(1.30).margin(1e-3));
    CHECK(found[0].second == Approx(0.05).epsilon(0.1));
    CHECK(found[1].first == Approx(1.36).margin(1e-3));
    CHECK(found[1].second == Approx(0.03).epsilon(0.1));
  }
}

// What a line whose frequency wanders leaves once a constant line is taken out is not more lines:
// 0.3 deg/s at 2 Hz, frequency-modulated by +-0.03 Hz (9 / T) three times over the record, beside
// white of sd 0.1 deg/s per sample. Its power sits in Bessel side bands 1 / (100 s) apart (J_k(3):
// 0.26, 0.34, 0.49, 0.31, 0.13), each far above the noise, none holding half of the remains (a test
// stand's line wandering over hours: ADIS16405 run 2's 0.564 Hz). One sinusoid on 3 of 3 seeds;
// checked by mutation: with every remains 5 / T away taken as a line (the share test removed) 2
// sinusoids, with no separation rule at all 6.
TEST_CASE("a wandering line's side bands are not further lines", "[diagnose][selection]") {
  const double A = 0.3 * M_PI / 180, fm = 0.01, beta = 0.03 / fm;
  for (std::uint64_t seed : {1940, 1941, 1942}) {
    auto r = simulate(kWhite, kLineN, seed);
    for (std::size_t k = 0; k < r.rows; ++k) {
      const double t = double(k) / kRate;
      r.gyro[0][k] += A * std::sin(2 * M_PI * 2.0 * t + beta * std::sin(2 * M_PI * fm * t) + 0.3 * double(seed));
    }
    const auto d = dg::diagnose(r, errorModelFromString(kWhite, "base.yaml"), gxOnly(seed)).axis("gx");
    INFO("seed " << seed << ": reported " << reportedList(d));
    CHECK(linesReported(d).size() == 1);
  }
}

// A strong line rounded coarsely without dither (0.3 deg/s at 2.3651 Hz rounded to 0.1 deg/s,
// then white noise of 0.07 deg/s per sample; what adis_inject.py's injection into a record already
// on its lattice makes): the rounding's odd harmonics, folded at Nyquist, are lines of the record
// at 3-30 % of the fundamental. Reported as 7 more sinusoids on 3 of 3 seeds once a channel could
// show several lines; a much weaker line (< 1/4) at a harmonic (k <= 50) of a line taken is its
// distortion, and is not proposed. What the harmonics leave once the line is taken out is the
// rounding's error, a short-tau excess off any value lattice (the noise is added after the
// rounding): since the lattice-free quantization candidate (twenty-seventh session) it may be
// reported as `quantization`, which it is; nothing else is.
TEST_CASE("the harmonics of a coarsely rounded line are not further lines", "[diagnose][selection]") {
  const double A = 0.3 * M_PI / 180, q = A / 3;
  for (std::uint64_t seed : {1920, 1921, 1922}) {
    auto r = simulate("gyro:\n  x:\n    - {type: white, density: 0.007 deg/s/sqrt(Hz)}\n", 100000, seed);
    for (std::size_t k = 0; k < r.rows; ++k)
      r.gyro[0][k] += q * std::round(A * std::sin(2 * M_PI * 2.3651 * double(k) / kRate + 0.1 * double(seed)) / q);
    const auto d = dg::diagnose(r, errorModelFromString("gyro:\n  x:\n    - {type: white, density: 0.007 deg/s/sqrt(Hz)}\n",
                                                        "base.yaml"),
                                gxOnly(seed))
                       .axis("gx");
    INFO("seed " << seed << ": reported " << reportedList(d));
    REQUIRE_FALSE(d.findings.empty());
    CHECK(linesReported(d).size() == 1);
    CHECK((reportedList(d) == "sinusoid " || reportedList(d) == "sinusoid quantization "));
    CHECK(d.findings[0].params.at("frequency") == Approx(2.3651).margin(1e-3));
  }
}

// A further effect on a channel that already has one is reported at the next threshold (4.5, its
// null calibrated on one-effect channels), a first one only at the threshold (5.5). White noise
// of 0.01 deg/s/sqrt(Hz) (sd s = 0.1 deg/s per sample), N = 30000 samples at 100 Hz, a line of
// 0.05 deg/s at 3.1 Hz (its own test alone z ~ 40: found first) and a ramp of 7.5 trend sd's
// (trend sd = s / sqrt(dt^2 N (N^2 - 1) / 12)). The ramp's score is its trend's t against the 16
// realisations' scatter, made Gaussian-equivalent, less a parameter's penalty: 3.9-5.8 on these
// seeds, nearly the same with and without the line (the line is taken out of the record first).
// Per seed the rule itself: reported beside the line iff its score >= 4.5, alone iff >= 5.5. Over
// the 24 seeds, against the injection: beside the line the ramp is found at least 10 times
// (14 measured); on the line-only records nothing but the line in at least 22 (a spurious second
// finding at ~ 2 % per channel, the calibration's rate: P(>= 3 of 24) = 1.3 %).
TEST_CASE("a further effect is reported at the next threshold and a first one only at the threshold",
          "[diagnose][selection]") {
  const double s = 0.01 * std::sqrt(kRate);  // [deg/s] per sample
  const double dt = 1.0 / kRate, n = double(kLineN);
  const double trendSd = s / std::sqrt(dt * dt * n * (n * n - 1) / 12);  // [deg/s/s]
  const std::string ramp = "    - {type: ramp, slope: " + std::to_string(7.5 * trendSd) + " deg/s/s}\n";
  const std::string line = "    - {type: sinusoid, amplitude: 0.05 deg/s, frequency: 3.1 Hz, phase: 0 deg}\n";
  const auto base = errorModelFromString(kWhite, "base.yaml");
  const dg::DiagnoseOptions o;
  auto rampScore = [](const dg::AxisDiagnosis& a) {
    for (const auto& f : a.findings)
      if (f.effect == "ramp") return f.score;
    return 0.0;
  };
  int beside = 0, clean = 0;
  for (std::uint64_t seed = 1950; seed < 1974; ++seed) {
    const auto both = dg::diagnose(simulate(kWhite + line + ramp, kLineN, seed), base, gxOnly(seed)).axis("gx");
    const auto single = dg::diagnose(simulate(kWhite + ramp, kLineN, seed), base, gxOnly(seed)).axis("gx");
    const auto lineOnly = dg::diagnose(simulate(kWhite + line, kLineN, seed), base, gxOnly(seed)).axis("gx");
    INFO("seed " << seed << ": " << reportedList(both) << "(ramp " << rampScore(both) << ") | "
                 << reportedList(single) << "(ramp " << rampScore(single) << ") | " << reportedList(lineOnly));
    REQUIRE(reportedList(both).rfind("sinusoid ", 0) == 0);
    const bool rampBeside = reportedList(both) == "sinusoid ramp ";
    CHECK(rampBeside == (rampScore(both) >= o.nextThreshold));
    CHECK((reportedList(single) == "ramp ") == (rampScore(single) >= o.threshold));
    beside += rampBeside;
    clean += reportedList(lineOnly) == "sinusoid ";
  }
  CHECK(beside >= 10);
  CHECK(clean >= 22);
}

// An AR beside other base terms is not refitted by Burg when an effect is added (improve.cpp,
// soleBaseAr): the refit on the record without the effect takes the white noise into the AR, and
// the model, which keeps its white term, counts it twice. Base white 0.01 deg/s/sqrt(Hz) + AR(1)
// (a1 = -0.9, sigma 0.005 deg/s) at 100 Hz, 300 s, a ramp of 2000 deg/h^2 hidden and added.
// Measured on these 5 seeds: the misfit after / before 1.9-2.7 with the refit (the added ramp made
// the model worse), 0-0.47 without it. Required: halved on every seed (the floor per case).
TEST_CASE("an AR beside white noise is not refitted when an effect is added", "[diagnose][selection]") {
  const std::string base = "gyro:\n  x:\n    - {type: white, density: 0.01 deg/s/sqrt(Hz)}\n"
                           "    - {type: ar, a: [-0.9], sigma: 0.005 deg/s, rate: 100 Hz}\n";
  for (std::uint64_t seed = 1400; seed < 1405; ++seed) {
    const auto r = simulate(base + "    - {type: ramp, slope: 2000 deg/h^2}\n", kLineN, seed);
    const auto imp = dg::improve(r, errorModelFromString(base, "base.yaml"), {dg::AddRequest::parse("ramp:gx")},
                                 gxOnly(seed));
    INFO("seed " << seed << ": misfit " << imp.before.axis("gx").misfit << " -> " << imp.after.axis("gx").misfit);
    CHECK(imp.after.axis("gx").misfit <= 0.5 * imp.before.axis("gx").misfit);
  }
}

// On a channel whose Allan curve is white over the whole measured tau, a white noise the model
// lacks raises the curve by one factor, which the fitted level s took whole: nothing was reported
// (the independent generator's white + GM + walk channels at 1600 Hz, 4-6x; docs/diagnose-log.md,
// "Twenty-fourth session"). The level's prior (allan_chi2.hpp, kLevelLnSd: the model's level known
// to 1.5x in Allan variance) makes a 4x white noise (Allan variance 16x: (ln 16 / ln 1.5)^2 = 46.8,
// less one parameter's ln K) a finding, and leaves a 1.5x one (2.25x: 4.0) the model's level.
TEST_CASE("a white noise far above the model's is named white and a small excess is its level",
          "[diagnose][selection]") {
  auto white = [](const std::string& density) {
    return "gyro:\n  x:\n    - {type: white, density: " + density + " deg/s/sqrt(Hz)}\n";
  };
  const auto model = errorModelFromString(white("0.01"), "model.yaml");
  for (std::uint64_t seed = 1500; seed < 1504; ++seed) {
    const auto big = dg::diagnose(simulate(white("0.04"), 30000, seed), model, gxOnly(seed));
    const auto small = dg::diagnose(simulate(white("0.015"), 30000, seed), model, gxOnly(seed));
    INFO("seed " << seed << ": 4x reported " << reportedList(big.axis("gx")) << ", 1.5x reported "
                 << reportedList(small.axis("gx")));
    CHECK(reportedList(big.axis("gx")) == "white ");
    CHECK(reportedList(small.axis("gx")).empty());
  }
}

// A model's ramp is a known line: the diagnosis takes it out of the record and the model
// (model_drift.hpp), so a drift beyond it is found as a ramp of the slope beyond, and one of the
// other sign -- which the Allan variance cannot tell from the model's (R^2 tau^2 / 2) -- too.
// Before, the ramp detector did not run where the model had a ramp: the steeper drift was named
// `warmup`, the reversed one "fits". White 0.0573 deg/s/sqrt(Hz) + GM (0.0286 deg/s, 5 s) at
// 100 Hz, 1200 s, the model's ramp 3000 deg/h^2, the record's 9000 or -3000 deg/h^2: the slope
// beyond is +-6000 deg/h^2 (~6x the base ADEV at T/8) against a least-squares slope scatter of
// ~100 deg/h^2 (sd; the GM's variance 12 * 2 sigma^2 tau / T^3): required within 400 deg/h^2, and
// `--add ramp` halves the misfit with the two ramps summing to the record's drift within the same.
TEST_CASE("a drift beyond the model's own ramp, or reversed, is found as a ramp", "[diagnose][selection]") {
  const std::string base = "gyro:\n  x:\n    - {type: white, density: 0.0573 deg/s/sqrt(Hz)}\n"
                           "    - {type: gauss_markov, sigma: 0.0286 deg/s, tau: 5 s}\n";
  const auto model = errorModelFromString(base + "    - {type: ramp, slope: 3000 deg/h^2}\n", "base.yaml");
  const double unit = M_PI / 180.0 / 3600.0 / 3600.0;  // deg/h^2 in rad/s^2
  for (const double truth : {9000.0, -3000.0}) {
    for (std::uint64_t seed = 1500; seed < 1503; ++seed) {
      const auto r = simulate(base + "    - {type: ramp, slope: " + std::to_string(truth) + " deg/h^2}\n",
                              120000, seed);
      const auto imp = dg::improve(r, model, {dg::AddRequest::parse("ramp:gx")}, gxOnly(seed));
      const auto& d = imp.before.axis("gx");
      INFO("record's ramp " << truth << " deg/h^2, seed " << seed << ": reported " << reportedList(d)
                            << "misfit " << d.misfit << " -> " << imp.after.axis("gx").misfit);
      CHECK(d.modelDrift == Approx(3000.0 * unit).epsilon(1e-9));
      REQUIRE(reportedList(d).rfind("ramp ", 0) == 0);
      CHECK(d.findings[0].params.at("slope") == Approx((truth - 3000.0) * unit).margin(400.0 * unit));
      CHECK(imp.after.axis("gx").misfit <= 0.5 * d.misfit);
      double sum = 0;
      for (const auto& e : imp.model.gyro.x)
        if (e.type == "ramp") sum += e.find("slope")->values[0];
      CHECK(sum == Approx(truth * unit).margin(400.0 * unit));
    }
  }
}

namespace {

// How many of three records make(seed), seed = first.., the diagnosis finds nothing on against model.
int cleanOfThree(const sinsim::errormodels::ErrorModelSpec& model, std::uint64_t first, const std::function<Record(std::uint64_t)>& make) {
  int clean = 0;
  for (std::uint64_t seed = first; seed < first + 3; ++seed) {
    const auto d = dg::diagnose(make(seed), model, gxOnly(seed)).axis("gx");
    INFO("seed " << seed << ": reported " << reportedList(d) << "misfit " << d.misfit);
    clean += reportedList(d).empty();
  }
  return clean;
}

int countType(const std::vector<sinsim::errormodels::EffectSpec>& effects, const std::string& type) {
  return int(std::count_if(effects.begin(), effects.end(), [&](const sinsim::errormodels::EffectSpec& e) { return e.type == type; }));
}

}  // namespace

// A model's warm-up is a known settling, A exp(-t/tau): taken out of the record and the model like a
// ramp (model_drift.hpp), so a record whose warm-up is larger, or of the other sign, shows the
// warm-up beyond the model's. Before, the warmup detector did not run where the model had one: a
// warm-up 3x the model's was `unexplained` (a level step), a reversed one "fits". White + GM as
// above at 100 Hz, 1200 s, the model's warm-up 0.1 deg/s with tau 120 s, the record's 0.3 or -0.1
// deg/s: the warm-up beyond is +-0.2 deg/s (its block means ~20x the noise's over the first tau).
// Amplitude and tau trade off over one record (tau seen 81..144 s), so A is required within
// 0.07 deg/s; `--add warmup` halves the misfit of the larger one (the reversed one's Allan variance
// is the model's) and writes the second warm-up beside the model's. A record whose warm-up is the
// model's fits.
TEST_CASE("a warm-up beyond the model's own, or reversed, is found as a warm-up", "[diagnose][selection]") {
  const std::string base = "gyro:\n  x:\n    - {type: white, density: 0.0573 deg/s/sqrt(Hz)}\n"
                           "    - {type: gauss_markov, sigma: 0.0286 deg/s, tau: 5 s}\n";
  const auto warmup = [](const std::string& A) { return "    - {type: warmup, amplitude: " + A + " deg/s, tau: 120 s}\n"; };
  const auto model = errorModelFromString(base + warmup("0.1"), "base.yaml");
  const double degs = M_PI / 180.0;
  for (const std::string truth : {"0.3", "-0.1"}) {
    for (std::uint64_t seed = 1520; seed < 1523; ++seed) {
      const auto r = simulate(base + warmup(truth), 120000, seed);
      const auto imp = dg::improve(r, model, {dg::AddRequest::parse("warmup:gx")}, gxOnly(seed));
      const auto& d = imp.before.axis("gx");
      INFO("record's warm-up " << truth << " deg/s, seed " << seed << ": reported " << reportedList(d)
                               << "misfit " << d.misfit << " -> " << imp.after.axis("gx").misfit);
      REQUIRE(d.modelWarmups.size() == 1);
      CHECK(d.modelWarmups[0].amplitude == Approx(0.1 * degs).epsilon(1e-9));
      CHECK(d.modelWarmups[0].tau == Approx(120.0).epsilon(1e-9));
      REQUIRE(reportedList(d).rfind("warmup ", 0) == 0);
      CHECK(d.findings[0].params.at("amplitude") == Approx((std::stod(truth) - 0.1) * degs).margin(0.07 * degs));
      // The reversed warm-up's Allan variance is the model's (the Allan variance cannot tell A from
      // -A): its misfit is small before, and is not to rise.
      if (truth == "0.3") CHECK(imp.after.axis("gx").misfit <= 0.5 * d.misfit);
      else CHECK(imp.after.axis("gx").misfit <= d.misfit + 0.01);
      CHECK(countType(imp.model.gyro.x, "warmup") == 2);
    }
  }
  CHECK(cleanOfThree(model, 1523, [&](std::uint64_t seed) { return simulate(base + warmup("0.1"), 120000, seed); }) >= 2);
}

// A model's temperature polynomial, at the record's temperatures, is known too: taken out likewise,
// so a thermal drift the record shows beyond the model's is found as `temperature`. Before, the
// detector did not run where the model had one. White 0.01 deg/s/sqrt(Hz) at 100 Hz over 300 s on
// the warming profile (Var T = 14.6 degC^2, as above), the model's c1 = 1.5e-3 deg/s/degC, the
// record's 4.5e-3 or -1.5e-3: the coefficient beyond, +-3e-3, is ~20 of its sd (1.5e-4, as above);
// required within 5 sd (7.5e-4). `--add temperature` writes it beside the model's and halves the
// misfit of the larger one (the reversed one's Allan variance is the model's: not to rise). A record
// whose thermal drift is the model's fits.
TEST_CASE("a thermal drift beyond the model's own, or reversed, is found as temperature", "[diagnose][selection]") {
  const auto temp = [](const std::string& c1) {
    return "    - {type: temperature, T0: 25 degC, coefficients: [" + c1 + " deg/s/degC]}\n";
  };
  const auto model = errorModelFromString(kWhite + temp("1.5e-3"), "base.yaml");
  const double unit = M_PI / 180.0;  // deg/s/degC in rad/s/K
  for (const std::string truth : {"4.5e-3", "-1.5e-3"}) {
    for (std::uint64_t seed = 1530; seed < 1533; ++seed) {
      const auto r = simulateWarming(kWhite + temp(truth), kLineN, seed);
      const auto imp = dg::improve(r, model, {dg::AddRequest::parse("temperature:gx")}, gxOnly(seed));
      const auto& d = imp.before.axis("gx");
      INFO("record's c1 " << truth << " deg/s/degC, seed " << seed << ": reported " << reportedList(d)
                          << "misfit " << d.misfit << " -> " << imp.after.axis("gx").misfit);
      CHECK(d.modelTemperature);
      REQUIRE(reportedList(d).rfind("temperature ", 0) == 0);
      CHECK(d.findings[0].params.at("c1") == Approx((std::stod(truth) - 1.5e-3) * unit).margin(7.5e-4 * unit));
      if (truth == "4.5e-3") CHECK(imp.after.axis("gx").misfit <= 0.5 * d.misfit);
      else CHECK(imp.after.axis("gx").misfit <= d.misfit + 0.01);
      CHECK(countType(imp.model.gyro.x, "temperature") == 2);
    }
  }
  CHECK(cleanOfThree(model, 1533, [&](std::uint64_t seed) { return simulateWarming(kWhite + temp("1.5e-3"), kLineN, seed); }) >= 2);
}

// ... except on a channel whose values lie on a lattice the diagnosis sees: less a line they would
// leave it, and the rounding would read as white noise (the third generator's seed 2 r0320,
// quantization at 2.6x beside the model's drift, was named `white`). There the model's ramp stays
// in record and model (modelDrift 0), and a model that is the truth fits. White 0.001
// deg/s/sqrt(Hz) (0.01 deg/s per sample) rounded to 0.05 deg/s, a ramp of 9000 deg/h^2. A model's
// warm-up stays there too (no modelWarmups); whether a truth model with a warm-up fits there is not
// asserted: a settling rounded with so little noise leaves level steps (docs/diagnose-log.md,
// "Thirtieth session").
TEST_CASE("a model's ramp and warm-up stay in a record on a visible lattice", "[diagnose][selection]") {
  const std::string truth = "gyro:\n  x:\n    - {type: white, density: 0.001 deg/s/sqrt(Hz)}\n"
                            "    - {type: ramp, slope: 9000 deg/h^2}\n"
                            "    - {type: quantization, lsb: 0.05 deg/s}\n";
  const auto model = errorModelFromString(truth, "truth.yaml");
  int fits = 0;
  for (std::uint64_t seed = 1510; seed < 1513; ++seed) {
    const auto d = dg::diagnose(simulate(truth, 60000, seed), model, gxOnly(seed)).axis("gx");
    INFO("seed " << seed << ": reported " << reportedList(d) << "misfit " << d.misfit);
    CHECK(d.modelDrift == 0.0);
    fits += reportedList(d).empty();
  }
  CHECK(fits >= 2);
  const std::string warm = "gyro:\n  x:\n    - {type: white, density: 0.003 deg/s/sqrt(Hz)}\n"
                           "    - {type: warmup, amplitude: 0.2 deg/s, tau: 60 s}\n"
                           "    - {type: quantization, lsb: 0.05 deg/s}\n";
  const auto d = dg::diagnose(simulate(warm, 60000, 1513), errorModelFromString(warm, "warm.yaml"), gxOnly(1513)).axis("gx");
  CHECK(d.modelWarmups.empty());
  CHECK(reportedList(d).find("warmup") == std::string::npos);
}

// A white + random-walk base against its exact model (a helper's blind generator, fifty-seventh
// session): the step scans measure their scale on the short-tau residuals, and the walk's wander
// over the long sums passed for an unexplained level step on 13 of 240 clean channels (on this
// model, 4 of 24 channels of sinsim synth's seeds 1-12). A step left unexplained must now be
// beyond the model's own Allan variance at some window either side. A real step of 10 sigma of
// the model's mean difference over 100 s either side is still reported.
TEST_CASE("a random walk the model holds leaves no unexplained level step", "[diagnose][selection]") {
  const std::string base = "gyro:\n  x:\n    - {type: white, density: 0.0056 rad/s/sqrt(Hz)}\n"
                           "    - {type: random_walk, K: 9.2e-5 rad/s/sqrt(s)}\n";
  int flagged = 0;
  for (std::uint64_t seed = 1; seed <= 16; ++seed) {
    const auto r = simulate(base, 180000, seed);
    const auto d = dg::diagnose(r, errorModelFromString(base, "base.yaml"), gxOnly(seed)).axis("gx");
    INFO("seed " << seed << ": reported " << reportedList(d) << ", " << d.unexplainedSteps.size()
                 << " unexplained steps");
    CHECK(reportedList(d).empty());
    flagged += d.unexplainedSteps.empty() ? 0 : 1;
  }
  CHECK(flagged == 0);
  // 10 x sqrt(2 AVAR(100 s)) of this model, 0.011 rad/s at t = 1000 s: still a step.
  auto r = simulate(base, 180000, 17);
  for (std::size_t k = 100000; k < r.rows; ++k) r.gyro[0][k] += 0.011;
  const auto d = dg::diagnose(r, errorModelFromString(base, "base.yaml"), gxOnly(17)).axis("gx");
  INFO("reported " << reportedList(d));
  const bool named = !d.findings.empty() && d.findings[0].reported && d.findings[0].effect == "bias_jumps";
  CHECK((named || !d.unexplainedSteps.empty()));
}
