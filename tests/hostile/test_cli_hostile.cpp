// Hostile input through the command line: exit code 1, a message naming the file (and line and
// key, or channel), and no output file or folder left behind.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <zlib.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "common/limits.hpp"
#include "test_support.hpp"

using Catch::Matchers::Contains;
namespace fs = std::filesystem;
using sinsim::test::runSinsim;
using sinsim::test::slurp;

namespace {

fs::path tempDir(const std::string& name) { return sinsim::test::freshTempDir("sinsim-hostile-cli-" + name); }
using sinsim::test::writeText;

/// A gzip record (fast level): `header`, then blocks of 100000 rows row(k), `blocks` times.
[[maybe_unused]] void writeGzRows(const fs::path& path, const char* header, const std::function<const char*(int)>& row, int blocks) {
  gzFile f = gzopen(path.string().c_str(), "wb1");
  REQUIRE(f != nullptr);
  gzputs(f, header);
  std::string block;
  for (int k = 0; k < 100000; ++k) block += row(k);
  for (int k = 0; k < blocks; ++k) gzwrite(f, block.data(), static_cast<unsigned>(block.size()));
  gzclose(f);
}

}  // namespace

TEST_CASE("sinsim run: duplicate keys, a device as the model, 1e308 s: exit 1, nothing written") {
  const fs::path d = tempDir("run");
  const std::string head = "start: {latitude: 45 deg, longitude: 7 deg}\n";
  const struct {
    const char* name;
    std::string text;
    std::string expected;
  } cases[] = {
      {"dup", head + "imu_rate: 100 Hz\nimu_rate: 200 Hz\nsegments: [{type: static, duration: 1 s}]\n",
       "dup.yaml:3: imu_rate: duplicate key (first given at "},
      {"device", head + "errors: /dev/zero\nsegments: [{type: static, duration: 1 s}]\n",
       "/dev/zero: is a device, pipe or socket"},
      {"long", head + "segments: [{type: static, duration: 1e308 s}]\n",
       "long.yaml:2: segments[0].duration: \"1e308 s\" is beyond any physical value"},
  };
  for (const auto& c : cases) {
    INFO(c.name);
    const fs::path scenario = d / (std::string(c.name) + ".yaml");
    writeText(scenario, c.text);
    const fs::path out = d / (std::string("out-") + c.name);
    CHECK(runSinsim("run " + scenario.string() + " -o " + out.string(), d / "err") == 1);
    CHECK_THAT(slurp(d / "err"), Contains(c.expected));
    CHECK_FALSE(fs::exists(out));
  }
}

TEST_CASE("sinsim analyze: a failure deep in the statistics names file and channel") {
  // Two samples: the Allan deviation needs three; the message used to name neither.
  const fs::path d = tempDir("analyze");
  writeText(d / "short.csv", "gx,gy\n0.1,0.2\n0.3,0.1\n");
  const fs::path json = d / "out.json";
  CHECK(runSinsim("analyze " + (d / "short.csv").string() + " --rate 100 --json " + json.string(),
                  d / "err") == 1);
  CHECK_THAT(slurp(d / "err"),
             Contains((d / "short.csv").string() + ": channel gx: Allan deviation: need at least 3"));
  CHECK_FALSE(fs::exists(json));
}

TEST_CASE("sinsim analyze and synth: rates and lengths beyond an IMU are refused at once") {
  const fs::path d = tempDir("rates");
  writeText(d / "slow.csv", "t,gx\n0,1\n1e6,2\n2e6,3\n3e6,4\n");
  const fs::path json = d / "out.json";
  CHECK(runSinsim("analyze " + (d / "slow.csv").string() + " --json " + json.string(), d / "err") ==
        1);
  CHECK_THAT(slurp(d / "err"), Contains("slow.csv: the time stamps' rate 1e-06 Hz is outside"));
  CHECK_FALSE(fs::exists(json));

  writeText(d / "m.yaml", "gyro: {}\n");
  const fs::path csv = d / "synth.csv";
  const auto t0 = std::chrono::steady_clock::now();
  CHECK(runSinsim("synth " + (d / "m.yaml").string() + " --rate 100 --duration 1e12 -o " +
                      csv.string(),
                  d / "err") == 1);
  CHECK_THAT(slurp(d / "err"), Contains("--duration 1e+12 s at 100 Hz is more than 1e+08 samples"));
  CHECK(std::chrono::steady_clock::now() - t0 < std::chrono::seconds(10));  // it ran for minutes
  CHECK_FALSE(fs::exists(csv));
}

