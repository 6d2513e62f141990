// Atomic file writing (common/atomic_file.hpp): a target appears whole or not at all, and no
// temporary is left behind on success or failure.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "common/atomic_file.hpp"
#include "common/error.hpp"

namespace fs = std::filesystem;

namespace {

/// A fresh empty folder for one test case, removed at the end.
struct ScratchDir {
  fs::path path;
  explicit ScratchDir(const std::string& name)
      : path(fs::temp_directory_path() /
             ("sinsim-atomic-" + name + "-" + std::to_string(::getpid()))) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  std::size_t entries() const {
    return std::size_t(std::distance(fs::directory_iterator(path), fs::directory_iterator()));
  }
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("writeFileAtomic writes the text and leaves only the target", "[atomic_file]") {
  ScratchDir d("write");
  const fs::path target = d.path / "model.yaml";
  const std::string text = std::string("gyro:\n  x: [{type: white}]\n") + std::string(1 << 20, 'x');
  sinsim::writeFileAtomic(target.string(), text);
  CHECK(slurp(target) == text);
  sinsim::writeFileAtomic(target.string(), "replaced\n");  // over an existing file
  CHECK(slurp(target) == "replaced\n");
  sinsim::writeFileAtomic(target.string(), "");
  CHECK(fs::file_size(target) == 0);
  CHECK(d.entries() == 1);
}

TEST_CASE("atomic write: failures leave no file and keep the old one", "[atomic_file]") {
  ScratchDir d("fail");
  // Missing folder: InputError naming the path; nothing is created anywhere.
  const fs::path missing = d.path / "no-such-folder" / "out.csv";
  CHECK_THROWS_AS(sinsim::writeFileAtomic(missing.string(), "x"), sinsim::InputError);
  CHECK_THROWS_WITH(sinsim::writeFileAtomic(missing.string(), "x"),
                    Catch::Matchers::Contains("no-such-folder"));
  CHECK(d.entries() == 0);

  // The rename fails (the target is a folder): Error, the temporary is removed, the folder stays.
  const fs::path folder = d.path / "taken";
  fs::create_directory(folder);
  CHECK_THROWS_AS(sinsim::writeFileAtomic(folder.string(), "x"), sinsim::Error);
  CHECK(fs::is_directory(folder));
  CHECK(d.entries() == 1);

  // A streaming writer abandoned half-way (an exception before commit): the old file is intact.
  const fs::path target = d.path / "nav.csv";
  sinsim::writeFileAtomic(target.string(), "old\n");
  try {
    sinsim::AtomicFile out(target.string());
    std::fputs("t,lat,lon\n0,", out.file());
    CHECK(fs::exists(out.tempPath()));
    throw std::runtime_error("run failed");
  } catch (const std::runtime_error&) {
  }
  CHECK(slurp(target) == "old\n");
  CHECK(d.entries() == 2);  // taken/ and nav.csv: no temporary
}

TEST_CASE("AtomicFile streams and commits, a moved-from writer does nothing", "[atomic_file]") {
  ScratchDir d("stream");
  const fs::path target = d.path / "errors.csv";
  sinsim::AtomicFile a(target.string());
  for (int i = 0; i < 1000; ++i) std::fprintf(a.file(), "%d\n", i);
  sinsim::AtomicFile b(std::move(a));
  CHECK(!fs::exists(target));  // nothing visible before commit
  b.commit();
  const std::string text = slurp(target);
  CHECK(text.substr(0, 4) == "0\n1\n");
  CHECK(text.size() == 10 * 2 + 90 * 3 + 900 * 4);
  CHECK_THROWS_AS(b.commit(), sinsim::Error);  // twice is a programming error, reported
  CHECK(d.entries() == 1);
}
