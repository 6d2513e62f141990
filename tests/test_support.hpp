// Helpers shared by several test suites.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "common/error.hpp"

namespace sinsim::test {

/// The message f() throws, as the user reads it (a ConfigError lists its first 20 problems, then
/// "... and N more"); "" when f() does not throw.
inline std::string messageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

/// Adds quantization noise as GMWM (simts' QN) and IEEE Std 952 make it to the rate samples y:
/// sqrt(12) qRate (U[k] - U[k-1]), U independent uniform on (0, 1) from std::mt19937_64(seed) --
/// not the simulator's streams, and on no value lattice. Its Allan variance is 3 qRate^2 dt^2/tau^2.
inline void addQuantizationNoise(std::vector<double>& y, double qRate, std::uint64_t seed) {
  std::mt19937_64 gen(seed);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  double prev = uni(gen);
  for (double& v : y) {
    const double next = uni(gen);
    v += std::sqrt(12.0) * qRate * (next - prev);
    prev = next;
  }
}

/// Is there a diagnostic of `file` at `line` for key path `key` whose message contains `fragment`?
inline bool hasDiagnostic(const std::vector<Diagnostic>& ds, const std::string& file, int line,
                          const std::string& key, const std::string& fragment) {
  for (const auto& d : ds)
    if (d.file == file && d.line == line && d.key == key &&
        d.message.find(fragment) != std::string::npos)
      return true;
  return false;
}

/// Runs the built `sinsim` with `args` (stdout discarded, stderr to errFile); its exit code, or
/// -1 when it did not exit normally.
inline int runSinsim(const std::string& args, const std::filesystem::path& errFile) {
  const std::string cmd =
      std::string(SINSIM_BINARY_DIR) + "/sinsim " + args + " > /dev/null 2> " + errFile.string();
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// The whole content of a text file ("" when it cannot be read).
inline std::string slurp(const std::filesystem::path& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

/// The folders freshTempDir made in this process, removed when it ends (kept when the environment
/// sets SINSIM_KEEP_TEST_FILES, to look at a failing test's files).
struct TempDirs {
  std::vector<std::filesystem::path> made;
  ~TempDirs() {
    if (std::getenv("SINSIM_KEEP_TEST_FILES") != nullptr) return;
    for (const auto& d : made) {
      std::error_code ignored;
      std::filesystem::remove_all(d, ignored);
    }
  }
};

inline TempDirs& tempDirs() {
  static TempDirs dirs;
  return dirs;
}

/// A fresh, empty folder `<temp>/<name>-<pid>` for one test's files: ctest runs test cases as
/// processes side by side, so a fixed name would let two of them share (and wipe) one folder.
inline std::filesystem::path freshTempDir(const std::string& name) {
  const std::filesystem::path d =
      std::filesystem::temp_directory_path() / (name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  tempDirs().made.push_back(d);
  return d;
}

/// Writes `text` to `p` byte for byte.
inline void writeText(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

}  // namespace sinsim::test
