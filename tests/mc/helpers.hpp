// Shared helpers of the Monte Carlo tests: temporary folders, running the CLI, comparing files.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace mctest {

namespace fs = std::filesystem;

inline fs::path tempDir(const std::string& name) {
  const fs::path d =
      fs::temp_directory_path() / ("sinsim_test_mc_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

inline std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

struct Result {
  int exitCode = -1;
  std::string out, err;
};

inline std::string sinsimPath() { return std::string(SINSIM_BINARY_DIR) + "/sinsim"; }

/// Runs `sinsim <args>`, capturing stdout and stderr into tmp.
inline Result sinsim(const std::string& args, const fs::path& tmp) {
  const std::string cmd = "'" + sinsimPath() + "' " + args + " > '" + (tmp / "stdout").string() +
                          "' 2> '" + (tmp / "stderr").string() + "'";
  const int status = std::system(cmd.c_str());
  Result r;
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(tmp / "stdout");
  r.err = slurp(tmp / "stderr");
  return r;
}

/// Every regular file below dir, as relative paths, sorted.
inline std::vector<std::string> listFiles(const fs::path& dir) {
  std::vector<std::string> r;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) r.push_back(fs::relative(e.path(), dir).string());
  std::sort(r.begin(), r.end());
  return r;
}

inline const std::string& sourceDir() {
  static const std::string s = SINSIM_SOURCE_DIR;
  return s;
}

inline bool anyChunk(const fs::path& dir) {
  std::error_code ec;
  if (!fs::exists(dir / "runs", ec)) return false;
  for (const auto& e : fs::recursive_directory_iterator(dir / "runs", ec))
    if (e.path().extension() == ".bin") return true;
  return false;
}

// Starts sinsim in the background (stdout/stderr to files in tmp); returns its pid.
inline pid_t spawn(const std::string& args, const fs::path& tmp) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    const std::string cmd = "exec '" + sinsimPath() + "' " + args + " > '" +
                            (tmp / "bg.out").string() + "' 2> '" + (tmp / "bg.err").string() + "'";
    ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  return pid;
}

}  // namespace mctest
