// Monte Carlo batches: N realisations of each error model along one reference (ideal IMU + truth,
// computed once), in parallel, checkpointed, and reduced to drift statistics.
//
// Reproducibility. Run k of every model uses the random streams StreamKey{seed, k}
// (errormodels/random.hpp: counter-based, a pure function of the key), so
//  - the comparison between models is paired: run k of model A and run k of model B see the same
//    driving noise wherever their effects sit at the same place in the model (same stream id);
//  - a run's result does not depend on which thread, process or MPI rank computed it, nor when.
// Results are stored per (model, run) and reduced in run order, so every output file is
// bit-identical for any thread count, rank count, and after interruption + --resume.
//
// Checkpoints (sim/mc_checkpoint.hpp). Runs are grouped in chunks of kChunkRuns consecutive runs
// of one model; each finished chunk is written to DIR/runs/ with a CRC-32, via a temporary +
// rename. An interrupted batch (Ctrl-C, kill, power cut between chunks) resumes from the chunks
// present; a chunk is recomputed when its file is missing or damaged (McResult::damaged). The
// folder is locked (flock) while a batch runs: a second process is refused.
// Threads take single runs (not chunks), so they stay busy to the end of a batch.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "errormodels/imu_model.hpp"
#include "sim/reference.hpp"

namespace sinsim::sim {

/// One error model of a batch.
struct McModel {
  std::string label;  // short name for files and reports (unique within the batch)
  errormodels::ImuErrorModel model;
  /// Text that identifies the model for resume checks (e.g. the model file's content).
  std::string identity;
};

/// The effects --budget switches off one at a time in `m`: all of its effects when it has two or
/// more, none otherwise (one effect's share is the whole drift).
std::vector<std::string> budgetEffects(const McModel& m);

/// A measured record navigated along the same reference (see cmd_mc --measured): its errors at
/// every output epoch, epochs() × kErrorFields.
struct McMeasured {
  std::string source;  // file name, for reports
  std::vector<float> errors;
};

struct McProgress {
  std::uint64_t runsDone = 0;   // by this process, this session
  std::uint64_t runsTotal = 0;  // this process's share still to do at the start of the session
  std::uint64_t runsResumed = 0;  // found in checkpoints
  double elapsed = 0.0;         // [s] since the workers started
};

/// How a batch is split across processes (MPI ranks). The default is one process.
struct McPartition {
  int rank = 0;
  int size = 1;
  /// Waits until every process reaches it (MPI_Barrier); empty for one process.
  std::function<void()> barrier;
  /// Logical OR of a flag across processes (MPI_Allreduce); empty for one process.
  std::function<bool(bool)> anyOf;
  /// Sum of a count across processes (MPI_Allreduce); empty for one process.
  std::function<std::uint64_t(std::uint64_t)> sum;
};

struct McOptions {
  std::uint64_t runs = 100;  // realisations per model
  std::uint64_t seed = 0;
  unsigned threads = 0;      // worker threads; 0: std::thread::hardware_concurrency()
  /// Times [s] at which CEP/R95, the model comparison, the budget and the measured percentile are
  /// reported; snapped to the nearest output epoch. Empty: the last epoch.
  std::vector<double> times;
  /// Adds, for every model, the variants with one effect switched off (ImuErrorModel::filtered)
  /// and reports each effect's share of the mean-square horizontal drift.
  bool budget = false;
  /// The label of the model every other model is compared with in the headlines (paired
  /// comparison of the horizontal drift); empty: every pair. Must name one of the models.
  std::string reference;
  NavigateOptions navigate;
  bool resume = false;
  std::string outDir;        // required
  std::string scenarioIdentity;  // text identifying the scenario for resume checks
  const McMeasured* measured = nullptr;
  /// Interrupt flag (SIGINT): workers finish or drop their chunk and stop; the folder stays
  /// resumable.
  const std::atomic<bool>* interrupt = nullptr;
  /// Stop after this many runs of this session have finished (0: no limit) — a deterministic
  /// stand-in for an interruption, for tests.
  std::uint64_t stopAfterRuns = 0;
  /// Called from the calling thread about 5 times a second while workers run, and once at the end.
  std::function<void(const McProgress&)> onProgress;
  McPartition partition;
};

struct McResult {
  bool complete = false;       // every run of every model present (outputs written by rank 0)
  std::uint64_t runsComputed = 0;  // by this process in this session
  std::uint64_t runsComputedAll = 0;  // by every process (MPI ranks) in this session
  std::uint64_t runsResumed = 0;   // found in checkpoints at the start
  std::uint64_t runsTotal = 0;     // runs × (models incl. budget variants)
  /// Runs in valid checkpoints at the end (whole chunks; rank 0 counts every rank's).
  std::uint64_t runsSaved = 0;
  /// Checkpoints found damaged (checksum mismatch, truncated, zeroed, older format) and
  /// therefore recomputed by this session (their paths; rank 0 sees every one).
  std::vector<std::string> damaged;
  /// Chunks recomputed because another --runs had cut them to another length (a grown batch's
  /// old last chunk): intact, not damaged.
  std::size_t resized = 0;
  std::vector<std::string> files;  // outputs written (rank 0, when complete)
  double wallTime = 0.0;           // [s]
  double cpuTime = 0.0;            // [s] of every process of the batch (MPI ranks summed)
  unsigned threads = 0;
  /// Per model (incl. budget variants, in order), runs × ref.runFloats() values (errors, then an
  /// aided run's filter view), for callers that want the raw values (tests); filled on rank 0
  /// when complete.
  std::vector<std::string> labels;
  std::vector<std::vector<float>> errors;
};

constexpr std::uint64_t kChunkRuns = 8;

/// The output epochs of the report times [s] (McOptions::times), each snapped to the nearest
/// epoch; no times: the last epoch. Throws InputError for a time outside the run.
std::vector<std::size_t> reportEpochs(const Reference& ref, const std::vector<double>& times);

/// InputError unless `reference` is empty or the label of one of `models` (McOptions::reference).
void requireReference(const std::vector<McModel>& models, const std::string& reference);

/// Runs (or resumes) a batch. Throws InputError for bad options or a checkpoint folder that
/// belongs to another batch; nothing is written before the options are validated.
McResult runMonteCarlo(const Reference& ref, const std::vector<McModel>& models,
                       const McOptions& options);

}  // namespace sinsim::sim
