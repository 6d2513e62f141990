// Round trips of the identify pipeline: records made by the simulator's own error plug-ins
// (ImuErrorModel, exactly what `sinsim synth` runs, sensor at rest with zero ideal signal) go
// through identify() and the fitted parameters are compared with the model that made them.
//
// Bound used throughout: |fitted - truth| <= 3 stated standard errors (per parameter; for AR
// coefficients the joint chi^2_p of (a_hat - a)' Cov^-1 (a_hat - a) <= its 0.999 quantile). With
// seeds fixed the outcome is deterministic; 3 sigma keeps a correct fitter's failure chance per
// check at 0.3 % had the seed been random, and a wrong stated uncertainty (or a biased fitter)
// shows up as a miss.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "common/error.hpp"
#include "errormodels/fit/ar_fit.hpp"
#include "errormodels/identify.hpp"
#include "errormodels/identify_lines.hpp"
#include "errormodels/imu_model.hpp"
#include "errormodels/model_io.hpp"
#include "errormodels/stats/special.hpp"
#include "errormodels/stats/line_fit.hpp"
#include "errormodels/stats/allan.hpp"
#include "identify_test_util.hpp"
#include "test_support.hpp"

using namespace sinsim;
using namespace sinsim::errormodels;
using identify_test::staticRecord;

namespace {

constexpr double kDeg = M_PI / 180.0;
// deg/sqrt(h) -> rad/sqrt(s) and deg/h/sqrt(h) -> rad/s/sqrt(s)
constexpr double kDegPerSqrtH = kDeg / 60.0;
constexpr double kDegPerHPerSqrtH = kDeg / 3600.0 / 60.0;

const fit::AllanTerm& term(const AxisIdentification& a, fit::AllanTermKind k) {
  REQUIRE(a.written.allan);
  return a.written.allan->term(k);
}

void requireWithin3Sigma(double fitted, double truth, double se, const char* what) {
  INFO(what << ": fitted " << fitted << " truth " << truth << " se " << se << " pull "
            << (fitted - truth) / se);
  REQUIRE(se > 0.0);
  CHECK(std::fabs(fitted - truth) <= 3.0 * se);
}

/// chi^2_p of the coefficient error against the fit's own covariance.
double coefficientChi2(const fit::ArFit& f, const std::vector<double>& a) {
  const std::size_t p = f.order;
  Eigen::VectorXd d(static_cast<Eigen::Index>(p));
  for (std::size_t i = 0; i < p; ++i) d(static_cast<Eigen::Index>(i)) = f.a[i + 1] - a[i + 1];
  return d.dot(f.covariance.ldlt().solve(d));
}

// The seed paper's AR(5) polynomials (seed-paper.md table), arburg convention [1, a1..a5].
const std::vector<double> kGx{1.0, -1.0327, -0.34341, 0.037895, 0.19732, 0.14724};
const std::vector<double> kAx{1.0, -0.51552, -0.068261, -0.047218, -0.049565, -0.13655};

}  // namespace

TEST_CASE("white noise: Allan fit returns N, auto chooses Allan terms", "[identify][roundtrip]") {
  // N = 0.2 deg/sqrt(h); 100 Hz for 2 h and 1 kHz for 20 min.
  const double N = 0.2 * kDegPerSqrtH;
  for (const auto& [rate, duration] : {std::pair{100.0, 7200.0}, std::pair{1000.0, 1200.0}}) {
    INFO("rate " << rate << " Hz");
    const Record r = staticRecord("gyro: {x: [{type: white, density: 0.2 deg/sqrt(h)}]}", rate,
                                  duration, 11);
    IdentifyOptions o;
    o.kind = IdentifyKind::Allan;
    const auto id = identify(r, o);
    const auto& w = term(id.axis("gx"), fit::AllanTermKind::White);
    REQUIRE(w.detected);
    requireWithin3Sigma(w.value, N, w.stdError, "N");
    // Auto: white noise holds no correlation the latent terms do not carry -> the composite
    // latent fit, which keeps the white noise.
    o.kind = IdentifyKind::Auto;
    const auto ida = identify(r, o);
    CHECK(ida.axis("gx").kind == IdentifyKind::Latent);
    CHECK_FALSE(ida.axis("gx").written.ar);
    REQUIRE(ida.axis("gx").written.latent);
    const auto& lw = ida.axis("gx").written.latent->model;
    CHECK(std::fabs(lw.white - N) <= 0.05 * N);
    // The file it writes loads in the simulator's loader.
    CHECK_NOTHROW(ImuErrorModel::fromString(ida.modelYaml(), "white.yaml"));
  }
}

// A quantization term is realised as the record made it: carried rounding where the record's
// values sit on the lattice of its LSB, dithered (a fresh uniform remainder,
// effects/quantization.cpp) where they do not -- GMWM's QN, sqrt(12) Q_r (U[k] - U[k-1]) with U
// uniform (test_support.hpp's addQuantizationNoise), or that record printed with 7 decimals (a
// 1e-7 rad/s lattice, far finer than its LSB).
// White 0.3 deg/sqrt(h) at 100 Hz for 20 min; the LSB 0.0005 deg equals the white's increment sd
// (the textbook regime of 3 Q^2 / tau^2).
TEST_CASE("a fitted quantization is written dithered only off the lattice its rounding leaves",
          "[identify][roundtrip]") {
  const double rate = 100.0, lsb = 0.0005 * kDeg, Q = lsb / std::sqrt(12.0);
  IdentifyOptions o;
  o.kind = IdentifyKind::Latent;
  // Rounded with carry: on the rate lattice lsb / dt, written as the carried rounding it is.
  const Record rounded = staticRecord(
      "gyro: {x: [{type: white, density: 0.3 deg/sqrt(h)}, {type: quantization, lsb: 0.0005 deg}]}", rate,
      1200.0, 21);
  const auto idr = identify(rounded, o);
  REQUIRE(idr.axis("gx").written.latent);
  CHECK(idr.axis("gx").written.latent->model.quantization > 0.0);
  CHECK_FALSE(idr.axis("gx").written.ditheredQuantization);
  CHECK(idr.modelYaml().find("dithered") == std::string::npos);
  // The same white with GMWM's QN of the same Q: no lattice.
  Record qn = staticRecord("gyro: {x: [{type: white, density: 0.3 deg/sqrt(h)}]}", rate, 1200.0, 21);
  sinsim::test::addQuantizationNoise(qn.gyro[0], Q * rate, 21);
  for (bool printed : {false, true}) {
    INFO((printed ? "printed with 7 decimals" : "full precision"));
    Record r = qn;
    if (printed)
      for (double& v : r.gyro[0]) v = 1e-7 * std::nearbyint(v / 1e-7);
    const auto id = identify(r, o);
    REQUIRE(id.axis("gx").written.latent);
    const double Qfit = id.axis("gx").written.latent->model.quantization;
    CHECK(Qfit == Approx(Q).epsilon(0.15));
    CHECK(id.axis("gx").written.ditheredQuantization);
    CHECK(id.axis("gx").written.latticeLsb == 0.0);
    CHECK(id.modelYaml().find("dithered: true") != std::string::npos);
    CHECK_NOTHROW(ImuErrorModel::fromString(id.modelYaml(), "qn.yaml"));
  }
}

// Values on a lattice were rounded at its step: the written LSB is the lattice's, exactly, not the
// Allan slope's estimate, which strong rounding biases low (successive rounding errors correlated:
// a blind round trip, bench/fit_blind/, found the LSB 1-13 % low with a 1 sigma of 0.2-2.5 %). The
// carried rounding at 0.0005 deg of white 0.3 deg/sqrt(h) (the increment sd 1.0 LSB) and of white
// 0.1 deg/sqrt(h) (0.33 LSB), 100 Hz, 20 min, three seeds each; the Allan fit's own LSB is printed.
TEST_CASE("a quantization on a value lattice is written at the lattice's LSB", "[identify][roundtrip]") {
  IdentifyOptions o;
  o.kind = IdentifyKind::Latent;
  for (const char* white : {"0.3", "0.1"})
    for (std::uint64_t seed = 31; seed < 34; ++seed) {
      const Record r = staticRecord(std::string("gyro: {x: [{type: white, density: ") + white +
                                        " deg/sqrt(h)}, {type: quantization, lsb: 0.0005 deg}]}",
                                    100.0, 1200.0, seed);
      const auto id = identify(r, o);
      REQUIRE(id.axis("gx").written.latent);
      const double allanLsb = std::sqrt(12.0) * id.axis("gx").written.latent->model.quantization;
      INFO("white " << white << " deg/sqrt(h), seed " << seed << ": Allan LSB " << allanLsb / (0.0005 * kDeg));
      REQUIRE(allanLsb > 0.0);
      CHECK(id.axis("gx").written.latticeLsb == Approx(0.0005 * kDeg).epsilon(1e-9));
      const auto spec = errorModelFromString(id.modelYaml(), "fitted.yaml");
      double written = 0.0;
      for (const auto& e : spec.gyro.x)
        if (e.type == "quantization") written = e.find("lsb")->values.at(0);
      CHECK(written == Approx(0.0005 * kDeg).epsilon(1e-8));
    }
}

