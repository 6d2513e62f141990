// Regression tests for what the independent hostile corpus (tests/hostile/corpus, docs/limits.md)
// found, one TEST_CASE per class: a crash, memory beyond 1.5 GB, a hang, nonsense accepted with
// exit 0, and errors that did not say where.
#include <catch2/catch.hpp>
#include <sys/stat.h>
#include <zlib.h>

#include <filesystem>
#include <string>

#include "common/error.hpp"
#include "common/limits.hpp"
#include "errormodels/imu_model.hpp"
#include "errormodels/stats/record.hpp"
#include "sim/scenario.hpp"
#include "test_support.hpp"

using Catch::Matchers::Contains;
namespace fs = std::filesystem;
using namespace sinsim;
using sinsim::test::runSinsim;
using sinsim::test::slurp;
using sinsim::test::writeText;

using sinsim::test::messageOf;

namespace {

fs::path tempDir(const std::string& name) {
  return sinsim::test::freshTempDir("sinsim-corpus-findings-" + name);
}

const std::string kStart = "start: {latitude: 45 deg, longitude: 7 deg}\n";

}  // namespace

TEST_CASE("corpus finding, crash: fit --max-order -1 wrapped to 2^64-1 and segfaulted") {
  const fs::path d = tempDir("crash");
  std::string csv = "gx\n";
  for (int k = 0; k < 3000; ++k) csv += std::to_string((k * 7919 % 1000) / 1000.0) + "\n";
  writeText(d / "r.csv", csv);
  for (const char* order : {"-1", "18446744073709551615", "65"}) {
    INFO(order);
    CHECK(runSinsim("fit " + (d / "r.csv").string() + " --rate 100 --kind ar -q --max-order " +
                        order + " -o " + (d / "m.yaml").string(),
                    d / "err") == 1);
    CHECK_THAT(slurp(d / "err"), Contains("--max-order: expected an integer from 1 to 64"));
    CHECK_FALSE(fs::exists(d / "m.yaml"));
  }
}

TEST_CASE("corpus finding, memory: a 1 MB gzip of one 600 MB line is refused at the line limit") {
  // 600 MB of one digit. The reader used to hold the whole text and double its buffer past 1 GiB
  // (std::bad_alloc under 1.5 GB), then refused text beyond 512 MiB; it now reads in chunks and
  // holds one line, at most kMaxRecordLineChars, so it stops after ~1 MiB of the line.
  const fs::path d = tempDir("bomb");
  const std::string path = (d / "bomb.csv.gz").string();
  gzFile f = gzopen(path.c_str(), "wb1");  // fast: the test is about reading
  REQUIRE(f != nullptr);
  gzputs(f, "t,gx\n");
  const std::string block(1 << 20, '7');
  for (int k = 0; k < 600; ++k) gzwrite(f, block.data(), static_cast<unsigned>(block.size()));
  gzclose(f);
  const std::string msg = messageOf([&] { errormodels::loadRecord(path, {}); });
  CHECK_THAT(msg, Contains(path + ":2") && Contains("a line longer than " +
                                                     std::to_string(limits::kMaxRecordLineChars)));
}

TEST_CASE("corpus finding, hang: a model of 20,000 effects made diagnose run for minutes") {
  std::string text = "gyro:\n  x:\n";
  for (std::size_t k = 0; k <= limits::kMaxModelEffects; ++k)
    text += "    - {type: white, density: 0.1 deg/sqrt(h)}\n";
  const std::string msg =
      messageOf([&] { errormodels::ImuErrorModel::fromString(text, "many.yaml"); });
  CHECK_THAT(msg, Contains("many.yaml:1") &&
                      Contains(std::to_string(limits::kMaxModelEffects + 1) + " effects"));
}

