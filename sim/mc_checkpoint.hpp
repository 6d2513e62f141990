// The checkpoint store of a Monte Carlo batch: one binary file per chunk of kChunkRuns
// consecutive runs of one model under DIR/runs/<label>-<fingerprint>/, written via a temporary +
// rename (a chunk file is whole or absent) and closed by a CRC-32 of everything before it, so a
// flipped bit, a truncation or a zeroed file is detected on resume and the chunk recomputed.
// A fingerprint of every input (reference, seed, bias window, model) in each chunk refuses a
// resume of another batch. The folder is locked (FolderLock) while the store lives on rank 0.
//
// File layout (little-endian, as written by the machine): ChunkHeader (magic "SSMCCHK2",
// fingerprint, first, count, epochs, fields: 8 bytes each), count × epochs × fields float32,
// then uint32 CRC-32 (zlib, ISO-HDLC polynomial) of header and payload.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "sim/montecarlo.hpp"
#include "sim/output.hpp"
#include "sim/reference.hpp"

namespace sinsim::sim {

/// One chunk: runs [first, first + count) of model `model`.
struct ChunkKey {
  std::size_t model = 0;
  std::uint64_t first = 0, count = 0;
};

/// What a chunk's inputs were (FNV-1a 64 of the reference samples, options and model identity).
std::uint64_t referenceFingerprint(const Reference& ref, const McOptions& options);
std::uint64_t modelFingerprint(std::uint64_t reference, const McModel& model);

class CheckpointStore {
 public:
  enum class State {
    missing,  // no file: compute
    valid,    // checksum and header match
    damaged,  // unreadable, truncated, zeroed, an older format or a checksum mismatch: recompute
    foreign,  // intact but computed from other inputs: refuse to resume
    resized,  // this batch's chunk as a batch of another --runs cut it (the last, short chunk): recompute
  };

  /// fingerprints[m] identifies model m (labels[m] names its folder). Touches no file.
  /// runFloats: floats per run (Reference::runFloats).
  CheckpointStore(std::string outDir, std::size_t epochs, std::size_t runFloats,
                  const std::vector<std::string>& labels,
                  std::vector<std::uint64_t> fingerprints);
  ~CheckpointStore();

  /// Rank 0, after the options are validated: creates DIR/runs/..., locks DIR (a second writer
  /// is refused), refuses to overwrite a batch without `resume` or to resume another batch's
  /// checkpoints, and removes the temporaries of a killed run. Throws InputError.
  void prepare(bool resume);

  /// Reads the chunk into out (count × runFloats floats); out == nullptr: only
  /// verifies it. out is unspecified unless the result is valid.
  State read(const ChunkKey& key, float* out) const;
  /// Writes the chunk atomically; throws Error with the reason (disk full, file size limit).
  void write(const ChunkKey& key, const float* data) const;
  std::string path(const ChunkKey& key) const;
  /// Rank 0, after a failed batch: releases the lock and removes the folders prepare() made that
  /// hold nothing (no checkpoint was saved), so a failed first run leaves no folder behind and
  /// its rerun needs no --resume. Folders with files are kept.
  void discardEmpty();

 private:
  std::string outDir_;
  std::size_t epochs_;
  std::size_t runFloats_;
  std::vector<std::string> dirs_;  // per model: "<label>-<8 hex digits of its fingerprint>"
  std::vector<std::string> stems_; // per model: "<label>-"
  std::vector<std::uint64_t> fps_;
  std::unique_ptr<FolderLock> lock_;
  bool createdOutDir_ = false;  // prepare() created DIR itself
};

}  // namespace sinsim::sim
