// `run` with the aiding keys of a scenario: coarse alignment from the static start, initial
// errors, the GNSS/INS filter (typed model), outputs; and the scenario reader's messages.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/constants.hpp"
#include "common/error.hpp"
#include "sim/run.hpp"
#include "sim/scenario_aiding.hpp"
#include "test_support.hpp"

using namespace sinsim;

using sinsim::kRadPerDeg;

namespace {

const char* kBase = R"(
name: aided
start: {latitude: 48 deg, longitude: 11 deg, height: 500 m, heading: 60 deg}
imu_rate: 100 Hz
vertical: free
segments:
  - {type: static, duration: 60 s}
  - {type: accelerate, speed: 10 m/s, duration: 10 s}
  - {type: cruise, duration: 50 s}
)";

std::string tmpDir(const char* name) {
  return sinsim::test::freshTempDir("sinsim-aided-" + std::string(name)).string();
}
// The message a scenario text is refused with; the test fails where it is accepted.
std::string refusal(const std::string& text, const std::string& name) {
  try {
    sim::parseScenario(text, name);
  } catch (const ConfigError& e) {
    return e.what();
  }
  FAIL("expected a ConfigError for " << name);
  return {};
}

}  // namespace

TEST_CASE("coarse alignment in a run: a 5 deg heading error is gyrocompassed away") {
  // Perfect IMU: the leveling and gyrocompassing errors are those of the strapdown's 60 s of
  // static navigation held at the start (none) — the closed-form limits with zero biases are 0;
  // 1e-6 rad allows the Earth-rate averaging over the held interval.
  const std::string text = std::string(kBase) + R"(
initial_errors: {attitude: [1 deg, -1 deg, 5 deg]}
alignment: {duration: 60 s}
)";
  const sim::Scenario sc = sim::parseScenario(text, "aided.yaml");
  double yawAfterAlign = NAN, yawFree = NAN;
  sim::RunOptions o;
  o.onRow = [&](const sim::NavError& e) {
    if (std::abs(e.t - 61.0) < 1e-9) yawAfterAlign = e.euler.z();
  };
  sim::run(sc, o);
  const sim::Scenario free = sim::parseScenario(std::string(kBase) + R"(
initial_errors: {attitude: [1 deg, -1 deg, 5 deg]}
)", "free.yaml");
  o.onRow = [&](const sim::NavError& e) {
    if (std::abs(e.t - 61.0) < 1e-9) yawFree = e.euler.z();
  };
  sim::run(free, o);
  CHECK(std::abs(yawFree - 5 * kRadPerDeg) < 1e-3);  // the initial error stays without alignment
  CHECK(std::abs(yawAfterAlign) < 1e-6);
}

TEST_CASE("a run with initial errors and an alignment but no filter writes no filter.csv") {
  // No filter runs, so there is no filter row to write: before, a header-only filter.csv was
  // written and listed among the run's files.
  const sim::Scenario sc = sim::parseScenario(std::string(kBase) + R"(
initial_errors: {attitude: [1 deg, -1 deg, 5 deg]}
alignment: {duration: 60 s}
)", "aligned.yaml");
  sim::RunOptions o;
  o.outDir = tmpDir("no-filter");
  std::filesystem::remove_all(o.outDir);
  const sim::RunSummary s = sim::run(sc, o);
  CHECK_FALSE(std::filesystem::exists(o.outDir + "/filter.csv"));
  CHECK(std::find(s.files.begin(), s.files.end(), "filter.csv") == s.files.end());
  CHECK(std::filesystem::exists(o.outDir + "/nav.csv"));
  std::ifstream j(o.outDir + "/summary.json");
  const nlohmann::json summary = nlohmann::json::parse(j);
  CHECK_FALSE(summary["files"].contains("filter"));
  std::filesystem::remove_all(o.outDir);
}