TEST_CASE("sinsim mc: a run count beyond memory is a limit error, not bad_alloc") {
  const fs::path d = tempDir("mc");
  writeText(d / "s.yaml", "start: {latitude: 45 deg, longitude: 7 deg}\nimu_rate: 10 Hz\n"
                          "segments: [{type: static, duration: 10 s}]\n");
  writeText(d / "m.yaml", "gyro:\n  all: [{type: white, density: 0.1 deg/sqrt(h)}]\n");
  const fs::path out = d / "out";
  CHECK(runSinsim("mc " + (d / "s.yaml").string() + " --model " + (d / "m.yaml").string() +
                      " --runs 4000000000 --no-progress -o " + out.string(),
                  d / "err") == 1);
  CHECK_THAT(slurp(d / "err"), Contains("--runs 4000000000 is above the limit of"));
  CHECK_THAT(slurp(d / "err"), !Contains("internal error"));
  CHECK_FALSE(fs::exists(out));
}

TEST_CASE("sinsim fit: a constant channel names file and channel, a missing folder is named") {
  const fs::path d = tempDir("fit");
  std::string csv = "gx\n";
  for (int k = 0; k < 400; ++k) csv += "0.25\n";  // zero variance: nothing to fit
  writeText(d / "const.csv", csv);
  const fs::path model = d / "m.yaml";
  CHECK(runSinsim("fit " + (d / "const.csv").string() + " --rate 100 -o " + model.string(),
                  d / "err") == 1);
  CHECK_THAT(slurp(d / "err"), Contains((d / "const.csv").string() + ": channel gx"));
  CHECK_FALSE(fs::exists(model));

  std::string noisy = "gx\n";
  for (int k = 0; k < 4000; ++k) noisy += std::to_string((k * 7919 % 1000) / 1000.0) + "\n";
  writeText(d / "noisy.csv", noisy);
  const fs::path missing = d / "no" / "such" / "m.yaml";
  CHECK(runSinsim("fit " + (d / "noisy.csv").string() + " --rate 100 --kind ar -o " +
                      missing.string(),
                  d / "err") == 1);
  CHECK_THAT(slurp(d / "err"), Contains("cannot write " + missing.string() + ": folder " +
                                        (d / "no" / "such").string() + " does not exist"));
}

TEST_CASE("sinsim diagnose: a failure deep in the statistics names the record") {
  const fs::path d = tempDir("diagnose");
  writeText(d / "short.csv", "gx\n0.1\n0.3\n");
  writeText(d / "m.yaml", "gyro:\n  x: [{type: white, density: 0.1 deg/sqrt(h)}]\n");
  CHECK(runSinsim("diagnose " + (d / "short.csv").string() + " --rate 100 --model " +
                      (d / "m.yaml").string(),
                  d / "err") == 1);
  CHECK_THAT(slurp(d / "err"), Contains((d / "short.csv").string() + ": "));
  CHECK_THAT(slurp(d / "err"), !Contains("internal error"));
}

