// The filter model's known errors (misalignment, a scale-factor matrix's off-diagonal part,
// g-sensitivity, ramp, warm-up, sinusoid; sim/aided/known_errors.hpp) are compensated: the aided
// navigation of a sensor that has them, with a filter model that states them, is the navigation
// of the same sensor without them. The reference is a run in which they are never generated.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "common/error.hpp"
#include "sim/run.hpp"
#include "sim/scenario.hpp"
#include "test_support.hpp"

using namespace sinsim;

namespace {

// A static start with coarse alignment (gyros good enough to gyrocompass; their warm-up of 180
// deg/h would wreck the heading if it were not removed), turns in both directions, a climb, and a 60-s outage.
const char* kScenario = R"(
name: known
start: {latitude: 48 deg, longitude: 11 deg, height: 500 m, heading: 30 deg}
imu_rate: 100 Hz
output_rate: 1 Hz
vertical: {channel: damped, time_constant: 100 s}
segments:
  - {type: static, duration: 60 s}
  - {type: accelerate, speed: 15 m/s, duration: 10 s}
  - {type: turn, heading_change: 90 deg, duration: 10 s}
  - {type: climb, height_change: 10 m, duration: 30 s}
  - {type: turn, heading_change: -180 deg, duration: 15 s}
  - {type: cruise, duration: 60 s}
  - {type: turn, heading_change: 45 deg, duration: 5 s}
  - {type: cruise, duration: 30 s}
alignment: {duration: 60 s}
initial_errors: {position: {sigma: 2 m}, velocity: {sigma: 0.05 m/s}}
gnss:
  rate: 1 Hz
  position_sigma: [1 m, 1 m, 2 m]
  outages: [{start: 120 s, duration: 60 s}]
seed: 7
)";

const char* kNoise = R"(
gyro:
  all:
    - {type: white, density: 0.01 deg/sqrt(h)}
    - {type: bias, sigma: 0.2 deg/h}
accel:
  all:
    - {type: white, density: 0.1 m/s/sqrt(h)}
    - {type: bias, sigma: 1 mg}
)";

// kNoise's effects at the same positions of their lists (the same random streams), plus known
// ones: the triads' linear errors, and errors added on single axes.
const char* kKnown = R"(
gyro:
  triad:
    - {type: misalignment, matrix: [[0, 0.3 deg, -0.2 deg], [0.1 deg, 0, 0.25 deg], [-0.15 deg, 0.2 deg, 0]]}
    - {type: scale_factor, matrix: [[500 ppm, 200 ppm, 0], [0, -300 ppm, 0], [100 ppm, 0, 200 ppm]]}
    - {type: g_sensitivity, diagonal: [0.002 deg/s/g, 0.003 deg/s/g, 0.001 deg/s/g]}
  all:
    - {type: white, density: 0.01 deg/sqrt(h)}
    - {type: bias, sigma: 0.2 deg/h}
    - {type: warmup, amplitude: 0.05 deg/s, tau: 120 s}
  x:
    - {type: ramp, slope: 5 deg/h/min}
  z:
    - {type: sinusoid, amplitude: 0.02 deg/s, frequency: 0.1 Hz, phase: 30 deg}
accel:
  triad:
    - {type: misalignment, matrix: [[0, 1 mrad, 0], [-1 mrad, 0, 2 mrad], [0.5 mrad, 0, 0]]}
  all:
    - {type: white, density: 0.1 m/s/sqrt(h)}
    - {type: bias, sigma: 1 mg}
  y:
    - {type: ramp, slope: 0.1 mg/min}
    - {type: warmup, amplitude: 2 mg, tau: 60 s}
)";

