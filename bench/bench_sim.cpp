// Simulator throughput: the ideal IMU alone (trajectory kinematics + RK4 between knots) and a
// whole error-free run (ideal IMU + strapdown + errors vs truth, no files) on the shipped car.
#include <benchmark/benchmark.h>

#include <string>

#include "nav/earth.hpp"
#include "sim/ideal_imu.hpp"
#include "sim/run.hpp"
#include "sim/scenario.hpp"

namespace {

const sinsim::sim::Scenario& car() {
  static const sinsim::sim::Scenario sc =
      sinsim::sim::loadScenario(std::string(SINSIM_SOURCE_DIR) + "/scenarios/car.yaml");
  return sc;
}

void BM_IdealImuCar(benchmark::State& state) {
  const sinsim::nav::Earth earth;
  const sinsim::sim::Trajectory traj(earth, car().motion());
  long long n = 0;
  for (auto _ : state) {
    sinsim::sim::IdealImu imu(traj, car().imuRate);
    while (!imu.done()) benchmark::DoNotOptimize(imu.next());
    n += imu.sampleCount();
  }
  state.counters["samples/s"] = benchmark::Counter(static_cast<double>(n), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_IdealImuCar)->Unit(benchmark::kMillisecond);

void BM_RunCar(benchmark::State& state) {
  long long n = 0;
  for (auto _ : state) {
    const auto s = sinsim::sim::run(car());
    benchmark::DoNotOptimize(s.final.horizontal());
    n += s.imuSamples;
  }
  state.counters["samples/s"] = benchmark::Counter(static_cast<double>(n), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_RunCar)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
