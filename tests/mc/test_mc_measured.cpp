// A measured record navigated like a model run: replaying realisation k of a model as a "record"
// must reproduce run k's drift, and its percentile in the batch must be run k's rank. Then the
// real ADIS16405 record end to end through the command line.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "errormodels/stats/record.hpp"
#include "helpers.hpp"
#include "sim/mc_output.hpp"
#include "sim/mc_stats.hpp"
#include "sim/measured.hpp"
#include "sim/montecarlo.hpp"
#include "sim/scenario.hpp"

using namespace sinsim;

TEST_CASE("measured path: a replayed model realisation gives that run's drift and rank") {
  const auto tmp = mctest::tempDir("replay");
  // Tilted by levelling-sized angles so that the attitude path matters.
  const nav::Vec3 rpy(0.01, -0.02, 0.3);
  const double rate = 100, duration = 120;
  sim::MotionStart start;
  start.lat = 51.08 * M_PI / 180;
  start.lon = -114.13 * M_PI / 180;
  start.h = 1100;
  start.roll = rpy.x();
  start.pitch = rpy.y();
  start.heading = rpy.z();
  const sim::Scenario sc = sim::staticScenario("replay", start, rate, 1.0,
                                               {nav::VerticalChannel::Held, 100.0}, duration);
  const sim::Reference ref = sim::buildReference(sc);
  const auto model = errormodels::ImuErrorModel::fromString(
      "gyro:\n  all: [{type: white, density: 0.3 deg/sqrt(h)}, {type: bias, sigma: 20 deg/h}]\n"
      "accel:\n  all: [{type: white, density: 0.05 m/s/sqrt(h)}, {type: bias, sigma: 1 mg}]\n",
      "m.yaml");
  const std::uint64_t seed = 77, k = 5;

  // The "record": realisation k, as rates (what a CSV holds).
  errormodels::Record rec;
  rec.source = "realisation-5";
  rec.rate_hz = rate;
  auto c = model.instantiate(rate, {seed, k});
  for (const auto& ideal : ref.samples) {
    nav::ImuSample s = ideal;
    c->corrupt(s, NAN);
    for (int a = 0; a < 3; ++a) {
      rec.gyro[a].push_back(s.dtheta_b[a] / s.dt);
      rec.accel[a].push_back(s.dv_b[a] / s.dt);
    }
  }
  rec.rows = ref.samples.size();

  sim::NavigateOptions nopt;
  nopt.biasWindow = 30;  // the turn-on bias is removed from record and runs alike
  sim::McMeasured measured;
  measured.source = rec.source;
  measured.errors.resize(ref.epochs() * sim::kErrorFields);
  sim::RecordSource replay(ref, rec);
  REQUIRE(sim::navigateErrors(replay, ref, nopt, measured.errors.data()));

  sim::McOptions opt;
  opt.runs = 16;
  opt.seed = seed;
  opt.navigate = nopt;
  opt.measured = &measured;
  opt.times = {60, 120};
  opt.outDir = (tmp / "out").string();
  const sim::McResult r = sim::runMonteCarlo(ref, {{"m", model, "m"}}, opt);
  REQUIRE(r.complete);
  sim::McBatch batch(ref);
  batch.runs = opt.runs;
  batch.errors = r.errors;
  const std::size_t eEnd = ref.epochs() - 1;
  const auto runs = sim::metricAcrossRuns(batch, 0, eEnd, sim::kHorizontal);
  const double hMeas = sim::metricValue(measured.errors.data() + eEnd * sim::kErrorFields,
                                        sim::kHorizontal);
  // rate × dt differs from the increment by an ulp or two; over 12 000 steps that stays far below
  // the float storage resolution (6e-8 relative).
  CHECK(hMeas == Approx(runs[k]).epsilon(1e-6));
  CHECK(hMeas > 1.0);  // the case is not trivial: metres of drift after the bias removal
  auto sorted = runs;
  std::sort(sorted.begin(), sorted.end());
  const auto rank = double(std::lower_bound(sorted.begin(), sorted.end(), runs[k]) - sorted.begin());
  const auto j = nlohmann::json::parse(mctest::slurp(tmp / "out" / "summary.json"));
  CHECK(double(j["measured"]["models"][0]["at"][1]["percentile"]) ==
        Approx(100.0 * (rank + 0.5) / 16.0).epsilon(1e-12));
  CHECK(mctest::fs::exists(tmp / "out" / "measured.csv"));
  mctest::fs::remove_all(tmp);
}

TEST_CASE("sinsim mc --measured: the ADIS16405 record against two models, end to end") {
  const auto tmp = mctest::tempDir("adis");
  const std::string data = std::string(SINSIM_SHARED_DIR) + "/data/adis16405/run1.csv.gz";
  const mctest::Result r = mctest::sinsim(
      "mc --measured '" + data + "' --gyro-unit deg/s --accel-unit g --rate 100 --duration 120 "
      "--bias-window 20 --runs 16 --times 60,120 --model '" + mctest::sourceDir() +
      "/scenarios/grade-consumer.yaml' --model '" + mctest::sourceDir() +
      "/scenarios/grade-tactical.yaml' -o '" + (tmp / "out").string() + "'", tmp);
  INFO(r.err);
  REQUIRE(r.exitCode == 0);
  const auto j = nlohmann::json::parse(mctest::slurp(tmp / "out" / "summary.json"));
  REQUIRE(j["measured"]["models"].size() == 2);
  for (const auto& m : j["measured"]["models"]) {
    const double p = m["at"][1]["percentile"];
    CHECK(p >= 0.0);
    CHECK(p <= 100.0);
    // The terminal says it too (before, only the files and the report did), as a whole number
    // from 10 up: "percentile 100", never "1e+02".
    const std::string said = "percentile " + (p >= 10.0 ? std::to_string(std::llround(p)) : std::string()) + "";
    INFO(r.out);
    CHECK(r.out.find("The measured record drifted ") != std::string::npos);
    if (p >= 10.0) CHECK(r.out.find(said + " of " + std::string(m["model"])) != std::string::npos);
  }
  CHECK(r.out.find("e+0") == std::string::npos);
  // 121 epochs (0..120 s at 1 Hz) plus the header.
  const std::string csv = mctest::slurp(tmp / "out" / "measured.csv");
  CHECK(std::count(csv.begin(), csv.end(), '\n') == 122);
  CHECK(r.err.find("did you forget") == std::string::npos);
  // The same record without the unit options navigates g as m/s^2 and deg/s as rad/s: said.
  const mctest::Result bare = mctest::sinsim(
      "mc --measured '" + data + "' --rate 100 --duration 120 --bias-window 20 --runs 4 --model '" +
      mctest::sourceDir() + "/scenarios/grade-consumer.yaml' -o '" + (tmp / "bare").string() + "'", tmp);
  INFO(bare.err);
  CHECK(bare.exitCode == 0);
  CHECK(bare.err.find("sinsim mc: warning: accelerometer mean |f| = 1.0") != std::string::npos);
  CHECK(bare.err.find("did you forget --accel-unit g?") != std::string::npos);
  CHECK(bare.err.find("did you forget --gyro-unit deg/s?") != std::string::npos);
  mctest::fs::remove_all(tmp);
}
