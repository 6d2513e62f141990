#include "common/read_file.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/error.hpp"

namespace sinsim {

namespace {
std::string& sandbox() {
  static std::string dir;
  return dir;
}
}  // namespace

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
