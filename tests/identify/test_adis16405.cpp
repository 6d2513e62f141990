// The real ADIS16405 records (../shared/data/adis16405, 100 Hz, 10 000 s each; data: SMAC-Group
// imudata, University of Calgary, CC BY-NC-SA 4.0): the model fitted on run 1 predicts run 2's
// Allan curve.
//
// Band: z = ln(model(tau) / adev_2(tau)) / sqrt(1 / (2 nu_1) + 1 / (2 nu_2)), with nu_1, nu_2 the
// Greenhall EDF of the run-1 and run-2 points (sd of ln ADEV ~ 1 / sqrt(2 nu)): the model carries
// run 1's estimation noise, the comparison run 2's. |z| <= 3.29 is the two-sided 99.9 % band.
// It holds for the gyros from 10 s to 82 s (tested below); where and why it does not hold
// elsewhere is in the README (run 2's long-tau floor is ~25 % above run 1's, the accelerometers'
// short-tau noise differs by 2-9 % between runs, the bias-instability asymptote overshoots in its
// transition region).
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "../adis16405_records.hpp"
#include "errormodels/identify.hpp"
#include "errormodels/stats/special.hpp"

using namespace sinsim::errormodels;

TEST_CASE("ADIS16405: run-1 model predicts run-2 gyro Allan curve, 10-82 s", "[identify][adis16405]") {
  const std::string dir = std::string(SINSIM_SHARED_DIR) + "/data/adis16405/";
  if (!std::ifstream(dir + "run1.csv.gz") || !std::ifstream(dir + "run2.csv.gz")) {
    WARN("ADIS16405 data not found in " << dir << ": skipped");
    return;
  }
  const RecordOptions ro = sinsim::test::adisOptions();
  IdentifyOptions o;
  o.axes = {"gx", "gy", "gz"};
  o.skipStart = 600.0;  // the warm-up drift of the first 5-10 min (data README)
  const Identification id1 = identify(loadRecord(dir + "run1.csv.gz", ro), o);
  const Identification id2 = identify(loadRecord(dir + "run2.csv.gz", ro), o);
  for (const auto& a : id1.axes) {
    const auto& b = id2.axis(a.channel);
    REQUIRE(a.allan.tau == b.allan.tau);
    const auto pred = a.modelAdev(b.allan.tau);
    std::size_t tested = 0;
    for (std::size_t i = 0; i < b.allan.size(); ++i) {
      if (b.allan.tau[i] < 10.0 || b.allan.tau[i] > 82.0) continue;
      const double z = std::log(pred[i] / b.allan.dev[i]) /
                       std::sqrt(1.0 / (2.0 * a.allan.edf[i]) + 1.0 / (2.0 * b.allan.edf[i]));
      INFO(a.channel << " tau " << b.allan.tau[i] << " model " << pred[i] << " run 2 "
                     << b.allan.dev[i] << " z " << z);
      CHECK(std::fabs(z) <= 3.29);
      ++tested;
    }
    CHECK(tested == 4);  // 10.24, 20.48, 40.96, 81.92 s
    // White noise vs the datasheet: ARW 2.0 deg/sqrt(h) typical. The model's ARW is the AR's
    // long-tau white level sqrt(E dt) / |A(1)| where auto writes the AR with slow terms beside it
    // (the AR's driving variance refitted jointly), else the white term's density N; the data
    // README measured ~2.4 deg/sqrt(h). Checked loosely (1.5-3.5): a datasheet "typical" is not a
    // bound. (gy is written as latent terms since the fifty-second session: terms consistent
    // throughout from an earlier start than its AR branch's, identify_auto.cpp.)
    REQUIRE(a.written.latent);
    const auto& model = a.written.latent->model;
    double arw = model.white * 180.0 / M_PI * 60.0;
    if (model.arVariance > 0.0) {
      double A1 = 0.0;
      for (double c : model.arPolynomial) A1 += c;
      arw = std::sqrt(model.arVariance * 0.01) / std::fabs(A1) * 180.0 / M_PI * 60.0;
    }
    INFO(a.channel << " ARW " << arw << " deg/sqrt(h)");
    CHECK(arw > 1.5);
    CHECK(arw < 3.5);
  }
}