TEST_CASE("sinsim diagnose: a channel the statistics cannot use is named with its record") {
  // gx varies, gy is one value: the failure must say which record and which channel, not only
  // what failed (it was burg's, deep inside, on the constant series; now the channel list is
  // checked first and says how to leave the channel out).
  const fs::path d = tempDir("diagnose-channel");
  std::string text = "gx,gy\n";
  for (int k = 0; k < 2000; ++k)
    text += std::to_string(((k * 7919) % 1000) / 1000.0 - 0.5) + ",0.25\n";
  writeText(d / "flat.csv", text);
  writeText(d / "m.yaml", "gyro:\n  all: [{type: white, density: 10 deg/sqrt(h)}]\n");
  CHECK(runSinsim("diagnose " + (d / "flat.csv").string() + " --rate 100 --threads 1 --model " +
                      (d / "m.yaml").string(),
                  d / "err") == 1);
  CHECK_THAT(slurp(d / "err"), Contains((d / "flat.csv").string() + ": channel gy is constant"));
  CHECK_THAT(slurp(d / "err"), Contains("leave it out: --channels gx"));
  CHECK_THAT(slurp(d / "err"), !Contains("internal error"));
}

// ASan reserves terabytes of address space, so an address-space limit cannot run under it (the
// hostile corpus turns its own off there too): this case is compiled in the plain build only.
#if defined(__SANITIZE_ADDRESS__)
#define SINSIM_TEST_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SINSIM_TEST_UNDER_ASAN 1
#endif
#endif
#ifndef SINSIM_TEST_UNDER_ASAN
// The reader holds a record's values only (8 bytes each, read in chunks), up to 3e8 of them: a
// 4-h record at 2 kHz needs 1.6 GB. Where the process has less (here `ulimit -v` 1.5 GB, as the
// hostile corpus runs), 2.5e7 rows of 7 zeros (1.4 GB of values, a 2.7 MB gzip) must end in a
// clear refusal naming the file and line -- not "internal error: std::bad_alloc" -- and write
// nothing.
TEST_CASE("sinsim analyze: a record beyond the memory left is refused by name, not bad_alloc") {
  const fs::path d = tempDir("memory");
  const fs::path rec = d / "rows.csv.gz";
  writeGzRows(rec, "t,gx,gy,gz,ax,ay,az\n", [](int) { return "0,0,0,0,0,0,0\n"; }, 250);
  const fs::path json = d / "out.json";
  const std::string cmd = "ulimit -v 1500000; " + std::string(SINSIM_BINARY_DIR) + "/sinsim analyze " +
                          rec.string() + " --rate 100 --json " + json.string() + " > /dev/null 2> " +
                          (d / "err").string();
  const int status = std::system(cmd.c_str());
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 1);
  const std::string err = slurp(d / "err");
  CHECK_THAT(err, Contains(rec.string() + ":") && Contains("does not fit in the memory left"));
  CHECK_THAT(err, !Contains("internal error") && !Contains("bad_alloc"));
  CHECK_FALSE(fs::exists(json));
}

TEST_CASE("sinsim analyze: too little memory to plan an FFT is an error, not FFTW's abort") {
  // 1e7 samples of one channel. Under `ulimit -v` 300-355 MB FFTW's planner found no memory for
  // its twiddles and aborted the process (SIGABRT, "fftw: alloc.c:29: assertion failed"); the
  // limits straddle where the record is read and the transform is planned.
  const fs::path d = tempDir("fft-memory");
  const fs::path rec = d / "one.csv.gz";
  writeGzRows(rec, "gx\n", [](int k) { return k % 3 ? "1\n" : "-2\n"; }, 100);
  int refused = 0;
  for (int limit = 300000; limit <= 420000; limit += 15000) {
    const std::string cmd = "ulimit -v " + std::to_string(limit) + "; " + std::string(SINSIM_BINARY_DIR) +
                            "/sinsim analyze " + rec.string() + " --rate 1000 > /dev/null 2> " +
                            (d / "err").string();
    const int status = std::system(cmd.c_str());
    INFO("ulimit -v " << limit << ": " << slurp(d / "err"));
    REQUIRE(WIFEXITED(status));
    CHECK((WEXITSTATUS(status) == 0 || WEXITSTATUS(status) == 1));
    if (WEXITSTATUS(status) == 1) {
      ++refused;
      CHECK_THAT(slurp(d / "err"), Contains(rec.string() + ": channel gx: ") || Contains("memory left"));
    }
  }
  CHECK(refused > 0);
}
#endif

