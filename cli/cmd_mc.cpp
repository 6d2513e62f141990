// sinsim mc SCENARIO --runs N [--model FILE ...] [--threads T] [--seed S] [--resume] -o DIR
//           [--times LIST] [--budget] [--measured DATA.csv ...]
// Monte Carlo batches (sim/montecarlo.hpp). With the MPI build (-DSINSIM_MPI=ON) the same command
// under mpirun splits the runs across ranks.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <sstream>
#include <thread>

#ifdef SINSIM_HAVE_MPI
#include <mpi.h>
#endif

#include "common/limits.hpp"
#include "cli/commands.hpp"
#include "cli/record_options.hpp"
#include "cli/terminal.hpp"
#include "common/constants.hpp"
#include "common/error.hpp"
#include "common/number_text.hpp"
#include "common/progress.hpp"
#include "common/units.hpp"
#include "errormodels/stats/record.hpp"
#include "sim/mc_batch.hpp"
#include "sim/nav_loop.hpp"

namespace sinsim::cli {
namespace {

std::vector<std::string> splitList(const std::string& s) {
  std::vector<std::string> r;
  std::string cur;
  for (char c : s) {
    if (c == ',') {
      r.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  r.push_back(cur);
  return r;
}

double parseAngle(const std::string& text, const std::string& what) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end && end != text.c_str() && std::string(end).find_first_not_of(" \t") == std::string::npos)
    return degToRad(v);  // as "v deg" reads
  try {
    return parseQuantityAs(text, Dimension::angle());
  } catch (const InputError& e) {
    throw InputError(what + ": " + e.text());
  }
}

std::string fmt(double v, const char* f = "%.6g") {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

struct Args {
  std::string scenario;
  std::uint64_t runs = 100;
  std::vector<std::string> models;
  unsigned threads = 0;
  std::optional<std::uint64_t> seed;
  bool resume = false;
  std::string outDir;
  std::string times;
  bool budget = false;
  std::string reference;
  std::string measured;
  RecordArgs record;  // of --measured
  std::string latitude = "51.08 deg", longitude = "-114.13 deg", height = "1100 m";
  std::string attitude, heading = "0 deg";
  std::string biasWindow;
  std::string vertical = "held";
  double outputRate = 1.0;
  bool noProgress = false;
  std::uint64_t stopAfter = 0;
};

#ifdef SINSIM_HAVE_MPI
// MPI is started only when the process was launched by an MPI launcher (mpirun/srun set these
// variables); a plain `sinsim mc` of the MPI build behaves exactly like the ordinary build.
bool launchedByMpi() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "MPI_LOCALNRANKS"})
    if (std::getenv(v)) return true;
  return false;
}

struct MpiSession {
  int rank = 0, size = 1;
  MpiSession() {
    int inited = 0;
    MPI_Initialized(&inited);
    if (!inited) {
      int provided = 0;
      MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    }
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
  }
  ~MpiSession() { MPI_Finalize(); }
};
#endif

// The --measured options as values (angles and times parsed, SI).
sim::MeasuredOptions measuredOptions(const Args& a) {
  sim::MeasuredOptions o;
  o.path = a.measured;
  o.record = recordOptions(a.record);
  o.lat = parseAngle(a.latitude, "--latitude");
  o.lon = parseAngle(a.longitude, "--longitude");
  o.h = parseOptionQuantity(a.height, Dimension::length(), "--height");
  if (!a.attitude.empty()) {
    const auto parts = splitList(a.attitude);
    if (parts.size() != 3) throw InputError("--attitude: expected roll,pitch,yaw");
    o.attitude = nav::Vec3(parseAngle(parts[0], "--attitude"), parseAngle(parts[1], "--attitude"),
                           parseAngle(parts[2], "--attitude"));
  }
  o.heading = parseAngle(a.heading, "--heading");
  if (!a.biasWindow.empty()) o.biasWindow = parseDuration(a.biasWindow, "--bias-window");
  o.strapdown.vertical = sim::verticalChannel(a.vertical, "--vertical");
  o.outputRate = a.outputRate;
  return o;
}

