#include "sim/mc_checkpoint.hpp"

#include <unistd.h>
#include <zlib.h>

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <thread>

#include "common/error.hpp"

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

std::string fileSafe(const std::string& s) {
  std::string r;
  for (char c : s)
    r += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.') ? c : '_';
  return r;
}

// ---- chunk files ---------------------------------------------------------------------------------

constexpr char kMagic[8] = {'S', 'S', 'M', 'C', 'C', 'H', 'K', '2'};

struct ChunkHeader {
  char magic[8];
  std::uint64_t fingerprint;
  std::uint64_t first;
  std::uint64_t count;
  std::uint64_t epochs;
  std::uint64_t fields;
};

std::uint32_t crcOf(std::uint32_t crc, const void* p, std::size_t n) {
  return std::uint32_t(::crc32_z(crc, static_cast<const Bytef*>(p), n));
}

}  // namespace

// The aiding a reference navigates with, as values (the filter model file's content is not in the
// scenario's text, so its states are hashed here).
// A free-inertial reference adds nothing (its checkpoints from before aiding still resume).
static void hashAiding(Fnv& f, const aided::AidingConfig& a) {
  if (a.inert()) return;
  auto vec = [&f](const auto& m) {
    f.value(m.rows());
    f.value(m.cols());
    f.bytes(m.data(), std::size_t(m.size()) * sizeof(double));
  };
  for (const aided::ValueOrSigma* v :
       {&a.initialErrors.position, &a.initialErrors.velocity, &a.initialErrors.attitude}) {
    f.value(v->random);
    vec(v->value);
    vec(v->sigma);
  }
  f.value(a.alignment.duration);
  f.value(a.gnss.enabled);
  f.value(a.gnss.rate);
  vec(a.gnss.positionSigma.value_or(nav::Vec3::Zero()));
  vec(a.gnss.velocitySigma.value_or(nav::Vec3::Zero()));
  vec(a.gnss.leverArm_b);
  for (const aided::TimeWindow& w : a.gnss.outages) {
    f.value(w.start);
    f.value(w.end);
    if (w.toTheEnd) f.value(true);  // holds the last epoch too (only then: older fingerprints stay)
  }
  f.value(a.filter.enabled);
  for (int i = 0; i < 6; ++i) {
    const aided::SensorAxisModel& m = i < 3 ? a.filter.sensors.gyro[i] : a.filter.sensors.accel[i - 3];
    f.value(m.whiteDensity);
    for (const aided::StateBlock& b : m.blocks) {
      f.text(b.name);
      f.value(b.period);
      for (const Eigen::MatrixXd* M : {&b.F, &b.Qc, &b.A, &b.Qs, &b.P0}) vec(*M);
      vec(b.x0);
    }
  }
}

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
  hashAiding(f, ref.aiding);
  return f.h;
}

std::uint64_t modelFingerprint(std::uint64_t base, const McModel& m) {
  Fnv f;
  f.value(base);
  f.text(m.identity);
  for (const auto& n : m.model.effectNames()) f.text(n);
  return f.h;
}

CheckpointStore::CheckpointStore(std::string outDir, std::size_t epochs, std::size_t runFloats,
                                 const std::vector<std::string>& labels,
                                 std::vector<std::uint64_t> fingerprints)
    : outDir_(std::move(outDir)), epochs_(epochs), runFloats_(runFloats),
      fps_(std::move(fingerprints)) {
  for (std::size_t m = 0; m < labels.size(); ++m) {
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(fps_[m]));
    stems_.push_back(fileSafe(labels[m]).substr(0, 80) + "-");
    dirs_.push_back(stems_.back() + std::string(hex, 8));
  }
}

CheckpointStore::~CheckpointStore() = default;

namespace {

// A chunk's file in its model's folder: r<first run, nine digits>.bin.
constexpr char kChunkPrefix = 'r';
constexpr const char* kChunkSuffix = ".bin";

std::string chunkFileName(std::uint64_t first) {
  char digits[24];
  std::snprintf(digits, sizeof digits, "%09llu", static_cast<unsigned long long>(first));
  return kChunkPrefix + std::string(digits) + kChunkSuffix;
}

bool isChunkFileName(const std::string& n) {
  const std::size_t suffix = std::strlen(kChunkSuffix);
  return n.size() > suffix + 1 && n[0] == kChunkPrefix &&
         n.compare(n.size() - suffix, suffix, kChunkSuffix) == 0;
}

}  // namespace

std::string CheckpointStore::path(const ChunkKey& k) const {
  return (fs::path(outDir_) / "runs" / dirs_[k.model] / chunkFileName(k.first)).string();
}

namespace {

/// Whether runs/ holds a chunk file (r<first>.bin in a model's folder): the empty model folders of
/// a batch stopped before its first chunk was saved hold nothing to resume or to protect.
bool holdsChunks(const fs::path& runsDir) {
  std::error_code ec;
  for (const auto& d : fs::directory_iterator(runsDir, ec)) {
    if (!d.is_directory(ec)) continue;
    for (const auto& f : fs::directory_iterator(d.path(), ec)) {
      if (isChunkFileName(f.path().filename().string())) return true;
    }
  }
  return false;
}

}  // namespace