// The run's navigation errors at every output epoch, truth `errors`, filter `filter` (model files
// in dir), `extra` scenario keys.
std::vector<sim::NavError> errorsOf(const std::filesystem::path& dir, const char* errors,
                                    const char* filter, const std::string& extra = "") {
  const std::string text = std::string(kScenario) + extra + "errors: " + errors +
                           "\nfilter: {model: " + filter + "}\n";
  const sim::Scenario sc = sim::parseScenario(text, (dir / "known.yaml").string(), dir.string());
  std::vector<sim::NavError> out;
  sim::RunOptions o;
  o.onRow = [&](const sim::NavError& e) { out.push_back(e); };
  sim::run(sc, o);
  return out;
}

double maxHorizontal(const std::vector<sim::NavError>& e) {
  double m = 0.0;
  for (const sim::NavError& x : e) m = std::max(m, x.horizontal());
  return m;
}

// The largest horizontal distance and yaw difference between two runs' errors, epoch by epoch.
std::pair<double, double> maxDifference(const std::vector<sim::NavError>& a,
                                        const std::vector<sim::NavError>& b) {
  REQUIRE(a.size() == b.size());
  double pos = 0.0, yaw = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    REQUIRE(a[i].t == b[i].t);
    pos = std::max(pos, std::hypot(a[i].pos_n.x() - b[i].pos_n.x(), a[i].pos_n.y() - b[i].pos_n.y()));
    yaw = std::max(yaw, std::abs(a[i].euler.z() - b[i].euler.z()));
  }
  return {pos, yaw};
}

}  // namespace

TEST_CASE("known errors in the filter's model are compensated: the navigation without them") {
  const auto dir = test::freshTempDir("sinsim-known-errors");
  test::writeText(dir / "noise.yaml", kNoise);
  test::writeText(dir / "known.yaml", kKnown);
  const auto reference = errorsOf(dir, "noise.yaml", "noise.yaml");
  const auto compensated = errorsOf(dir, "known.yaml", "known.yaml");
  const auto ignored = errorsOf(dir, "known.yaml", "noise.yaml");  // the filter not told
  const double scale = maxHorizontal(reference);
  const auto [dPos, dYaw] = maxDifference(reference, compensated);
  const auto [dPosIgnored, dYawIgnored] = maxDifference(reference, ignored);
  INFO("reference max horizontal " << scale << " m; compensated differs by " << dPos << " m, "
       << dYaw << " rad yaw; ignored by " << dPosIgnored << " m, " << dYawIgnored << " rad");
  REQUIRE(scale > 1.0);  // the outage's drift: a scale to compare with
  // What is left is second order (the scale and misalignment errors times each other and times
  // the estimated bias): a few per cent of the drift, while the untold filter is off by metres.
  CHECK(dPos < 0.03 * scale);
  CHECK(dYaw < 1e-3);
  CHECK(dPosIgnored > 10.0 * scale);
  CHECK(dYawIgnored > 30.0 * dYaw);
}

TEST_CASE("known errors added to the signal are removed exactly") {
  // A ramp, a warm-up and a sinusoid only: nothing multiplies the signal, so the compensated
  // increments are the unperturbed ones to rounding, and so is the navigation.
  const auto dir = test::freshTempDir("sinsim-known-added");
  test::writeText(dir / "noise.yaml", kNoise);
  test::writeText(dir / "added.yaml", R"(
gyro:
  all:
    - {type: white, density: 0.01 deg/sqrt(h)}
    - {type: bias, sigma: 0.2 deg/h}
    - {type: warmup, amplitude: 0.05 deg/s, tau: 120 s}
    - {type: sinusoid, amplitude: 0.02 deg/s, frequency: 0.1 Hz}
  y: [{type: ramp, slope: 5 deg/h/min}]
accel:
  all:
    - {type: white, density: 0.1 m/s/sqrt(h)}
    - {type: bias, sigma: 1 mg}
  z: [{type: ramp, slope: 0.1 mg/min}]
)");
  const auto [dPos, dYaw] =
      maxDifference(errorsOf(dir, "noise.yaml", "noise.yaml"), errorsOf(dir, "added.yaml", "added.yaml"));
  CHECK(dPos < 1e-6);
  CHECK(dYaw < 1e-9);
}

