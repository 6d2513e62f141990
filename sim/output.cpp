#include "sim/output.hpp"

#include <unistd.h>

#include <filesystem>
#include <system_error>

#include "common/error.hpp"

namespace sinsim::sim {

namespace fs = std::filesystem;

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
  f.tempPath = (fs::path(dir_) / ("." + name + ".tmp." + std::to_string(::getpid()))).string();
  f.fp = std::fopen(f.tempPath.c_str(), "w");
  if (!f.fp) throw Error("cannot write " + f.tempPath);
  files_.push_back(f);
  return f.fp;
}

void OutputFiles::commit() {
  for (File& f : files_) {
    const bool bad = std::ferror(f.fp) != 0;
    const bool closeFailed = std::fclose(f.fp) != 0;
    f.fp = nullptr;
    if (bad || closeFailed) throw Error("write error on " + f.finalPath + " (disk full?)");
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

}  // namespace sinsim::sim
