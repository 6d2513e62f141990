// The one navigation loop (sim/nav_loop.hpp): `run` (a trajectory source) and `mc` (a reference
// source) navigate identically; the initial-bias window removes a constant bias exactly; the
// aiding hook sees every interval with the measured and ideal samples kept apart.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "errormodels/imu_model.hpp"
#include "common/progress.hpp"
#include "sim/imu_source.hpp"
#include "sim/nav_loop.hpp"
#include "sim/reference.hpp"
#include "sim/run.hpp"
#include "sim/scenario.hpp"

using namespace sinsim;

namespace {

const char* kMoving = R"(
name: loop
start: {latitude: 45 deg, longitude: 7 deg, height: 200 m, heading: 10 deg, speed: 10 m/s}
imu_rate: 100 Hz
output_rate: 1 Hz
vertical: {channel: damped, time_constant: 50 s}
segments:
  - {type: accelerate, speed: 25 m/s, duration: 10 s}
  - {type: turn, heading_change: 90 deg, duration: 10 s}
  - {type: climb, height_change: 20 m, duration: 10 s}
)";

const char* kNoisy =
    "gyro:\n  all: [{type: white, density: 0.2 deg/sqrt(h)}, {type: bias, sigma: 30 deg/h}]\n"
    "accel:\n  all: [{type: white, density: 0.04 m/s/sqrt(h)}, {type: bias, sigma: 2 mg}]\n";

}  // namespace

TEST_CASE("nav loop: run (trajectory source) and mc (reference source) give the same errors") {
  sim::Scenario sc = sim::parseScenario(kMoving, "loop.yaml");
  sc.errors = errormodels::ImuErrorModel::fromString(kNoisy, "noisy.yaml");
  sc.seed = 3;
  std::vector<sim::NavError> rows;
  sim::RunOptions ro;
  ro.onRow = [&](const sim::NavError& e) { rows.push_back(e); };
  sim::run(sc, ro);

  const sim::Reference ref = sim::buildReference(sc);
  auto c = sc.errors.instantiate(sc.imuRate, {3, 0});
  std::vector<float> out(ref.epochs() * sim::kErrorFields);
  REQUIRE(sim::navigateRealisation(ref, c.get(), {}, out.data()));
  REQUIRE(rows.size() == ref.epochs());
  // The same samples through the same loop: the mc floats are the run's doubles rounded to float
  // (relative 6e-8), nothing more.
  for (std::size_t e = 0; e < rows.size(); ++e) {
    INFO("epoch " << e);
    CHECK(out[e * sim::kErrorFields + sim::kNorth] == float(rows[e].pos_n.x()));
    CHECK(out[e * sim::kErrorFields + sim::kDown] == float(rows[e].pos_n.z()));
    CHECK(out[e * sim::kErrorFields + sim::kYaw] == float(rows[e].euler.z()));
  }
  CHECK(rows.back().horizontal() > 1.0);  // not trivial: metres of drift
}

TEST_CASE("nav loop: the bias window removes a constant bias exactly, in run as in mc") {
  sim::Scenario sc = sim::parseScenario(kMoving, "loop.yaml");
  const auto biased = errormodels::ImuErrorModel::fromString(
      "gyro:\n  all: [{type: bias, sigma: 100 deg/h}]\naccel:\n  all: [{type: bias, sigma: 10 mg}]\n",
      "bias.yaml");
  // measured − ideal = b·dt in every interval, so the window's mean is b to rounding and the
  // corrected samples are the ideal ones to ~1e-16 relative: the navigation equals the perfect
  // IMU's to far below a micrometre (the perfect IMU itself drifts < 1 mm here).
  sc.errors = biased;
  sim::RunOptions ro;
  ro.biasWindow = 5.0;
  const sim::RunSummary removed = sim::run(sc, ro);
  sc.errors = errormodels::ImuErrorModel::none();
  const sim::RunSummary perfect = sim::run(sc, {});
  sc.errors = biased;
  const sim::RunSummary kept = sim::run(sc, {});
  CHECK(std::abs(removed.final.horizontal() - perfect.final.horizontal()) < 1e-6);
  CHECK(std::abs(removed.final.vertical() - perfect.final.vertical()) < 1e-6);
  CHECK(kept.final.horizontal() > 10.0);  // the bias alone: tens of metres in 30 s
  CHECK_THROWS_AS(sim::run(sc, [] { sim::RunOptions o; o.biasWindow = 1e-4; return o; }()),
                  InputError);  // shorter than one interval
}