// The batch's outcome on the terminal (rank 0): damaged checkpoints, an interruption, or the
// summary line and each model's headline.
void printBatch(const sim::McCommandResult& batch, int size) {
  const sim::McResult& r = batch.result;
  const sim::McOptions& opt = batch.options;
  if (opt.partition.rank != 0) return;
  for (const std::string& w : batch.warnings) std::cerr << "sinsim mc: warning: " << w << "\n";
  if (!r.damaged.empty()) {
    std::cerr << "sinsim mc: " << r.damaged.size()
              << " damaged checkpoint(s) (checksum mismatch, truncated or unreadable) were "
                 "recomputed:";
    for (const auto& p : r.damaged) std::cerr << " " << p;
    std::cerr << "\n";
  }
  const double steps = double(r.runsComputedAll) * double(batch.samples);
  if (!r.complete) {
    // Runs are saved in whole chunks: runs of a chunk cut short are not counted.
    std::cerr << (progress::interruptFlag().load() ? interruptedMessage("mc")
                                                   : std::string("sinsim mc: stopped (run limit); "))
              << r.runsComputedAll << " runs computed this session, ";
    if (r.runsSaved == 0)  // (one process: its empty folders were removed)
      std::cerr << "none saved (runs are saved in chunks of " << sim::kChunkRuns
                << " per model, and no chunk was finished). Run the same command again.\n";
    else
      std::cerr << r.runsSaved << " of " << r.runsTotal << " runs saved in " << opt.outDir
                << "/runs. Continue with the same command and --resume.\n";
    return;
  }
  std::cout << "sinsim mc: " << batch.scenarioName << ", " << batch.modelCount << " model(s) x "
            << opt.runs << " runs"
            << (r.labels.size() > batch.modelCount
                    ? " (+ " + std::to_string(r.labels.size() - batch.modelCount) + " budget variants)"
                    : std::string())
            << " -> "
            << opt.outDir << " (";
  for (std::size_t i = 0; i < r.files.size(); ++i) std::cout << (i ? ", " : "") << r.files[i];
  std::cout << ")\n  " << r.runsComputedAll << " runs computed";
  if (r.runsResumed) std::cout << ", " << r.runsResumed << " resumed from checkpoints";
  if (!r.damaged.empty()) std::cout << " (" << r.damaged.size() << " damaged checkpoint(s) recomputed)";
  if (r.resized)
    std::cout << " (" << r.resized << " chunk(s) an earlier --runs had cut to another length recomputed)";
  std::cout << " in " << fmt(r.wallTime, "%.2f") << " s wall, " << fmt(r.cpuTime, "%.2f")
            << " s CPU, " << r.threads << " thread(s)"
            << (size > 1 ? " per rank, " + std::to_string(size) + " MPI ranks" : std::string())
            << "; " << fmt(steps / std::max(r.wallTime, 1e-9) / 1e6, "%.2f")
            << " M IMU steps/s\n";
  for (const sim::McHeadline& h : batch.headlines.models)
    std::cout << "  " << h.label << ": horizontal error at " << durationText(h.t) << ": CEP "
              << lengthText(h.cep) << ", R95 " << lengthText(h.r95) << "\n";
  for (const sim::McPairedHeadline& p : batch.headlines.pairs)
    std::cout << "  " << p.sentence() << " Wilcoxon " << pStatement(p.pWilcoxon) << ".\n";
  for (const sim::McAidedSummary& s : batch.headlines.aided)
    for (const std::string& line : s.sentences()) std::cout << "  " << line << "\n";
  if (!batch.headlines.measured.empty()) std::cout << "  " << batch.headlines.measured << "\n";
}