// Issue 11, `fit --kind gm` (white + GM (+ RW), fit/latent_fit.hpp) on the ADIS16405 runs, all six
// channels, 10 min skipped:
//  (a) the fitted model's ADEV lies inside the 99 % band of the run's own Allan estimate at every
//      point of the fitted tau range (tau >= 2 samples). The band is the chi^2 interval of the
//      estimate with its Greenhall EDF nu: nu adev^2 / model^2 in [chi2_nu(0.005), chi2_nu(0.995)].
//      A right model leaves ~1 % of points outside: with ~10 points per fit, 12 fits, ~1.2 in all
//      (Poisson: P(>= 5) ~ 0.8 %). Asserted: <= 2 outside per fit and <= 6 over the 12 fits: gx
//      leaves its last two octaves outside on both runs (4 of the 6; docs/fitting.md, "ADIS16405"):
//      from 0.04 s the one GM of --kind gm goes to the sensor's 2-sample filter hump and the slow
//      flattening becomes a walk that overshoots 327 s and 655 s; --kind latent's second GM (106 s)
//      fits them. (<= 4 until the Allan covariance's cross terms were corrected, 2026-12-04: run 1
//      gx then failed the consistency test from 0.04 s and started at 0.32 s.)
//  (b) the run-1 model predicts run 2's Allan curve over run 1's fitted range: z as in the test
//      above (both runs' estimation noise), |z| <= 3.29 (two-sided 99.9 %). Asserted for the three
//      gyros at every point; the accelerometers' run-2 curves differ from run 1 beyond the
//      estimation noise on part of the range (ay most), so only printed. Per-axis results are in
//      docs/fitting.md ("ADIS16405").
namespace {

Identification gmFit(const std::string& file) {
  const RecordOptions ro = sinsim::test::adisOptions();
  IdentifyOptions o;
  o.kind = IdentifyKind::Gm;
  o.skipStart = 600.0;
  return identify(loadRecord(file, ro), o);
}

}  // namespace

TEST_CASE("ADIS16405: GM model inside the 99 % band of its run, run 1 predicts run 2",
          "[identify][adis16405][latent]") {
  const std::string dir = std::string(SINSIM_SHARED_DIR) + "/data/adis16405/";
  if (!std::ifstream(dir + "run1.csv.gz") || !std::ifstream(dir + "run2.csv.gz")) {
    WARN("ADIS16405 data not found in " << dir << ": skipped");
    return;
  }
  const Identification id1 = gmFit(dir + "run1.csv.gz"), id2 = gmFit(dir + "run2.csv.gz");
  std::size_t outside = 0;
  for (const Identification* id : {&id1, &id2})
    for (const auto& a : id->axes) {
      REQUIRE(a.latent);
      const auto pred = a.modelAdev(a.allan.tau);
      std::size_t tested = 0, inside = 0;
      for (std::size_t i = 0; i < a.allan.size(); ++i) {
        const double tau = a.allan.tau[i];
        if (tau < a.latent->tau.front() * (1 - 1e-9) || tau > a.latent->tau.back() * (1 + 1e-9)) continue;
        if (tau < 2.0 / id->rate_hz) continue;
        const double nu = a.allan.edf[i], r = nu * std::pow(a.allan.dev[i] / pred[i], 2);
        ++tested;
        if (r >= chiSquareQuantile(0.005, nu) && r <= chiSquareQuantile(0.995, nu)) ++inside;
        else WARN(a.channel << " tau " << tau << " s outside: model " << pred[i] << " adev " << a.allan.dev[i]);
      }
      WARN(a.channel << " (a) " << a.latent->terms.name() << ": inside " << inside << "/" << tested << " from "
                     << a.latent->tau.front() << " s");
      CHECK(tested >= 6);
      CHECK(tested - inside <= 2);
      outside += tested - inside;
    }
  CHECK(outside <= 6);
  for (const auto& a : id1.axes) {
    const auto& b = id2.axis(a.channel);
    const auto pred = a.modelAdev(b.allan.tau);
    std::size_t tested = 0, inside = 0;
    double worst = 0.0;
    for (std::size_t i = 0; i < b.allan.size(); ++i) {
      const double tau = b.allan.tau[i];
      if (tau < a.latent->tau.front() * (1 - 1e-9) || tau > a.latent->tau.back() * (1 + 1e-9)) continue;
      const double z = std::log(pred[i] / b.allan.dev[i]) /
                       std::sqrt(1.0 / (2.0 * a.allan.edf[i]) + 1.0 / (2.0 * b.allan.edf[i]));
      ++tested;
      if (std::fabs(z) <= 3.29) ++inside;
      worst = std::max(worst, std::fabs(z));
    }
    WARN(a.channel << " (b) run 2 inside " << inside << "/" << tested << ", max |z| " << worst);
    CHECK(tested >= 6);
    if (a.sensor == fit::SensorSignal::Gyro) CHECK(inside == tested);
  }
}