// A quiet sensor behind a coarse register: the integral moves 0.1 and 0.25 LSB per sample, so
// successive roundings are correlated and the Allan variance at tau = dt is up to 4x below the
// classical 3 Q^2 / tau^2. Before the lattice's exact form (fit/lattice_rounding.hpp) the terms
// failed the short-tau points and auto wrote an AR (bench/fit_blind: 22/22 quantization + white
// records), losing the quantization. Auto, 100 Hz, 20 min, LSB 0.002 deg, six seeds each: the
// written set quantization + white in >= 5 of 6; where it is, the Allan chi^2 consistent and N
// within 3 sigma. Measured with `sinsim synth` + `sinsim fit --kind auto` on seeds 11-30: 19/20 at
// each motion (a drift added once each).
TEST_CASE("quantization where the integral moves below one LSB per sample: auto keeps quantization + white",
          "[identify][roundtrip]") {
  const double lsb = 0.002 * kDeg, dt = 0.01;
  IdentifyOptions o;
  o.kind = IdentifyKind::Auto;
  for (double motion : {0.1, 0.25}) {
    int right = 0;
    const double N = motion * lsb / std::sqrt(dt);
    for (std::uint64_t seed = 41; seed < 47; ++seed) {
      const Record r = staticRecord("gyro: {x: [{type: white, density: " + std::to_string(N / kDegPerSqrtH) +
                                        " deg/sqrt(h)}, {type: quantization, lsb: 0.002 deg}]}",
                                    100.0, 1200.0, seed);
      const auto id = identify(r, o);
      const auto& ax = id.axis("gx");
      INFO("motion " << motion << " LSB, seed " << seed);
      REQUIRE(ax.written.latent);
      const auto& f = *ax.written.latent;
      CHECK(ax.kind == IdentifyKind::Latent);
      CHECK(ax.written.latticeLsb == Approx(lsb).epsilon(1e-9));
      if (f.terms.name() != "quantization + white") continue;
      ++right;
      CHECK(f.consistent);
      CHECK(f.model.lattice.correlated());
      requireWithin3Sigma(f.model.white, N, f.parameter("white").stdError, "N");
    }
    INFO("motion " << motion << " LSB: quantization + white in " << right << " of 6");
    CHECK(right >= 5);
  }
}

TEST_CASE("white + random walk: Allan fit returns N and K at two rates", "[identify][roundtrip]") {
  struct Case { double rate, duration, kDegHSqrtH; };
  // K chosen so the ADEV minimum sqrt(3) N / K (62 s, 12 s) lies well inside each record (the
  // fit uses m <= N / 10: tau <= 720 s and 120 s). Over 30 seeds each (README) the random walk
  // was selected in 29/30 and 27/30 records (otherwise a bias instability took its place) and the
  // pulls of K had SD 0.8-0.9; these seeds are among the detected ones.
  for (const Case c : {Case{100.0, 7200.0, 20.0}, Case{1000.0, 1200.0, 100.0}}) {
    INFO("rate " << c.rate << " Hz");
    const Record r = staticRecord(
        "gyro: {x: [{type: white, density: 0.2 deg/sqrt(h)}, {type: random_walk, K: " +
            std::to_string(c.kDegHSqrtH) + " deg/h/sqrt(h)}]}",
        c.rate, c.duration, 12);
    IdentifyOptions o;
    o.kind = IdentifyKind::Allan;
    const auto id = identify(r, o);
    const auto& ax = id.axis("gx");
    const auto& w = term(ax, fit::AllanTermKind::White);
    const auto& k = term(ax, fit::AllanTermKind::RandomWalk);
    REQUIRE(w.detected);
    REQUIRE(k.detected);
    requireWithin3Sigma(w.value, 0.2 * kDegPerSqrtH, w.stdError, "N");
    requireWithin3Sigma(k.value, c.kDegHSqrtH * kDegPerHPerSqrtH, k.stdError, "K");
    // Auto writes the composite latent fit (no short correlation), white noise kept.
    o.kind = IdentifyKind::Auto;
    const auto ida = identify(r, o);
    CHECK(ida.axis("gx").kind == IdentifyKind::Latent);
    REQUIRE(ida.axis("gx").written.latent);
    CHECK(ida.axis("gx").written.latent->terms.white);
  }
}

TEST_CASE("auto never drops the term that dominates short tau: white + slow GM (issue 11)",
          "[identify][roundtrip]") {
  // The case: 1 kHz, 20 min, white noise over a GM bias with tau = 5 s. The white noise
  // dominates the Allan curve below ~0.1 s, the GM above; auto once wrote a flicker floor alone
  // (no white), its model ADEV 111x below the record at tau = 1 ms.
  const double N = 0.3 * kDegPerSqrtH, sigma = 0.01 * kDeg, T = 5.0;
  const Record r = staticRecord(
      "gyro: {x: [{type: white, density: 0.3 deg/sqrt(h)}, "
      "{type: gauss_markov, sigma: 0.01 deg/s, tau: 5 s}]}",
      1000.0, 1200.0, 21);
  IdentifyOptions o;
  o.kind = IdentifyKind::Auto;
  const auto id = identify(r, o);
  const auto& ax = id.axis("gx");
  CHECK(ax.kind == IdentifyKind::Latent);
  REQUIRE(ax.written.latent);
  const auto& f = *ax.written.latent;
  INFO("terms " << f.terms.name() << ", N " << f.model.white / N << " x truth");
  CHECK(f.terms.white);
  CHECK(std::fabs(f.model.white - N) <= 0.05 * N);  // 1.2 M samples: N to ~0.1 %
  REQUIRE(f.model.gm.size() >= 1);
  const auto& gm = f.model.gm.back();
  // One record of 240 tau: sigma within 40 %, tau within a factor 2.5 (the ADEV hump's position
  // is estimated from ~24 independent tau-lengths).
  CHECK(gm.sigma == Approx(sigma).epsilon(0.4));
  CHECK(gm.tau > T / 2.5);
  CHECK(gm.tau < T * 2.5);
}

TEST_CASE("auto on white + GM + random walk: the terms, not an AR that absorbs them (issue 11)",
          "[identify][roundtrip]") {
  // 100 Hz, 20 min: white 0.2 deg/sqrt(h), a GM of 0.005 deg/s with tau 0.5 s (50 samples), a walk
  // of 120 deg/h/sqrt(h) (dominating tau > ~100 s). A Burg AR(20) predicts 2-9 % of the variance
  // here (the GM's and the walk's slow correlation), and the old rule (AR when the prediction gain
  // is >= 1.02) wrote an AR(20) with a flicker term on 8 of 8 such records (`sinsim synth`, seeds
  // 1-8), dropping the GM and the walk. The terms predict the next sample as well as the AR does,
  // so auto must write them: white and the GM always, a long-tau term always, the right set in
  // most seeds (the walk can read as flicker over 20 min: 38/40 right on the NumPy grid).
  int right = 0;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    INFO("seed " << seed);
    const Record r = staticRecord(
        "gyro: {x: [{type: white, density: 0.2 deg/sqrt(h)}, {type: gauss_markov, sigma: 0.005 deg/s, "
        "tau: 0.5 s}, {type: random_walk, K: 120 deg/h/sqrt(h)}]}",
        100.0, 1200.0, seed);
    IdentifyOptions o;
    const auto id = identify(r, o);
    const auto& ax = id.axis("gx");
    for (const auto& d : ax.decision) INFO(d);
    REQUIRE(ax.kind == IdentifyKind::Latent);
    REQUIRE(ax.written.latent);
    const auto& t = ax.written.latent->terms;
    CHECK(t.white);
    REQUIRE(t.gm >= 1);
    CHECK((t.randomWalk || t.flicker));
    const double tau = ax.written.latent->model.gm.front().tau;
    CHECK(tau > 0.25);
    CHECK(tau < 1.0);
    right += t.name() == "white + gm + random_walk";
  }
  CHECK(right >= 4);
}

TEST_CASE("Gauss-Markov: GM fit returns sigma and tau at two rates", "[identify][roundtrip]") {
  // sigma 0.05 deg/s, tau 0.5 s. The synthesized rate samples are interval means of the
  // continuous process; that lowers the lag-0 variance by ~dt / (3 tau) (0.7 % at 100 Hz,
  // 0.07 % at 1 kHz), well inside 3 SE (relative SE of sigma ~ sqrt(tau / T) ~ 3-4 %).
  for (const auto& [rate, duration] : {std::pair{100.0, 600.0}, std::pair{1000.0, 300.0}}) {
    INFO("rate " << rate << " Hz");
    const Record r = staticRecord(
        "gyro: {x: [{type: gauss_markov, sigma: 0.05 deg/s, tau: 0.5 s}]}", rate, duration, 13);
    IdentifyOptions o;
    o.kind = IdentifyKind::Gm;
    const auto id = identify(r, o);
    const auto& g = id.axis("gx").gaussMarkov;
    REQUIRE(g);
    REQUIRE(g->bartlettCovariance);
    requireWithin3Sigma(g->sigma, 0.05 * kDeg, g->sigmaStdError, "sigma");
    requireWithin3Sigma(g->tau, 0.5, g->tauStdError, "tau");
    CHECK_NOTHROW(ImuErrorModel::fromString(id.modelYaml(), "gm.yaml"));
  }
}

