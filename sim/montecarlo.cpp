#include "sim/montecarlo.hpp"

#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <thread>

#include "common/error.hpp"
#include "common/limits.hpp"
#include "sim/mc_checkpoint.hpp"
#include "sim/mc_output.hpp"

namespace sinsim::sim {
namespace {

namespace fs = std::filesystem;

double processCpuTime() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

}  // namespace

std::vector<std::string> budgetEffects(const McModel& m) {
  if (m.model.empty()) return {};
  std::vector<std::string> names = m.model.effectNames();
  if (names.size() < 2) names.clear();
  return names;
}

std::vector<std::size_t> reportEpochs(const Reference& ref, const std::vector<double>& times) {
  std::vector<std::size_t> epochs;
  for (double t : times) {
    if (!(std::isfinite(t) && t >= 0 && t <= ref.epochTime(ref.epochs() - 1) + 1e-9))
      throw InputError("--times: report time " + limits::fmt(t) + " s is outside the run (0 to " +
                       limits::fmt(ref.epochTime(ref.epochs() - 1)) + " s)");
    const std::size_t e = std::size_t(std::llround(t * ref.outputRate));
    const auto same = std::find(epochs.begin(), epochs.end(), e);
    if (same != epochs.end())  // counted twice in every table and test otherwise (per_run.csv's rows too)
      throw InputError("--times: times " + std::to_string(same - epochs.begin() + 1) + " and " +
                       std::to_string(epochs.size() + 1) + " (" +
                       limits::fmt(times[std::size_t(same - epochs.begin())]) + " s, " + limits::fmt(t) +
                       " s) fall on the same output epoch (" + limits::fmt(ref.epochTime(e)) + " s at " +
                       limits::fmt(ref.outputRate) + " Hz); give each time once");
    epochs.push_back(e);
  }
  if (epochs.empty()) epochs.push_back(ref.epochs() - 1);
  return epochs;
}

void requireReference(const std::vector<McModel>& models, const std::string& reference) {
  if (reference.empty()) return;
  std::string labels;
  bool found = false;
  for (const McModel& m : models) found |= m.label == reference, labels += " " + m.label;
  if (!found)
    throw InputError("--reference " + reference + ": no model has that label (the models:" + labels + ")");
}

McResult runMonteCarlo(const Reference& ref, const std::vector<McModel>& primaryModels,
                       const McOptions& opt) {
  const auto wallStart = std::chrono::steady_clock::now();
  const double cpuStart = processCpuTime();

  // ---- validate ----------------------------------------------------------------------------------
  if (opt.runs == 0) throw InputError("--runs must be at least 1");
  if (double(opt.runs) > limits::kMaxMcRuns)
    throw InputError("--runs " + std::to_string(opt.runs) + " is above the limit of " +
                     limits::fmt(limits::kMaxMcRuns) + " runs per model (docs/limits.md)");
  if (opt.outDir.empty()) throw InputError("an output folder is required (-o DIR)");
  if (primaryModels.empty()) throw InputError("no error model given");
  if (ref.epochs() < 2) throw InputError("the scenario has fewer than two output epochs");
  if (opt.measured && opt.measured->errors.size() != ref.epochs() * kErrorFields)
    throw InputError("the measured record does not cover the reference's output epochs");
  for (std::size_t i = 0; i < primaryModels.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (primaryModels[i].label == primaryModels[j].label)
        throw InputError("two models share the label " + primaryModels[i].label);
  requireReference(primaryModels, opt.reference);
  const std::vector<std::size_t> timeEpochs = reportEpochs(ref, opt.times);

  // ---- the batch: models and budget variants -----------------------------------------------------
  McBatch batch(ref);
  batch.runs = opt.runs;
  batch.seed = opt.seed;
  batch.timeEpochs = timeEpochs;
  batch.measured = opt.measured;
  batch.biasWindow = opt.navigate.biasWindow;
  batch.reference = opt.reference;
  std::vector<McModel> models = primaryModels;
  for (std::size_t i = 0; i < primaryModels.size(); ++i) {
    batch.entries.push_back({primaryModels[i].label, primaryModels[i].model.source(), -1, ""});
    batch.effectNames.push_back(primaryModels[i].model.empty()
                                    ? std::vector<std::string>{}
                                    : primaryModels[i].model.effectNames());
  }
  if (opt.budget) {
    for (std::size_t i = 0; i < primaryModels.size(); ++i) {
      for (const auto& name : budgetEffects(primaryModels[i])) {
        McModel v = primaryModels[i];
        v.label = primaryModels[i].label + " without " + name;
        v.model = primaryModels[i].model.filtered([&](const std::string& n) { return n != name; });
        models.push_back(v);
        batch.entries.push_back({v.label, primaryModels[i].model.source(), int(i), name});
        batch.effectNames.push_back(v.model.effectNames());
      }
    }
  }

  // Every run's errors are held for the statistics: refuse before anything is allocated.
  const double resultBytes =
      double(models.size()) * double(opt.runs) * double(ref.runFloats()) * sizeof(float);
  if (resultBytes > limits::kMaxMcResultBytes)
    throw InputError("--runs " + std::to_string(opt.runs) + " with " +
                     std::to_string(models.size()) + " model(s) and " +
                     std::to_string(ref.epochs()) + " output epochs needs " +
                     limits::fmt(resultBytes / double(1u << 30), 3) +
                     " GiB of run errors, above the limit of " +
                     limits::fmt(limits::kMaxMcResultBytes / double(1u << 30), 3) +
                     " GiB (docs/limits.md): fewer runs or a shorter run");
  const std::uint64_t base = referenceFingerprint(ref, opt);
  std::vector<std::uint64_t> fps;
  std::vector<std::string> labels;
  for (const auto& m : models) {
    fps.push_back(modelFingerprint(base, m));
    labels.push_back(m.label);
  }
  CheckpointStore store(opt.outDir, ref.epochs(), ref.runFloats(), labels, fps);

  std::vector<ChunkKey> all;
  for (std::uint64_t first = 0; first < opt.runs; first += kChunkRuns)
    for (std::size_t m = 0; m < models.size(); ++m)
      all.push_back({m, first, std::min(kChunkRuns, opt.runs - first)});

  // ---- the folder (rank 0 prepares and locks it; the others wait) -------------------------------
  if (opt.partition.rank == 0) store.prepare(opt.resume);
  if (opt.partition.barrier) opt.partition.barrier();

  // ---- this process's pending chunks --------------------------------------------------------------
  McResult result;
  result.runsTotal = opt.runs * models.size();
  std::vector<ChunkKey> pending;
  std::uint64_t pendingRuns = 0;
  for (std::size_t w = 0; w < all.size(); ++w) {
    const ChunkKey& wk = all[w];
    const CheckpointStore::State st = store.read(wk, nullptr);
    if (st == CheckpointStore::State::foreign)
      throw InputError("cannot resume: checkpoint " + store.path(wk) +
                       " was computed from other inputs");
    if (st == CheckpointStore::State::valid) {
      result.runsResumed += wk.count;
      continue;
    }
    if (st == CheckpointStore::State::damaged) result.damaged.push_back(store.path(wk));
    if (st == CheckpointStore::State::resized) ++result.resized;
    if (int(w % std::size_t(opt.partition.size)) != opt.partition.rank) continue;
    pending.push_back(wk);
    pendingRuns += wk.count;
  }

  // ---- workers ------------------------------------------------------------------------------------
  unsigned threads = opt.threads ? opt.threads : std::max(1u, std::thread::hardware_concurrency());
  threads = unsigned(std::max<std::uint64_t>(1, std::min<std::uint64_t>(threads, pendingRuns)));
  result.threads = threads;
  std::atomic<std::uint64_t> runsDone{0};
  std::atomic<bool> stop{false};
  std::atomic<unsigned> running{threads};
  std::mutex mu;
  std::condition_variable cv;
  std::exception_ptr failure;
  const std::size_t perRun = ref.runFloats();

  // Runs are handed out one at a time, so the threads stay busy to the last run whatever the
  // chunk size; a chunk's buffer lives while any of its runs is in flight, and the thread that
  // finishes its last run writes the chunk file. Unfinished chunks (interruption) are dropped.
  std::vector<std::uint64_t> chunkStart(pending.size() + 1, 0);  // first pending-run index
  for (std::size_t i = 0; i < pending.size(); ++i)
    chunkStart[i + 1] = chunkStart[i] + pending[i].count;
  struct OpenChunk {
    std::vector<float> buf;
    std::atomic<std::uint64_t> remaining{0};
  };
  std::vector<std::unique_ptr<OpenChunk>> open(pending.size());
  std::atomic<std::uint64_t> nextRun{0};

  auto worker = [&]() {
    try {
      for (;;) {
        if (stop.load() || (opt.interrupt && opt.interrupt->load())) break;
        const std::uint64_t g = nextRun.fetch_add(1);
        if (g >= pendingRuns) break;
        const auto ci = std::size_t(
            std::upper_bound(chunkStart.begin(), chunkStart.end(), g) - chunkStart.begin() - 1);
        const ChunkKey& wk = pending[ci];
        const std::uint64_t r = g - chunkStart[ci];
        OpenChunk* oc = nullptr;
        {
          std::lock_guard<std::mutex> lock(mu);
          if (!open[ci]) {
            open[ci] = std::make_unique<OpenChunk>();
            open[ci]->buf.assign(std::size_t(wk.count) * perRun, 0.0f);
            open[ci]->remaining = wk.count;
          }
          oc = open[ci].get();
        }
        const McModel& m = models[wk.model];
        std::unique_ptr<errormodels::ImuCorruptor> c;
        if (!m.model.empty()) c = m.model.instantiate(ref.imuRate, {opt.seed, wk.first + r});
        if (!navigateRealisation(ref, c.get(), opt.navigate, oc->buf.data() + r * perRun,
                                 opt.interrupt, {opt.seed, wk.first + r}))
          break;  // interrupted mid-run: the chunk stays unfinished
        const std::uint64_t done = runsDone.fetch_add(1) + 1;
        if (opt.stopAfterRuns && done >= opt.stopAfterRuns) stop.store(true);
        if (oc->remaining.fetch_sub(1) == 1) {  // the chunk's last run: every other is stored
          store.write(wk, oc->buf.data());
          std::lock_guard<std::mutex> lock(mu);
          open[ci].reset();
        }
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(mu);
      if (!failure) failure = std::current_exception();
      stop.store(true);
    }
    {
      std::lock_guard<std::mutex> lock(mu);
      --running;
    }
    cv.notify_all();
  };

  const auto workStart = std::chrono::steady_clock::now();
  std::vector<std::thread> pool;
  if (!pending.empty())
    for (unsigned t = 0; t < threads; ++t) pool.emplace_back(worker);
  auto progress = [&]() {
    if (!opt.onProgress) return;
    McProgress p;
    p.runsDone = runsDone.load();
    p.runsTotal = pendingRuns;
    p.runsResumed = result.runsResumed;
    p.elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - workStart).count();
    opt.onProgress(p);
  };
  {
    std::unique_lock<std::mutex> lock(mu);
    while (!pool.empty() && running.load() > 0) {
      cv.wait_for(lock, std::chrono::milliseconds(200));
      lock.unlock();
      progress();
      lock.lock();
    }
  }
  for (auto& t : pool) t.join();
  progress();
  if (failure) {
    if (opt.partition.rank == 0 && opt.partition.size <= 1) store.discardEmpty();
    std::rethrow_exception(failure);
  }
  result.runsComputed = runsDone.load();

  if (opt.partition.barrier) opt.partition.barrier();

  // ---- reduction (rank 0): every chunk, read back in run order -------------------------------------
  result.labels.clear();
  for (const auto& e : batch.entries) result.labels.push_back(e.label);
  if (opt.partition.rank == 0) {
    bool complete = true;
    batch.errors.assign(models.size(), {});
    for (std::size_t m = 0; m < models.size(); ++m) batch.errors[m].resize(opt.runs * perRun);
    for (const ChunkKey& wk : all) {
      float* dst = batch.errors[wk.model].data() + wk.first * perRun;
      if (store.read(wk, dst) == CheckpointStore::State::valid)
        result.runsSaved += wk.count;
      else
        complete = false;
    }
    result.complete = complete;
    // Stopped before any chunk was saved: nothing to resume, no empty folders left behind.
    if (!complete && result.runsSaved == 0 && opt.partition.size <= 1) store.discardEmpty();
    if (complete) {
      writeMcOutputs(batch, opt.outDir, result.files);
      result.errors = std::move(batch.errors);
    }
  }
  if (opt.partition.anyOf) result.complete = opt.partition.anyOf(result.complete);
  result.runsComputedAll =
      opt.partition.sum ? opt.partition.sum(result.runsComputed) : result.runsComputed;

  result.wallTime =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
  result.cpuTime = processCpuTime() - cpuStart;
  if (opt.partition.sum)  // every rank's CPU, not rank 0's alone (to the microsecond)
    result.cpuTime =
        1e-6 * double(opt.partition.sum(std::uint64_t(std::llround(std::max(0.0, result.cpuTime) * 1e6))));
  return result;
}

}  // namespace sinsim::sim