// `fit --kind gm` on 1000-s windows of the ADIS16405 runs (10 min skipped): no start of the tau
// range is consistent on the accelerometers, and the least-bad start (1.28-2.56 s) left the
// record's short-tau white noise to a GM of tau 0.02-0.15 s, which is white within the range
// and falls away below it: the written model's ADEV at 2 samples was 13x (ax) below the
// record's. A GM faster than half the range's first tau cannot be told from white noise there;
// it is searched from that tau up (latent_fit.cpp), and white noise carries the short end. The
// model's ADEV at 2 samples (where it is extrapolated from the fitted range) is asserted within
// a factor 2 of the record's on every channel of both windows (an internal filter or the LSB
// lattice moves real sensors' shortest tau by tens of percent, not by factors).
// `--kind latent` has quantization among its terms: on run 2's window it fitted one to ay from
// 0.64 s up, whose ADEV at 2 samples was 4.1x the record's (the issue's "an LSB whose noise at one
// sample is 10x the record's"); the points below a scanned start now refute such a term
// (latent_fit.cpp, quantizationRefutedBelow), and the same bound is asserted for that kind.
TEST_CASE("ADIS16405 windows: the GM and latent models keep the record's short-tau noise",
          "[identify][adis16405][latent]") {
  const std::string dir = std::string(SINSIM_SHARED_DIR) + "/data/adis16405/";
  if (!std::ifstream(dir + "run1.csv.gz") || !std::ifstream(dir + "run2.csv.gz")) {
    WARN("ADIS16405 data not found in " << dir << ": skipped");
    return;
  }
  for (const IdentifyKind kind : {IdentifyKind::Gm, IdentifyKind::Latent})
    for (const char* run : {"run1.csv.gz", "run2.csv.gz"}) {
      const RecordOptions ro = sinsim::test::adisOptions(600.0, 1000.0);
      IdentifyOptions o;
      o.kind = kind;
      const Identification id = identify(loadRecord(dir + run, ro), o);
      for (const auto& a : id.axes) {
        REQUIRE(a.latent);
        std::size_t i = 0;
        while (i < a.allan.size() && a.allan.tau[i] < 0.02 * (1 - 1e-9)) ++i;
        REQUIRE(i < a.allan.size());
        const double ratio = a.modelAdev({a.allan.tau[i]})[0] / a.allan.dev[i];
        INFO((kind == IdentifyKind::Gm ? "gm " : "latent ")
             << run << " " << a.channel << " " << a.latent->terms.name() << " from " << a.latent->tau.front()
             << " s: model / record ADEV at " << a.allan.tau[i] << " s = " << ratio);
        CHECK(ratio > 0.5);
        CHECK(ratio < 2.0);
      }
    }
}

namespace {

/// `fit` (auto, no skip) of one whole run's `axes`; nullopt, with a warning, where the data is absent.
std::optional<Identification> identifyRun(const std::string& run, std::vector<std::string> axes,
                                          IdentifyKind kind = IdentifyKind::Auto) {
  const std::string file = sinsim::test::adisDir() + run + ".csv.gz";
  if (!std::ifstream(file)) {
    WARN("ADIS16405 data not found: " << file << ": skipped");
    return std::nullopt;
  }
  IdentifyOptions o;
  o.axes = std::move(axes);
  o.kind = kind;
  return identify(loadRecord(file, sinsim::test::adisOptions()), o);
}

}  // namespace