int runMc(const Args& a) {
  if (a.runs == 0) throw OptionError("--runs: expected at least 1 run per model, got 0");
  int rank = 0, size = 1;
  sim::McPartition partition;
#ifdef SINSIM_HAVE_MPI
  if (launchedByMpi()) {
    static MpiSession mpi;  // finalised at exit
    rank = mpi.rank;
    size = mpi.size;
  }
  if (size > 1) {
    partition.rank = rank;
    partition.size = size;
    partition.barrier = [] { MPI_Barrier(MPI_COMM_WORLD); };
    partition.anyOf = [](bool v) {
      int in = v ? 1 : 0, out = 0;
      MPI_Allreduce(&in, &out, 1, MPI_INT, MPI_LOR, MPI_COMM_WORLD);
      return out != 0;
    };
    partition.sum = [](std::uint64_t v) {
      unsigned long long in = v, out = 0;
      MPI_Allreduce(&in, &out, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
      return std::uint64_t(out);
    };
  }
#endif
  try {
    sim::McRequest req;
    req.scenarioPath = a.scenario;
    if (!a.measured.empty()) req.measured = measuredOptions(a);
    req.models = a.models;
    req.seed = a.seed;
    sim::McOptions& opt = req.options;
    opt.runs = a.runs;
    opt.threads = a.threads;
    if (opt.threads == 0 && size > 1) {
      // Ranks sharing a machine share its cores.
      const char* local = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
      const unsigned ranksHere = local ? unsigned(std::max(1, std::atoi(local))) : 1u;
      opt.threads = std::max(1u, std::thread::hardware_concurrency() / ranksHere);
    }
    if (!a.times.empty())
      for (const auto& t : splitList(a.times)) opt.times.push_back(parseDuration(t, "--times"));
    opt.budget = a.budget;
    opt.reference = a.reference;
    opt.navigate.biasWindow = a.biasWindow.empty() ? 0.0 : parseDuration(a.biasWindow, "--bias-window");
    opt.resume = a.resume;
    opt.outDir = a.outDir;
    opt.stopAfterRuns = a.stopAfter;
    opt.partition = partition;

    if (rank != 0 || a.noProgress) endProgressLine();
    opt.interrupt = &progress::interruptFlag();
    opt.onProgress = [](const sim::McProgress& p) { progress::update("runs", p.runsDone, p.runsTotal); };
    const sim::McCommandResult batch = [&] {
      try {
        return sim::runMcBatch(req);
      } catch (const MotionError& e) {
        throw InputError(req.scenarioPath + ": " + e.text());
      }
    }();
    endProgressLine();
    printBatch(batch, size);
    return batch.result.complete ? 0 : interruptedExitCode();
  } catch (...) {
#ifdef SINSIM_HAVE_MPI
    if (size > 1) {
      try {
        throw;
      } catch (const std::exception& e) {
        std::cerr << "sinsim: error (rank " << rank << "): " << e.what() << "\n";
      }
      MPI_Abort(MPI_COMM_WORLD, 1);
    }
#endif
    throw;
  }
}

}  // namespace

void addMcCommand(CLI::App& app, Action& action) {
  auto a = std::make_shared<Args>();
  CLI::App* c = app.add_subcommand(
      "mc", "Monte Carlo: N realisations per error model, drift statistics, paired comparison");
  c->add_option("scenario", a->scenario, "Scenario YAML file");
  c->add_option("--runs", a->runs, "Realisations per model (default 100)");
  // One file per --model (repeat it): `--model A.yaml scenario.yaml` must not take the scenario
  // for a second model.
  c->add_option("--model", a->models,
                "Error model file (repeat for a comparison; none: perfect IMU). Default: the "
                "scenario's errors:")
      ->allow_extra_args(false);
  c->add_option("--threads", a->threads, "Worker threads (default: all cores)")
      ->check(CLI::Range(0u, sinsim::limits::kMaxThreads));
  c->add_option("--seed", a->seed, "Seed; run k uses StreamKey{seed, k} (default: the scenario's)");
  c->add_flag("--resume", a->resume, "Continue an interrupted batch in DIR from its checkpoints");
  c->add_option("-o,--output", a->outDir, "Output folder (default out/mc-<scenario name>)");
  c->add_option("--times", a->times,
                "Report times, comma-separated (\"60,300\" s or \"5 min,10 min\"; default: the end)");
  c->add_flag("--budget", a->budget, "Error budget: switch each effect off in turn");
  c->add_option("--reference", a->reference,
                "Compare every model with this one only (its label: the model file's name without .yaml; "
                "default: every pair)");
  c->add_option("--measured", a->measured,
                "A static record (CSV, .gz) to navigate and place in each model's envelope");
  addRecordOptions(c, a->record);  // of the --measured record
  c->add_option("--latitude", a->latitude, "Where the record was taken (default 51.08 deg: Calgary)");
  c->add_option("--longitude", a->longitude, "(default -114.13 deg)");
  c->add_option("--height", a->height, "(default 1100 m)");
  c->add_option("--attitude", a->attitude,
                "roll,pitch,yaw of the record's IMU (plain numbers: deg); default: levelled "
                "from the mean specific force, yaw = --heading");
  c->add_option("--heading", a->heading, "Yaw when levelling from the data (default 0 deg)");
  c->add_option("--bias-window", a->biasWindow,
                "Remove the mean error of the first T seconds (record and every model run alike; "
                "default with --measured: min(60 s, 10 % of the record), else 0)");
  c->add_option("--vertical", a->vertical,
                "Vertical channel for --measured: held (default), free or damped");
  c->add_option("--output-rate", a->outputRate, "Statistics epochs per second for --measured (1)");
  c->add_flag("--no-progress", a->noProgress, "No progress bar even on a terminal");
  c->add_option("--stop-after", a->stopAfter, "Stop after N runs as if interrupted (testing)")
      ->group("");
  c->callback([&action, a]() { action = [a]() { return runMc(*a); }; });
}

}  // namespace sinsim::cli
