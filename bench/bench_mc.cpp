// Monte Carlo throughput. The floor: 1000 runs × 10 min × 100 Hz with the 6-axis AR(5)
// preset (60 M strapdown steps, 3.6 G AR samples at 1 kHz) in ≤ 30 s on 2 cores, and scaling from
// 1 to 2 threads ≥ 1.85×. Timed end to end: the reference (ideal IMU + truth), every run, the
// statistics and the output files. Wall time (UseRealTime) is what the floor is about; the CPU
// time of the process is reported as a counter (the machine may be shared).
//
//   cmake --build build --target bench_mc && build/bench/bench_mc
//   build/bench/bench_mc --benchmark_filter=Scaling     # the 1 → 2 thread pair only (~10 s)
#include <benchmark/benchmark.h>

#include <time.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "sim/montecarlo.hpp"
#include "sim/scenario.hpp"

using namespace sinsim;

namespace {


double cpuTime() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

void runBatch(benchmark::State& state, std::uint64_t runs, unsigned threads) {
  const sim::Scenario sc =
      sim::loadScenario(std::string(SINSIM_SOURCE_DIR) + "/bench/car-10min.yaml");  // 10 min
  const auto model = errormodels::ImuErrorModel::load(std::string(SINSIM_SOURCE_DIR) +
                                                      "/scenarios/adis16355-ar5.yaml");
  const std::string dir = (std::filesystem::temp_directory_path() /
                           ("sinsim_bench_mc_" + std::to_string(::getpid())))
                              .string();
  double steps = 0, cpu = 0;
  for (auto _ : state) {
    std::filesystem::remove_all(dir);
    const double c0 = cpuTime();
    const sim::Reference ref = sim::buildReference(sc);
    sim::McOptions opt;
    opt.runs = runs;
    opt.seed = 1;
    opt.threads = threads;
    opt.outDir = dir;
    const sim::McResult r = sim::runMonteCarlo(ref, {{"ar5", model, "ar5"}}, opt);
    if (!r.complete) state.SkipWithError("batch incomplete");
    steps += double(runs) * double(ref.samples.size());
    cpu += cpuTime() - c0;
  }
  std::filesystem::remove_all(dir);
  state.counters["steps"] = benchmark::Counter(steps, benchmark::Counter::kAvgIterations);
  state.counters["steps_per_s"] = benchmark::Counter(steps, benchmark::Counter::kIsRate);
  state.counters["cpu_s"] = benchmark::Counter(cpu, benchmark::Counter::kAvgIterations);
  state.counters["cpu_ns_per_step"] = 1e9 * cpu / steps;
}

// The case: 1000 runs, all cores.
void BM_Mc1000RunsAr5TenMinutes(benchmark::State& state) { runBatch(state, 1000, 0); }
BENCHMARK(BM_Mc1000RunsAr5TenMinutes)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

// Scaling: the same 100 runs on 1 and on 2 threads.
void BM_McScaling(benchmark::State& state) { runBatch(state, 100, unsigned(state.range(0))); }
BENCHMARK(BM_McScaling)->Arg(1)->Arg(2)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