TEST_CASE("aided run: filter.csv, imu.csv and per-outage drift in the summary") {
  const std::string text = std::string(kBase) + R"(
initial_errors: {position: {sigma: 3 m}, velocity: {sigma: 0.1 m/s}, attitude: {sigma: [0.5 deg, 0.5 deg, 3 deg]}}
gnss: {rate: 1 Hz, position_sigma: [1 m, 1 m, 2 m], outages: [[90 s, 110 s]]}
)";
  // A gnss block without a filter is refused with its line and key.
  try {
    sim::parseScenario(text, "aided.yaml");
    FAIL("expected a ConfigError");
  } catch (const ConfigError& e) {
    CHECK(std::string(e.what()).find("aided.yaml:") != std::string::npos);
    CHECK(std::string(e.what()).find("gnss") != std::string::npos);
  }
  const sim::Scenario sc = sim::parseScenario(text + R"(
filter: {model: {gyro: {all: [{type: white, density: 0.1 deg/sqrt(h)}], x: [{type: bias, sigma: 1 deg/h}],
                        triad: [{type: misalignment, matrix: [[0, 0, 0], [0, 0, 0], [1 mrad, 0, 0]]}]},
                 accel: {all: [{type: white, density: 0.05 m/s/sqrt(h)}]}}}
)", "aided.yaml");
  sim::RunOptions o;
  o.writeImu = true;
  o.outDir = tmpDir("run");
  std::filesystem::remove_all(o.outDir);
  const sim::RunSummary s = sim::run(sc, o);
  REQUIRE(s.outages.size() == 1);
  // Perfect IMU, exact GNSS model: the outage drift is the 20-s growth of a converged, metre-level
  // error; a filter that ignored the fixes would carry the 3 m start plus 0.1 m/s x 110 s.
  CHECK(s.outages[0].maxHorizontal < 3.0);
  CHECK(s.outages[0].sigmaHorizontal > 0.0);
  std::ifstream f(o.outDir + "/filter.csv"), imu(o.outDir + "/imu.csv");
  std::string header, row;
  REQUIRE(std::getline(f, header));
  CHECK(header.rfind("t_s,north_m", 0) == 0);
  int rows = 0, emptyNis = 0;
  while (std::getline(f, row)) {
    ++rows;
    // No NaN or inf in the file: the NIS of an epoch without a fix is an empty field, with
    // nis_dof 0 (columns ..., nees, nis, nis_dof, aiding, outage).
    CHECK(row.find("nan") == std::string::npos);
    CHECK(row.find("inf") == std::string::npos);
    std::vector<std::string> fields;
    std::stringstream ss(row);
    for (std::string x; std::getline(ss, x, ',');) fields.push_back(x);
    if (row.back() == ',') fields.push_back("");
    REQUIRE(fields.size() == 24);
    const bool outage = fields[23] == "1";
    CHECK(fields[20].empty() == outage);
    CHECK((fields[21] == "0") == outage);
    CHECK(!fields[19].empty());  // the NEES exists at every filter epoch
    emptyNis += fields[20].empty() ? 1 : 0;
  }
  CHECK(rows == 120);  // one per GNSS clock second
  CHECK(emptyNis == 20);  // the 90-110 s outage
  REQUIRE(std::getline(imu, header));
  CHECK(header.find("ideal_wx_radps") != std::string::npos);
  rows = 0;
  while (std::getline(imu, row)) ++rows;
  CHECK(rows == 12000);
  nlohmann::json j;
  std::ifstream(o.outDir + "/summary.json") >> j;
  CHECK(j["outages"].size() == 1);
  // What the filter used of its model: its states per axis, white densities, known errors.
  const nlohmann::json& fj = j["filter"];
  CHECK(fj["model"] == "inline");
  CHECK(fj["sensor_states"] == 1);
  CHECK(fj["states_per_axis"]["gyro.x"][0]["process"] == "bias");
  CHECK(fj["states_per_axis"]["gyro.y"].empty());
  CHECK(fj["white_density_si"]["accel.z"].get<double>() == Approx(0.05 / 60.0).epsilon(1e-12));
  CHECK(fj["compensated_known_errors"] == nlohmann::json::array({"gyro.triad[0].misalignment"}));
  std::filesystem::remove_all(o.outDir);
}

