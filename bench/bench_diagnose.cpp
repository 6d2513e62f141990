// Diagnosis benchmark (issue 12: 1 M x 6 channels with trial selection <= 20 s on 2 cores): the
// ADIS16355 AR(5) preset simulated at 1 kHz for 1000 s (10^6 samples per channel) with a 0.37 Hz
// line on ax (a candidate with a signal, so the selection takes it out and proposes again),
// diagnosed against the preset with 32 realisations on 1 and 2 threads. The ratio of the two
// rows is the thread scaling (realisations, then channels, on worker threads).
// Run: build/bench/bench_diagnose
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include "errormodels/diagnose/diagnose.hpp"
#include "errormodels/model_io.hpp"

namespace {

using namespace sinsim;
using namespace sinsim::errormodels;

const ErrorModelSpec& preset() {
  static const ErrorModelSpec m = loadErrorModel(std::string(SINSIM_SOURCE_DIR) + "/scenarios/adis16355-ar5.yaml");
  return m;
}

const Record& record() {
  static const Record r = [] {
    const std::vector<double> ideal = {0, 0, 0, 0, 0, -9.80665};  // [rad/s x3, m/s^2 x3]
    Record rec = diagnose::simulateRecord(preset(), 1000.0, 1000000, 7, 0, ideal);
    for (std::size_t k = 0; k < rec.rows; ++k)  // 2 mg at 0.37 Hz [m/s^2]
      rec.accel[0][k] += 0.002 * 9.80665 * std::sin(2 * M_PI * 0.37 * double(k) / 1000.0);
    return rec;
  }();
  return r;
}

void BM_Diagnose(benchmark::State& state) {
  const auto& rec = record();
  diagnose::DiagnoseOptions o;
  o.threads = unsigned(state.range(0));
  o.realisations = 32;
  for (auto _ : state) benchmark::DoNotOptimize(diagnose::diagnose(rec, preset(), o));
  state.SetItemsProcessed(state.iterations() * std::int64_t(6 * rec.rows));
}
BENCHMARK(BM_Diagnose)->Arg(1)->Arg(2)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