void CheckpointStore::prepare(bool resume) {
  const fs::path runsDir = fs::path(outDir_) / "runs";
  std::error_code ec;
  if (fs::exists(outDir_, ec) && !fs::is_directory(outDir_, ec))
    throw InputError("output folder " + outDir_ + " exists and is not a folder");
  createdOutDir_ = !fs::exists(outDir_, ec);
  fs::create_directories(outDir_, ec);
  if (ec) throw InputError("cannot create " + outDir_ + ": " + ec.message());
  lock_ = std::make_unique<FolderLock>(outDir_);
  if (!resume && fs::is_directory(runsDir, ec) && holdsChunks(runsDir))
    throw InputError(outDir_ + " holds the checkpoints of a batch (" + runsDir.string() +
                     "); pass --resume to continue it, or choose another folder");
  if (resume && fs::exists(runsDir, ec)) {
    // Chunks computed from other inputs mean the user is resuming the wrong batch.
    for (std::size_t m = 0; m < dirs_.size(); ++m) {
      if (fs::exists(runsDir / dirs_[m], ec)) continue;
      for (const auto& entry : fs::directory_iterator(runsDir, ec)) {
        const std::string n = entry.path().filename().string();
        if (n.rfind(stems_[m], 0) == 0)
          throw InputError("cannot resume " + outDir_ + ": its checkpoints of model " +
                           stems_[m].substr(0, stems_[m].size() - 1) +
                           " were computed from other inputs (scenario, model, seed or bias "
                           "window changed); remove " + (runsDir / n).string() +
                           " or choose another folder");
      }
    }
  }
  // Temporaries of a process killed while writing: never valid.
  removeStaleTemporaries(outDir_, false);
  if (fs::is_directory(runsDir, ec)) removeStaleTemporaries(runsDir.string(), true);
  for (const auto& d : dirs_) {
    fs::create_directories(runsDir / d, ec);
    if (ec) throw InputError("cannot create " + (runsDir / d).string() + ": " + ec.message());
  }
}

void CheckpointStore::discardEmpty() {
  lock_.reset();
  std::error_code ec;  // fs::remove takes a folder only when it is empty
  const fs::path runsDir = fs::path(outDir_) / "runs";
  for (const auto& d : dirs_) fs::remove(runsDir / d, ec);
  fs::remove(runsDir, ec);
  if (createdOutDir_) fs::remove(outDir_, ec);
}

CheckpointStore::State CheckpointStore::read(const ChunkKey& k, float* out) const {
  std::FILE* f = std::fopen(path(k).c_str(), "rb");
  if (!f) return errno == ENOENT ? State::missing : State::damaged;
  const std::size_t n = std::size_t(k.count) * runFloats_;
  std::vector<float> scratch;
  if (!out) {
    scratch.resize(n);
    out = scratch.data();
  }
  ChunkHeader h{};
  std::uint32_t stored = 0;
  State st = State::damaged;
  const bool header = std::fread(&h, sizeof h, 1, f) == 1 && std::memcmp(h.magic, kMagic, 8) == 0;
  if (header && h.count != k.count && h.first == k.first && h.fingerprint == fps_[k.model] &&
      h.epochs == epochs_ && h.fields == kErrorFields) {
    // Grown or shrunk with --resume --runs: the old last chunk is short (or long), not damaged.
    std::fclose(f);
    return State::resized;
  }
  if (header && h.count == k.count && h.epochs == epochs_ && h.fields == kErrorFields &&
      std::fread(out, sizeof(float), n, f) == n && std::fread(&stored, sizeof stored, 1, f) == 1 &&
      std::fgetc(f) == EOF &&
      crcOf(crcOf(0, &h, sizeof h), out, n * sizeof(float)) == stored) {
    // Intact: now whether it belongs to this batch.
    if (h.fingerprint != fps_[k.model]) st = State::foreign;
    else if (h.first == k.first) st = State::valid;
  }
  std::fclose(f);
  return st;
}

void CheckpointStore::write(const ChunkKey& k, const float* data) const {
  ChunkHeader h{};
  std::memcpy(h.magic, kMagic, 8);
  h.fingerprint = fps_[k.model];
  h.first = k.first;
  h.count = k.count;
  h.epochs = epochs_;
  h.fields = kErrorFields;
  const std::size_t n = std::size_t(k.count) * runFloats_;
  const std::uint32_t crc = crcOf(crcOf(0, &h, sizeof h), data, n * sizeof(float));
  const std::string final = path(k);
  const std::string tmp = final + ".tmp." + std::to_string(::getpid()) + "." +
                          std::to_string(std::hash<std::thread::id>()(std::this_thread::get_id()));
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) throw Error(writeErrorMessage(tmp, errno));
  errno = 0;
  bool ok = std::fwrite(&h, sizeof h, 1, f) == 1 && std::fwrite(data, sizeof(float), n, f) == n &&
            std::fwrite(&crc, sizeof crc, 1, f) == 1 && std::fflush(f) == 0;
  int err = errno;
  ok = (std::fclose(f) == 0) && ok;
  if (!err) err = errno;
  std::error_code ec;
  if (ok) fs::rename(tmp, final, ec);
  if (!ok || ec) {
    fs::remove(tmp, ec);
    throw Error("checkpoint: " + writeErrorMessage(final, err));
  }
}

}  // namespace sinsim::sim
