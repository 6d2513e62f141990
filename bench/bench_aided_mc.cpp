// Aided Monte Carlo throughput on ONE core: scenarios/car-10min-aided.yaml (10 min, 100 Hz IMU, 1 Hz
// GNSS, 30 s and 60 s outages, filter with 9 + 18 states from scenarios/aided-model.yaml) against the
// same scenario navigated free-inertially (aiding keys cleared, same IMU errors). The brief asks a
// 1000-run Monte Carlo of the default aided scenario in under a minute on one core; the counters
// give the CPU time per run and that projection (cpu_s_per_1000_runs), and the ratio aided/free
// follows from the two benchmarks' cpu_ms_per_run. CPU time of the process, since the machine
// may be shared; the reference (ideal IMU + truth) is built once outside the timing.
//
// BM_AidedMcCar: the case, scenarios/car.yaml (34.6 min, 207 800 IMU epochs a run) with
// the same aiding, sensor model and filter, and a 30 s and a 60 s outage twice each; its
// cpu_s_per_1000_runs / 2 is the 1000-run time on 2 cores (threads scale 1.9×, docs/benchmarks.md).
// BM_FreeMcCar: the same drive and IMU errors free-inertially, the reference of the ratio.
// bench/car-aided.yaml is BM_AidedMcCar's scenario as a file, for the whole 1000 runs with
// `sinsim mc bench/car-aided.yaml --runs 1000 --threads 2` (docs/aided.md, "Speed").
//
//   cmake --build build --target bench_aided_mc && build/bench/bench_aided_mc
//   build/bench/bench_aided_mc --benchmark_filter=Full    # the whole 1000 runs (minutes)
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

// car.yaml's drive with car-10min-aided.yaml's errors, aiding and filter, outages over the drive.
sim::Scenario carAided() {
  const std::string dir = std::string(SINSIM_SOURCE_DIR) + "/scenarios/";
  sim::Scenario car = sim::loadScenario(dir + "car.yaml");
  const sim::Scenario aided = sim::loadScenario(dir + "car-10min-aided.yaml");
  car.errors = aided.errors;
  car.aiding = aided.aiding;
  car.aiding.gnss.outages = {{400, 430}, {800, 860}, {1300, 1330}, {1700, 1760}};
  return car;
}

void runBatch(benchmark::State& state, bool aided, std::uint64_t runs, bool car = false) {
  sim::Scenario sc =
      car ? carAided()
          : sim::loadScenario(std::string(SINSIM_SOURCE_DIR) + "/scenarios/car-10min-aided.yaml");
  if (!aided) sc.aiding = {};
  const sim::Reference ref = sim::buildReference(sc);
  const std::string dir = (std::filesystem::temp_directory_path() /
                           ("sinsim_bench_aided_mc_" + std::to_string(::getpid())))
                              .string();
  double cpu = 0, steps = 0;
  for (auto _ : state) {
    std::filesystem::remove_all(dir);
    const double c0 = cpuTime();
    sim::McOptions opt;
    opt.runs = runs;
    opt.seed = 1;
    opt.threads = 1;
    opt.outDir = dir;
    const sim::McResult r = sim::runMonteCarlo(ref, {{"m", sc.errors, "m"}}, opt);
    if (!r.complete) state.SkipWithError("batch incomplete");
    cpu += cpuTime() - c0;
    steps += double(runs) * double(ref.samples.size());
  }
  std::filesystem::remove_all(dir);
  const double perRun = cpu / double(state.iterations()) / double(runs);
  state.counters["cpu_ms_per_run"] = 1e3 * perRun;
  state.counters["cpu_s_per_1000_runs"] = 1e3 * perRun;
  state.counters["imu_epochs_per_cpu_s"] = steps / cpu;
}

void BM_AidedMc(benchmark::State& s) { runBatch(s, true, std::uint64_t(s.range(0))); }
void BM_FreeMc(benchmark::State& s) { runBatch(s, false, std::uint64_t(s.range(0))); }
void BM_AidedMcFull(benchmark::State& s) { runBatch(s, true, 1000); }
void BM_AidedMcCar(benchmark::State& s) { runBatch(s, true, std::uint64_t(s.range(0)), true); }
void BM_FreeMcCar(benchmark::State& s) { runBatch(s, false, std::uint64_t(s.range(0)), true); }
BENCHMARK(BM_AidedMc)->Arg(40)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(BM_FreeMc)->Arg(40)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(BM_AidedMcCar)->Arg(20)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(BM_FreeMcCar)->Arg(20)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(BM_AidedMcFull)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