TEST_CASE("kind gm on a white-dominated record: the ACF comparison may fail, the fit may not",
          "[identify][roundtrip]") {
  // White noise over a GM 100x smaller in sd: past lag 0 the sample ACF is estimation noise
  // (sd ~ sigma_w^2 / sqrt(n), 10x the GM's covariance), so its log-linear slope is positive in
  // about half of the records and the ACF GM fit (a comparison, not written) throws. Once that
  // failed the whole `fit --kind gm`. Over 8 seeds the chance that none throws is ~2^-8, so the
  // first CHECK shows the path was taken; the composite fit must succeed on every seed and keep
  // the white density (6e4 samples: relative sd of N ~ 0.3 %; 5 % is > 10 sd).
  const double N = 0.3 * kDegPerSqrtH;
  int comparisonsMissing = 0;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    INFO("seed " << seed);
    const Record r = staticRecord(
        "gyro: {x: [{type: white, density: 0.3 deg/sqrt(h)}, "
        "{type: gauss_markov, sigma: 0.0005 deg/s, tau: 20 s}]}",
        100.0, 600.0, seed);
    IdentifyOptions o;
    o.kind = IdentifyKind::Gm;
    const auto id = identify(r, o);
    const auto& ax = id.axis("gx");
    if (!ax.gaussMarkov) ++comparisonsMissing;
    REQUIRE(ax.written.latent);
    CHECK(std::fabs(ax.written.latent->model.white - N) <= 0.05 * N);
    CHECK_NOTHROW(ImuErrorModel::fromString(id.modelYaml(), "gm.yaml"));
  }
  CHECK(comparisonsMissing >= 1);
}

TEST_CASE("kind gm on carried increment quantization writes the increment LSB beside white + GM",
          "[identify][roundtrip]") {
  // A gyro whose angle increments are rounded to 0.0005 deg with the remainder carried (a rate
  // lattice of 0.05 deg/s at 100 Hz, as coarse as the white noise's 0.05 deg/s per sample).
  // `--kind gm` had no quantization among its sets: it wrote the lattice as each sample rounded, or
  // (on accelerometers as coarse as their noise) nothing, the model's ADEV then 0.33x the record's
  // at one sample. Now the increment LSB is written, exact, and the model's ADEV at one sample
  // and at every octave tau up to 10 s is within 15 % of the record's (its own estimate's
  // scatter there is ~1-5 %).
  const double lsb = 0.0005 * kDeg;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    INFO("seed " << seed);
    const Record r = staticRecord(
        "gyro: {x: [{type: white, density: 0.3 deg/sqrt(h)}, "
        "{type: gauss_markov, sigma: 20 deg/h, tau: 30 s}, "
        "{type: quantization, lsb: 0.0005 deg, carry: yes}]}",
        100.0, 1200.0, seed);
    IdentifyOptions o;
    o.kind = IdentifyKind::Gm;
    const auto id = identify(r, o);
    const auto& ax = id.axis("gx");
    REQUIRE(ax.written.latent);
    const auto& m = ax.written.latent->model;
    INFO("terms " << m.termNames());
    CHECK(m.quantization > 0.0);
    CHECK(m.lattice.step == Approx(lsb).epsilon(1e-6));
    CHECK(m.gm.size() == 1);
    CHECK(ax.written.roundedRateLsb == 0.0);  // not also each sample rounded
    const auto& c = ax.allan;
    std::vector<double> tau;
    for (double t : c.tau)
      if (t <= 10.0) tau.push_back(t);
    const auto model = ax.modelAdev(tau);
    for (std::size_t i = 0; i < tau.size(); ++i) {
      INFO("tau " << tau[i] << " model " << model[i] << " record " << c.dev[i]);
      CHECK(model[i] / c.dev[i] == Approx(1.0).margin(0.15));
    }
    CHECK_NOTHROW(ImuErrorModel::fromString(id.modelYaml(), "gm.yaml"));
  }
}

TEST_CASE("paper's AR(5): MDL picks 5 on 1 h at 1 kHz, coefficients and sigma within bounds",
          "[identify][roundtrip][ar]") {
  // Gx of the paper's table at its own rate (1 kHz), driving sigma 0.020539 deg/s (the preset
  // scenarios/adis16355-ar5.yaml). 1 h = 3.6 M samples.
  const double sigma = 0.020539 * kDeg;
  const Record r = staticRecord(
      "gyro: {x: [{type: ar, a: [-1.0327, -0.34341, 0.037895, 0.19732, 0.14724], sigma: 0.020539 "
      "deg/s, rate: 1 kHz}]}",
      1000.0, 3600.0, 14);
  IdentifyOptions o;
  o.kind = IdentifyKind::Ar;
  o.maxOrder = 12;
  const auto id = identify(r, o);
  const auto& ax = id.axis("gx");
  REQUIRE(ax.ar);
  CHECK(ax.ar->mdlOrder == 5);
  REQUIRE(ax.written.ar);
  const auto& f = *ax.written.ar;
  REQUIRE(f.order == 5);
  // chi^2_5 0.999 quantile: 20.515
  CHECK(coefficientChi2(f, kGx) <= chiSquareQuantile(0.999, 5.0));
  requireWithin3Sigma(f.drivingVariance, sigma * sigma, f.drivingVarianceStdError, "E");
  CHECK(ax.written.arRate == 1000.0);

  // Auto picks the AR too (gain ~ 850; no term model predicts like it), with no slow term beside
  // it: there is none in the record.
  IdentifyOptions oa;
  oa.maxOrder = 12;
  const auto ida = identify(r, oa);
  CHECK(ida.axis("gx").kind == IdentifyKind::ArSlow);
  REQUIRE(ida.axis("gx").arSlow);
  CHECK(ida.axis("gx").arSlow->ar.fit.order == 5);
  REQUIRE(ida.axis("gx").written.latent);
  CHECK(ida.axis("gx").written.latent->terms.name() == "ar");

  // The model's predicted Allan curve against the measured one: ln ADEV has sd ~ 1/sqrt(2 edf);
  // every octave point within 4 of those (4 sigma: 20 points, a joint false-alarm chance < 0.2 %).
  const auto pred = ax.modelAdev(ax.allan.tau);
  for (std::size_t i = 0; i < ax.allan.size(); ++i) {
    INFO("tau " << ax.allan.tau[i] << " measured " << ax.allan.dev[i] << " model " << pred[i]
                << " edf " << ax.allan.edf[i]);
    CHECK(std::fabs(std::log(pred[i] / ax.allan.dev[i])) <= 4.0 / std::sqrt(2.0 * ax.allan.edf[i]));
  }
}

TEST_CASE("AR(5) defined at 100 Hz: recovered at its own rate", "[identify][roundtrip][ar]") {
  // The Ax polynomial run as a 100 Hz model in a 100 Hz IMU (2 h = 720 000 samples).
  const Record r = staticRecord(
      "accel: {x: [{type: ar, a: [-0.51552, -0.068261, -0.047218, -0.049565, -0.13655], sigma: "
      "3 mg, rate: 100 Hz}]}",
      100.0, 7200.0, 15);
  IdentifyOptions o;
  o.kind = IdentifyKind::Ar;
  o.maxOrder = 12;
  const auto id = identify(r, o);
  const auto& f = *id.axis("ax").written.ar;
  CHECK(id.axis("ax").ar->mdlOrder == 5);
  REQUIRE(f.order == 5);
  CHECK(coefficientChi2(f, kAx) <= chiSquareQuantile(0.999, 5.0));
  const double sigma = 3e-3 * 9.80665;
  requireWithin3Sigma(f.drivingVariance, sigma * sigma, f.drivingVarianceStdError, "E");
}

// `--kind ar` writes the AR alone. On white + random walk (the walk's ADEV K sqrt(tau/3) crosses
// the white's at sqrt(3) N / K = 62 s, inside the 2-h record) the AR is white noise at long tau,
// and the record leaves its 99 % band well before the last octave point: warned, with the ratio
// there (at the last point, 1311 s, white's N / sqrt(tau) over the walk's K sqrt(tau / 3) is
// sqrt(3) N / (K tau) = 0.048; measured 0.037, the point's estimate scattering by ~30 %). The AR(5)
// record at 100 Hz (no slow part) is not warned.
TEST_CASE("kind ar warns where the record's slow part is beyond the AR", "[identify][ar]") {
  IdentifyOptions o;
  o.kind = IdentifyKind::Ar;
  o.maxOrder = 12;
  auto arWarning = [](const Identification& id) {
    for (const auto& w : id.warnings)
      if (w.find("the AR model's ADEV is below the record's 99 % band") != std::string::npos) return w;
    return std::string();
  };
  const auto walk = identify(staticRecord("gyro: {x: [{type: white, density: 0.2 deg/sqrt(h)}, "
                                          "{type: random_walk, K: 20 deg/h/sqrt(h)}]}",
                                          100.0, 7200.0, 12),
                             o);
  const std::string w = arWarning(walk);
  INFO(w);
  REQUIRE_FALSE(w.empty());
  CHECK(w.rfind("gx: ", 0) == 0);
  const auto& ax = walk.axis("gx");
  const double ratio = ax.modelAdev({ax.allan.tau.back()})[0] / ax.allan.dev.back();
  CHECK(ratio < 0.1);
  CHECK(w.find("--kind ar+slow") != std::string::npos);

  const auto ar5 = identify(staticRecord("accel: {x: [{type: ar, a: [-0.51552, -0.068261, -0.047218, "
                                         "-0.049565, -0.13655], sigma: 3 mg, rate: 100 Hz}]}",
                                         100.0, 7200.0, 15),
                            o);
  CHECK(arWarning(ar5).empty());
}

