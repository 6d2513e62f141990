// Benchmarks of the statistics of records (issue 4 peers: Octave CSV load 2.5 s, NaveGo OADEV
// 0.65 s, PyWavelets db5 denoise 60 ms, all on 1 M samples).
// Run: build/bench/bench_stats --benchmark_min_time=1
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "errormodels/stats/allan.hpp"
#include "errormodels/stats/record.hpp"
#include "errormodels/stats/spectrum.hpp"
#include "errormodels/stats/wavelet.hpp"

using namespace sinsim::errormodels;

namespace {

constexpr std::size_t kN = 1000000;

/// 1 M samples of white + random-walk rate noise (seeded: stream "bench-stats").
const std::vector<double>& signal1M() {
  static const std::vector<double> y = [] {
    std::mt19937_64 rng(4);
    std::normal_distribution<double> g;
    std::vector<double> v(kN);
    double walk = 0;
    for (auto& x : v) {
      walk += 1e-3 * g(rng);
      x = 0.4 + 0.03 * g(rng) + walk;
    }
    return v;
  }();
  return y;
}

/// Removes the generated file when the benchmark exits.
struct TempFile {
  std::string path;
  ~TempFile() {
    std::error_code ec;
    std::filesystem::remove(path, ec);
  }
};

/// A 1 M x 6 CSV like the ADIS16405 records (values quantized to the sensor LSBs), written once
/// per run into the temp folder and removed at exit.
const std::string& csv1Mx6() {
  static const TempFile file{[] {
    const std::string p =
        (std::filesystem::temp_directory_path() / "sinsim_bench_stats_1Mx6.csv").string();
    std::mt19937_64 rng(5);
    std::normal_distribution<double> g;
    std::FILE* f = std::fopen(p.c_str(), "w");
    std::fputs("gx,gy,gz,ax,ay,az\n", f);
    for (std::size_t i = 0; i < kN; ++i) {
      std::fprintf(f, "%.2f,%.2f,%.2f,%.5f,%.5f,%.5f\n", 0.05 * std::round(8 + g(rng)),
                   0.05 * std::round(-8 + g(rng)), 0.05 * std::round(-6 + g(rng)),
                   0.00333 * std::round(g(rng)), 0.00333 * std::round(g(rng)),
                   0.00333 * std::round(-305 + g(rng)));
    }
    std::fclose(f);
    return p;
  }()};
  return file.path;
}

RecordOptions adisOptions() {
  RecordOptions o;
  o.rate_hz = 100;
  o.gyro_unit = "deg/s";
  o.accel_unit = "g";
  return o;
}

void BM_LoadCsv_1Mx6(benchmark::State& state) {
  const std::string& path = csv1Mx6();
  for (auto _ : state) benchmark::DoNotOptimize(loadRecord(path, adisOptions()));
  state.SetItemsProcessed(state.iterations() * kN);
}
BENCHMARK(BM_LoadCsv_1Mx6)->Unit(benchmark::kMillisecond);

void BM_LoadCsvGz_Adis16405Run1(benchmark::State& state) {
  const std::string path = std::string(SINSIM_SHARED_DIR) + "/data/adis16405/run1.csv.gz";
  for (auto _ : state) benchmark::DoNotOptimize(loadRecord(path, adisOptions()));
  state.SetItemsProcessed(state.iterations() * kN);
}
BENCHMARK(BM_LoadCsvGz_Adis16405Run1)->Unit(benchmark::kMillisecond);

void BM_Oadev_Octave_1M(benchmark::State& state) {
  const auto& y = signal1M();
  AllanOptions opt;
  opt.confidence_intervals = state.range(0) != 0;
  for (auto _ : state) benchmark::DoNotOptimize(allanDeviation(y, 100.0, AllanVariant::Overlapping, opt));
}
BENCHMARK(BM_Oadev_Octave_1M)->Arg(0)->Arg(1)->ArgName("with_ci")->Unit(benchmark::kMillisecond);

void BM_Mdev_Octave_1M(benchmark::State& state) {
  const auto& y = signal1M();
  AllanOptions opt;
  opt.confidence_intervals = false;
  for (auto _ : state) benchmark::DoNotOptimize(allanDeviation(y, 100.0, AllanVariant::Modified, opt));
}
BENCHMARK(BM_Mdev_Octave_1M)->Unit(benchmark::kMillisecond);

void BM_Db5Denoise_1M(benchmark::State& state) {
  const auto& y = signal1M();
  DenoiseOptions opt;  // db5, symmetric, max level (16), universal, soft
  for (auto _ : state) benchmark::DoNotOptimize(waveletDenoise(y, opt));
}
BENCHMARK(BM_Db5Denoise_1M)->Unit(benchmark::kMillisecond);

void BM_Acf_Fft_1M_10kLags(benchmark::State& state) {
  const auto& y = signal1M();
  for (auto _ : state) benchmark::DoNotOptimize(autocorrelation(y, 100.0, 10000));
}
BENCHMARK(BM_Acf_Fft_1M_10kLags)->Unit(benchmark::kMillisecond);

void BM_Welch_1M(benchmark::State& state) {
  const auto& y = signal1M();
  WelchOptions opt;
  opt.segment_length = 4096;
  for (auto _ : state) benchmark::DoNotOptimize(welchPsd(y, 100.0, opt));
}
BENCHMARK(BM_Welch_1M)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