TEST_CASE("aiding keys: every problem with its line and key") {
  const std::string text = std::string(kBase) + R"(
initial_errors: {position: [1 m, 2 m], attitude: {sigma: -1 deg}}
alignment: {duration: -5 s}
gnss: {rate: 0 Hz, outages: [[50 s, 40 s]]}
filter: {model: no-such-file.yaml}
)";
  {
    const std::string m = refusal(text, "bad.yaml");
    for (const char* key : {"initial_errors.position", "initial_errors.attitude.sigma",
                            "alignment.duration", "gnss.rate", "gnss.outages[0]", "filter.model"})
      CHECK(m.find(key) != std::string::npos);
  }
  // Fixes that measure nothing, and an antenna a million km away (1e9 mm read as m).
  {
    const std::string m = refusal(std::string(kBase) + R"(
gnss: {rate: 1 Hz, lever_arm: [1e9 m, 0 m, 0 m]}
filter: {model: {gyro: {all: [{type: white, density: 0.01 deg/sqrt(h)}]}}}
)", "bad.yaml");
    CHECK(m.find("bad.yaml:11: gnss: expected position_sigma, velocity_sigma or both") !=
          std::string::npos);
    CHECK(m.find("gnss.lever_arm: expected an antenna within 1 km") != std::string::npos);
  }
  // A lever arm of two values: that, in body axes, and no second message about its size.
  {
    const std::string m = refusal(std::string(kBase) + R"(
gnss: {rate: 1 Hz, position_sigma: 1 m, lever_arm: [1 m, 2 m]}
filter: {model: {gyro: {all: [{type: white, density: 0.01 deg/sqrt(h)}]}}}
)", "bad.yaml");
    INFO(m);
    CHECK(m.find("gnss.lever_arm: expected 3 values (x, y, z in body axes), got 2") != std::string::npos);
    CHECK(m.find("within 1 km") == std::string::npos);
  }
  // Fixes finer than any GNSS (a blind probe's 1e-9 m: NEES mean 1e12, no word): refused, each
  // sigma at its key; 1 mm and 1 mm/s are taken.
  {
    const std::string m = refusal(std::string(kBase) + R"(
gnss: {rate: 1 Hz, position_sigma: [1 m, 1 m, 1e-9 m], velocity_sigma: 0.5 mm/s}
filter: {model: {gyro: {all: [{type: white, density: 0.01 deg/sqrt(h)}]}}}
)", "fine.yaml");
    INFO(m);
    CHECK(m.find("fine.yaml:11: gnss.position_sigma: expected at least 1 mm") != std::string::npos);
    CHECK(m.find("fine.yaml:11: gnss.velocity_sigma: expected at least 1 mm/s") != std::string::npos);
  }
  // `none` is a perfect IMU for `errors`, no filter model (was "no such model file: .../none").
  {
    const std::string m = refusal(std::string(kBase) + "gnss: {rate: 1 Hz, position_sigma: 1 m}\nfilter: {model: none}\n",
                                  "none.yaml");
    INFO(m);
    CHECK(m.find("none.yaml:11: filter.model: a filter needs a sensor model") != std::string::npos);
  }
  CHECK_NOTHROW(sim::parseScenario(std::string(kBase) + R"(
gnss: {rate: 1 Hz, position_sigma: 1 mm, velocity_sigma: 1 mm/s}
filter: {model: {gyro: {all: [{type: white, density: 0.01 deg/sqrt(h)}]}}}
)", "rtk.yaml"));
}

