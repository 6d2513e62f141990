// Hostile input, library level: every limit of common/limits.hpp is enforced where the file is
// read, with a message naming file, line and key, before anything is expanded or allocated.
#include <catch2/catch.hpp>

#include <chrono>
#include <string>

#include "common/config.hpp"
#include "common/limits.hpp"
#include "errormodels/imu_model.hpp"
#include "errormodels/stats/record.hpp"
#include "sim/scenario.hpp"
#include "test_support.hpp"

using namespace sinsim;
using Catch::Matchers::Contains;
using sinsim::test::hasDiagnostic;

using sinsim::test::messageOf;

namespace {

// The diagnostics of a scenario text that must be refused.
std::vector<Diagnostic> scenarioProblems(const std::string& text) {
  try {
    sim::parseScenario(text, "s.yaml", ".");
  } catch (const ConfigError& e) {
    return e.diagnostics();
  }
  FAIL("the scenario was accepted");
  return {};
}

std::string scenarioWith(const std::string& start, const std::string& segments,
                         const std::string& extra = "") {
  return "start: {latitude: 45 deg, longitude: 7 deg" + start + "}\n" + extra +
         "segments:\n" + segments;
}

}  // namespace

TEST_CASE("limit: scenario and segment durations") {
  // 1e308 s overflowed llround into imu_samples = -9223372036854775808; 1e-300 s ran 0 s.
  const std::pair<const char*, const char*> cases[] = {
      {"1e308 s", "is beyond any physical value"},  // the reader's general magnitude limit
      {"1e-300 s", "expected a duration from 1e-05 s to 864000 s"},
      {"864001 s", "expected a duration from 1e-05 s to 864000 s"}};
  for (const auto& [d, expected] : cases) {
    const auto ds = scenarioProblems(
        scenarioWith("", std::string("  - {type: static, duration: ") + d + "}\n"));
    CHECK(hasDiagnostic(ds, "s.yaml", 3, "segments[0].duration", expected));
  }
  // Each segment within limits, the sum over 10 days.
  const auto ds = scenarioProblems(scenarioWith(
      "", "  - {type: static, duration: 500000 s}\n  - {type: static, duration: 500000 s}\n"));
  CHECK(hasDiagnostic(ds, "s.yaml", 3, "segments", "more than 864000 s"));
}

TEST_CASE("limit: IMU rate and sample count (duration x rate), before any sample is made") {
  auto ds = scenarioProblems(
      scenarioWith("", "  - {type: static, duration: 60 s}\n", "imu_rate: 1e12 Hz\n"));
  CHECK(hasDiagnostic(ds, "s.yaml", 2, "imu_rate", "faster than any IMU or process rate"));
  ds = scenarioProblems(
      scenarioWith("", "  - {type: static, duration: 60 s}\n", "imu_rate: 1e-300 Hz\n"));
  CHECK(hasDiagnostic(ds, "s.yaml", 2, "imu_rate", "expected a rate of at least"));
  // 8 days at 1 kHz: 6.9e8 samples.
  ds = scenarioProblems(scenarioWith(
      "", "  - {type: static, duration: 691200 s}\n", "imu_rate: 1 kHz\noutput_rate: 1 Hz\n"));
  CHECK(hasDiagnostic(ds, "s.yaml", 5, "segments", "6.912e+08 IMU samples, more than 1e+08"));
}

TEST_CASE("limit: repeats are counted before they are expanded") {
  const auto t0 = std::chrono::steady_clock::now();
  const auto ds = scenarioProblems(scenarioWith(
      "",
      "  - type: repeat\n    count: 1000000\n    segments:\n"
      "      - type: repeat\n        count: 1000000\n        segments:\n"
      "          - {type: static, duration: 1 s}\n"));
  CHECK(hasDiagnostic(ds, "s.yaml", 3, "segments",
                      "more than " + std::to_string(sinsim::limits::kMaxSegments) + " segments"));
  // Expanding first took minutes and GBs; the count is immediate (10 s is a loose bound for a
  // loaded sanitizer build).
  CHECK(std::chrono::steady_clock::now() - t0 < std::chrono::seconds(10));
}

TEST_CASE("limit: nested aliases (billion laughs) stop at the node budget") {
  // 9 levels of 10 aliases each: 10^9 segment nodes when expanded, 1 KB of text.
  std::string text = "start: {latitude: 45 deg, longitude: 7 deg}\nx0: &a0 {type: static, duration: 1 s}\n";
  for (int i = 1; i <= 9; ++i) {
    text += "x" + std::to_string(i) + ": &a" + std::to_string(i) + " [";
    for (int k = 0; k < 10; ++k) text += (k ? ", *a" : "*a") + std::to_string(i - 1);
    text += "]\n";
  }
  text += "segments: [{type: repeat, count: 1, segments: *a9}]\n";
  REQUIRE(text.size() < 1200);
  const auto t0 = std::chrono::steady_clock::now();
  const std::string msg = messageOf([&] { ConfigFile::fromString(text, "laughs.yaml"); });
  CHECK_THAT(msg, Contains("laughs.yaml: the document expands (through its aliases) to more than"));
  CHECK(std::chrono::steady_clock::now() - t0 < std::chrono::seconds(10));
}