TEST_CASE("AR(5) + random walk: auto writes AR(5) and the walk, fitted jointly", "[identify][roundtrip][composite]") {
  // Gx AR(5) at 1 kHz with driving sigma 1e-3 rad/s: long-tau white level
  // N_AR = sigma sqrt(dt) / |A(1)| = 4.98e-3 rad/sqrt(s); K = 9e-4 rad/s/sqrt(s) puts the ADEV
  // minimum at sqrt(3) N_AR / K ~ 10 s. 20 min record. The AR predicts the next sample far better
  // than any term model (its innovation is 1/850 of the variance): auto's AR branch, the AR with
  // the slow terms beside it (as --kind ar+slow); the walk must not be dropped.
  const double K = 9e-4;
  const double Kdeg = K / kDegPerHPerSqrtH;
  const Record r = staticRecord(
      "gyro: {x: [{type: ar, a: [-1.0327, -0.34341, 0.037895, 0.19732, 0.14724], sigma: " +
          std::to_string(1e-3 / kDeg) + " deg/s, rate: 1 kHz}, {type: random_walk, K: " +
          std::to_string(Kdeg) + " deg/h/sqrt(h)}]}",
      1000.0, 1200.0, 16);
  IdentifyOptions o;
  o.maxOrder = 10;
  const auto id = identify(r, o);
  const auto& ax = id.axis("gx");
  INFO(ax.written.notes.size() << " notes");
  for (const auto& d : ax.decision) INFO(d);
  REQUIRE(ax.kind == IdentifyKind::ArSlow);
  REQUIRE(ax.arSlow);
  REQUIRE(ax.written.latent);
  CHECK(ax.arSlow->ar.fit.order == 5);
  CHECK(coefficientChi2(ax.arSlow->ar.fit, kGx) <= chiSquareQuantile(0.999, 5.0));
  REQUIRE(ax.written.latent->terms.name() == "ar + random_walk");
  const auto& k = ax.written.latent->parameter("random_walk");
  requireWithin3Sigma(k.value, K, k.stdError, "K");
  const auto m = ImuErrorModel::fromString(id.modelYaml(), "composite.yaml");
  // The fit's spec is what the file says: the one reader gives back the same effects, their values
  // to the printed digits (9 significant; 5e-9 relative), and the writer the same text, comments
  // (the fit's provenance and uncertainties) included.
  const ErrorModelSpec spec = id.modelSpec();
  const ErrorModelSpec read = errorModelFromString(id.modelYaml(), "composite.yaml");
  CHECK(errorModelYaml(read) == id.modelYaml());
  REQUIRE(read.gyro.x.size() == spec.gyro.x.size());
  for (std::size_t i = 0; i < spec.gyro.x.size(); ++i) {
    CHECK(read.gyro.x[i].type == spec.gyro.x[i].type);
    CHECK(read.gyro.x[i].comments == spec.gyro.x[i].comments);
    for (const auto& p : spec.gyro.x[i].parameters)
      for (std::size_t k = 0; k < p.values.size(); ++k)
        CHECK(read.gyro.x[i].find(p.key)->values[k] ==
              Approx(p.values[k]).epsilon(5e-9).margin(1e-300));
  }
  CHECK(read.headerComments == spec.headerComments);
  // effect names read "gyro.x[i].<type>"
  const auto names = m.effectNames();
  auto has = [&](const std::string& type) {
    return std::any_of(names.begin(), names.end(), [&](const std::string& n) {
      return n.rfind("gyro.x", 0) == 0 && n.size() > type.size() &&
             n.compare(n.size() - type.size(), type.size(), type) == 0;
    });
  };
  CHECK(has(".ar"));
  CHECK(has(".random_walk"));
}

TEST_CASE("identify: bad options and records are InputErrors", "[identify][errors]") {
  const Record r = staticRecord("gyro: {x: [{type: white, density: 0.2 deg/sqrt(h)}]}", 100.0,
                                60.0, 1);
  IdentifyOptions o;
  o.axes = {"gq"};
  CHECK_THROWS_AS(identify(r, o), InputError);
  o.axes = {"ax"};  // not in the record
  CHECK_THROWS_WITH(identify(r, o), Catch::Contains("not in the record"));
  o.axes = {};
  o.skipStart = 100.0;
  CHECK_THROWS_WITH(identify(r, o), Catch::Contains("beyond the record"));
  o.skipStart = 0.0;
  o.arOnDenoised = true;
  CHECK_THROWS_AS(identify(r, o), InputError);
  o.denoise = DenoiseChoice::Db5;  // denoised, but the paper's literal AR is a --kind ar option
  CHECK_THROWS_WITH(identify(r, o), Catch::Contains("--kind ar option, got --kind auto"));
  o.denoise = DenoiseChoice::None;
  o.arOnDenoised = false;
  o.order = 0;
  CHECK_THROWS_AS(identify(r, o), InputError);
  CHECK_THROWS_AS(identifyKindByName("arma"), InputError);
  CHECK_THROWS_WITH(orderCriterionByName("hq"), Catch::Contains("known: mdl"));
  Record shortRec = staticRecord("gyro: {x: [{type: white, density: 0.2 deg/sqrt(h)}]}", 100.0,
                                 0.3, 1);
  CHECK_THROWS_WITH(identify(shortRec, {}), Catch::Contains("too short"));
}

TEST_CASE("ar+slow: AR(5) + random walk and AR(5) + slow GM, written as effects the simulator runs",
          "[identify][roundtrip][ar_slow]") {
  // The paper's gx AR(5) at its 1 kHz (slowest poles 0.982: 1/e time ~55 ms), driving sigma
  // 1e-3 rad/s: A(1) = 6.345e-3, long-tau white level N_AR = sigma sqrt(dt) / |A(1)| = 5.0e-3
  // rad/sqrt(s). 20 min records made by the simulator's plug-ins (not the fit's closed forms).
  // Slow terms: K = 1e-3 rad/s/sqrt(s) (the walk crosses the AR's white level at
  // sqrt(3) N_AR / K ~ 9 s, 160 T_c and 3.7 octaves below tau_max = 120 s); a GM of sigma
  // 2.5e-3 rad/s, tau 20 s (hump ~0.4 sigma^2 at ~40 s, ~4x the AR's level there).
  const double sigmaE = 1e-3;
  const std::string ar = "{type: ar, a: [-1.0327, -0.34341, 0.037895, 0.19732, 0.14724], sigma: " +
                         std::to_string(sigmaE / kDeg) + " deg/s, rate: 1 kHz}";
  struct Case { std::string slow, terms, param; double truth; };
  const double K = 1e-3, s = 2.5e-3;
  const std::vector<Case> cases{
      {"{type: random_walk, K: " + std::to_string(K / kDegPerHPerSqrtH) + " deg/h/sqrt(h)}",
       "ar + random_walk", "random_walk", K},
      {"{type: gauss_markov, sigma: " + std::to_string(s / kDeg) + " deg/s, tau: 20 s, rate: 1 kHz}",
       "ar + gm", "gm1.sigma", s}};
  for (const auto& c : cases) {
    INFO(c.terms);
    const Record r = staticRecord("gyro: {x: [" + ar + ", " + c.slow + "]}", 1000.0, 1200.0, 23);
    IdentifyOptions o;
    o.kind = IdentifyKind::ArSlow;
    o.maxOrder = 10;
    const auto id = identify(r, o);
    const auto& ax = id.axis("gx");
    REQUIRE(ax.arSlow);
    REQUIRE(ax.written.latent);
    CHECK(ax.arSlow->ar.fit.order == 5);
    CHECK(coefficientChi2(ax.arSlow->ar.fit, kGx) <= chiSquareQuantile(0.999, 5.0));
    REQUIRE(ax.written.latent->terms.name() == c.terms);
    const auto& p = ax.written.latent->parameter(c.param);
    requireWithin3Sigma(p.value, c.truth, p.stdError, c.param.c_str());
    requireWithin3Sigma(ax.written.latent->parameter("ar.sigma").value, sigmaE,
                        ax.written.latent->parameter("ar.sigma").stdError, "ar.sigma");
    // The AR alone (Burg's E) falls short of the record at the longest fitted tau, by more than
    // the Allan estimate's 99 % band (the slow term's share there); the joint model does not.
    const auto& f = ax.arSlow->joint;
    const std::size_t last = f.m.size() - 1;
    const double edf = fit::edfOverlappingWhite(f.samples, f.m[last]);  // white EDF: the
    // narrowest band; the joint model must sit inside even that, the AR alone outside
    const double lo = f.avar[last] * edf / chiSquareQuantile(0.995, edf);
    const double hi = f.avar[last] * edf / chiSquareQuantile(0.005, edf);
    CHECK(ax.arSlow->arOnlyAvar[last] < lo);
    // The written model: the one reader gives the same effects back and the simulator builds
    // them (an `ar` effect and the slow term's, on gyro.x).
    const ErrorModelSpec read = errorModelFromString(id.modelYaml(), "ar_slow.yaml");
    CHECK(errorModelYaml(read) == id.modelYaml());
    REQUIRE(read.gyro.x.size() == 2);
    CHECK(read.gyro.x[0].type == "ar");
    CHECK(read.gyro.x[1].type == (c.param == "random_walk" ? "random_walk" : "gauss_markov"));
    const auto m = ImuErrorModel::fromString(id.modelYaml(), "ar_slow.yaml");
    CHECK(m.effectNames().size() == 2);
    (void)hi;
  }
}

