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
#include "sim/mc_output.hpp"

namespace sinsim::sim {
namespace {

namespace fs = std::filesystem;

// ---- fingerprints (FNV-1a 64): what a checkpoint was computed from -----------------------------

struct Fnv {
  std::uint64_t h = 1469598103934665603ull;
  void bytes(const void* p, std::size_t n) {
    const auto* c = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) {
      h ^= c[i];
      h *= 1099511628211ull;
    }
  }
  void text(const std::string& s) {
    const std::uint64_t n = s.size();
    bytes(&n, sizeof n);
    bytes(s.data(), s.size());
  }
  template <class T>
  void value(const T& v) {
    bytes(&v, sizeof v);
  }
};

std::uint64_t referenceFingerprint(const Reference& ref, const McOptions& opt) {
  Fnv f;
  f.text("sinsim-mc 1");
  f.text(opt.scenarioIdentity);
  f.value(ref.imuRate);
  f.value(ref.decimation);
  f.value(int(ref.strapdown.vertical));
  f.value(ref.strapdown.dampingTimeConstant);
  f.value(ref.temperature.present);
  f.value(ref.temperature.start);
  f.value(ref.temperature.rate);
  const nav::NavState& s0 = ref.initial;
  f.value(s0.lat);
  f.value(s0.lon);
  f.value(s0.h);
  f.bytes(s0.v_n.data(), 3 * sizeof(double));
  f.bytes(s0.q_nb.coeffs().data(), 4 * sizeof(double));
  for (const auto& s : ref.samples) {
    f.value(s.t);
    f.value(s.dt);
    f.bytes(s.dtheta_b.data(), 3 * sizeof(double));
    f.bytes(s.dv_b.data(), 3 * sizeof(double));
  }
  f.bytes(ref.hRef.data(), ref.hRef.size() * sizeof(double));
  f.value(opt.seed);
  f.value(opt.navigate.biasWindow);
  f.value(kChunkRuns);
  return f.h;
}

std::uint64_t modelFingerprint(std::uint64_t base, const McModel& m) {
  Fnv f;
  f.value(base);
  f.text(m.identity);
  for (const auto& n : m.model.effectNames()) f.text(n);
  return f.h;
}

std::string fileSafe(const std::string& s) {
  std::string r;
  for (char c : s)
    r += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.') ? c : '_';
  return r;
}

// ---- chunk files ---------------------------------------------------------------------------------

constexpr char kMagic[8] = {'S', 'S', 'M', 'C', 'C', 'H', 'K', '1'};

struct ChunkHeader {
  char magic[8];
  std::uint64_t fingerprint;
  std::uint64_t first;
  std::uint64_t count;
  std::uint64_t epochs;
  std::uint64_t fields;
};

struct Work {
  std::size_t model;
  std::uint64_t first, count;
};

std::string chunkPath(const std::string& dir, const std::string& modelDir, std::uint64_t first) {
  char name[32];
  std::snprintf(name, sizeof name, "r%09llu.bin", static_cast<unsigned long long>(first));
  return (fs::path(dir) / "runs" / modelDir / name).string();
}

enum class ChunkState { missing, valid, foreign };

// Reads a chunk file into out (count × epochs × fields floats) when it matches.
ChunkState readChunk(const std::string& path, std::uint64_t fingerprint, const Work& w,
                     std::size_t epochs, float* out) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return ChunkState::missing;
  ChunkHeader h{};
  ChunkState st = ChunkState::missing;  // damaged or short: recompute
  if (std::fread(&h, sizeof h, 1, f) == 1 && std::memcmp(h.magic, kMagic, 8) == 0) {
    if (h.fingerprint != fingerprint) {
      st = ChunkState::foreign;
    } else if (h.first == w.first && h.count == w.count && h.epochs == epochs &&
               h.fields == kErrorFields) {
      const std::size_t n = std::size_t(w.count) * epochs * kErrorFields;
      if (!out) {
        // only check the size
        std::fseek(f, 0, SEEK_END);
        if (std::size_t(std::ftell(f)) == sizeof h + n * sizeof(float)) st = ChunkState::valid;
      } else if (std::fread(out, sizeof(float), n, f) == n && std::fgetc(f) == EOF) {
        st = ChunkState::valid;
      }
    }
  }
  std::fclose(f);
  return st;
}