TEST_CASE("coarse alignment is refused unless the vehicle is at rest over its window") {
  // An independent user's probe: a coarse alignment over a moving start ran silently and started
  // the filter kilometres off (NEES ~1e9 while aided by 1 m fixes); so did a window longer than the
  // static start. kBase: 60 s static, then it accelerates.
  std::string moving = kBase;
  moving.replace(moving.find("heading: 60 deg}"), 16, "heading: 60 deg, speed: 5 m/s}");
  moving.replace(moving.find("{type: static, duration: 60 s}"), 30, "{type: cruise, duration: 60 s}");
  for (const auto& [text, what] :
       {std::pair<std::string, std::string>{moving + "alignment: {duration: 30 s}\n",
                                            "it moves from t = 0 s (cruise segment, at 5 m/s)"},
        {std::string(kBase) + "alignment: {duration: 90 s}\n",
         "it moves from t = 60 s (accelerate segment)"}}) {
    try {
      sim::parseScenario(text, "align.yaml");
      FAIL("expected a ConfigError");
    } catch (const ConfigError& e) {
      const std::string m = e.what();
      INFO(m);
      CHECK(m.find("align.yaml:") != std::string::npos);
      CHECK(m.find("alignment.duration: coarse alignment needs the vehicle at rest") != std::string::npos);
      CHECK(m.find(what) != std::string::npos);
    }
  }
  // The static start's 60 s, or less, aligns.
  CHECK(sim::parseScenario(std::string(kBase) + "alignment: {duration: 60 s}\n", "ok.yaml")
            .aiding.alignment.duration == 60.0);
}

TEST_CASE("an outage given past the scenario's end lasts to the end, and says so") {
  // kBase lasts 120 s. Windows are [start, end): one that ends at 120 s leaves the last epoch its
  // fix; one given past the end holds it too and is reported ending at 120 s (not at 500 s).
  const sim::Scenario sc = sim::parseScenario(std::string(kBase) + R"(
gnss: {rate: 1 Hz, position_sigma: 1 m, outages: [[30 s, 40 s], [100 s, 500 s]]}
filter: {model: {gyro: {all: [{type: white, density: 0.1 deg/sqrt(h)}]}}}
)", "past.yaml");
  const auto& w = sc.aiding.gnss.outages;
  REQUIRE(w.size() == 2);
  CHECK(w[1].end == 120.0);
  CHECK(w[1].contains(120.0));
  CHECK(w[1].contains(119.0));
  CHECK_FALSE(w[1].contains(99.0));
  CHECK_FALSE(w[0].contains(40.0));
  CHECK(w[0].contains(39.99));
}

TEST_CASE("GNSS off: the aided run navigates bit-identically to the free-inertial run") {
  // Same seed, same IMU errors (the aiding's streams are separate, aided_navigation.hpp). With no
  // fix ever used — one outage over the whole run — and a filter model of zero-mean processes,
  // the filter predicts but estimates nothing, so the navigation must not move by a single bit;
  // likewise with the aiding hook present but every aiding key off.
  const std::string imu = std::string(kBase) + R"(
output_rate: 100 Hz
seed: 7
errors:
  gyro: {all: [{type: white, density: 0.1 deg/sqrt(h)}, {type: bias, sigma: 10 deg/h}]}
  accel: {all: [{type: white, density: 0.05 m/s/sqrt(h)}, {type: gauss_markov, sigma: 1 mg, tau: 60 s}]}
)";
  auto rows = [](const sim::Scenario& sc, sim::NavAiding* hook) {
    std::vector<sim::NavError> r;
    sim::RunOptions o;
    o.aiding = hook;
    o.onRow = [&](const sim::NavError& e) { r.push_back(e); };
    sim::run(sc, o);
    return r;
  };
  const std::vector<sim::NavError> free = rows(sim::parseScenario(imu, "free.yaml"), nullptr);
  const sim::Scenario off = sim::parseScenario(imu + R"(
gnss: {rate: 1 Hz, position_sigma: 1 m, outages: [[0 s, 200 s]]}
filter: {model: {gyro: {all: [{type: white, density: 0.1 deg/sqrt(h)}, {type: bias, sigma: 10 deg/h}]},
                 accel: {all: [{type: gauss_markov, sigma: 1 mg, tau: 60 s}]}}}
)", "off.yaml");
  REQUIRE(!off.aiding.inert());
  const std::vector<sim::NavError> aided = rows(off, nullptr);
  const sim::Scenario plain = sim::parseScenario(imu, "plain.yaml");
  sim::ScenarioAiding inertHook(sim::sharedEarth(), plain, {7, 0});
  const std::vector<sim::NavError> hooked = rows(plain, &inertHook);
  REQUIRE(free.size() == 12001);
  REQUIRE(aided.size() == free.size());
  REQUIRE(hooked.size() == free.size());
  int differ = 0;
  for (std::size_t k = 0; k < free.size(); ++k)
    for (const auto* other : {&aided, &hooked}) {
      const sim::NavError &a = free[k], &b = (*other)[k];
      if (!(a.pos_n == b.pos_n && a.vel_n == b.vel_n && a.euler == b.euler)) ++differ;
    }
  CHECK(differ == 0);
  CHECK(free.back().horizontal() > 1.0);  // the IMU errors do make the free run drift
}

