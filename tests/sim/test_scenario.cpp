// Scenario parsing: the shipped examples load, every bad input is reported with file, line and
// key path, all problems of a file at once.
#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <string>

#include "common/constants.hpp"
#include "common/error.hpp"
#include "sim/scenario.hpp"
#include "test_support.hpp"

using namespace sinsim;

namespace {

// The diagnostics of parsing `text`, or a test failure if it parses.
std::vector<Diagnostic> problems(const std::string& text) {
  try {
    sim::parseScenario(text, "bad.yaml");
  } catch (const ConfigError& e) {
    return e.diagnostics();
  }
  FAIL("scenario parsed without error:\n" << text);
  return {};
}

bool has(const std::vector<Diagnostic>& ds, int line, const std::string& key,
         const std::string& fragment) {
  return test::hasDiagnostic(ds, "bad.yaml", line, key, fragment);
}

std::string listing(const std::vector<Diagnostic>& ds) {
  std::string s;
  for (const auto& d : ds) s += d.str() + "\n";
  return s;
}

const char* kGood = R"(start: {latitude: 45 deg, longitude: 7 deg}
segments: [{type: static, duration: 10 s}]
)";
}  // namespace

TEST_CASE("shipped scenarios load with the documented durations") {
  const std::string dir = std::string(SINSIM_SOURCE_DIR) + "/scenarios/";
  const sim::Scenario st = sim::loadScenario(dir + "static.yaml");
  CHECK(st.duration() == 3600.0);
  CHECK(st.start.lat == Approx(45.0 * kPi / 180.0).epsilon(1e-15));
  const sim::Scenario car = sim::loadScenario(dir + "car.yaml");
  CHECK(car.duration() >= 1800.0);  // issue 2: ≥ 30 min
  CHECK(car.duration() == Approx(90.0 + 7 * 284.0).epsilon(1e-12));
  const sim::Scenario air = sim::loadScenario(dir + "aircraft.yaml");
  CHECK(air.duration() > 1800.0);
  CHECK(air.imuRate == 100.0);
  CHECK(air.outputRate == 1.0);
  CHECK(air.strapdown.vertical == nav::VerticalChannel::Damped);
}

TEST_CASE("defaults and units") {
  const sim::Scenario sc = sim::parseScenario(kGood, "good.yaml");
  CHECK(sc.name == "good");
  CHECK(sc.imuRate == 100.0);
  CHECK(sc.outputRate == 1.0);
  CHECK(sc.decimation() == 100);
  CHECK(sc.errors.empty());
  CHECK_FALSE(sc.temperature.present);
  CHECK(std::isnan(sc.temperature.at(0.0)));
  CHECK_FALSE(sc.seed.has_value());

  const sim::Scenario t = sim::parseScenario(R"(
start: {latitude: 1 deg, longitude: 2 deg, speed: 36 kph, heading: -90 deg}
imu_rate: 200 Hz
output_rate: 10 Hz
vertical: held
temperature: {start: 20 degC, end: 30 degC}
seed: 7
segments:
  - {type: cruise, duration: 1 min}
  - {type: turn, heading: 0 deg, duration: 10 s}
  - {type: repeat, count: 3, segments: [{type: accelerate, speed: 20 m/s, duration: 5 s},
                                        {type: decelerate, speed: 10 m/s, duration: 5 s}]}
)", "t.yaml");
  CHECK(t.start.speed == Approx(10.0).epsilon(1e-15));
  CHECK(t.decimation() == 20);
  CHECK(t.strapdown.vertical == nav::VerticalChannel::Held);
  CHECK(t.temperature.at(0.0) == Approx(293.15).epsilon(1e-15));
  CHECK(t.temperature.at(t.duration()) == Approx(303.15).epsilon(1e-14));
  CHECK(*t.seed == 7);
  REQUIRE(t.segments.size() == 8);
  CHECK(t.duration() == 100.0);
  CHECK(t.segments[1].change == Approx(kPi / 2).epsilon(1e-15));  // -90° → 0°: a right turn
  CHECK(t.segments[7].change == Approx(-10.0).epsilon(1e-15));
}

TEST_CASE("bad scenario: unknown key names it, its line and the known keys") {
  const auto ds = problems(R"(start:
  latitude: 45 deg
  longitud: 7 deg
segments: [{type: static, duration: 10 s}]
)");
  INFO(listing(ds));
  CHECK(has(ds, 3, "start.longitud", "did you mean \"longitude\""));
  CHECK(has(ds, 2, "start.longitude", "missing key"));  // the line where start's map begins
}