TEST_CASE("nav loop: the aiding hook sees every interval, measured and ideal apart, with truth") {
  sim::Scenario sc = sim::parseScenario(kMoving, "loop.yaml");
  sc.errors = errormodels::ImuErrorModel::fromString(kNoisy, "noisy.yaml");
  struct Probe : sim::NavAiding {
    long long calls = 0, differ = 0, withTruth = 0;
    double lastT = 0;
    nav::NavState start(const nav::NavState& truth) override {
      nav::NavState s = truth;
      s.lat += 10.0 / 6.4e6;  // ~10 m north of the truth
      return s;
    }
    void epoch(const sim::ImuEpoch& e, const nav::ImuSample& integrated,
               nav::Strapdown& s) override {
      CHECK(integrated.dtheta_b == e.measured.dtheta_b);  // the default compensate(): unchanged
      ++calls;
      differ += (e.measured.dtheta_b != e.ideal.dtheta_b) ? 1 : 0;
      withTruth += e.hasTruth ? 1 : 0;
      lastT = s.state().t;
      CHECK(e.truth.t == Approx(e.ideal.t).margin(1e-9));  // truth at the interval's end
    }
  } probe;
  sim::RunOptions ro;
  ro.aiding = &probe;
  std::vector<sim::NavError> rows;
  ro.onRow = [&](const sim::NavError& e) { rows.push_back(e); };
  const sim::RunSummary s = sim::run(sc, ro);
  CHECK(probe.calls == s.imuSamples);
  CHECK(probe.differ == s.imuSamples);     // white noise: every measured sample differs
  CHECK(probe.withTruth == s.imuSamples);  // a trajectory source knows the truth everywhere
  CHECK(probe.lastT == Approx(s.duration));
  // The navigation started where start() put it: δlat = 10 / 6.4e6 rad north, times the
  // WGS-84 meridian radius at 45° plus the height, M + h = 6 367 581.8 m (closed form
  // a(1 − e²)/(1 − e² sin²φ)^1.5): 9.9493 m; 1 mm allows for the printed digits.
  REQUIRE(rows.size() > 1);
  CHECK(rows.front().pos_n.x() == Approx(9.9493).margin(1e-3));
}

// Ctrl-C sets progress::interruptFlag(); the loop looks at it every 1024 intervals and at its end.
// Every 65536 let a short aided run (200 s at 100 Hz) finish with exit 0 after Ctrl-C and took
// 1.5 s to stop a long one (a blind probe, fifty-seventh session).
TEST_CASE("nav loop: a set interrupt flag stops a run within 1024 intervals, and a short run at its end") {
  sim::Scenario sc = sim::parseScenario(kMoving, "loop.yaml");  // 3000 intervals
  std::size_t rows = 0;
  sim::RunOptions ro;
  ro.onRow = [&](const sim::NavError&) { ++rows; };
  progress::interruptFlag().store(true);
  CHECK_THROWS_AS(sim::run(sc, ro), sinsim::Interrupted);
  CHECK(rows <= 12);  // 1 Hz rows of the first 1024 intervals at 100 Hz
  rows = 0;
  sim::Scenario shortOne = sim::parseScenario(
      "start: {latitude: 45 deg, longitude: 7 deg}\nimu_rate: 100 Hz\nsegments: [{type: static, duration: 5 s}]\n",
      "short.yaml");  // 500 intervals: never at a multiple of 1024
  CHECK_THROWS_AS(sim::run(shortOne, ro), sinsim::Interrupted);
  progress::interruptFlag().store(false);
  CHECK_NOTHROW(sim::run(shortOne, ro));
}
