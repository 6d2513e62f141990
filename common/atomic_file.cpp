#include "common/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>
#include <utility>

#include "common/error.hpp"
#include "common/read_file.hpp"

namespace sinsim {
namespace {

namespace fs = std::filesystem;

/// Opens a fresh hidden temporary beside `path`: ".NAME.tmp.PID.N", N a process-wide counter, so
/// threads and processes writing the same target never share one; O_EXCL never reuses a stale
/// file.
fs::path folderOf(const fs::path& target) {
  return target.has_parent_path() ? target.parent_path() : fs::path(".");
}

std::FILE* openTemporary(const std::string& path, std::string& temp) {
  static std::atomic<unsigned long> counter{0};
  requireWritableTarget(path);
  const fs::path target(path);
  const fs::path dir = folderOf(target);
  for (int attempt = 0; attempt < 100; ++attempt) {
    temp = (dir / ("." + target.filename().string() + ".tmp." + std::to_string(::getpid()) + "." +
                   std::to_string(counter++)))
               .string();
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0 && errno == EEXIST) continue;
    if (fd < 0) throw InputError("cannot write " + path + ": " + std::strerror(errno));
    std::FILE* f = ::fdopen(fd, "wb");
    if (!f) {
      const int e = errno;
      ::close(fd);
      ::unlink(temp.c_str());
      throw Error("cannot write " + path + ": " + std::strerror(e));
    }
    return f;
  }
  throw Error("cannot write " + path + ": no free temporary name beside it");
}

}  // namespace

void requireWritableTarget(const std::string& path) {
  const fs::path target(path);
  const fs::path dir = folderOf(target);
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw InputError("cannot write " + path + ": folder " + dir.string() + " does not exist");
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    throw InputError("cannot write " + path + ": folder " + dir.string() + ": " + std::strerror(errno));
  // The rename at the end replaces whatever the name points at: a device (`-o /dev/null` run as
  // root would turn /dev/null into a regular file), a pipe or a folder is refused first.
  const fs::file_status st = fs::status(target, ec);
  if (fs::is_directory(st))
    throw InputError("cannot write " + path + ": it is a folder; give a file name");
  if (fs::exists(st) && !fs::is_regular_file(st))
    throw InputError("cannot write " + path +
                     ": it is a device, pipe or socket; sinsim writes regular files only");
  requireNotAnInput(path);
}

void requireWritableTargets(const std::vector<std::string>& paths) {
  for (std::size_t i = 0; i < paths.size(); ++i) {
    if (paths[i].empty()) continue;
    requireWritableTarget(paths[i]);
    std::error_code ec;
    const fs::path here = fs::weakly_canonical(paths[i], ec);
    for (std::size_t j = 0; j < i; ++j)
      if (!paths[j].empty() && fs::weakly_canonical(paths[j], ec) == here)
        throw InputError("cannot write " + paths[i] + ": it is also the output " + paths[j] +
                         "; give each output its own file");
  }
}

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  fp_ = openTemporary(path_, temp_);
}

AtomicFile::AtomicFile(AtomicFile&& other) noexcept
    : path_(std::move(other.path_)), temp_(std::move(other.temp_)), fp_(other.fp_) {
  other.fp_ = nullptr;
  other.temp_.clear();
}

AtomicFile::~AtomicFile() { discard(); }

void AtomicFile::commit() {
  if (!fp_) throw Error("cannot write " + path_ + ": already committed");
  const bool bad = std::ferror(fp_) != 0;
  const bool closeFailed = std::fclose(fp_) != 0;
  const int e = errno;
  fp_ = nullptr;
  if (bad || closeFailed) {
    discard();
    throw Error("write error on " + path_ + " (disk full?): " + std::strerror(e));
  }
  if (::rename(temp_.c_str(), path_.c_str()) != 0) {
    const int re = errno;
    discard();
    throw Error("cannot move " + temp_ + " to " + path_ + ": " + std::strerror(re));
  }
  temp_.clear();
}

void AtomicFile::discard() noexcept {
  if (fp_) std::fclose(fp_);
  fp_ = nullptr;
  if (!temp_.empty()) ::unlink(temp_.c_str());
  temp_.clear();
}

void writeFileAtomic(const std::string& path, std::string_view text) {
  AtomicFile out(path);
  if (!text.empty() && std::fwrite(text.data(), 1, text.size(), out.file()) != text.size())
    throw Error("write error on " + path + " (disk full?): " + std::strerror(errno));
  out.commit();
}

}  // namespace sinsim