TEST_CASE("corpus finding, nonsense accepted: models, temperatures and options that ran with exit 0") {
  // A model without any sensor section, or `gyro: ~`, ran as a perfect IMU.
  CHECK_THAT(messageOf([] { errormodels::ImuErrorModel::fromString("description: x\n", "d.yaml"); }),
             Contains("d.yaml:1") && Contains("write `gyro: {}`"));
  CHECK_THAT(messageOf([] { errormodels::ImuErrorModel::fromString("gyro: ~\n", "n.yaml"); }),
             Contains("n.yaml:1: gyro: no effects given"));
  // 1e308 ppm passed the magnitude check (dimensionless values took another path).
  CHECK_THAT(messageOf([] {
               errormodels::ImuErrorModel::fromString(
                   "gyro: {triad: [{type: scale_factor, diagonal: [1e308 ppm, 0 ppm, 0 ppm]}]}\n",
                   "sf.yaml");
             }),
             Contains("sf.yaml:1") && Contains("beyond any physical value"));
  // A temperature rate of 1e10 degC/s reached 2e11 degC.
  CHECK_THAT(messageOf([] {
               sim::parseScenario(kStart + "temperature: {start: 20 degC, rate: 1e10 degC/s}\n"
                                           "segments: [{type: static, duration: 10 s}]\n",
                                  "t.yaml", ".");
             }),
             Contains("t.yaml:2: temperature: the temperature goes from 20 to 1e+11 degC"));

  const fs::path d = tempDir("nonsense");
  writeText(d / "m.yaml", "gyro: {all: [{type: white, density: 0.1 deg/sqrt(h)}]}\n");
  // An empty argument read as "not given": `run ""` ran the default scenario, `--seed ""` seed 0.
  CHECK(runSinsim("run \"\" -o " + (d / "out").string(), d / "err") == 2);
  CHECK_THAT(slurp(d / "err"), Contains("an empty value on the command line"));
  CHECK(runSinsim("synth " + (d / "m.yaml").string() + " --rate 100 --duration 1 --seed \"\" -o " +
                      (d / "x.csv").string(),
                  d / "err") == 2);
  CHECK_THAT(slurp(d / "err"), Contains("--seed: an empty value"));
  // A pipe (or a device) as the output: the temporary was renamed over it; as root
  // `-o /dev/null` would have replaced /dev/null by a regular file.
  const fs::path fifo = d / "fifo";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  CHECK(runSinsim("synth " + (d / "m.yaml").string() + " --rate 100 --duration 1 -o " +
                      fifo.string(),
                  d / "err") == 1);
  CHECK_THAT(slurp(d / "err"), Contains(fifo.string() + ": it is a device, pipe or socket"));
  CHECK(fs::is_fifo(fifo));
  // Options beyond sense ran: a 1e308 s ACF lag, a NaN reporting threshold, --rate 0.
  writeText(d / "r.csv", [] {
    std::string s = "t,gx\n";
    for (int k = 0; k < 3000; ++k)
      s += std::to_string(k * 0.01) + "," + std::to_string((k * 7919 % 1000) / 1000.0) + "\n";
    return s;
  }());
  const std::string rec = (d / "r.csv").string();
  CHECK(runSinsim("analyze " + rec + " --max-lag 1e308", d / "err") == 1);
  CHECK_THAT(slurp(d / "err"), Contains("--max-lag: expected a lag from 0 to"));
  CHECK(runSinsim("analyze " + rec + " --rate 0", d / "err") == 1);
  CHECK_THAT(slurp(d / "err"), Contains("--rate: expected a positive sample rate"));
  CHECK(runSinsim("diagnose " + rec + " --model " + (d / "m.yaml").string() +
                      " --threshold nan --threads 1",
                  d / "err") == 2);  // a bad command line since the fifty-seventh session
  CHECK_THAT(slurp(d / "err"), Contains("--threshold: expected a positive score"));
}

