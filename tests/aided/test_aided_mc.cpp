// Monte Carlo of an aided scenario (initial errors, GNSS with an outage, the filter from its
// model): run k of the batch is `run` with run index k (the same navigation, float-rounded), and
// the batch's raw errors and its stats.csv / summary.json are bit-identical for 1 and 2 threads
// (monte-carlo reproducibility, sim/montecarlo.hpp, now with the aiding's streams keyed by run).
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "errormodels/imu_model.hpp"
#include "sim/montecarlo.hpp"
#include "sim/run.hpp"
#include "test_support.hpp"

using namespace sinsim;

namespace {

const char* kAided = R"(
name: aided-mc
start: {latitude: 48 deg, longitude: 11 deg, height: 500 m, heading: 60 deg}
imu_rate: 100 Hz
output_rate: 1 Hz
segments:
  - {type: static, duration: 10 s}
  - {type: accelerate, speed: 10 m/s, duration: 10 s}
  - {type: turn, heading_change: 90 deg, duration: 10 s}
  - {type: cruise, duration: 50 s}
errors:
  gyro: {all: [{type: white, density: 0.2 deg/sqrt(h)}, {type: gauss_markov, sigma: 30 deg/h, tau: 100 s}]}
  accel: {all: [{type: white, density: 0.1 m/s/sqrt(h)}, {type: gauss_markov, sigma: 3 mg, tau: 100 s}]}
initial_errors: {position: {sigma: 2 m}, velocity: {sigma: 0.1 m/s}, attitude: {sigma: [0.3 deg, 0.3 deg, 2 deg]}}
gnss: {rate: 1 Hz, position_sigma: [1 m, 1 m, 2 m], outages: [[50 s, 70 s]]}
filter:
  model:
    gyro: {all: [{type: white, density: 0.2 deg/sqrt(h)}, {type: gauss_markov, sigma: 30 deg/h, tau: 100 s}]}
    accel: {all: [{type: white, density: 0.1 m/s/sqrt(h)}, {type: gauss_markov, sigma: 3 mg, tau: 100 s}]}
)";

sim::McResult batch(const sim::Reference& ref, const sim::Scenario& sc, unsigned threads,
                    const std::string& dir) {
  sim::McOptions opt;
  opt.runs = 12;  // two chunks, the second partial
  opt.seed = 99;
  opt.threads = threads;
  opt.outDir = dir;
  opt.scenarioIdentity = kAided;
  return sim::runMonteCarlo(ref, {{"errors", sc.errors, "errors"}}, opt);
}

}  // namespace

TEST_CASE("mc with the filter: run k is `run` k, and 1 and 2 threads give the same bits") {
  const auto tmp = test::freshTempDir("sinsim-aided-mc");
  const sim::Scenario sc = sim::parseScenario(kAided, "aided-mc.yaml");
  const sim::Reference ref = sim::buildReference(sc);
  REQUIRE(ref.truthAll.size() == ref.samples.size());
  const sim::McResult one = batch(ref, sc, 1, (tmp / "t1").string());
  const sim::McResult two = batch(ref, sc, 2, (tmp / "t2").string());
  REQUIRE(one.complete);
  REQUIRE(two.complete);
  CHECK(two.threads == 2);
  REQUIRE(one.errors.size() == 1);
  CHECK(one.errors[0] == two.errors[0]);
  for (const char* f : {"stats.csv", "summary.json", "report.html"}) {
    INFO(f);
    const std::string a = test::slurp(tmp / "t1" / f), b = test::slurp(tmp / "t2" / f);
    CHECK(!a.empty());
    CHECK(a == b);  // no thread count or timing is written to either
  }

  // Run 5 of the batch against `run` with run index 5 and the batch's seed.
  const std::size_t perRun = ref.epochs() * sim::kErrorFields;
  sim::RunOptions o;
  o.seed = 99;
  o.runIndex = 5;
  std::vector<sim::NavError> rows;
  o.onRow = [&](const sim::NavError& e) { rows.push_back(e); };
  sim::run(sc, o);
  REQUIRE(rows.size() == ref.epochs());
  int differ = 0;
  double aidedMax = 0.0;
  for (std::size_t e = 0; e < rows.size(); ++e) {
    const float* m = one.errors[0].data() + 5 * perRun + e * sim::kErrorFields;
    if (m[sim::kNorth] != float(rows[e].pos_n.x()) || m[sim::kEast] != float(rows[e].pos_n.y()) ||
        m[sim::kYaw] != float(rows[e].euler.z()))
      ++differ;
    if (rows[e].t > 20.0 && rows[e].t < 50.0) aidedMax = std::max(aidedMax, rows[e].horizontal());
  }
  CHECK(differ == 0);
  // The filter is working in the batch: while fixes arrive, the horizontal error stays within a
  // few GNSS sigmas (1 m per axis; 6 m is > 4 sigma of the 2-D error), far below the 2 m start
  // plus 0.1 m/s velocity error growing free for 50 s.
  CHECK(aidedMax < 6.0);
}