TEST_CASE("a gyro record in deg/s read as rad/s is named, a plausible one is not", "[identify][units]") {
  // ADIS16405 run 1 read without --gyro-unit: means 0.43, -0.40, -0.26 and sample sd ~0.37 per
  // axis, deg/s taken for rad/s (a gyro of 20 deg/s noise and a 37 deg/s offset). Made here as
  // white of 0.037 "rad/s/sqrt(Hz)" (sd 0.37 at 100 Hz) and biases of that size; the same record
  // scaled to rad/s (white 0.037 deg/s/sqrt(Hz), biases in deg/s) draws no warning.
  auto warned = [](const std::string& unit) {
    const std::string model = "gyro:\n  all: [{type: white, density: 0.037 " + unit + "/sqrt(Hz)}]\n" +
                              "  x: [{type: bias, value: 0.43 " + unit + "}]\n  y: [{type: bias, value: -0.40 " +
                              unit + "}]\n  z: [{type: bias, value: -0.26 " + unit + "}]\n";
    const Record r = staticRecord(model, 100.0, 600.0, 5);
    IdentifyOptions o;
    o.kind = IdentifyKind::Gm;
    const auto id = identify(r, o);
    for (const std::string& w : id.warnings)
      if (w.find("did you forget --gyro-unit deg/s?") != std::string::npos) return w;
    return std::string();
  };
  const std::string w = warned("rad/s");
  INFO(w);
  CHECK(w.find("gyro mean |w| = 0.64") != std::string::npos);  // |(0.43, -0.40, -0.26)| = 0.642
  CHECK(warned("deg/s").empty());
}

namespace {
// The simulator's sinusoid (0.05 deg/s at 7.3 Hz, interval means at 100 Hz: 0.9913 of it) on gx
// beside white noise of 0.3 deg/s per sample on every gyro.
const std::string kLineModel =
    "gyro:\n  all: [{type: white, density: 0.03 deg/s/sqrt(Hz)}]\n"
    "  x: [{type: sinusoid, amplitude: 0.05 deg/s, frequency: 7.3 Hz, phase: 40 deg}]\n";

/// The fit's warnings that hold `what`.
std::vector<std::string> warningsOf(const Identification& id, const std::string& what) {
  std::vector<std::string> out;
  for (const std::string& w : id.warnings)
    if (w.find(what) != std::string::npos) out.push_back(w);
  return out;
}
std::vector<std::string> lineWarnings(const Identification& id) { return warningsOf(id, "narrow line"); }
}  // namespace

TEST_CASE("a vibration line left in the record is warned, with its frequency and size", "[identify][lines]") {
  const Record r = staticRecord(kLineModel, 100.0, 1200.0, 8);
  IdentifyOptions o;
  o.kind = IdentifyKind::Latent;
  o.fitLines = false;
  const auto id = identify(r, o);
  const auto lines = lineWarnings(id);
  REQUIRE(lines.size() == 1);
  INFO(lines[0]);
  CHECK(lines[0].rfind("gx: a narrow line at 7.3", 0) == 0);
  // The coherent amplitude, sized on the whole record as `diagnose` and the default fit do: the
  // 0.05 deg/s line averaged over a sample (sinc(pi f dt) = 0.9913), within 4 sd (0.0012 deg/s).
  const std::size_t at = lines[0].find("amplitude ");
  REQUIRE(at != std::string::npos);
  const double a = std::stod(lines[0].substr(at + 10));  // deg/s
  CHECK(a == Approx(0.05 * 0.9913).margin(4 * 0.0012));
  CHECK(lines[0].find("its band") == std::string::npos);  // a pure line: no broadening said
  CHECK(id.axis("gx").written.lines.empty());
}

// A vibration whose phase wanders (a random walk of 0.02 rad per sample: 48 rad^2 over the 1200 s,
// a linewidth of 0.0064 Hz, inside one Welch bin): the bin holds the whole line's power, A^2 / 2,
// while a sinusoid fitted on the whole record catches only its coherent part. The warning gives
// both, as the ADIS16405's 0.56 Hz vibration showed them (0.41 and 0.86 mg on ax).
TEST_CASE("a broadened line is warned with its coherent amplitude and its band's", "[identify][lines]") {
  Record r = staticRecord("gyro:\n  all: [{type: white, density: 0.03 deg/s/sqrt(Hz)}]\n", 100.0, 1200.0, 8);
  const double A = 0.05 * M_PI / 180;  // rad/s
  std::mt19937_64 gen(21);
  std::normal_distribution<double> step(0.0, 0.02);
  double phase = 0.3;
  for (std::size_t k = 0; k < r.rows; ++k, phase += step(gen))
    r.gyro[0][k] += A * std::sin(2 * M_PI * 7.3 * double(k) / 100.0 + phase);
  IdentifyOptions o;
  o.kind = IdentifyKind::Latent;
  o.fitLines = false;
  const auto lines = lineWarnings(identify(r, o));
  REQUIRE(lines.size() == 1);
  INFO(lines[0]);
  const std::size_t at = lines[0].find("amplitude "), band = lines[0].find("and its band ");
  REQUIRE(at != std::string::npos);
  REQUIRE(band != std::string::npos);
  const double coherent = std::stod(lines[0].substr(at + 10)), whole = std::stod(lines[0].substr(band + 13));
  CHECK(whole == Approx(0.05).epsilon(0.2));  // the bin's power: Hann scalloping is at most 16 % low
  CHECK(coherent < 0.7 * whole);
}

// Fitted (the default): the line is written as a sinusoid and taken out before the noise terms,
// which then see white noise alone. The estimates' sd from N = 120000 samples of sd 0.3 deg/s:
// amplitude 0.3 sqrt(2 / N) = 0.0012 deg/s (bound: 4 sd), frequency sqrt(6 / N^3) sd / (pi A dt)
// ~ 1e-5 Hz (bound 1e-3), phase sd / A sqrt(2 / N) = 0.025 rad (bound 0.15); the white density's
// ~0.2 % (bound 1 %).
TEST_CASE("a vibration line is fitted as a sinusoid and taken out before the noise terms", "[identify][lines]") {
  const Record r = staticRecord(kLineModel, 100.0, 1200.0, 8);
  IdentifyOptions o;
  o.kind = IdentifyKind::Latent;
  const auto id = identify(r, o);
  const auto lines = lineWarnings(id);
  REQUIRE(lines.size() == 1);
  INFO(lines[0]);
  CHECK(lines[0].rfind("gx: a narrow line at 7.3", 0) == 0);
  CHECK(lines[0].find("written as a sinusoid") != std::string::npos);
  const auto& gx = id.axis("gx");
  REQUIRE(gx.written.lines.size() == 1);
  const FittedLine& l = gx.written.lines[0];
  CHECK(l.frequency == Approx(7.3).margin(1e-3));
  CHECK(l.amplitude * 180 / M_PI == Approx(0.05).margin(4 * 0.0012));
  CHECK(std::remainder(l.phase - 40 * M_PI / 180, 2 * M_PI) == Approx(0).margin(0.15));
  REQUIRE(gx.written.latent);
  CHECK(gx.written.latent->terms.name() == "white");
  const double density = gx.written.latent->model.white * 180 / M_PI;
  CHECK(density == Approx(0.03).epsilon(0.01));
  // The model file holds the line; the model's Allan curve holds it too (a sinusoid's Allan
  // variance peaks near tau = 0.37 / f at 0.52 A^2: 0.05 s here, above the white noise's).
  const auto spec = id.modelSpec();
  const auto& xs = spec.sensor(Sensor::gyro).x;
  CHECK(std::count_if(xs.begin(), xs.end(), [](const EffectSpec& e) { return e.type == "sinusoid"; }) == 1);
  const auto withLine = gx.modelAdev({0.05});
  auto noLine = gx;
  noLine.written.lines.clear();
  const double w2 = noLine.modelAdev({0.05})[0] * noLine.modelAdev({0.05})[0];
  CHECK(withLine[0] * withLine[0] - w2 == Approx(sinusoidAllanVariance(l.amplitude, l.frequency, 0.05)).epsilon(1e-9));
  // Nothing on the clean channels.
  CHECK(id.axis("gy").written.lines.empty());
  CHECK(id.axis("gz").written.lines.empty());
}