TEST_CASE("limit: heights and speeds, given or reached, stay in range (no NaN from 1e308 m)") {
  auto ds = scenarioProblems(scenarioWith(", height: 1e308 m", "  - {type: static, duration: 1 s}\n"));
  CHECK(hasDiagnostic(ds, "s.yaml", 1, "start.height", "beyond any physical value"));
  ds = scenarioProblems(scenarioWith(", height: 200 km", "  - {type: static, duration: 1 s}\n"));
  CHECK(hasDiagnostic(ds, "s.yaml", 1, "start.height", "expected a height from"));
  ds = scenarioProblems(scenarioWith(", speed: 1e300 m/s", "  - {type: static, duration: 1 s}\n"));
  CHECK(hasDiagnostic(ds, "s.yaml", 1, "start.speed", "beyond any physical value"));
  // Reached by a segment rather than given at the start.
  ds = scenarioProblems(scenarioWith(
      "", "  - {type: accelerate, duration: 100 s, speed: 20 km/s}\n"));
  CHECK(hasDiagnostic(ds, "s.yaml", 3, "segments[0]", "the speed reaches 20000 m/s"));
}

TEST_CASE("limit: a segment's peak angular rate and acceleration (no 1e6 deg turn in 1 s)") {
  // A turn of Δψ in T follows ψ = Δψ S(t/T) with S'(u) = 1 − cos 2πu: peak rate 2Δψ/T, so 90 deg
  // reaches the 10,000 deg/s limit at T = 18 ms exactly.
  const auto turn = [](const std::string& duration, const std::string& speed = "0 m/s") {
    return scenarioWith(", speed: " + speed,
                        "  - {type: turn, heading_change: 90 deg, duration: " + duration + "}\n");
  };
  CHECK_NOTHROW(sim::parseScenario(turn("18.1 ms"), "s.yaml", "."));
  auto ds = scenarioProblems(turn("17.9 ms"));
  CHECK(hasDiagnostic(ds, "s.yaml", 3, "segments[0]", "the turn reaches an angular rate of 1.01e+04 deg/s"));
  // Centripetal peak s·2Δψ/T: 100 m/s, 90 deg in 31.4 ms would pull 1e4 m/s² (1000 g).
  CHECK_NOTHROW(sim::parseScenario(turn("31.5 ms", "100 m/s"), "s.yaml", "."));
  ds = scenarioProblems(turn("31.3 ms", "100 m/s"));
  CHECK(hasDiagnostic(ds, "s.yaml", 3, "segments[0]", "the turn reaches an acceleration of 1e+04 m/s^2"));
  // Along the path: 2Δv/T; 11 km/s in 1 s (the hostile corpus' orbital turn) is 22,000 m/s².
  ds = scenarioProblems(scenarioWith("", "  - {type: accelerate, duration: 1 s, speed: 11 km/s}\n"));
  CHECK(hasDiagnostic(ds, "s.yaml", 3, "segments[0]", "acceleration of 2.2e+04 m/s^2"));
  CHECK(hasDiagnostic(ds, "s.yaml", 3, "segments[0]", "a duration of 2.2 s fits"));
}

TEST_CASE("limit: segment peaks bound the profile's sampled rates and accelerations") {
  // The closed forms of sim::segmentPeaks against the motion profile sampled densely: equal (to
  // the sampling) for accelerations, flat turns and excursions, an upper bound for coordinated
  // turns and climbs.
  const std::string text = scenarioWith(", speed: 50 m/s",
                                        "  - {type: accelerate, duration: 7 s, speed: 80 m/s}\n"
                                        "  - {type: turn, heading_change: -120 deg, duration: 9 s}\n"
                                        "  - {type: turn, heading_change: 70 deg, bank: 30 deg}\n"
                                        "  - {type: climb, height_change: 300 m, duration: 20 s}\n"
                                        "  - {type: pitch, angle: 10 deg, duration: 3 s}\n"
                                        "  - {type: roll, angle: -25 deg, duration: 4 s}\n");
  const sim::Scenario sc = sim::parseScenario(text, "s.yaml", ".");
  const sim::MotionProfile m = sc.motion();
  REQUIRE(m.segments().size() == 6);
  for (const sim::Segment& g : m.segments()) {
    double rate = 0.0, acc = 0.0;
    for (int k = 0; k <= 20000; ++k) {
      const sim::MotionPoint p = m.at(g.t0 + g.duration * k / 20000.0);
      rate = std::max(rate, p.eulerRate.norm());
      acc = std::max(acc, p.a_n.norm());
    }
    const sim::SegmentPeaks peak = sim::segmentPeaks(g);
    INFO(g.type);
    const bool exact = !(g.kind == sim::SegmentKind::Climb ||
                         (g.kind == sim::SegmentKind::Turn && g.bank == sim::BankMode::Coordinated));
    CHECK(rate <= peak.angularRate * (1 + 1e-9) + 1e-12);
    CHECK(acc <= peak.acceleration * (1 + 1e-9) + 1e-12);
    if (exact) {
      CHECK(rate == Approx(peak.angularRate).epsilon(1e-6).margin(1e-12));
      CHECK(acc == Approx(peak.acceleration).epsilon(1e-6).margin(1e-12));
    }
  }
}