TEST_CASE("start warnings: gyros that cannot gyrocompass and a start prior too wide warn, a good gyro and a narrow prior do not") {
  // The heading 1-sigma after alignment is ≈ σ_gyro,east / (Ω cos L) (nav/alignment.hpp): at 48°
  // Ω cos L = 10.1 deg/h, so a 20 deg/h gyro bias gives ~110° (the warning's threshold is 10°) and
  // a 0.05 deg/h one ~0.3°.
  auto scenario = [](const char* gyroBias) {
    return std::string(kBase) + R"(
alignment: {duration: 50 s}
gnss: {rate: 1 Hz, position_sigma: 1 m}
filter:
  model:
    gyro: {all: [{type: white, density: 0.01 deg/sqrt(h)}, {type: bias, sigma: )" +
           gyroBias + R"(}]}
    accel: {all: [{type: white, density: 0.05 m/s/sqrt(h)}, {type: bias, sigma: 0.5 mg}]}
)";
  };
  const sim::RunSummary bad = sim::run(sim::parseScenario(scenario("20 deg/h"), "mems.yaml"));
  REQUIRE(bad.warnings.size() >= 1);
  CHECK(bad.warnings[0].find("gyrocompass") != std::string::npos);
  // The heading then wanders beyond the filter's linearisation: its innovations say so too.
  for (std::size_t i = 1; i < bad.warnings.size(); ++i)
    CHECK(bad.warnings[i].find("GNSS innovations") != std::string::npos);
  const sim::RunSummary good = sim::run(sim::parseScenario(scenario("0.05 deg/h"), "fog.yaml"));
  CHECK(good.warnings.empty());
  // Without alignment the start is the user's: a 30° heading sigma is as far outside the filter's
  // validity, and so is 3° (more than 5 % of the runs start beyond 5°: 9.6 %); 2° is not (1.2 %).
  auto given = [](const char* yawSigma) {
    return std::string(kBase) + R"(
initial_errors: {attitude: {sigma: [1 deg, 1 deg, )" + yawSigma + R"(]}}
gnss: {rate: 1 Hz, position_sigma: 1 m}
filter: {model: {gyro: {all: [{type: white, density: 0.01 deg/sqrt(h)}]}}}
)";
  };
  const sim::RunSummary wide = sim::run(sim::parseScenario(given("30 deg"), "wide.yaml"));
  REQUIRE(wide.warnings.size() >= 1);
  CHECK(wide.warnings[0].find("initial_errors.attitude") != std::string::npos);
  for (std::size_t i = 1; i < wide.warnings.size(); ++i) {
    INFO(wide.warnings[i]);
    CHECK(wide.warnings[i].find("GNSS innovations") != std::string::npos);
  }
  const sim::RunSummary three = sim::run(sim::parseScenario(given("3 deg"), "three.yaml"));
  REQUIRE(three.warnings.size() >= 1);
  CHECK(three.warnings[0].find("attitude 1-sigma of 3 deg (roll, pitch, yaw: 1, 1, 3 deg)") != std::string::npos);
  CHECK(three.warnings[0].find("a 1-sigma above 2.55 deg") != std::string::npos);
  for (const std::string& w : sim::run(sim::parseScenario(given("2 deg"), "two.yaml")).warnings) {
    INFO(w);
    CHECK(w.find("initial_errors.attitude") == std::string::npos);
  }
  // A start position uncertain by more than 10 km (a blind probe's 1000 km: no word but the
  // innovations', and a filter that never recovered) is warned; 10 km is not.
  auto placed = [](const char* sigma) {
    return std::string(kBase) + "initial_errors: {position: {sigma: " + sigma + R"(}}
gnss: {rate: 1 Hz, position_sigma: 1 m}
filter: {model: {gyro: {all: [{type: white, density: 0.01 deg/sqrt(h)}]}}}
)";
  };
  const std::vector<std::string> far = sim::run(sim::parseScenario(placed("1000 km"), "far.yaml")).warnings;
  REQUIRE(far.size() >= 1);
  CHECK(far[0].find("initial_errors.position: the filter starts with a horizontal 1-sigma of 1000 km") == 0);
  for (const std::string& w : sim::run(sim::parseScenario(placed("10 km"), "near.yaml")).warnings) {
    INFO(w);
    CHECK(w.find("initial_errors.position") == std::string::npos);
  }
}

