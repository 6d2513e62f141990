// Error-model generation speed. The issue's floor: 1 h of 6-axis AR(5) errors at 1 kHz
// (3.6 M IMU samples × 6 axes = 21.6 M process samples) in under 1 s on one core.
#include <benchmark/benchmark.h>

#include "errormodels/imu_model.hpp"
#include "errormodels/random.hpp"

using namespace sinsim::errormodels;

namespace {

const char* kAr5 = R"(
gyro:
  x: [{type: ar, a: [-1.0327, -0.34341, 0.037895, 0.19732, 0.14724], sigma: 0.01 deg/s, rate: 1 kHz}]
  y: [{type: ar, a: [-1.2391, -0.063362, 0.091524, 0.13092, 0.086379], sigma: 0.01 deg/s, rate: 1 kHz}]
  z: [{type: ar, a: [-1.0604, -0.30249, 0.043657, 0.18006, 0.14555], sigma: 0.01 deg/s, rate: 1 kHz}]
accel:
  x: [{type: ar, a: [-0.51552, -0.068261, -0.047218, -0.049565, -0.13655], sigma: 1 mg, rate: 1 kHz}]
  y: [{type: ar, a: [-0.46354, -0.078197, -0.077146, -0.020449, -0.062445], sigma: 1 mg, rate: 1 kHz}]
  z: [{type: ar, a: [-0.41897, -0.10907, -0.077718, -0.074069, -0.1431], sigma: 1 mg, rate: 1 kHz}]
)";

void corruptHour(benchmark::State& state, const char* text, double rate, double processRate) {
  auto model = ImuErrorModel::fromString(text, "bench.yaml");
  const long n = long(3600.0 * rate);
  double sink = 0.0;
  for (auto _ : state) {
    auto c = model.instantiate(rate, {1, 0});
    sinsim::ImuSample s;
    s.dt = 1.0 / rate;
    for (long k = 1; k <= n; ++k) {
      s.t = double(k) / rate;
      s.dtheta_b.setZero();
      s.dv_b.setZero();
      c->corrupt(s, NAN);
      sink += s.dtheta_b.x() + s.dv_b.z();
    }
  }
  benchmark::DoNotOptimize(sink);
  const double processSamples = 6.0 * 3600.0 * processRate;
  state.counters["process_samples"] = processSamples;
  state.counters["samples_per_s"] =
      benchmark::Counter(processSamples, benchmark::Counter::kIsIterationInvariantRate);
}

// 1 h, 6 axes, AR(5) at 1 kHz into a 1 kHz IMU: 21.6 M process samples per iteration.
void BM_Ar5SixAxesOneHour1kHz(benchmark::State& state) { corruptHour(state, kAr5, 1000.0, 1000.0); }
BENCHMARK(BM_Ar5SixAxesOneHour1kHz)->Unit(benchmark::kMillisecond)->Iterations(3);

// Same process count into a 100 Hz IMU (10 held AR samples integrated per interval).
void BM_Ar5SixAxesOneHourInto100Hz(benchmark::State& state) { corruptHour(state, kAr5, 100.0, 1000.0); }
BENCHMARK(BM_Ar5SixAxesOneHourInto100Hz)->Unit(benchmark::kMillisecond)->Iterations(3);

// Raw Gaussian stream speed (Philox4x64-10 + ziggurat with its vector fast path).
void BM_NormalStream(benchmark::State& state) {
  NormalStream s(1, 0, 0);
  double sink = 0.0;
  for (auto _ : state) sink += s.next();
  benchmark::DoNotOptimize(sink);
}
BENCHMARK(BM_NormalStream);

}  // namespace

BENCHMARK_MAIN();