TEST_CASE("sinsim fit and diagnose: a dead channel among live ones is named with the option that leaves it out") {
  const fs::path d = tempDir("dead");
  std::string csv = "gx,gy,gz\n";
  for (int k = 0; k < 4000; ++k)
    csv += std::to_string((k * 7919 % 1000) / 1000.0) + "," + std::to_string((k * 104729 % 997) / 997.0) + ",0\n";
  writeText(d / "dead.csv", csv);
  const fs::path model = d / "m.yaml";
  CHECK(runSinsim("fit " + (d / "dead.csv").string() + " --rate 100 --kind ar -o " + model.string(), d / "err") == 1);
  CHECK_THAT(slurp(d / "err"), Contains("channel gz is constant: nothing to fit; leave it out: --axes gx,gy"));
  CHECK_FALSE(fs::exists(model));
  // The hint, followed, fits the live channels; the diagnosis names the dead one the same way.
  REQUIRE(runSinsim("fit " + (d / "dead.csv").string() + " --rate 100 --kind ar --axes gx,gy -q -o " + model.string(),
                    d / "err") == 0);
  const fs::path improved = d / "m.improved.yaml";
  CHECK(runSinsim("diagnose " + (d / "dead.csv").string() + " --rate 100 --realisations 8 --model " + model.string() +
                      " -o " + improved.string(),
                  d / "err") == 1);
  CHECK_THAT(slurp(d / "err"), Contains("channel gz is constant: nothing to diagnose; leave it out: --channels gx gy"));
  CHECK_FALSE(fs::exists(improved));
  // A dead channel stuck at a value the mean cannot reproduce exactly (0.1: its variance after
  // mean removal is ~1e-34, not 0) is named the same way, not left to fail deep in the fit.
  std::string stuck = "gx,gy,gz\n";
  for (int k = 0; k < 4000; ++k)
    stuck += std::to_string((k * 7919 % 1000) / 1000.0) + "," + std::to_string((k * 104729 % 997) / 997.0) + ",0.1\n";
  writeText(d / "stuck.csv", stuck);
  CHECK(runSinsim("fit " + (d / "stuck.csv").string() + " --rate 100 --kind ar -o " + model.string(), d / "err") == 1);
  CHECK_THAT(slurp(d / "err"), Contains("channel gz is constant: nothing to fit; leave it out: --axes gx,gy"));
  // analyze describes what is there, the dead channel included, and says it is dead: the table
  // shows no noise terms for it (not zeros read as a perfect sensor), stderr and the JSON say why.
  const fs::path json = d / "a.json";
  const std::string analyze = std::string(SINSIM_BINARY_DIR) + "/sinsim analyze " + (d / "dead.csv").string() +
                              " --rate 100 --json " + json.string() + " > " + (d / "out").string() + " 2> " +
                              (d / "warn").string();
  REQUIRE(std::system(analyze.c_str()) == 0);
  CHECK_THAT(slurp(d / "warn"), Contains("analyze: warning: channel gz is constant (0 rad/s at every sample)"));
  CHECK_THAT(slurp(d / "warn"), !Contains("channel gx is constant") && !Contains("channel gy is constant"));
  CHECK_THAT(slurp(d / "out"), Contains("gz: constant at every sample"));
  CHECK_THAT(slurp(json), Contains("\"constant\": true"));
  // Columns under other names: listed, with a mapping that reads them.
  writeText(d / "named.csv", "gyro_x,gyro_y\n0.1,0.2\n0.3,0.1\n");
  CHECK(runSinsim("fit " + (d / "named.csv").string() + " --rate 100 -o " + model.string(), d / "err") == 1);
  CHECK_THAT(slurp(d / "err"), Contains("the file's other columns: gyro_x, gyro_y;"));
}