TEST_CASE("bad scenario: missing start") {
  const auto ds = problems("segments: [{type: static, duration: 10 s}]\n");
  INFO(listing(ds));
  CHECK(has(ds, 1, "start", "missing key"));
}

TEST_CASE("bad scenario: negative and zero durations") {
  const auto ds = problems(R"(start: {latitude: 45 deg, longitude: 7 deg}
segments:
  - {type: static, duration: 10 s}
  - {type: static, duration: -3 s}
  - {type: static, duration: 0 s}
)");
  INFO(listing(ds));
  CHECK(has(ds, 4, "segments[1].duration", "expected a positive duration, got \"-3 s\""));
  CHECK(has(ds, 5, "segments[2].duration", "expected a positive duration"));
}

TEST_CASE("bad scenario: a unit that does not fit") {
  const auto ds = problems(R"(start:
  latitude: 45 m
  longitude: 7 deg
segments: [{type: static, duration: 10 m/s}]
)");
  INFO(listing(ds));
  CHECK(has(ds, 2, "start.latitude", "expected a value in deg"));
  CHECK(has(ds, 4, "segments[0].duration", "expected a value in s"));
}

TEST_CASE("bad scenario: unknown segment type lists the known ones") {
  const auto ds = problems(R"(start: {latitude: 45 deg, longitude: 7 deg}
segments:
  - {type: static, duration: 10 s}
  - {type: hover, duration: 10 s}
)");
  INFO(listing(ds));
  CHECK(has(ds, 4, "segments[1].type",
            "unknown segment type \"hover\" (known: accelerate, climb, cruise, decelerate, "
            "descend, pitch, roll, static, turn, repeat)"));
}

TEST_CASE("bad scenario: every problem of the file is reported at once") {
  const auto ds = problems(R"(start: {latitude: 95 deg, longitude: 7 deg, speed: -1 m/s}
imu_rate: 100 Hz
output_rate: 3 Hz
vertical: sinking
colour: red
segments:
  - {type: turn, heading_change: 90 deg, heading: 10 deg, duration: 5 s}
  - {type: climb, height_change: -5 m, duration: 5 s}
  - {type: repeat, count: 0, segments: [{type: cruise}]}
)");
  INFO(listing(ds));
  CHECK(has(ds, 1, "start.latitude", "89 deg"));
  CHECK(has(ds, 1, "start.speed", "speed ≥ 0"));
  CHECK(has(ds, 3, "output_rate", "divide"));
  CHECK(has(ds, 4, "vertical", "free, held, damped"));
  CHECK(has(ds, 5, "colour", "unknown key"));
  CHECK(has(ds, 7, "segments[0]", "not both"));
  CHECK(has(ds, 8, "segments[1].height_change", "use descend"));
  CHECK(has(ds, 9, "segments[2].count", "count ≥ 1"));
  CHECK(has(ds, 9, "segments[2].segments[0].duration", "missing key"));
  CHECK(ds.size() == 9);
}

TEST_CASE("bad scenario: a repeat count of 2.5 is one problem, said once") {
  const auto ds = problems(R"(start: {latitude: 45 deg, longitude: 7 deg}
segments:
  - {type: repeat, count: 2.5, segments: [{type: static, duration: 1 s}]}
)");
  INFO(listing(ds));
  CHECK(has(ds, 3, "segments[0].count", "expected an integer"));
  CHECK(ds.size() == 1);
}