TEST_CASE("an outage's maximum is over every IMU epoch in its window, with the sigma the next filter step predicts") {
  // A 1 mg north accelerometer bias the filter's model lacks: the error grows through the 30 s
  // outage to its last IMU epoch (119.99 s), 10 ms before the next fix; a maximum taken at the
  // 1 Hz fixes stopped at 119 s, 4 % low. A window inside the alignment has no filter: empty.
  const sim::Scenario sc = sim::parseScenario(R"(
name: outage-max
start: {latitude: 48 deg, longitude: 11 deg, height: 500 m, heading: 0 deg}
imu_rate: 100 Hz
output_rate: 100 Hz
segments:
  - {type: static, duration: 60 s}
  - {type: accelerate, speed: 10 m/s, duration: 10 s}
  - {type: cruise, duration: 60 s}
errors: {accel: {x: [{type: bias, value: 1 mg}]}}
alignment: {duration: 20 s}
gnss: {rate: 1 Hz, position_sigma: [1 m, 1 m, 2 m], outages: [[5 s, 15 s], [90 s, 120 s]]}
filter: {model: {gyro: {all: [{type: white, density: 0.1 deg/sqrt(h)}]},
                 accel: {all: [{type: white, density: 0.05 m/s/sqrt(h)}]}}}
)", "outage-max.yaml");
  sim::RunOptions o;
  o.outDir = tmpDir("outage-max");
  std::filesystem::remove_all(o.outDir);
  double maxRow = 0.0, atRow = NAN;
  o.onRow = [&](const sim::NavError& e) {
    if (e.t >= 90.0 && e.t < 120.0 && e.horizontal() >= maxRow) maxRow = e.horizontal(), atRow = e.t;
  };
  const sim::RunSummary s = sim::run(sc, o);
  REQUIRE(s.outages.size() == 2);
  CHECK(std::isnan(s.outages[0].maxHorizontal));
  CHECK(std::isnan(s.outages[0].sigmaHorizontal));
  const sim::aided::OutageResult& w = s.outages[1];
  CHECK(w.t == Approx(119.99).margin(1e-9));
  CHECK(atRow == Approx(119.99).margin(1e-9));
  CHECK(w.maxHorizontal == Approx(maxRow).epsilon(1e-9));
  // The filter's sigma at the last fix epoch inside the window (119 s), from filter.csv: the one
  // the step at 120 s predicts (before its fix) grew about as much as in the second before.
  std::ifstream f(o.outDir + "/filter.csv");
  std::string row;
  std::vector<double> sigma;  // horizontal sigma at 118 s, 119 s
  while (std::getline(f, row))
    if (row.rfind("118.000000,", 0) == 0 || row.rfind("119.000000,", 0) == 0) {
      std::vector<double> v;
      std::stringstream ss(row);
      for (std::string x; std::getline(ss, x, ',');) v.push_back(x.empty() ? NAN : std::stod(x));
      sigma.push_back(std::hypot(v[10], v[11]));
    }
  REQUIRE(sigma.size() == 2);
  REQUIRE(sigma[1] > sigma[0]);
  CHECK(w.sigmaHorizontal - sigma[1] > 0.8 * (sigma[1] - sigma[0]));
  CHECK(w.sigmaHorizontal - sigma[1] < 1.25 * (sigma[1] - sigma[0]));
  nlohmann::json j;
  std::ifstream(o.outDir + "/summary.json") >> j;
  CHECK(j["outages"][0]["max_horizontal_m"].is_null());
  CHECK(j["outages"][1]["max_horizontal_m"].get<double>() == Approx(maxRow).epsilon(1e-9));
  std::filesystem::remove_all(o.outDir);
}