TEST_CASE("sinsim: an output never replaces a file the command read") {
  // `fit rec.csv -o rec.csv` replaced the record with the model, `synth m.yaml -o m.yaml` the
  // model with a record, `run s.yaml --html s.yaml` the scenario with a page: exit 0 each time.
  const fs::path d = tempDir("same");
  std::string rec = "t,gx\n";
  for (int k = 0; k < 400; ++k) rec += std::to_string(0.01 * k) + "," + std::to_string(0.001 * (k % 7) - 0.003) + "\n";
  writeText(d / "rec.csv", rec);
  writeText(d / "m.yaml", "gyro: {all: [{type: white, density: 0.1 deg/sqrt(h)}]}\n");
  writeText(d / "s.yaml", "start: {latitude: 45 deg, longitude: 7 deg}\nsegments: [{type: static, duration: 2 s}]\n");
  fs::create_symlink(d / "rec.csv", d / "link.csv");
  const std::string r = (d / "rec.csv").string(), m = (d / "m.yaml").string(), s = (d / "s.yaml").string();
  const struct {
    std::string args, target;
  } cases[] = {
      {"fit " + r + " -o " + r, r},
      {"fit " + r + " -o " + (d / "link.csv").string(), (d / "link.csv").string()},  // another name, the same file
      {"analyze " + r + " --json " + r, r},
      {"analyze " + r + " --html " + r, r},
      {"synth " + m + " --rate 100 --duration 10 -o " + m, m},
      {"diagnose " + r + " --model " + m + " --json " + m, m},
      {"run " + s + " -o " + (d / "o").string() + " --html " + s, s},
  };
  for (const auto& c : cases) {
    INFO(c.args);
    CHECK(runSinsim(c.args, d / "err") == 1);
    CHECK_THAT(slurp(d / "err"), Contains("cannot write " + c.target + ": it is an input of this command"));
  }
  CHECK(slurp(d / "rec.csv") == rec);  // every input as it was
  CHECK(slurp(d / "m.yaml") == "gyro: {all: [{type: white, density: 0.1 deg/sqrt(h)}]}\n");
  CHECK(fs::is_symlink(d / "link.csv"));
  CHECK(slurp(d / "s.yaml").rfind("start:", 0) == 0);
  CHECK(runSinsim("fit " + r + " -o " + (d / "model.yaml").string() + " -q", d / "err") == 0);  // another file: as ever
}

TEST_CASE("sinsim: bytes that are not UTF-8 in a message are shown as hex escapes and valid UTF-8 as it is") {
  CHECK(sinsim::limits::echo("gyro_\xe9t\xc3\xa9") == "gyro_\\xe9t\xc3\xa9");      // Latin-1 é, UTF-8 é
  CHECK(sinsim::limits::echo("\xc3") == "\\xc3");                                  // a cut sequence
  CHECK(sinsim::limits::echo("\xe2\x82\xac\xed\xa0\x80") == "\xe2\x82\xac\\xed\\xa0\\x80");  // €, a surrogate
  CHECK(sinsim::limits::messageText("a\n\tb\x01\xff") == "a\n\tb\\x01\\xff");
  // Through the command line: a Latin-1 key in a scenario (an editor's "temp\xe9rature").
  const fs::path d = tempDir("latin1");
  writeText(d / "s.yaml", "start: {latitude: 45 deg, longitude: 7 deg}\ntemp\xe9rature: 20 degC\n"
                          "segments: [{type: static, duration: 1 s}]\n");
  CHECK(runSinsim("run " + (d / "s.yaml").string() + " -o " + (d / "o").string(), d / "err") == 1);
  const std::string err = slurp(d / "err");
  CHECK_THAT(err, Contains("temp\\xe9rature"));
  CHECK(err.find('\xe9') == std::string::npos);
  CHECK_FALSE(fs::exists(d / "o"));
}

