#include "common/read_file.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>
#include <sstream>
#include <utility>

#include "common/error.hpp"

namespace sinsim {

namespace {
std::string& sandbox() {
  static std::string dir;
  return dir;
}

/// The inputs read so far, by device and inode (a link or another spelling is the same file).
struct Inputs {
  std::mutex mutex;
  bool tracking = false;  // the whole process (a command line run)
  int scopes = 0;         // open InputFilesScopes
  std::set<std::pair<dev_t, ino_t>> files;
};
Inputs& inputs() {
  static Inputs in;
  return in;
}
}  // namespace

void trackInputFiles() {
  std::lock_guard<std::mutex> lock(inputs().mutex);
  inputs().tracking = true;
}

InputFilesScope::InputFilesScope() {
  std::lock_guard<std::mutex> lock(inputs().mutex);
  ++inputs().scopes;
}

InputFilesScope::~InputFilesScope() {
  std::lock_guard<std::mutex> lock(inputs().mutex);
  if (--inputs().scopes == 0 && !inputs().tracking) inputs().files.clear();
}

void requireNotAnInput(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return;  // nothing there yet
  std::lock_guard<std::mutex> lock(inputs().mutex);
  if (inputs().files.count({st.st_dev, st.st_ino}))
    throw InputError("cannot write " + path + ": it is an input of this command, which it would replace; "
                     "give another output name");
}

void restrictInputFilesTo(const std::string& dir) {
  sandbox() = dir.empty() ? "" : std::filesystem::weakly_canonical(dir).string() + "/";
}

void requireRegularFile(const std::string& path, const std::string& what) {
  if (!sandbox().empty()) {
    std::error_code ec;
    const std::string full = std::filesystem::weakly_canonical(path, ec).string();
    if (ec || full.rfind(sandbox(), 0) != 0)
      throw InputError(path + ": outside the input sandbox " + sandbox());
  }
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    throw InputError(path + ": cannot open file: " + std::strerror(errno));
  if (S_ISDIR(st.st_mode)) throw InputError(path + ": is a directory, expected a " + what);
  if (!S_ISREG(st.st_mode))
    throw InputError(path + ": is a device, pipe or socket, expected a " + what +
                     " (a regular file)");
  std::lock_guard<std::mutex> lock(inputs().mutex);
  if (inputs().tracking || inputs().scopes > 0) inputs().files.insert({st.st_dev, st.st_ino});
}

std::string readRegularFile(const std::string& path, std::size_t maxBytes,
                            const std::string& what) {
  requireRegularFile(path, what);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open file: " + std::strerror(errno));
  std::string text;
  char buf[1 << 16];
  while (in.read(buf, sizeof buf) || in.gcount() > 0) {
    text.append(buf, static_cast<std::size_t>(in.gcount()));
    if (text.size() > maxBytes)
      throw InputError(path + ": " + what + " larger than " + std::to_string(maxBytes) +
                       " bytes (see docs/limits.md)");
  }
  if (in.bad()) throw InputError(path + ": read error on " + what);
  return text;
}

}  // namespace sinsim