void writeChunk(const std::string& path, std::uint64_t fingerprint, const Work& w,
                std::size_t epochs, const float* data) {
  ChunkHeader h{};
  std::memcpy(h.magic, kMagic, 8);
  h.fingerprint = fingerprint;
  h.first = w.first;
  h.count = w.count;
  h.epochs = epochs;
  h.fields = kErrorFields;
  const std::string tmp = path + ".tmp." + std::to_string(::getpid()) + "." +
                          std::to_string(std::hash<std::thread::id>()(std::this_thread::get_id()));
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) throw Error("cannot write " + tmp);
  const std::size_t n = std::size_t(w.count) * epochs * kErrorFields;
  bool ok = std::fwrite(&h, sizeof h, 1, f) == 1 && std::fwrite(data, sizeof(float), n, f) == n;
  ok = (std::fclose(f) == 0) && ok;
  std::error_code ec;
  if (ok) fs::rename(tmp, path, ec);
  if (!ok || ec) {
    fs::remove(tmp, ec);
    throw Error("cannot write checkpoint " + path + " (disk full?)");
  }
}

double processCpuTime() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

}  // namespace

McResult runMonteCarlo(const Reference& ref, const std::vector<McModel>& primaryModels,
                       const McOptions& opt) {
  const auto wallStart = std::chrono::steady_clock::now();
  const double cpuStart = processCpuTime();

  // ---- validate ----------------------------------------------------------------------------------
  if (opt.runs == 0) throw InputError("--runs must be at least 1");
  if (opt.outDir.empty()) throw InputError("an output folder is required (-o DIR)");
  if (primaryModels.empty()) throw InputError("no error model given");
  if (ref.epochs() < 2) throw InputError("the scenario has fewer than two output epochs");
  if (opt.measured && opt.measured->errors.size() != ref.epochs() * kErrorFields)
    throw InputError("the measured record does not cover the reference's output epochs");
  for (std::size_t i = 0; i < primaryModels.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (primaryModels[i].label == primaryModels[j].label)
        throw InputError("two models share the label " + primaryModels[i].label);
  std::vector<std::size_t> timeEpochs;
  for (double t : opt.times) {
    if (!(std::isfinite(t) && t >= 0 && t <= ref.epochTime(ref.epochs() - 1) + 1e-9))
      throw InputError("report time " + std::to_string(t) + " s is outside the run (0 to " +
                       std::to_string(ref.epochTime(ref.epochs() - 1)) + " s)");
    timeEpochs.push_back(std::size_t(std::llround(t * ref.outputRate)));
  }
  if (timeEpochs.empty()) timeEpochs.push_back(ref.epochs() - 1);

  // ---- the batch: models and budget variants -----------------------------------------------------
  McBatch batch(ref);
  batch.runs = opt.runs;
  batch.seed = opt.seed;
  batch.timeEpochs = timeEpochs;
  batch.measured = opt.measured;
  batch.biasWindow = opt.navigate.biasWindow;
  std::vector<McModel> models = primaryModels;
  for (std::size_t i = 0; i < primaryModels.size(); ++i) {
    batch.entries.push_back({primaryModels[i].label, primaryModels[i].model.source(), -1, ""});
    batch.effectNames.push_back(primaryModels[i].model.empty()
                                    ? std::vector<std::string>{}
                                    : primaryModels[i].model.effectNames());
  }
  if (opt.budget) {
    for (std::size_t i = 0; i < primaryModels.size(); ++i) {
      const auto names = batch.effectNames[i];
      if (names.size() < 2) continue;  // one effect: its share is the whole drift
      for (const auto& name : names) {
        McModel v = primaryModels[i];
        v.label = primaryModels[i].label + " without " + name;
        v.model = primaryModels[i].model.filtered([&](const std::string& n) { return n != name; });
        models.push_back(v);
        batch.entries.push_back({v.label, primaryModels[i].model.source(), int(i), name});
        batch.effectNames.push_back(v.model.effectNames());
      }
    }
  }

  const std::uint64_t base = referenceFingerprint(ref, opt);
  std::vector<std::uint64_t> fps;
  std::vector<std::string> dirs;
  for (const auto& m : models) {
    fps.push_back(modelFingerprint(base, m));
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(fps.back()));
    dirs.push_back(fileSafe(m.label).substr(0, 80) + "-" + std::string(hex, 8));
  }

  std::vector<Work> all;
  for (std::uint64_t first = 0; first < opt.runs; first += kChunkRuns)
    for (std::size_t m = 0; m < models.size(); ++m)
      all.push_back({m, first, std::min(kChunkRuns, opt.runs - first)});

  // ---- the folder (rank 0 prepares it; the others wait) ------------------------------------------
  const fs::path runsDir = fs::path(opt.outDir) / "runs";
  if (opt.partition.rank == 0) {
    std::error_code ec;
    if (fs::exists(opt.outDir, ec) && !fs::is_directory(opt.outDir, ec))
      throw InputError("output folder " + opt.outDir + " exists and is not a folder");
    if (!opt.resume && fs::exists(runsDir, ec) && !fs::is_empty(runsDir, ec))
      throw InputError(opt.outDir + " holds the checkpoints of a batch (" + runsDir.string() +
                       "); pass --resume to continue it, or choose another folder");
    if (opt.resume && fs::exists(runsDir, ec)) {
      // Chunks computed from other inputs mean the user is resuming the wrong batch.
      for (std::size_t m = 0; m < models.size(); ++m) {
        if (fs::exists(runsDir / dirs[m], ec)) continue;
        for (const auto& entry : fs::directory_iterator(runsDir, ec)) {
          const std::string n = entry.path().filename().string();
          const std::string stem = fileSafe(models[m].label).substr(0, 80) + "-";
          if (n.rfind(stem, 0) == 0)
            throw InputError("cannot resume " + opt.outDir + ": its checkpoints of model " +
                             models[m].label + " were computed from other inputs (scenario, "
                             "model, seed or bias window changed); remove " +
                             (runsDir / n).string() + " or choose another folder");
        }
      }
    }
    // Temporaries of a process that was killed while writing: never valid, remove them.
    if (fs::exists(opt.outDir, ec)) {
      std::vector<fs::path> stale;
      for (auto it = fs::recursive_directory_iterator(opt.outDir, ec);
           it != fs::recursive_directory_iterator(); it.increment(ec))
        if (it->is_regular_file(ec) && it->path().filename().string().find(".tmp.") != std::string::npos)
          stale.push_back(it->path());
      for (const auto& p : stale) fs::remove(p, ec);
    }
    for (const auto& d : dirs) {
      fs::create_directories(runsDir / d, ec);
      if (ec) throw InputError("cannot create " + (runsDir / d).string() + ": " + ec.message());
    }
  }
  if (opt.partition.barrier) opt.partition.barrier();

  // ---- this process's pending chunks --------------------------------------------------------------
  McResult result;
  result.runsTotal = opt.runs * models.size();
  std::vector<Work> pending;
  std::uint64_t pendingRuns = 0;
  for (std::size_t w = 0; w < all.size(); ++w) {
    const Work& wk = all[w];
    const std::string path = chunkPath(opt.outDir, dirs[wk.model], wk.first);
    const ChunkState st = readChunk(path, fps[wk.model], wk, ref.epochs(), nullptr);
    if (st == ChunkState::foreign)
      throw InputError("cannot resume: checkpoint " + path + " was computed from other inputs");
    if (st == ChunkState::valid) {
      result.runsResumed += wk.count;
      continue;
    }
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
  const std::size_t perRun = ref.epochs() * kErrorFields;

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
        const Work& wk = pending[ci];
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
                                 opt.interrupt))
          break;  // interrupted mid-run: the chunk stays unfinished
        const std::uint64_t done = runsDone.fetch_add(1) + 1;
        if (opt.stopAfterRuns && done >= opt.stopAfterRuns) stop.store(true);
        if (oc->remaining.fetch_sub(1) == 1) {  // the chunk's last run: every other is stored
          writeChunk(chunkPath(opt.outDir, dirs[wk.model], wk.first), fps[wk.model], wk,
                     ref.epochs(), oc->buf.data());
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
  if (failure) std::rethrow_exception(failure);
  result.runsComputed = runsDone.load();

  if (opt.partition.barrier) opt.partition.barrier();

  // ---- reduction (rank 0): every chunk, read back in run order -------------------------------------
  result.labels.clear();
  for (const auto& e : batch.entries) result.labels.push_back(e.label);
  if (opt.partition.rank == 0) {
    bool complete = true;
    batch.errors.assign(models.size(), {});
    for (std::size_t m = 0; m < models.size(); ++m) batch.errors[m].resize(opt.runs * perRun);
    for (const Work& wk : all) {
      float* dst = batch.errors[wk.model].data() + wk.first * perRun;
      if (readChunk(chunkPath(opt.outDir, dirs[wk.model], wk.first), fps[wk.model], wk,
                    ref.epochs(), dst) != ChunkState::valid)
        complete = false;
    }
    result.complete = complete;
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
  return result;
}

}  // namespace sinsim::sim