TEST_CASE("sinsim analyze, synth and diagnose: an output in a missing folder is refused before the work, nothing written") {
  // Before: analyze wrote its JSON and then refused the HTML (exit 1 with one output written);
  // diagnose ran the whole diagnosis, wrote the improved model and the JSON, then refused the
  // HTML; synth created the folder, while every other output file's missing folder was refused.
  const fs::path d = tempDir("outputs");
  const std::string model = std::string(SINSIM_SOURCE_DIR) + "/scenarios/adis16355-ar5.yaml";
  const std::string rec = (d / "r.csv").string();
  REQUIRE(runSinsim("synth " + model + " --rate 100 --duration 60 --seed 1 -o " + rec, d / "err") == 0);
  const std::string missing = (d / "no" / "such").string();
  const struct {
    std::string args, refused;
    std::vector<fs::path> notWritten;
  } cases[] = {
      {"analyze " + rec + " --json " + (d / "a.json").string() + " --html " + missing + "/a.html",
       missing + "/a.html", {d / "a.json"}},
      {"synth " + model + " --rate 100 --duration 60 -o " + missing + "/s.csv", missing + "/s.csv", {}},
      {"diagnose " + rec + " --model " + model + " --add white:gx -o " + (d / "m.yaml").string() +
           " --json " + (d / "d.json").string() + " --html " + missing + "/d.html",
       missing + "/d.html", {d / "m.yaml", d / "d.json"}},
      {"diagnose " + rec + " --model " + model + " --add white:gx -o " + missing + "/m.yaml",
       missing + "/m.yaml", {}},
  };
  for (const auto& c : cases) {
    INFO(c.args);
    CHECK(runSinsim(c.args, d / "err") == 1);
    const std::string err = slurp(d / "err");
    CHECK_THAT(err, Contains("cannot write " + c.refused + ": folder " + missing + " does not exist"));
    CHECK(err.find("wall") == std::string::npos);  // refused before the diagnosis ran
    for (const fs::path& p : c.notWritten) CHECK_FALSE(fs::exists(p));
  }
  CHECK_FALSE(fs::exists(d / "no"));
}

TEST_CASE("sinsim analyze and diagnose: two outputs given the same file are refused before the work") {
  // Before: `--json r --html r` wrote the JSON, then the HTML over it (exit 0, the JSON lost).
  const fs::path d = tempDir("sameout");
  const std::string model = std::string(SINSIM_SOURCE_DIR) + "/scenarios/adis16355-ar5.yaml";
  const std::string rec = (d / "r.csv").string();
  REQUIRE(runSinsim("synth " + model + " --rate 100 --duration 60 --seed 1 -o " + rec, d / "err") == 0);
  const std::string out = (d / "out").string();
  const std::string alias = (d / "." / "out").string();
  const std::string cases[] = {
      "analyze " + rec + " --json " + out + " --html " + alias,
      "diagnose " + rec + " --model " + model + " --json " + out + " --html " + out,
      "diagnose " + rec + " --model " + model + " --add white:gx -o " + out + " --json " + alias,
  };
  for (const std::string& c : cases) {
    INFO(c);
    CHECK(runSinsim(c, d / "err") == 1);
    const std::string err = slurp(d / "err");
    CHECK_THAT(err, Contains(": it is also the output "));
    CHECK_THAT(err, Contains("give each output its own file"));
    CHECK(err.find("wall") == std::string::npos);  // refused before the diagnosis ran
    CHECK_FALSE(fs::exists(d / "out"));
  }
  // Different files: as ever.
  CHECK(runSinsim("analyze " + rec + " --json " + (d / "a.json").string() + " --html " + (d / "a.html").string(),
                  d / "err") == 0);
  CHECK(fs::exists(d / "a.json"));
  CHECK(fs::exists(d / "a.html"));
}