TEST_CASE("limit: a value overflowing in SI units, and huge model values") {
  const std::string msg = messageOf([] {
    errormodels::ImuErrorModel::fromString(
        "gyro:\n  all:\n    - {type: white, density: 1e308 deg/sqrt(h)}\n", "m.yaml");
  });
  CHECK_THAT(msg, Contains("m.yaml:3: gyro.all[0].density:"));
  CHECK_THAT(msg, Contains("beyond any physical value"));
  CHECK_THAT(messageOf([] { parseQuantity("1e308 km"); }), Contains("overflows in SI units"));
  // An AR process rate of 1e12 Hz would draw 1e10 numbers per IMU sample.
  CHECK_THAT(messageOf([] {
               errormodels::ImuErrorModel::fromString(
                   "gyro:\n  x: [{type: ar, a: [-0.5], sigma: 1 deg/s, rate: 1e12 Hz}]\n", "m.yaml");
             }),
             Contains("m.yaml:2: gyro.x[0].rate: \"1e12 Hz\" is faster than any IMU"));
}

TEST_CASE("limit: at most 20 problems are listed, the rest counted") {
  std::string text = "gyro:\n  x:\n";
  for (int i = 0; i < 100; ++i) text += "    - {type: white, density: -" + std::to_string(i + 1) + " deg/sqrt(h)}\n";
  const std::string msg = messageOf([&] { errormodels::ImuErrorModel::fromString(text, "m.yaml"); });
  CHECK(std::count(msg.begin(), msg.end(), '\n') == 20);  // 20 problems + the count line
  CHECK_THAT(msg, Contains("... and 80 more problem(s) in m.yaml"));
}

TEST_CASE("limit: an offending value is echoed to at most 80 characters") {
  const std::string big(100000, 'x');
  const std::string msg = messageOf([&] {
    sim::parseScenario(scenarioWith("", "  - {type: static, duration: " + big + "}\n"), "s.yaml",
                       ".");
  });
  CHECK_THAT(msg, Contains("s.yaml:3: segments[0].duration:"));
  CHECK_THAT(msg, Contains("... (100000 characters)"));
  CHECK(msg.size() < 600);
}

TEST_CASE("limit: record columns, field length, values, and the sample rate range") {
  using errormodels::parseRecord;
  std::string header;
  for (int i = 0; i < 65; ++i) header += (i ? ",c" : "c") + std::to_string(i);
  CHECK_THAT(messageOf([&] { parseRecord(header + "\n", "r.csv"); }),
             Contains("r.csv:1: header: more than 64 columns"));
  CHECK_THAT(messageOf([] { parseRecord("t,gx\n0," + std::string(100, '1') + "\n", "r.csv"); }),
             Contains("r.csv:2: column \"gx\": a field longer than 64 characters"));
  CHECK_THAT(messageOf([] { parseRecord("t,gx\n0,1e300\n1,0\n", "r.csv"); }),
             Contains("r.csv:2: column \"gx\": value 1e+300 (SI) is beyond any sensor"));
  // Time steps of 1e6 s (1e-6 Hz) and 1e-12 s (1e12 Hz); a rate option of 1e-300 Hz.
  CHECK_THAT(messageOf([] { parseRecord("t,gx\n0,1\n1e6,2\n2e6,3\n", "r.csv"); }),
             Contains("r.csv: the time stamps' rate 1e-06 Hz is outside what an IMU record can be "
                      "(0.001 to 100000 Hz"));
  CHECK_THAT(messageOf([] { parseRecord("t,gx\n0,1\n1e-12,2\n2e-12,3\n", "r.csv"); }),
             Contains("outside what an IMU record can be"));
  errormodels::RecordOptions o;
  o.rate_hz = 1e-300;
  CHECK_THAT(messageOf([&] { parseRecord("gx\n1\n2\n", "r.csv", o); }),
             Contains("r.csv: the rate option (--rate) 1e-300 Hz is outside"));
}

TEST_CASE("limit: the ideal IMU checks duration x rate before its integer conversion") {
  // Guarded separately from the scenario reader: a Trajectory built in code reaches it directly.
  CHECK_FALSE(limits::tooManySamples(2078.0, 100.0));
  CHECK(limits::tooManySamples(1e308, 100.0));   // overflows to inf
  CHECK(limits::tooManySamples(1e7, 100.0));     // 1e9 samples
  CHECK(limits::tooManySamples(NAN, 100.0));
}