// The Allan variance of a sinusoid (line_fit.hpp) against the overlapping estimator on its interval
// means, over many periods: within 1 %.
TEST_CASE("a sinusoid's Allan variance in closed form matches the estimator", "[identify][lines]") {
  const double A = 2.0, f = 1.37, dt = 0.01;
  const std::size_t N = 200000;
  std::vector<double> y(N);
  for (std::size_t k = 0; k < N; ++k)  // interval means of A sin(2 pi f t + 0.3)
    y[k] = A / (2 * M_PI * f * dt) * (std::cos(2 * M_PI * f * k * dt + 0.3) - std::cos(2 * M_PI * f * (k + 1) * dt + 0.3));
  AllanOptions ao;
  ao.grid = TauGrid::Octave;
  const auto c = allanDeviation(y, 1 / dt, AllanVariant::Overlapping, ao);
  for (std::size_t i = 0; i < c.tau.size() && c.tau[i] < 20; ++i) {
    INFO("tau " << c.tau[i]);
    CHECK(c.dev[i] * c.dev[i] == Approx(sinusoidAllanVariance(A, f, c.tau[i])).epsilon(0.01).margin(1e-6 * A * A));
  }
}

// The fit's line test on long records (identify_lines.cpp: segments of N / 16 where that is longer
// than the diagnosis's 4096): 2^20 samples at 1 kHz, 65536-sample segments, tested from 0.18 Hz.
// Null records (each a false line at p < 1e-3, look-elsewhere corrected: expected <= 0.1 per
// class): 60 white, 30 Gauss-Markov (tau 0.02-20 s, 10x the white's variance), 30 random walks
// beside white noise. A line at 0.5 Hz, below the 4096-sample test's 2.9 Hz, of amplitude 0.05 x
// the white sd, is found in 10 of 10 (its power against the noise in one 0.015 Hz bin: ~40x).
TEST_CASE("the fit's line test on a long record: no line in noise, a line below 3 Hz found", "[identify][lines]") {
  const std::size_t n = std::size_t(1) << 20;
  const double rate = 1000;
  auto white = [&](std::mt19937_64& g) {
    std::normal_distribution<double> N01;
    std::vector<double> x(n);
    for (double& v : x) v = N01(g);
    return x;
  };
  auto demean = [](std::vector<double> x) {
    double m = 0;
    for (double v : x) m += v / double(x.size());
    for (double& v : x) v -= m;
    return x;
  };
  int falseWhite = 0, falseGm = 0, falseWalk = 0, found = 0;
  for (int s = 0; s < 60; ++s) {
    std::mt19937_64 g(7000 + s);
    falseWhite += int(detail::recordLines(demean(white(g)), rate).size());
  }
  for (int s = 0; s < 30; ++s) {
    std::mt19937_64 g(7100 + s);
    const double tau = 0.02 * std::pow(1000.0, s / 29.0), phi = std::exp(-1 / (rate * tau));
    std::vector<double> x = white(g), e = white(g);
    double b = 0;
    for (std::size_t k = 0; k < n; ++k) b = phi * b + std::sqrt(10 * (1 - phi * phi)) * e[k], x[k] += b;
    falseGm += int(detail::recordLines(demean(x), rate).size());
  }
  for (int s = 0; s < 30; ++s) {
    std::mt19937_64 g(7200 + s);
    std::vector<double> x = white(g), e = white(g);
    double b = 0;
    for (std::size_t k = 0; k < n; ++k) b += 0.01 * e[k], x[k] += b;
    falseWalk += int(detail::recordLines(demean(x), rate).size());
  }
  for (int s = 0; s < 10; ++s) {
    std::mt19937_64 g(7300 + s);
    std::vector<double> x = white(g);
    for (std::size_t k = 0; k < n; ++k) x[k] += 0.05 * std::sin(2 * M_PI * 0.5 * double(k) / rate + s);
    const auto lines = detail::recordLines(demean(x), rate);
    found += int(std::count_if(lines.begin(), lines.end(),
                               [](const auto& l) { return std::fabs(l.welch.freq - 0.5) < 0.05; }));
  }
  INFO("false lines: white " << falseWhite << "/60, GM " << falseGm << "/30, walk " << falseWalk << "/30");
  CHECK(falseWhite <= 2);
  CHECK(falseGm <= 1);
  CHECK(falseWalk <= 1);
  CHECK(found == 10);
}

namespace {
const std::string kSettlingModel =
    "gyro:\n  all: [{type: white, density: 0.03 deg/s/sqrt(Hz)}, {type: gauss_markov, sigma: 0.01 deg/s, tau: 5 s}]\n"
    "  x: [{type: warmup, amplitude: 0.08 deg/s, tau: 60 s}]\n";

std::vector<std::string> settlingWarnings(const Identification& id) {
  return warningsOf(id, "starts with a settling");
}
}  // namespace

// A warm-up on gx only (0.08 deg/s decaying with tau 60 s beside a GM of 0.01 deg/s): fit warns on
// gx alone, with the time constant near 60 s and a --skip; with that skip the warning is gone and
// gx's written terms are the generator's white + GM (fit/start_settling.hpp; the test's statistics
// are test_fit [settling]).
TEST_CASE("a settling at the record start is warned with the skip that removes it", "[identify][settling]") {
  const Record r = staticRecord(kSettlingModel, 100.0, 1200.0, 5);
  IdentifyOptions o;
  o.kind = IdentifyKind::Gm;
  o.axes = {"gx", "gy", "gz"};
  const auto id = identify(r, o);
  const auto warned = settlingWarnings(id);
  REQUIRE(warned.size() == 1);
  INFO(warned[0]);
  CHECK(warned[0].rfind("gx: the record starts with a settling: 0.0", 0) == 0);
  const auto& gx = id.axis("gx");
  REQUIRE(gx.settling);
  CHECK(gx.settling->tau > 30.0);
  CHECK(gx.settling->tau < 120.0);
  CHECK(gx.settling->amplitude * 180 / M_PI > 0.04);
  CHECK(gx.settling->amplitude * 180 / M_PI < 0.16);
  const std::size_t at = warned[0].find("--skip ");
  REQUIRE(at != std::string::npos);
  const double skip = std::stod(warned[0].substr(at + 7));
  CHECK(skip >= gx.settling->settledAfter);
  CHECK(skip < 600.0);
  // The skip counts from the file's start: a record already cut at load by 20 s (as `--skip 20`
  // leaves it, Record::skipped_s) is told a skip 20 s longer than the same samples uncut.
  Record cut = r;
  cut.skipped_s = 20.0;
  const auto cutWarned = settlingWarnings(identify(cut, o));
  REQUIRE(cutWarned.size() == 1);
  CHECK(std::stod(cutWarned[0].substr(cutWarned[0].find("--skip ") + 7)) == Approx(skip + 20.0).margin(1.0));
  // --skip auto: the same fit again from where the settling has settled.
  IdentifyOptions automatic = o;
  automatic.skipAuto = true;
  const auto refit = identify(r, automatic);
  CHECK(double(refit.skipped) / r.rate_hz == Approx(gx.settling->settledAfter).margin(0.02));
  REQUIRE_FALSE(refit.warnings.empty());
  CHECK(refit.warnings[0].rfind("--skip auto: fitted from ", 0) == 0);
  REQUIRE(refit.axis("gx").written.latent);
  CHECK(refit.axis("gx").written.latent->terms.name() == "white + gm");
  o.skipStart = skip;
  const auto settled = identify(r, o);
  CHECK(settlingWarnings(settled).empty());
  REQUIRE(settled.axis("gx").written.latent);
  CHECK(settled.axis("gx").written.latent->terms.name() == "white + gm");
}