TEST_CASE("bad scenario: motions that cannot be flown, located at their segment") {
  SECTION("static while moving") {
    const auto ds = problems(R"(start: {latitude: 45 deg, longitude: 7 deg, speed: 10 m/s}
segments:
  - {type: cruise, duration: 10 s}
  - {type: static, duration: 10 s}
)");
    INFO(listing(ds));
    CHECK(has(ds, 4, "segments[1]", "at rest"));
  }
  SECTION("too steep a climb, inside a repeat") {
    const auto ds = problems(R"(start: {latitude: 45 deg, longitude: 7 deg, speed: 10 m/s}
segments:
  - type: repeat
    count: 3
    segments:
      - {type: climb, height_change: 40 m, duration: 10 s}
      - {type: decelerate, speed: 1 m/s, duration: 10 s}
)");
    INFO(listing(ds));
    // 10 m/s: 2·40/10 = 8 m/s peak vertical speed is fine; at 1 m/s on the second lap it is not
    CHECK(has(ds, 6, "segments[0].segments[0]", "too steep"));
    CHECK(has(ds, 6, "segments[0].segments[0]", "(repetition 2 of 3)"));
    CHECK(ds.size() == 1);
  }
  SECTION("decelerate that speeds up, bank without speed") {
    const auto ds = problems(R"(start: {latitude: 45 deg, longitude: 7 deg}
segments:
  - {type: turn, heading_change: 90 deg, bank: 20 deg}
)");
    INFO(listing(ds));
    CHECK(has(ds, 3, "segments[0]", "needs forward speed"));
  }
  SECTION("bank: auto beyond the 80 deg an explicit bank may have") {
    // 180 deg in 5 s at 300 m/s: peak tan(phi) = 2 * 300 * pi / 5 / 9.80665 -> 88.51 deg; it ran.
    // The shortest duration keeping 80 deg: 2 * 300 * pi / (9.80665 tan 80 deg) = 33.89 s.
    const auto ds = problems(R"(start: {latitude: 45 deg, longitude: 7 deg, speed: 300 m/s}
segments:
  - {type: turn, heading_change: 180 deg, duration: 5 s, bank: auto}
)");
    INFO(listing(ds));
    CHECK(has(ds, 3, "segments[0]", "bank: auto peaks at 88.5099 deg, beyond 80 deg"));
    CHECK(has(ds, 3, "segments[0]", "at least 33.8922 s"));
    // 34 s keeps it: parses.
    CHECK_NOTHROW(sim::parseScenario(R"(start: {latitude: 45 deg, longitude: 7 deg, speed: 300 m/s}
segments:
  - {type: turn, heading_change: 180 deg, duration: 34 s, bank: auto}
)", "ok.yaml"));
  }
}

TEST_CASE("bad scenario: error model file that does not exist is located at errors") {
  try {
    sim::parseScenario(std::string(kGood) + "errors: no/such/model.yaml\n", "bad.yaml", "/tmp");
    FAIL("parsed");
  } catch (const ConfigError& e) {
    INFO(e.what());
    CHECK(std::string(e.what()).find("/tmp/no/such/model.yaml") != std::string::npos);
  }
}

TEST_CASE("One TemperatureProfile for synth's --temperature: constant, ramp, CSV table", "[scenario][temperature]") {
  // Closed forms: degC + 273.15; a ramp over [0, T] is linear and ends on its end value; a table
  // is piecewise linear through its knots (exactly at the knots: w = 1 gives t_i + (t_{i+1} - t_i),
  // exact for these small integers) and held outside its span. 1e-12 K: a few ulps of 300 K.
  const sim::TemperatureProfile c = sim::temperatureFromText("25 degC", 100.0);
  CHECK(c.at(0.0) == Approx(298.15).margin(1e-12));
  CHECK(c.at(1e6) == Approx(298.15).margin(1e-12));
  const sim::TemperatureProfile r = sim::temperatureFromText("20 degC..45 degC", 100.0);
  CHECK(r.at(0.0) == Approx(293.15).margin(1e-12));
  CHECK(r.at(50.0) == Approx(305.65).margin(1e-12));
  CHECK(r.at(100.0) == Approx(318.15).margin(1e-12));
  const auto dir = sinsim::test::freshTempDir("temperature_table");
  const std::string csv = (dir / "t.csv").string();
  sinsim::test::writeText(csv, "t,temp\n0,20\n10,30\n20,25\n");
  const sim::TemperatureProfile t = sim::temperatureFromText(csv, 100.0);
  CHECK(t.at(-5.0) == Approx(293.15).margin(1e-12));   // held before the first row
  CHECK(t.at(5.0) == Approx(298.15).margin(1e-12));
  CHECK(t.at(10.0) == Approx(303.15).margin(1e-12));   // a knot
  CHECK(t.at(15.0) == Approx(300.65).margin(1e-12));
  CHECK(t.at(99.0) == Approx(298.15).margin(1e-12));   // held after the last row
  // Calls need not come in increasing time (the old reader kept a cursor and required it).
  CHECK(t.at(5.0) == Approx(298.15).margin(1e-12));
  CHECK_THROWS_AS(sim::temperatureFromText("hot", 100.0), InputError);
  // Outside (0 K, 1000 degC], as a scenario's temperature: refused (a ramp to 1e300 degC wrote
  // a record the reader then refused).
  CHECK_THROWS_WITH(sim::temperatureFromText("20 degC..1e300 degC", 100.0), Catch::Contains("outside (-273.15, 1000] degC"));
  CHECK_THROWS_WITH(sim::temperatureFromText("2000 degC", 100.0), Catch::Contains("outside (-273.15, 1000] degC"));
  sinsim::test::writeText(csv, "t,temp\n0,20\n10,-300\n");
  CHECK_THROWS_WITH(sim::temperatureFromText(csv, 100.0), Catch::Contains("outside (-273.15, 1000] degC"));
  // Not a regular file: refused by name, never opened (a FIFO waited for a writer, /dev/zero
  // filled the memory).
  const std::string fifo = (dir / "fifo").string();
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  CHECK_THROWS_WITH(sim::temperatureFromText(fifo, 100.0), Catch::Contains("expected a temperature CSV (a regular file)"));
  CHECK_THROWS_WITH(sim::temperatureFromText("/dev/zero", 100.0), Catch::Contains("expected a temperature CSV (a regular file)"));
}

TEST_CASE("bad scenario: a longitude beyond ±360 deg and a pitch of 90 deg are refused, located") {
  const auto ds = problems(R"(start:
  latitude: 45 deg
  longitude: 540 deg
  attitude: {pitch: 90 deg}
segments: [{type: static, duration: 10 s}]
)");
  INFO(listing(ds));
  CHECK(has(ds, 3, "start.longitude", "expected a longitude within ±360 deg"));
  CHECK(has(ds, 4, "start.attitude.pitch", "strictly between -90 and 90 deg"));
  // 0–360° longitudes are read modulo 360° (the same place).
  const sim::Scenario sc = sim::parseScenario(R"(start: {latitude: 45 deg, longitude: 200 deg}
segments: [{type: static, duration: 10 s}]
)", "lon.yaml");
  CHECK(sc.start.lon * 180.0 / kPi == Approx(-160.0).epsilon(1e-12));
}

TEST_CASE("bad scenario: a refused segment or rate makes no follow-on errors") {
  // Found by a blind probe: a refused segment shortened the scenario, so an outage inside the
  // intended run was reported "after the scenario's end"; a refused IMU rate was compared with the
  // GNSS rate ("GNSS at 1 Hz is faster than the IMU (-100 Hz)").
  const std::string aiding = R"(gnss:
  rate: 1 Hz
  position_sigma: [1 m, 1 m, 2 m]
  outages: [[30 s, 40 s]]
)";
  auto ds = problems(R"(start: {latitude: 45 deg, longitude: 7 deg}
segments:
  - {type: static, duration: 20 s}
  - {type: climb, height_change: 10 m, duration: 10 s}
  - {type: cruise, duration: 20 s}
)" + aiding);
  INFO(listing(ds));
  CHECK(has(ds, 4, "segments[1]", "needs forward speed"));
  CHECK(listing(ds).find("after the scenario's end") == std::string::npos);
  ds = problems(R"(start: {latitude: 45 deg, longitude: 7 deg}
imu_rate: -100 Hz
segments: [{type: static, duration: 50 s}]
)" + aiding);
  INFO(listing(ds));
  CHECK(has(ds, 2, "imu_rate", "expected a rate of at least"));
  CHECK(listing(ds).find("faster than the IMU") == std::string::npos);
}

TEST_CASE("a scenario's name never leads its default output folder out of out/") {
  auto folder = [](const std::string& name) {
    const sim::Scenario sc = sim::parseScenario("name: \"" + name + "\"\nstart: {latitude: 45 deg, longitude: 7 deg, "
                                                "height: 0 m, heading: 0 deg}\nsegments:\n  - {type: static, duration: 10 s}\n",
                                                "s.yaml");
    return sc.folderName();
  };
  CHECK(folder("car-10min_v2.1") == "car-10min_v2.1");  // an ordinary name as it is
  CHECK(folder("../../escaped") == ".._.._escaped");     // one folder inside out/, not two up
  CHECK(folder("/tmp/abs") == "_tmp_abs");
  CHECK(folder("..") == "scenario");
  CHECK(folder(".") == "scenario");
  CHECK(folder("a\\\\b c") == "a_b_c");
  const sim::Scenario sc = sim::parseScenario("name: \"..\"\nstart: {latitude: 45 deg, longitude: 7 deg, height: 0 m, "
                                              "heading: 0 deg}\nsegments:\n  - {type: static, duration: 10 s}\n",
                                              "s.yaml");
  CHECK(sc.folderName("mc-") == "mc-..");  // one name, not the parent: no separator in it
}