TEST_CASE("corpus finding, unnamed errors: the file or option is named") {
  const fs::path d = tempDir("unnamed");
  // `errors: /tmp` named /tmp but not the scenario line that gave it.
  writeText(d / "s.yaml", kStart + "errors: " + d.string() + "\n" +
                              "segments: [{type: static, duration: 1 s}]\n");
  CHECK(runSinsim("run " + (d / "s.yaml").string() + " -o " + (d / "out").string(), d / "err") == 1);
  CHECK_THAT(slurp(d / "err"),
             Contains((d / "s.yaml").string() + ":2: errors: " + d.string() + ": is a directory"));
  // An AR process slower than the IMU is found only when instantiated: the model file and the
  // effect's line are named.
  writeText(d / "ar.yaml", "gyro: {x: [{type: ar, a: [-0.5], sigma: 1 deg/s, rate: 5 Hz}]}\n");
  CHECK(runSinsim("synth " + (d / "ar.yaml").string() + " --rate 100 --duration 1 -o " +
                      (d / "x.csv").string(),
                  d / "err") == 1);
  CHECK_THAT(slurp(d / "err"),
             Contains((d / "ar.yaml").string() + ":1: gyro.x[0].ar: the process is defined at 5 Hz"));
  // A state that turns non-finite: the scenario (and model) are named.
  writeText(d / "ramp.yaml", "gyro: {x: [{type: ramp, slope: 1e11 rad/s/s}]}\n");
  writeText(d / "s2.yaml", kStart + "segments: [{type: static, duration: 10 s}]\n");
  CHECK(runSinsim("run " + (d / "s2.yaml").string() + " --model " + (d / "ramp.yaml").string() +
                      " -o " + (d / "out2").string(),
                  d / "err") == 1);
  CHECK_THAT(slurp(d / "err"), Contains((d / "s2.yaml").string() + " with model " +
                                        (d / "ramp.yaml").string() + ": the navigation error became non-finite"));
  CHECK_FALSE(fs::exists(d / "out2"));
  // Option values: the option is named; one that cannot be read is a bad command line (exit 2).
  writeText(d / "m.yaml", "gyro: {}\n");
  CHECK(runSinsim("synth " + (d / "m.yaml").string() + " --rate 100 --duration 1 --latitude 1e400 -o " +
                      (d / "x.csv").string(),
                  d / "err") == 2);
  CHECK_THAT(slurp(d / "err"), Contains("--latitude: "));
  // A record's --duration of zero is a bad command line too, named as the option (not the record).
  writeText(d / "rec.csv", "t,gx,gy,gz,ax,ay,az\n0,0,0,0,0,0,9.8\n0.01,0,0,0,0,0,9.8\n");
  CHECK(runSinsim("analyze " + (d / "rec.csv").string() + " --duration 0s --json " +
                      (d / "a.json").string(),
                  d / "err") == 2);
  CHECK_THAT(slurp(d / "err"), Contains("--duration: expected a positive time"));
  CHECK_FALSE(fs::exists(d / "a.json"));
  // An option the diagnosis checks (--realisations 4) is the command line's: exit 2, the record's
  // name not put in front of it.
  writeText(d / "w.yaml", "gyro: {x: [{type: white, density: 0.1 deg/sqrt(h)}]}\n");
  CHECK(runSinsim("diagnose " + (d / "rec.csv").string() + " --model " + (d / "w.yaml").string() +
                      " --realisations 4 --json " + (d / "g.json").string(),
                  d / "err") == 2);
  CHECK_THAT(slurp(d / "err"), Contains("sinsim: error: --realisations: at least 8"));
  CHECK_FALSE(fs::exists(d / "g.json"));
  CHECK(runSinsim("run " + (d / "s2.yaml").string() + " --bias-window 1e-9 -o " +
                      (d / "out3").string(),
                  d / "err") == 1);
  CHECK_THAT(slurp(d / "err"), Contains("--bias-window"));
}

TEST_CASE("corpus finding, slow parse: a segment reached through many aliases is parsed once") {
  // 4 levels of 8 aliases: 4096 copies of one segment with a bad duration. Each copy used to be
  // parsed anew (the slow fuzz input: ~100,000 copies, 3 s in the sanitizer build) and reported
  // once per copy; now the aliased node is parsed, and reported, once.
  std::string items = "&s0 {type: static, duration: -1 s}";
  for (int k = 0; k < 7; ++k) items += ", *s0";
  for (int level = 1; level <= 4; ++level) {
    const std::string r = "r" + std::to_string(level);
    std::string next = "&" + r + " {type: repeat, count: 1, segments: [" + items + "]}";
    for (int k = 0; k < 7; ++k) next += ", *" + r;
    items = next;
  }
  try {
    sim::parseScenario(kStart + "segments: [" + items + "]\n", "a.yaml", ".");
    FAIL("accepted");
  } catch (const ConfigError& e) {
    REQUIRE(e.diagnostics().size() == 1);
    CHECK_THAT(e.diagnostics()[0].message, Contains("expected a positive duration"));
  }
}

TEST_CASE("fuzz finding, slow parse: an alias inside the node it names is a structure without end") {
  // fuzz_scenario, 10-minute campaign: `lap: &lap [..., {segments: *lap}]` (seed
  // tests/fuzz/seeds/scenario/recursive-alias-timeout.yaml) was walked to the 500,000-node budget,
  // 3.2 s of CPU under the sanitizers; the cycle is now found on the first repetition.
  const std::string text = kStart + "segments: &s\n  - {type: static, duration: 1 s}\n"
                                    "  - {type: repeat, count: 2, segments: *s}\n";
  const std::string msg = messageOf([&] { sim::parseScenario(text, "r.yaml", "."); });
  CHECK_THAT(msg, Contains("r.yaml:") && Contains("an alias refers to a node that contains it"));
  CHECK_THAT(msg, !Contains("500000"));
}