TEST_CASE("GNSS whose every fix falls after the end, in the alignment or in outages is warned, not refused") {
  // One outage over the whole run is GNSS off on purpose (the free-inertial comparison); a rate
  // too slow for the run is a slip. Both run, with the warning.
  const std::string filter = R"(
filter: {model: {gyro: {all: [{type: white, density: 0.1 deg/sqrt(h)}]}, accel: {all: [{type: white, density: 0.05 m/s/sqrt(h)}]}}}
)";
  auto warnings = [&](const std::string& extra) {
    std::string all;
    for (const std::string& w : sim::run(sim::parseScenario(std::string(kBase) + filter + extra, "fixes.yaml"), {}).warnings)
      all += w + "\n";
    return all;
  };
  // 120 s: a fix every 1000 s never comes; every 100 s comes at 100 s, inside [90 s, 120 s].
  CHECK_THAT(warnings("gnss: {rate: 0.001 Hz, position_sigma: [1 m, 1 m, 2 m]}\n"),
             Catch::Contains("gnss: no fix is used: fixes every 1000 s (rate 0.001 Hz)"));
  CHECK_THAT(warnings("gnss: {rate: 0.01 Hz, position_sigma: [1 m, 1 m, 2 m], outages: [[90 s, 120 s]]}\n"),
             Catch::Contains("no fix is used"));
  CHECK_THAT(warnings("alignment: {duration: 60 s}\ngnss: {rate: 1 Hz, position_sigma: [1 m, 1 m, 2 m], outages: [[50 s, 200 s]]}\n"),
             Catch::Contains("no fix is used"));
  // One fix is enough: at 100 s outside the outage; at 120 s, the scenario's last epoch.
  CHECK(warnings("gnss: {rate: 0.01 Hz, position_sigma: [1 m, 1 m, 2 m], outages: [[10 s, 90 s]]}\n").find("no fix") ==
        std::string::npos);
  CHECK(warnings("gnss: {rate: 1 Hz, position_sigma: [1 m, 1 m, 2 m], outages: [[0 s, 119.5 s]]}\n").find("no fix") ==
        std::string::npos);
}

TEST_CASE("run warns when the GNSS innovations are far beyond what the filter's model predicts") {
  // Truth: white gyro and accelerometer noise of a MEMS and a 10 mg accelerometer bias; the
  // filter's model: the same, or ten times less noise and no bias. The NIS sum over the fixes is
  // a chi-square of 3 per fix when the model is right.
  const std::string base = std::string(kBase) + R"(
errors: {gyro: {all: [{type: white, density: 0.3 deg/sqrt(h)}]},
         accel: {all: [{type: white, density: 0.1 m/s/sqrt(h)}], x: [{type: bias, value: 10 mg}]}}
gnss: {rate: 1 Hz, position_sigma: [1 m, 1 m, 2 m]}
)";
  auto warnings = [&](const std::string& filter) {
    std::string all;
    for (const std::string& w : sim::run(sim::parseScenario(base + filter, "nis.yaml"), {}).warnings) all += w;
    return all;
  };
  const std::string right = warnings(R"(
filter: {model: {gyro: {all: [{type: white, density: 0.3 deg/sqrt(h)}]},
                 accel: {all: [{type: white, density: 0.1 m/s/sqrt(h)}, {type: bias, sigma: 10 mg}]}}}
)");
  CHECK(right.find("innovations") == std::string::npos);
  const std::string blind = warnings(R"(
filter: {model: {gyro: {all: [{type: white, density: 0.03 deg/sqrt(h)}]},
                 accel: {all: [{type: white, density: 0.01 m/s/sqrt(h)}]}}}
)");
  CHECK_THAT(blind, Catch::Contains("filter: the GNSS innovations are") &&
                        Catch::Contains("understates the errors (over-confident"));
}
