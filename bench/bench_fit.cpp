// Fitting benchmarks: Burg AR(5) on 1e6 samples (issue 4: <= 10 ms; Octave arburg 51 ms).
// Run: build/bench/bench_fit --benchmark_min_time=1
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "common/parallel.hpp"
#include "errormodels/fit/allan_fit.hpp"
#include "errormodels/fit/ar_fit.hpp"
#include "errormodels/fit/latent_fit.hpp"

namespace {

using namespace sinsim::errormodels::fit;

// The paper's Gx AR(5) driven by unit white noise, seeded.
const std::vector<double>& gxSeries(std::size_t n) {
  static std::vector<double> x;
  if (x.size() != n) {
    const double a[6] = {1.0, -1.0327, -0.34341, 0.037895, 0.19732, 0.14724};
    std::mt19937_64 rng(1);
    std::normal_distribution<double> w;
    x.assign(n, 0.0);
    for (std::size_t t = 0; t < n; ++t) {
      double v = w(rng);
      for (std::size_t i = 1; i <= 5 && i <= t; ++i) v -= a[i] * x[t - i];
      x[t] = v;
    }
  }
  return x;
}

void BM_Burg(benchmark::State& state, BurgAlgorithm algo) {
  const auto& x = gxSeries(static_cast<std::size_t>(state.range(0)));
  ArOptions opt;
  opt.burgAlgorithm = algo;
  for (auto _ : state) benchmark::DoNotOptimize(burg(x, static_cast<std::size_t>(state.range(1)), opt));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK_CAPTURE(BM_Burg, auto, BurgAlgorithm::Auto)
    ->Args({1000000, 5})->Args({1000000, 20})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Burg, direct, BurgAlgorithm::Direct)
    ->Args({1000000, 5})->Unit(benchmark::kMillisecond);

void BM_YuleWalker(benchmark::State& state) {
  const auto& x = gxSeries(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(yuleWalker(x, 5));
}
BENCHMARK(BM_YuleWalker)->Arg(1000000)->Unit(benchmark::kMillisecond);

// Allan-term fit of a 2 h, 100 Hz curve (17 octave points), independent vs correlated points.
void BM_AllanFit(benchmark::State& state) {
  const double dt = 0.01;
  const std::size_t M = 720000;
  const std::array<double, kAllanTermCount> theta = {1e-10, 9e-6, 1e-8, 1e-8, 1e-12};
  std::vector<double> tau, edf;
  for (std::size_t m = 1; m <= M / 10; m *= 2) {
    tau.push_back(double(m) * dt);
    edf.push_back(edfOverlappingWhite(M, m));
  }
  const auto adev = allanModelAdev(theta, tau);
  AllanFitOptions opt;
  if (state.range(0)) {
    opt.sampleInterval = dt;
    opt.recordLength = M;
  }
  for (auto _ : state) benchmark::DoNotOptimize(fitAllanTerms(tau, adev, edf, opt));
}
BENCHMARK(BM_AllanFit)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

// Composite latent-process fit (issue 11: 1 M samples x 6 channels <= 2 s on 2 cores).
// LatentFit: one channel of 1e6 samples at 1 kHz, white + GM + random walk, all 48 term sets.
// LatentFitSixChannels: six such channels (different seeds), fitted on two threads (channels are
// independent; each thread takes the next channel when it is free, as sinsim fit does), wall
// time: the target, measured end to end (the Allan
// variance of each record included).
namespace {

std::vector<double> latentRecord(unsigned seed) {
  std::vector<double> x;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> w;
  const double dt = 1e-3, phi = std::exp(-dt / 2.0);
  double g = 0.0, rw = 0.0;
  for (int k = 0; k < 1000000; ++k) {
    g = phi * g + 3e-3 * std::sqrt(1 - phi * phi) * w(rng);
    rw += 1e-5 * std::sqrt(dt) * w(rng);
    x.push_back(1e-3 / std::sqrt(dt) * w(rng) + g + rw);
  }
  return x;
}

void BM_LatentFit(benchmark::State& state) {
  static const std::vector<double> x = latentRecord(11);
  LatentFitOptions o;
  o.sampleInterval = 1e-3;
  // 0: the set by the Allan score alone, 1: by the Whittle likelihood, 2: rescored by the block likelihood
  o.whittleSelection = state.range(0) >= 1;
  o.blockSelection = state.range(0) == 2;
  for (auto _ : state) benchmark::DoNotOptimize(fitLatentModel(x, o));
}
BENCHMARK(BM_LatentFit)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

void BM_LatentFitSixChannels(benchmark::State& state) {
  static std::vector<std::vector<double>> channels;
  if (channels.empty())
    for (unsigned c = 0; c < 6; ++c) channels.push_back(latentRecord(11 + c));
  LatentFitOptions o;
  o.sampleInterval = 1e-3;
  o.whittleSelection = state.range(0) >= 1;
  o.blockSelection = state.range(0) == 2;
  for (auto _ : state) {
    std::vector<std::size_t> chosen(6);
    sinsim::parallelFor<int>(6, 2, [&](std::size_t c, int&) {
      chosen[c] = fitLatentModel(channels[c], o).terms.termCount();
    });
    benchmark::DoNotOptimize(chosen);
  }
}
BENCHMARK(BM_LatentFitSixChannels)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->MeasureProcessCPUTime();

}  // namespace