TEST_CASE("a known temperature polynomial is removed at the sensor's temperature, refused without "
          "one") {
  // The sensor warms from 10 to 50 degC over the drive; every bias follows a polynomial in it
  // (the gyros' 0.01 deg/s/degC, 0.15 deg/s at 40 degC; the accelerometers' 0.1 mg/degC). The filter's model states it; the
  // navigation reads the sensor temperature as an INS reads its IMU's.
  const auto dir = test::freshTempDir("sinsim-known-temperature");
  test::writeText(dir / "noise.yaml", kNoise);
  const std::string thermalGyro = R"(
gyro:
  all:
    - {type: white, density: 0.01 deg/sqrt(h)}
    - {type: bias, sigma: 0.2 deg/h}
    - {type: temperature, T0: 25 degC, coefficients: [0.01 deg/s/degC, 1e-4 deg/s/degC^2]}
accel:
  all:
    - {type: white, density: 0.1 m/s/sqrt(h)}
    - {type: bias, sigma: 1 mg}
    - {type: temperature, T0: 25 degC, coefficients: [0.1 mg/degC]}
)";
  test::writeText(dir / "thermal.yaml", thermalGyro);
  const std::string warm = "temperature: {start: 10 degC, end: 50 degC}\n";
  const auto [dPos, dYaw] = maxDifference(errorsOf(dir, "noise.yaml", "noise.yaml", warm),
                                          errorsOf(dir, "thermal.yaml", "thermal.yaml", warm));
  CHECK(dPos < 1e-6);
  CHECK(dYaw < 1e-9);
  try {  // no temperature in the scenario: the filter's model cannot be compensated
    sim::parseScenario(std::string(kScenario) + "errors: noise.yaml\nfilter: {model: thermal.yaml}\n",
                       (dir / "cold.yaml").string(), dir.string());
    FAIL("expected a ConfigError");
  } catch (const ConfigError& e) {
    INFO(e.what());
    CHECK(std::string(e.what()).find("thermal.yaml:6: gyro.all[2]: temperature: the filter "
                                     "compensates it at the sensor's temperature") != std::string::npos);
  }
}

TEST_CASE("known errors carry no filter state") {
  const auto dir = test::freshTempDir("sinsim-known-states");
  test::writeText(dir / "noise.yaml", kNoise);
  test::writeText(dir / "known.yaml", kKnown);
  const std::string base = std::string(kScenario) + "errors: noise.yaml\n";
  const sim::Scenario plain =
      sim::parseScenario(base + "filter: {model: noise.yaml}\n", (dir / "a.yaml").string(), dir.string());
  const sim::Scenario known =
      sim::parseScenario(base + "filter: {model: known.yaml}\n", (dir / "b.yaml").string(), dir.string());
  // the scale_factor matrix's diagonal is the one state added per gyro axis
  CHECK(known.aiding.filter.sensors.stateCount() == plain.aiding.filter.sensors.stateCount() + 3);
  CHECK(!known.aiding.filter.knownAdded.empty());
  CHECK(!known.aiding.filter.knownLinear.empty());
  CHECK(plain.aiding.filter.knownAdded.empty());
  CHECK(plain.aiding.filter.knownLinear.empty());
  // Listed (summary.json, the terminal) as the file places them.
  const std::vector<std::string> labels = {
      "gyro.triad[0].misalignment", "gyro.triad[1].scale_factor off-diagonal",
      "gyro.triad[2].g_sensitivity", "gyro.all[2].warmup", "gyro.x[0].ramp", "gyro.z[0].sinusoid",
      "accel.triad[0].misalignment", "accel.y[0].ramp", "accel.y[1].warmup"};
  CHECK(known.aiding.filter.knownLabels == labels);
  CHECK(plain.aiding.filter.knownLabels.empty());
}