// Below the fit's Welch reach (12 rate / L; 0.29 Hz at 100 Hz with 4096-sample segments), a line
// is found on the whole record's periodogram (stats/spectral_lines.hpp, lowLineTest) at a
// look-elsewhere p < 1e-6. Null records of 20 min at 100 Hz, 40 per class: white; white + a GM
// of 30x its variance whose corner 1 / (2 pi tau) sweeps the scanned band (12 to 400 cycles per
// record); white + a random walk; white + six GMs a decade apart (tau 0.1 s - 10^4 s, a flicker's
// 1/f). Each record's false-line chance is 1e-6 by the test's own law (its largest over the 160
// was p 0.008 while calibrating): none allowed.
TEST_CASE("the fit's line test below the Welch bins finds no line in red noise", "[identify][lines]") {
  const std::size_t n = 120000;
  const double rate = 100, T = double(n) / rate;
  std::mt19937_64 g(9000);
  auto white = [&] {
    std::normal_distribution<double> N01;
    std::vector<double> x(n);
    for (double& v : x) v = N01(g);
    return x;
  };
  int falseLines[4] = {0, 0, 0, 0};
  double smallestP = 1;
  auto count = [&](int cls, const std::vector<double>& x) {
    const LowLine l = lowLineTest(x, rate, 4096, 12);
    smallestP = std::min(smallestP, l.p);
    falseLines[cls] += int(l.p < 1e-6);
  };
  for (int s = 0; s < 40; ++s) {
    count(0, white());
    std::vector<double> gm = white(), e = white();
    const double tau = T / (2 * M_PI * 12) / std::pow(30.0, s / 39.0), phi = std::exp(-1 / (rate * tau));
    double b = 0;
    for (std::size_t k = 0; k < n; ++k) b = phi * b + std::sqrt(30 * (1 - phi * phi)) * e[k], gm[k] += b;
    count(1, gm);
    std::vector<double> walk = white();
    b = 0;
    for (std::size_t k = 0; k < n; ++k) b += 0.03 * e[k], walk[k] += b;
    count(2, walk);
    std::vector<double> flicker = white();
    for (int q = 0; q < 6; ++q) {
      const double ph = std::exp(-1 / (rate * std::pow(10.0, q - 1.0)));
      const std::vector<double> eq = white();
      double bq = 0;
      for (std::size_t k = 0; k < n; ++k) bq = ph * bq + std::sqrt(1 - ph * ph) * eq[k], flicker[k] += bq;
    }
    count(3, flicker);
  }
  INFO("false low lines: white " << falseLines[0] << ", GM " << falseLines[1] << ", walk " << falseLines[2]
                                 << ", flicker " << falseLines[3] << " of 40 each; smallest p " << smallestP);
  CHECK(falseLines[0] + falseLines[1] + falseLines[2] + falseLines[3] == 0);
  CHECK(smallestP > 1e-4);
}

// A slow line (0.05 Hz: 60 cycles in 20 min, below the fit's Welch reach of 0.29 Hz) of 0.1 x the
// white sd beside a GM (tau 5 s) whose variance is 1/4.5 of the line's: taken out as a sinusoid,
// frequency within 1e-4 Hz (its sd ~ sqrt(6) sd / (pi A sqrt(N) T) = 2e-5 Hz), amplitude within 4
// sd (sd sqrt(2 / N) 0.3 deg/s = 0.0012 deg/s), and the GM left to the noise terms (left in, the
// line took its place: a GM at the line's period, 3.3 s, sigma 0.023 deg/s). Six seeds.
TEST_CASE("a slow line below the Welch bins is taken out and the GM beside it fitted", "[identify][lines]") {
  const std::string model =
      "gyro:\n  all: [{type: white, density: 0.03 deg/s/sqrt(Hz)}, {type: gauss_markov, sigma: 0.01 deg/s, tau: 5 s}]\n"
      "  x: [{type: sinusoid, amplitude: 0.03 deg/s, frequency: 0.05 Hz, phase: 10 deg}]\n";
  int found = 0, gmRight = 0;
  for (int seed = 1; seed <= 6; ++seed) {
    const Record r = staticRecord(model, 100.0, 1200.0, std::uint64_t(seed));
    IdentifyOptions o;
    o.kind = IdentifyKind::Gm;
    const auto id = identify(r, o);
    const auto& gx = id.axis("gx");
    INFO("seed " << seed);
    REQUIRE(gx.written.lines.size() <= 1);
    if (gx.written.lines.size() == 1) {
      const FittedLine& l = gx.written.lines[0];
      CHECK(l.frequency == Approx(0.05).margin(1e-4));
      CHECK(l.amplitude * 180 / M_PI == Approx(0.03).margin(4 * 0.0012));
      found += int(std::fabs(l.frequency - 0.05) < 1e-4);
    }
    REQUIRE(gx.written.latent);
    const auto& m = gx.written.latent->model;
    if (m.gm.size() == 1) {
      INFO("GM sigma " << m.gm[0].sigma * 180 / M_PI << " deg/s, tau " << m.gm[0].tau << " s");
      gmRight += int(m.gm[0].tau > 2.5 && m.gm[0].tau < 10 && m.gm[0].sigma * 180 / M_PI > 0.007 &&
                     m.gm[0].sigma * 180 / M_PI < 0.014);
    }
    CHECK(id.axis("gy").written.lines.empty());
  }
  CHECK(found == 6);
  CHECK(gmRight >= 5);
}

// A record on a lattice far coarser than its noise: white noise of sd 1 beside a slow GM (sd
// 0.012, tau 3.6 s), 500 Hz, 800 s, rounded to a lattice of 5 (98 % of the samples on one level:
// the diagnosis challenge's quantization of 5 sd). The rounding's simulated excess covariance
// (latticeExcess) is negative at some points; beside a trial model below the record there, the
// sum was no covariance and every fit failed ("zero modelled Allan variance") on 6 of 6 such
// records. Now each kind fits, and the white density it writes is within a factor 2 of what the
// rounded record shows at one sample (its Allan deviation at dt).
TEST_CASE("a record on a lattice five times coarser than its noise is fitted", "[identify][lattice]") {
  const double rate = 500;
  const std::size_t n = 400000;
  const double phi = std::exp(-1 / (rate * 3.6));
  for (int seed = 0; seed < 3; ++seed) {
    std::mt19937_64 g(4200 + seed);
    std::normal_distribution<double> N01;
    Record r;
    r.source = "coarse-lattice";
    r.rate_hz = rate;
    r.rows = n;
    std::vector<double> x(n);
    double b = 0;
    for (double& v : x) {
      b = phi * b + 0.012 * std::sqrt(1 - phi * phi) * N01(g);
      v = 5.0 * std::round((N01(g) + b + 0.3) / 5.0);
    }
    const double onLevel = double(std::count(x.begin(), x.end(), 0.0)) / double(n);
    INFO("seed " << seed << ", share on one level " << onLevel);
    CHECK(onLevel > 0.95);
    r.gyro[0] = x;
    for (IdentifyKind kind : {IdentifyKind::Gm, IdentifyKind::Latent, IdentifyKind::Auto}) {
      IdentifyOptions o;
      o.kind = kind;
      std::optional<Identification> id;
      REQUIRE_NOTHROW(id = identify(r, o));
      const auto& gx = id->axis("gx");
      const double adev1 = gx.allan.dev.front();  // at tau = dt
      const double written = gx.modelAdev({1 / rate})[0];
      CHECK(written == Approx(adev1).epsilon(0.5));
    }
  }
}

// White noise behind a low-pass filter (a 4-sample moving average, as a decimating sensor's) with
// a random walk: no start from the first Allan point fits, the scanned start leaves the short end
// to the white noise, and the model is extrapolated there above the record (at tau = dt the
// moving average keeps a quarter of the white noise's ADEV). The fit says so, with the ratio; the
// same record unfiltered starts at the first point and says nothing.
TEST_CASE("a model extrapolated below its scanned start is warned with its ratio to the record",
          "[identify][latent]") {
  const double rate = 100.0;
  for (std::uint64_t seed = 61; seed < 64; ++seed) {
    const Record plain = staticRecord(
        "gyro: {x: [{type: white, density: 0.3 deg/sqrt(h)}, {type: random_walk, K: 3 deg/h/sqrt(h)}]}", rate,
        1200.0, seed);
    Record filtered = plain;
    const std::vector<double>& x = plain.gyro[0];
    for (std::size_t k = 3; k < x.size(); ++k) filtered.gyro[0][k] = 0.25 * (x[k] + x[k - 1] + x[k - 2] + x[k - 3]);
    for (IdentifyKind kind : {IdentifyKind::Gm, IdentifyKind::Latent}) {
      IdentifyOptions o;
      o.kind = kind;
      o.axes = {"gx"};
      const auto f = identify(filtered, o);
      const auto p = identify(plain, o);
      const auto warned = warningsOf(f, "below the fitted range");
      INFO("seed " << seed << (kind == IdentifyKind::Gm ? " gm" : " latent") << ": filtered fitted from "
                   << f.axis("gx").latent->tau.front() << " s, "
                   << f.axis("gx").modelAdev({1 / rate})[0] / f.axis("gx").allan.dev.front()
                   << "x the record at dt");
      CHECK(f.axis("gx").latent->tau.front() > 1.5 / rate);
      REQUIRE(warned.size() == 1);
      CHECK(warned[0].find("falls below the fitted terms") != std::string::npos);
      CHECK(warningsOf(p, "below the fitted range").empty());
    }
  }
}

// A record too short for auto's Allan-term description (fewer than 7 octave points: 300 samples
// give 5) was refused by --kind auto ("fewer than 7 Allan points") while gm and latent fit it.
// Now auto fits it the same way: white noise, its density within 3 sigma, on 5 seeds.
namespace {
/// identify(r) of gx alone with `kind`, required not to throw.
Identification identifyGx(const Record& r, IdentifyKind kind) {
  IdentifyOptions o;
  o.kind = kind;
  o.axes = {"gx"};
  std::optional<Identification> id;
  REQUIRE_NOTHROW(id = identify(r, o));
  return *id;
}
}  // namespace

