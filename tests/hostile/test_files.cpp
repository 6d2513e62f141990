// Hostile input, files: duplicate keys, several documents, NUL bytes, directories and devices
// where a file is expected, empty model files, byte-order marks, and enough digits in messages.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "common/config.hpp"
#include "errormodels/imu_model.hpp"
#include "errormodels/stats/record.hpp"
#include "sim/scenario.hpp"
#include "test_support.hpp"

using namespace sinsim;
using Catch::Matchers::Contains;
namespace fs = std::filesystem;

using sinsim::test::messageOf;

namespace {

fs::path tempDir(const std::string& name) { return sinsim::test::freshTempDir("sinsim-hostile-" + name); }
using sinsim::test::writeText;

}  // namespace

TEST_CASE("duplicate keys are refused naming the lines of both and the key path (the first used to win)") {
  const std::string msg = messageOf([] {
    ConfigFile::fromString("imu_rate: 100 Hz\nseed: 1\nimu_rate: 200 Hz\n", "dup.yaml");
  });
  CHECK_THAT(msg, Contains("dup.yaml:3: imu_rate: duplicate key (first given at dup.yaml:1)"));
  // ... at any depth, e.g. a noise density inside an effect, named by its whole path.
  CHECK_THAT(messageOf([] {
               errormodels::ImuErrorModel::fromString(
                   "gyro:\n  all:\n    - type: white\n      density: 0.1 deg/sqrt(h)\n"
                   "      density: 9 deg/sqrt(h)\n",
                   "m.yaml");
             }),
             Contains("m.yaml:5: gyro.all[0].density: duplicate key (first given at m.yaml:4)"));
  CHECK_THAT(messageOf([] {
               ConfigFile::fromString("segments:\n  - {type: static, duration: 1 s}\n"
                                      "  - {type: static, duration: 1 s, duration: 2 s}\n",
                                      "s.yaml");
             }),
             Contains("s.yaml:3: segments[1].duration: duplicate key (first given at s.yaml:3)"));
}

TEST_CASE("a second YAML document is refused, not ignored") {
  CHECK_THAT(messageOf([] { ConfigFile::fromString("a: 1\n---\nb: 2\n", "two.yaml"); }),
             Contains("two.yaml:3: a second YAML document"));
}

TEST_CASE("a NUL byte in YAML says so (it was 'unknown escape character')") {
  const std::string text("a: 1\nb: \"x\0s\"\n", 14);
  CHECK_THAT(messageOf([&] { ConfigFile::fromString(text, "nul.yaml"); }),
             Contains("nul.yaml:2: a NUL byte"));
}

TEST_CASE("a directory or a device where a file is expected is refused by name") {
  const fs::path dir = tempDir("devices");
  for (const std::string& target : std::vector<std::string>{"/dev/zero", dir.string()}) {
    writeText(dir / "s.yaml",
              "start: {latitude: 45 deg, longitude: 7 deg}\nerrors: " + target +
                  "\nsegments: [{type: static, duration: 1 s}]\n");
    const std::string msg = messageOf([&] { sim::loadScenario((dir / "s.yaml").string()); });
    CHECK_THAT(msg, Contains(target + ": is a "));
    CHECK_THAT(msg, Contains(target == "/dev/zero" ? "device" : "directory"));
  }
  CHECK_THAT(messageOf([] { errormodels::loadRecord("/dev/zero"); }),
             Contains("/dev/zero: is a device, pipe or socket, expected a record"));
  CHECK_THAT(messageOf([&] { ConfigFile::load(dir.string()); }),
             Contains(dir.string() + ": is a directory"));
}

TEST_CASE("an empty model file is refused with the way to write a perfect IMU") {
  const fs::path dir = tempDir("empty");
  writeText(dir / "empty.yaml", "# nothing here\n\n");
  CHECK_THAT(messageOf([&] { errormodels::ImuErrorModel::load((dir / "empty.yaml").string()); }),
             Contains("empty.yaml:1: the file is empty (no YAML content): an empty error model; "
                      "write `gyro: {}` if you mean a perfect IMU"));
  writeText(dir / "perfect.yaml", "gyro: {}\n");
  CHECK(errormodels::ImuErrorModel::load((dir / "perfect.yaml").string()).empty());
}

TEST_CASE("a CSV record starting with a UTF-8 byte-order mark is read (it was 'no time column')") {
  const auto r = errormodels::parseRecord("\xEF\xBB\xBFt,gx\n0,1\n0.01,2\n0.02,3\n", "bom.csv");
  CHECK(r.t.size() == 3);
  CHECK(r.rate_hz == Approx(100.0).epsilon(1e-12));  // 1 / median step, steps exact to 1 ulp
}

TEST_CASE("an AR pole just inside the margin prints with enough digits") {
  // |z| = 0.9999999999 is refused by the 1e-9 stability margin; it used to print as "1".
  CHECK_THAT(messageOf([] {
               errormodels::ImuErrorModel::fromString(
                   "gyro:\n  x: [{type: ar, a: [-0.9999999999], sigma: 1 deg/s, rate: 1 kHz}]\n",
                   "ar.yaml");
             }),
             Contains("largest pole magnitude 0.9999999999 "));
}

TEST_CASE("a stray ',' in block context is a syntax error, not an endless loop") {
  // yaml-cpp 0.7's LoadAll loops for ever, allocating, on ", a" (found by fuzz_config).
  CHECK_THAT(messageOf([] { ConfigFile::fromString(", a\n", "comma.yaml"); }),
             Contains("comma.yaml:1: YAML syntax error"));
  CHECK_THAT(messageOf([] { ConfigFile::fromString("# note\n, as stated\nx: 1\n", "c2.yaml"); }),
             Contains("c2.yaml:2: YAML syntax error"));
}
