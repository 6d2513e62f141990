// Aided navigation throughput: strapdown + closed-loop error-state filter with 9 + 18 states
// (bias, Gauss-Markov and random walk on each of the 6 sensor axes), 100 Hz IMU, 1 Hz GNSS
// position fixes. items_processed = IMU epochs (the brief asks >= 200 k/s per core). BM_FreeRun,
// the reference of the ratio: the same samples through the strapdown alone (free-inertial).
// BM_AidedRunScale: the same with a scale-factor state per axis as well (9 + 24 states).
//
// Input: an ideal drive (static, accelerate, turn, cruise; 300 s) precomputed before timing,
// replayed through the aiding; each benchmark iteration is one whole run.
//
//   cmake --build build --target bench_aided && build/bench/bench_aided
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "common/constants.hpp"
#include "sim/aided/aided_navigation.hpp"
#include "sim/ideal_imu.hpp"
#include "sim/scenario.hpp"
#include "sim/trajectory.hpp"

using namespace sinsim;
using namespace sinsim::sim::aided;

using sinsim::kRadPerDeg;

namespace {

const char* kDrive = R"(
name: bench
start: {latitude: 45 deg, longitude: 7 deg, height: 300 m, heading: 30 deg}
imu_rate: 100 Hz
vertical: free
segments:
  - {type: static, duration: 20 s}
  - {type: accelerate, speed: 15 m/s, duration: 15 s}
  - {type: turn, heading_change: 90 deg, duration: 15 s}
  - {type: cruise, duration: 250 s}
)";

FilterSensorModel model18() {
  const double d = kRadPerDeg;
  FilterSensorModel m;
  for (int i = 0; i < 3; ++i) {
    m.gyro[i].whiteDensity = 0.15 * d / 60.0;
    m.gyro[i].blocks = {biasState(10 * d / 3600), gaussMarkovState(20 * d / 3600, 200),
                        randomWalkState(3 * d / 3600 / 60)};
    m.accel[i].whiteDensity = 0.1 / 60.0;
    m.accel[i].blocks = {biasState(0.01), gaussMarkovState(0.02, 300),
                         randomWalkState(0.05 / 3600 / 60)};
  }
  return m;
}

struct Drive {
  sim::Scenario sc = sim::parseScenario(kDrive, "bench.yaml");
  nav::NavState start;
  std::vector<nav::ImuSample> samples;
  std::vector<nav::NavState> truth;
  Drive(const nav::Earth& earth) {
    const sim::Trajectory traj(earth, sc.motion());
    sim::IdealImu imu(traj, sc.imuRate);
    start = imu.truth();
    while (!imu.done()) {
      samples.push_back(imu.next());
      truth.push_back(imu.truth());
    }
  }
};

void BM_FreeRun(benchmark::State& state) {
  const nav::Earth earth;
  const Drive d(earth);
  for (auto _ : state) {
    nav::Strapdown sd(earth, d.start, d.sc.strapdown);
    for (std::size_t k = 0; k < d.samples.size(); ++k) sd.update(d.samples[k], d.truth[k].h);
    benchmark::DoNotOptimize(sd.state());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long long>(d.samples.size()));
}
BENCHMARK(BM_FreeRun)->Unit(benchmark::kMillisecond);

// model18 plus a scale-factor state per axis (3000 ppm prior), last on each axis.
FilterSensorModel model24() {
  FilterSensorModel m = model18();
  for (int i = 0; i < 3; ++i) {
    m.gyro[i].blocks.push_back(scaleFactorState(3000e-6));
    m.accel[i].blocks.push_back(scaleFactorState(3000e-6));
  }
  return m;
}

void aidedRun(benchmark::State& state, const FilterSensorModel& fm) {
  const nav::Earth earth;
  const Drive drive(earth);
  const sim::Scenario& sc = drive.sc;
  const nav::NavState& start = drive.start;
  const std::vector<nav::ImuSample>& samples = drive.samples;
  const std::vector<nav::NavState>& truth = drive.truth;
  AidingConfig cfg;
  cfg.initialErrors.position.value = nav::Vec3(2, -1, 1);
  cfg.gnss.enabled = true;
  cfg.filter.enabled = true;
  for (auto _ : state) {
    AidedNavigation aided(earth, cfg, fm, sc.strapdown, {1, 0});
    nav::Strapdown sd(earth, aided.initialState(start), sc.strapdown);
    for (std::size_t k = 0; k < samples.size(); ++k) {
      const nav::ImuSample u = aided.compensate(samples[k]);
      sd.update(u, truth[k].h);
      benchmark::DoNotOptimize(aided.afterInterval(u, samples[k], truth[k], sd));
    }
    benchmark::DoNotOptimize(sd.state());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long long>(samples.size()));
  state.counters["states"] = 9 + fm.stateCount();
}
void BM_AidedRun(benchmark::State& state) { aidedRun(state, model18()); }
BENCHMARK(BM_AidedRun)->Unit(benchmark::kMillisecond);

void BM_AidedRunScale(benchmark::State& state) { aidedRun(state, model24()); }
BENCHMARK(BM_AidedRunScale)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