TEST_CASE("auto fits a record too short for the Allan-term description", "[identify][roundtrip]") {
  for (std::uint64_t seed = 71; seed < 76; ++seed) {
    const Record r = staticRecord("gyro: {x: [{type: white, density: 0.3 deg/sqrt(h)}]}", 100.0, 3.0, seed);
    const Identification id = identifyGx(r, IdentifyKind::Auto);
    const auto& gx = id.axis("gx");
    INFO("seed " << seed);
    REQUIRE(gx.written.latent);
    CHECK(gx.written.latent->terms.name() == "white");
    requireWithin3Sigma(gx.written.latent->model.white, 0.3 * kDegPerSqrtH, gx.written.latent->parameter("white").stdError,
                        "N");
  }
}

// The AR + slow-terms fit takes an interior minimum of the record's ADEV for the start of a long-tau
// rise (a random walk's) and gives Burg the record minus a level smoothed there. Two ADEV minima
// are no such rise, from null records of the challenge generators: an AR whose poles oscillate
// (AR(5) at 500 Hz) has one of its own at tau = 2 dt, and white noise beside a slow AR pole (0.97
// at 125 Hz) has one before the AR's hump, which falls again. Smoothed there, Burg saw the record
// high-passed: AR(20), 1.6x the record at one sample, or an AR(20) + GM whose diagnosis named
// `white`. A level is now taken out only for a rise that lasts to the longest tau and a smoother
// much slower than the AR it leaves (tau_min >= 10 T_c).
TEST_CASE("auto and ar+slow keep an AR whose ADEV has a minimum of its own", "[identify]") {
  const struct {
    const char* truth;
    double rate;
  } cases[] = {
      {"gyro: {x: [{type: ar, a: [0.35816, -0.60131, 0.03282, 0.49693, 0.15315], sigma: 0.02 rad/s, rate: 500 Hz}]}",
       500.0},
      {"gyro: {x: [{type: white, density: 1e-4 rad/s/sqrt(Hz)}, {type: ar, a: [-1.61746, 0.62752], sigma: 1.07e-4 rad/s, "
       "rate: 125 Hz}]}",
       125.0}};
  for (const auto& c : cases)
    for (std::uint64_t seed = 81; seed < 84; ++seed)
      for (auto kind : {IdentifyKind::Auto, IdentifyKind::ArSlow}) {
        INFO(c.truth << ", seed " << seed << ", kind " << toString(kind));
        const Record r = staticRecord(c.truth, c.rate, 400000 / c.rate, seed);
        const Identification id = identifyGx(r, kind);
        const auto& gx = id.axis("gx");
        REQUIRE(gx.written.latent);
        CHECK(gx.written.latent->model.arPolynomial.size() - 1 < 20);
        // the model's ADEV against the record's over the octaves to 1 s: within 5 %
        const std::vector<double> tau(gx.allan.tau.begin(), gx.allan.tau.begin() + std::ptrdiff_t(std::log2(c.rate)) + 1);
        const auto model = gx.modelAdev(tau);
        for (std::size_t i = 0; i < tau.size(); ++i) {
          INFO("tau " << tau[i] << " s");
          CHECK(std::fabs(std::log(model[i] / gx.allan.dev[i])) < std::log(1.05));
        }
      }
}

// A noiseless ramp has no stable AR (Burg's reflection coefficient reaches 1): --kind auto
// refused it ("the polynomial is not stable") while gm and latent fit it. Auto now writes the
// latent terms there, as latent does, with the reason in the model's notes.
TEST_CASE("auto writes the latent terms where the record has no stable AR", "[identify]") {
  Record r;
  r.source = "ramp";
  r.rate_hz = 100.0;
  r.rows = 20000;
  r.gyro[0].resize(r.rows);
  for (std::size_t k = 0; k < r.rows; ++k) r.gyro[0][k] = 1e-6 * double(k);
  const Identification id = identifyGx(r, IdentifyKind::Auto);
  const auto& gx = id.axis("gx");
  CHECK(gx.kind == IdentifyKind::Latent);
  REQUIRE(gx.written.latent);
  CHECK(identifyGx(r, IdentifyKind::Latent).axis("gx").written.latent->terms.name() ==
        gx.written.latent->terms.name());
  CHECK(id.modelYaml().find("auto: no AR") != std::string::npos);
}

// The Allan variance holds a drift's square (R^2 tau^2 / 2), not its sign: every fit wrote a
// ramp rising whichever way the record drifted, so a model fitted to a falling record drifted
// the other way in simulation, and the diagnosis of the same record found the record's drift
// twice the model's, reversed (challenge null records, docs/fitting-log.md). The written ramp
// takes the record's least-squares trend's sign; its size stays the fit's.
TEST_CASE("a fitted ramp has the sign of the record's trend", "[identify]") {
  const double R = 2000.0;  // deg/h^2: ~14x the white noise's ADEV at tau = 120 s
  for (const double sign : {-1.0, 1.0})
    for (const IdentifyKind kind : {IdentifyKind::Latent, IdentifyKind::Allan, IdentifyKind::Auto})  // gm: no drift
      for (std::uint64_t seed = 81; seed < 84; ++seed) {
        const Record r = staticRecord("gyro: {x: [{type: white, density: 0.3 deg/sqrt(h)}, {type: ramp, slope: " +
                                          std::to_string(sign * R) + " deg/h/h}]}",
                                      100.0, 1200.0, seed);
        const ErrorModelSpec spec = identifyGx(r, kind).modelSpec();
        const EffectSpec* ramp = nullptr;
        for (const auto& e : spec.gyro.x)
          if (e.type == "ramp") ramp = &e;
        INFO("kind " << int(kind) << ", true slope " << sign * R << " deg/h^2, seed " << seed);
        REQUIRE(ramp);
        REQUIRE(ramp->find("slope"));
        const double slope = ramp->find("slope")->values.at(0) * 3600.0 * 3600.0 / kDeg;
        CHECK(slope * sign > 0.0);
        CHECK(std::fabs(slope - sign * R) < 0.2 * R);
      }
}

// White noise beside a GM per decade (the alternative challenge generator's flicker; 0.034 s to
// 883 s at 125 Hz, 3200 s): Burg's AR(20) holds some of the slow GMs' power, so the AR + slow-terms
// fit scanned its start up to ~1 s and set the AR's driving variance there, 0.31-0.35x the record's
// ADEV at one sample, while the latent terms, though not consistent (chi2 46-56 / 9-10 dof), were
// within 1.2-1.3x at every point. Auto now writes the terms where they are within 25 %, or half as
// far off (in ln) at their worst as the AR branch. Rate over 10 seeds: the written model within
// 1.5x of the record at every octave point in >= 8 (before: 5; then 9, the tenth AR + slow terms
// at 2.35x, its whole-range terms 1.7x), and never 3x off (before: 3.03x and 3.22x). Where the
// whole-range terms fail that test, the terms from a scanned start (as --kind latent) are tried
// the same way: seed 2 (the AR branch at 2.35x) is now those terms, 1.12x at worst, and every
// seed is within 1.5x (the worst 1.44x).
TEST_CASE("auto writes the terms where its AR branch is further off the record than they are", "[identify]") {
  const std::string truth =
      "gyro: {x: [{type: white, density: 8.53e-5 rad/s/sqrt(Hz)}, {type: gauss_markov, sigma: 1.33e-4 rad/s, tau: "
      "0.0344 s}, {type: gauss_markov, sigma: 1.77e-4 rad/s, tau: 1.28 s}, {type: gauss_markov, sigma: 1.57e-4 rad/s, "
      "tau: 28 s}, {type: gauss_markov, sigma: 1.28e-4 rad/s, tau: 883 s}]}";
  int near = 0;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const Record r = staticRecord(truth, 125.0, 3200.0, seed);
    const Identification id = identifyGx(r, IdentifyKind::Auto);
    const auto& gx = id.axis("gx");
    const auto model = gx.modelAdev(gx.allan.tau);
    double worst = 0.0;
    for (std::size_t i = 0; i < model.size(); ++i) worst = std::max(worst, std::fabs(std::log(model[i] / gx.allan.dev[i])));
    INFO("seed " << seed << ": written " << toString(gx.kind) << ", worst ADEV ratio " << std::exp(worst));
    near += worst < std::log(1.5);
    CHECK(worst < std::log(1.5));
  }
  CHECK(near == 10);
}

TEST_CASE("a record shorter than a minute is warned: its slow terms cannot be told", "[identify]") {
  // 100 samples at 100 Hz of a white + random-walk gyro: tau reaches 0.33 s, the walk is minutes.
  auto warned = [](double duration) {
    const Record r = staticRecord("gyro: {x: [{type: white, density: 0.2 deg/sqrt(h)}, {type: random_walk, K: 5 deg/h/sqrt(h)}]}",
                                  100.0, duration, 3);
    for (const std::string& w : identify(r, IdentifyOptions{}).warnings)
      if (w.find("the record is") != std::string::npos) return w;
    return std::string();
  };
  const std::string w = warned(1.0);
  CHECK(w.find("the record is 1 s long (100 samples): the fit sees tau up to 0.333 s only") != std::string::npos);
  CHECK(warned(600.0).empty());
}