// The AR + slow terms branch of `fit` (auto) on run 2's accelerometers, whose joint fit is scanned to
// a start of ~5 s: with Burg on the record itself, the AR(20) carried the slow terms' power as its
// low-frequency level, and the joint fit, which can lower that level only with the driving variance,
// left the model 0.61x (ax) and 0.81x (az) the record at one sample. With the slow terms filtered
// out of Burg's record (fit/ar_slow_fit.cpp slowTermsFilteredOut) 0.72x and 0.84x; asserted: every
// accelerometer at >= 0.7x there (ay, whose fit starts at 2.56 s without that warning: 0.97x).
TEST_CASE("ADIS16405 run 2: the AR + slow model near the record at one sample", "[identify][adis16405]") {
  const auto id = identifyRun("run2", {"ax", "ay", "az"});
  if (!id) return;
  for (const auto& a : id->axes) {
    REQUIRE(a.written.latent);
    REQUIRE(a.written.latent->model.arVariance > 0.0);
    REQUIRE(a.allan.tau.at(0) == Approx(0.01));
    const double ratio = a.modelAdev({a.allan.tau[0]})[0] / a.allan.dev[0];
    INFO(a.channel << ": model / record ADEV at 0.01 s " << ratio);
    CHECK(ratio >= 0.7);
    CHECK(ratio <= 1.1);
  }
}

// auto on run 1's gy: its AR branch (AR(4) + flicker + walk) held only from a scanned start of 20 s
// and was 1.14-1.17x the record's ADEV below it; the latent terms are consistent from 0.04 s, and
// auto now writes them where the AR branch starts later (identify_auto.cpp; before, only where that
// branch was more than 25 % off below its start). Asserted: within 10 % of the record from 0.04 s
// to 2.56 s (the old model: 1.14-1.17x there). Since the AR branch's driving variance is bounded by
// Burg's, it starts at 0.08 s within 1 % below, but is consistent nowhere (p 1e-4 at its least-bad
// start, 0.61x the record at 655 s), so its closeness below the terms' start does not count
// (sixty-first session; the terms are 1.17x at 0.01 s).
TEST_CASE("ADIS16405 run 1 gy: auto writes the terms consistent from an earlier start", "[identify][adis16405]") {
  const auto id = identifyRun("run1", {"gy"});
  if (!id) return;
  const auto& a = id->axis("gy");
  REQUIRE(a.written.latent);
  CHECK(a.written.latent->model.arVariance == 0.0);
  std::size_t tested = 0;
  for (std::size_t i = 0; i < a.allan.size(); ++i) {
    if (a.allan.tau[i] < 0.039 || a.allan.tau[i] > 2.57) continue;
    const double ratio = a.modelAdev({a.allan.tau[i]})[0] / a.allan.dev[i];
    INFO("tau " << a.allan.tau[i] << " s: model / record ADEV " << ratio);
    CHECK(std::fabs(std::log(ratio)) < std::log(1.1));
    ++tested;
  }
  CHECK(tested == 7);  // 0.04 .. 2.56 s
}

// `--kind ar+slow` on run 1's gy (AR(3) from Burg): the joint fit, scanned to a late start, raised
// the AR's driving variance 35 % above Burg's to carry the record's excess at 10-100 s, and the
// model was 1.14-1.16x the record's ADEV from 0.01 to 2.56 s. The one-step prediction error of AR +
// slow terms is at least the AR's own driving variance, so Burg's bounds it
// (LatentFitOptions::arVarianceMax): the slow terms carry the excess. Asserted: within 5 % of the
// record from 0.01 to 10.24 s (measured 0.994-1.010).
TEST_CASE("ADIS16405 run 1 gy: ar+slow holds the AR's driving variance at most Burg's", "[identify][adis16405]") {
  const auto id = identifyRun("run1", {"gy"}, IdentifyKind::ArSlow);
  if (!id) return;
  const auto& a = id->axis("gy");
  REQUIRE(a.written.latent);
  REQUIRE(a.written.latent->model.arVariance > 0.0);
  std::size_t tested = 0;
  for (std::size_t i = 0; i < a.allan.size(); ++i) {
    if (a.allan.tau[i] > 10.25) continue;
    const double ratio = a.modelAdev({a.allan.tau[i]})[0] / a.allan.dev[i];
    INFO("tau " << a.allan.tau[i] << " s: model / record ADEV " << ratio);
    CHECK(std::fabs(std::log(ratio)) < std::log(1.05));
    ++tested;
  }
  CHECK(tested == 11);  // 0.01 .. 10.24 s
}
