#include "sim/output.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstring>

#include <filesystem>
#include <system_error>

#include "common/error.hpp"
#include "common/read_file.hpp"

namespace sinsim::sim {

namespace fs = std::filesystem;

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string r = "\"";
  for (char c : s) {
    if (c == '"') r += '"';
    r += c;
  }
  return r + "\"";
}

OutputFiles::OutputFiles(const std::string& dir) : dir_(dir) {
  std::error_code ec;
  if (fs::exists(dir_, ec)) {
    if (!fs::is_directory(dir_, ec))
      throw InputError("output folder " + dir_ + " exists and is not a folder");
    return;
  }
  createdDir_ = fs::create_directories(dir_, ec);
  if (ec) throw InputError("cannot create output folder " + dir_ + ": " + ec.message());
}

OutputFiles::~OutputFiles() {
  if (!committed_) discard();
}

std::FILE* OutputFiles::open(const std::string& name) {
  File f;
  f.finalPath = (fs::path(dir_) / name).string();
  // The rename at commit replaces whatever the name points at: not a device, pipe or folder.
  std::error_code ec;
  const fs::file_status st = fs::status(f.finalPath, ec);
  if (fs::exists(st) && !fs::is_regular_file(st))
    throw InputError("cannot write " + f.finalPath + ": it is " +
                     (fs::is_directory(st) ? std::string("a folder; give a file name")
                                           : std::string("a device, pipe or socket; sinsim "
                                                         "writes regular files only")));
  requireNotAnInput(f.finalPath);
  f.tempPath = (fs::path(dir_) / ("." + name + ".tmp." + std::to_string(::getpid()))).string();
  f.fp = std::fopen(f.tempPath.c_str(), "w");
  if (!f.fp) throw Error(writeErrorMessage(f.tempPath, errno));
  files_.push_back(f);
  return f.fp;
}

void OutputFiles::commit() {
  for (File& f : files_) {
    errno = 0;
    const bool bad = std::fflush(f.fp) != 0 || std::ferror(f.fp) != 0;
    const int err = errno;
    const bool closeFailed = std::fclose(f.fp) != 0;
    f.fp = nullptr;
    if (bad || closeFailed) throw Error(writeErrorMessage(f.finalPath, err ? err : errno));
  }
  for (File& f : files_) {
    std::error_code ec;
    fs::rename(f.tempPath, f.finalPath, ec);
    if (ec) throw Error("cannot move " + f.tempPath + " to " + f.finalPath + ": " + ec.message());
  }
  committed_ = true;
}

void OutputFiles::discard() noexcept {
  for (File& f : files_) {
    if (f.fp) std::fclose(f.fp);
    f.fp = nullptr;
    std::error_code ec;
    fs::remove(f.tempPath, ec);
  }
  if (createdDir_) {
    std::error_code ec;
    fs::remove(dir_, ec);  // only succeeds when empty
  }
}

FolderLock::FolderLock(const std::string& dir) {
  fd_ = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd_ < 0) throw InputError("cannot open output folder " + dir + ": " + std::strerror(errno));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    ::close(fd_);
    fd_ = -1;
    if (err == EWOULDBLOCK)
      throw InputError("another sinsim process is writing into " + dir +
                       "; wait for it to finish (an interrupted `mc` batch goes on with `mc --resume`) or "
                       "choose another folder");
    throw InputError("cannot lock output folder " + dir + ": " + std::strerror(err));
  }
}

FolderLock::~FolderLock() {
  if (fd_ >= 0) ::close(fd_);  // releases the lock
}

namespace {

// The names sinsim gives its temporaries, and only those: ".NAME.tmp.PID" (OutputFiles) and
// "NAME.tmp.PID.THREAD" (checkpoints).
bool isSinsimTemporary(const std::string& name) {
  const auto at = name.rfind(".tmp.");
  if (at == std::string::npos || at == 0) return false;
  const std::string tail = name.substr(at + 5);
  return !tail.empty() && tail.find_first_not_of("0123456789.") == std::string::npos &&
         std::isdigit(static_cast<unsigned char>(tail.front())) != 0;
}

}  // namespace

std::size_t removeStaleTemporaries(const std::string& dir, bool recursive) {
  std::error_code ec;
  std::vector<fs::path> stale;
  auto consider = [&](const fs::directory_entry& e) {
    if (e.is_regular_file(ec) && isSinsimTemporary(e.path().filename().string()))
      stale.push_back(e.path());
  };
  if (recursive) {
    for (auto it = fs::recursive_directory_iterator(dir, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
      consider(*it);
  } else {
    for (auto it = fs::directory_iterator(dir, ec); !ec && it != fs::directory_iterator();
         it.increment(ec))
      consider(*it);
  }
  std::size_t n = 0;
  for (const auto& p : stale) n += fs::remove(p, ec) ? 1 : 0;
  return n;
}

std::string writeErrorMessage(const std::string& path, int err) {
  std::string m = "cannot write " + path;
  if (err) m += std::string(": ") + std::strerror(err);
  if (err == EFBIG) m += " (a file size limit: see ulimit -f)";
  else if (err == ENOSPC || err == EDQUOT || err == 0) m += " (disk full?)";
  return m;
}

}  // namespace sinsim::sim
