// `sinsim mc` output files: bit-identical for any thread count, after a run-limited stop, after
// SIGKILL and after Ctrl-C (SIGINT) followed by --resume; refusals that protect checkpoints.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <sstream>
#include <thread>

#include "helpers.hpp"

using namespace mctest;

namespace {

// 30 s with motion (speed-up, turn, climb), 100 Hz IMU: every part of the mechanization works.
const char* kScenario = R"(name: mc-short
start: {latitude: 48 deg, longitude: 11 deg, height: 500 m, heading: 90 deg}
imu_rate: 100 Hz
output_rate: 1 Hz
vertical: {channel: damped, time_constant: 100 s}
segments:
  - {type: static, duration: 5 s}
  - {type: accelerate, speed: 15 m/s, duration: 8 s}
  - {type: turn, heading_change: 90 deg, duration: 8 s}
  - {type: climb, height_change: 5 m, duration: 9 s}
)";

fs::path writeScenario(const fs::path& dir) {
  const fs::path p = dir / "short.yaml";
  std::ofstream(p) << kScenario;
  return p;
}

std::string models() {
  return " --model '" + sourceDir() + "/scenarios/adis16355-ar5.yaml' --model '" + sourceDir() +
         "/scenarios/adis16355-gm.yaml'";
}

// Same set of files with the same bytes.
void requireSameFolders(const fs::path& a, const fs::path& b) {
  const auto fa = listFiles(a), fb = listFiles(b);
  REQUIRE(fa == fb);
  REQUIRE(!fa.empty());
  for (const auto& f : fa) {
    INFO(f);
    CHECK(slurp(a / f) == slurp(b / f));
  }
}

// Waits until the first checkpoint chunk appears (or the child ends), then sends sig.
int interruptAfterFirstChunk(pid_t pid, const fs::path& out, int sig) {
  const auto start = std::chrono::steady_clock::now();
  int status = 0;
  while (!anyChunk(out)) {
    if (::waitpid(pid, &status, WNOHANG) == pid) return status;
    if (std::chrono::steady_clock::now() - start > std::chrono::seconds(60)) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ::kill(pid, sig);
  ::waitpid(pid, &status, 0);
  return status;
}

// per_run.csv (20 runs, --times 10,30 of a 30 s run, 2 models + 12 budget variants): one row
// per model, run and time, and its values agree with the distribution stats.csv reports.
void checkPerRunCsv(const fs::path& dir) {
  std::istringstream in(slurp(dir / "per_run.csv"));
  std::string line;
  std::getline(in, line);
  CHECK(line == "model,run,t [s],north [m],east [m],down [m],horizontal [m],vertical [m],"
                "vn [m/s],ve [m/s],vd [m/s],roll [rad],pitch [rad],yaw [rad]");
  std::size_t rows = 0;
  std::vector<double> horizontalAt30;
  while (std::getline(in, line)) {
    ++rows;
    if (line.rfind("adis16355-ar5,", 0) != 0) continue;
    std::vector<double> v;
    std::istringstream fields(line.substr(line.find(',') + 1));
    for (std::string f; std::getline(fields, f, ',');) v.push_back(std::stod(f));
    REQUIRE(v.size() == 13);
    CHECK(v[5] == Approx(std::hypot(v[2], v[3])).epsilon(1e-8));  // horizontal = |(north, east)|
    if (v[1] == 30.0) horizontalAt30.push_back(v[5]);
  }
  CHECK(rows == 14u * 20u * 2u);
  REQUIRE(horizontalAt30.size() == 20u);
  // stats.csv's mean horizontal error of the model at 30 s (column 3) from the same runs.
  std::istringstream stats(slurp(dir / "stats.csv"));
  double mean = NAN;
  while (std::getline(stats, line))
    if (line.rfind("adis16355-ar5,30.000000,", 0) == 0)
      mean = std::stod(line.substr(std::string("adis16355-ar5,30.000000,").size()));
  double sum = 0;
  for (double h : horizontalAt30) sum += h;
  // Both printed with 9 significant digits from the same float errors: agree to ~1e-8.
  CHECK(sum / 20.0 == Approx(mean).epsilon(1e-7));
}

}  // namespace

TEST_CASE("sinsim mc: threads 1 and 2 write identical files, a stopped batch resumes to the same files") {
  const fs::path tmp = tempDir("threads");
  const fs::path sc = writeScenario(tmp);
  const std::string common = "mc '" + sc.string() + "' --runs 20 --seed 5 --budget --times 10,30" + models();

  const Result r1 = sinsim(common + " --threads 1 -o '" + (tmp / "t1").string() + "'", tmp);
  INFO(r1.err);
  REQUIRE(r1.exitCode == 0);
  // The terminal honours --times: each model at each time, and the paired comparison at each.
  for (const char* t : {"10 s", "30 s"}) {
    CHECK(r1.out.find(std::string("adis16355-ar5: horizontal error at ") + t + ": CEP ") != std::string::npos);
    CHECK(r1.out.find(std::string("adis16355-gm: horizontal error at ") + t + ": CEP ") != std::string::npos);
    CHECK(r1.out.find(std::string(" at ") + t + " (mean ") != std::string::npos);
  }
  CHECK(r1.out.find("20 paired runs, paired t-test p = ") != std::string::npos);
  CHECK(r1.out.find("2 model(s) x 20 runs (+ 12 budget variants) -> ") != std::string::npos);
  CHECK(r1.out.find("e+0") == std::string::npos);  // no exponent notation for a drift
  checkPerRunCsv(tmp / "t1");
  const Result r2 = sinsim(common + " --threads 2 -o '" + (tmp / "t2").string() + "'", tmp);
  REQUIRE(r2.exitCode == 0);
  for (const char* f : {"stats.csv", "summary.json", "report.html"})
    REQUIRE(fs::file_size(tmp / "t1" / f) > 0);
  requireSameFolders(tmp / "t1", tmp / "t2");

  // A batch stopped after 30 of the 280 runs (2 models + 12 budget variants, 20 runs each) leaves
  // checkpoints and no outputs; --resume (with another thread count) finishes it identically.
  const fs::path part = tmp / "part";
  const Result s = sinsim(common + " --threads 2 --stop-after 30 -o '" + part.string() + "'", tmp);
  CHECK(s.exitCode == 130);
  CHECK(s.err.find("--resume") != std::string::npos);
  CHECK_FALSE(fs::exists(part / "stats.csv"));
  CHECK(anyChunk(part));
  const Result res = sinsim(common + " --threads 1 --resume -o '" + part.string() + "'", tmp);
  INFO(res.err);
  REQUIRE(res.exitCode == 0);
  CHECK(res.out.find("resumed from checkpoints") != std::string::npos);
  requireSameFolders(tmp / "t1", part);
  fs::remove_all(tmp);
}

TEST_CASE("sinsim mc: a batch grown with --resume recomputes its short last chunk, not called damaged") {
  const fs::path tmp = tempDir("grown");
  const fs::path sc = writeScenario(tmp);
  const std::string common = "mc '" + sc.string() + "' --seed 3 --threads 1 --model '" + sourceDir() +
                             "/scenarios/adis16355-gm.yaml'";
  REQUIRE(sinsim(common + " --runs 6 -o '" + (tmp / "g").string() + "'", tmp).exitCode == 0);
  const Result grown = sinsim(common + " --runs 10 --resume -o '" + (tmp / "g").string() + "'", tmp);
  INFO(grown.err);
  REQUIRE(grown.exitCode == 0);
  CHECK(grown.err.find("damaged") == std::string::npos);
  CHECK(grown.out.find("damaged") == std::string::npos);
  CHECK(grown.out.find("1 chunk(s) an earlier --runs had cut to another length recomputed") !=
        std::string::npos);
  REQUIRE(sinsim(common + " --runs 10 -o '" + (tmp / "fresh").string() + "'", tmp).exitCode == 0);
  requireSameFolders(tmp / "fresh", tmp / "g");
  fs::remove_all(tmp);
}

TEST_CASE("sinsim mc: --budget of a model with one effect says there is nothing to switch off") {
  const fs::path tmp = tempDir("budget1");
  const fs::path sc = writeScenario(tmp);
  std::ofstream(tmp / "one.yaml") << "gyro: {x: [{type: white, density: 0.1 deg/sqrt(h)}]}\n";
  const Result r = sinsim("mc '" + sc.string() + "' --runs 2 --threads 1 --budget --model '" +
                              (tmp / "one.yaml").string() + "' -o '" + (tmp / "o").string() + "'",
                          tmp);
  INFO(r.err);
  REQUIRE(r.exitCode == 0);
  CHECK(r.err.find("--budget: model one has one effect, which is all its drift: nothing to switch off") !=
        std::string::npos);
  CHECK(r.out.find("budget variants") == std::string::npos);
  fs::remove_all(tmp);
}

TEST_CASE("sinsim mc: --reference compares every model with one, and names the labels when it matches none") {
  const fs::path tmp = tempDir("reference");
  const fs::path sc = writeScenario(tmp);
  std::string models;
  for (const char* name : {"a", "b", "c", "d"}) {
    std::ofstream(tmp / (std::string(name) + ".yaml")) << "gyro: {x: [{type: white, density: 0.1 deg/sqrt(h)}]}\n";
    models += " --model '" + (tmp / (std::string(name) + ".yaml")).string() + "'";
  }
  auto sentences = [](const std::string& out) {
    std::size_t n = 0;
    for (std::size_t at = out.find("horizontal drift"); at != std::string::npos; at = out.find("horizontal drift", at + 1))
      ++n;
    return n;
  };
  const std::string base = "mc '" + sc.string() + "' --runs 3 --threads 1" + models;
  const Result all = sinsim(base + " -o '" + (tmp / "all").string() + "'", tmp);
  REQUIRE(all.exitCode == 0);
  CHECK(sentences(all.out) == 6);  // 4 models: every pair, one report time
  const Result one = sinsim(base + " --reference c -o '" + (tmp / "one").string() + "'", tmp);
  INFO(one.err);
  REQUIRE(one.exitCode == 0);
  CHECK(sentences(one.out) == 3);  // c against a, b and d
  std::istringstream lines(one.out);
  for (std::string line; std::getline(lines, line);)
    if (line.find("horizontal drift") != std::string::npos) {
      INFO(line);
      CHECK((line.find(" c ") != std::string::npos || line.find("  c ") != std::string::npos));
    }
  CHECK(fs::exists(tmp / "one" / "report.html"));
  const Result bad = sinsim(base + " --reference e -o '" + (tmp / "bad").string() + "'", tmp);
  CHECK(bad.exitCode != 0);
  CHECK(bad.err.find("--reference e: no model has that label (the models: a b c d)") != std::string::npos);
  CHECK_FALSE(fs::exists(tmp / "bad"));
  fs::remove_all(tmp);
}

TEST_CASE("sinsim mc: a model fitted on a record shorter than the scenario is said to extrapolate") {
  const fs::path tmp = tempDir("extrapolate");
  const fs::path sc = writeScenario(tmp);  // 30 s
  const std::string effects = "gyro: {x: [{type: white, density: 0.1 deg/sqrt(h)}]}\n";
  std::ofstream(tmp / "brief.yaml") << "record_duration: 20 s\n" << effects;
  std::ofstream(tmp / "long.yaml") << "record_duration: 1 min\n" << effects;
  std::ofstream(tmp / "unknown.yaml") << effects;
  const Result r = sinsim("mc '" + sc.string() + "' --runs 2 --threads 1 --model '" + (tmp / "brief.yaml").string() +
                              "' --model '" + (tmp / "long.yaml").string() + "' --model '" +
                              (tmp / "unknown.yaml").string() + "' -o '" + (tmp / "o").string() + "'",
                          tmp);
  INFO(r.err);
  REQUIRE(r.exitCode == 0);
  CHECK(r.err.find("model brief was fitted on a 20 s record and the scenario runs 30 s: its drift beyond 20 s is "
                   "extrapolated") != std::string::npos);
  CHECK(r.err.find("model long was fitted") == std::string::npos);
  CHECK(r.err.find("model unknown was fitted") == std::string::npos);
  fs::remove_all(tmp);
}

TEST_CASE("sinsim mc: stopped before its first chunk, nothing is left to resume or to refuse") {
  const fs::path tmp = tempDir("nochunk");
  const fs::path sc = writeScenario(tmp);
  const std::string common = "mc '" + sc.string() + "' --seed 3 --threads 1 --runs 16 --model '" +
                             sourceDir() + "/scenarios/adis16355-gm.yaml' -o '" + (tmp / "n").string() + "'";
  const Result s = sinsim(common + " --stop-after 3", tmp);
  CHECK(s.exitCode == 130);
  CHECK(s.err.find("none saved (runs are saved in chunks of 8 per model") != std::string::npos);
  CHECK(s.err.find("--resume") == std::string::npos);
  CHECK_FALSE(fs::exists(tmp / "n"));  // the folder it created, empty, is gone
  // A folder that held only the empty model folders of such a batch is no batch to protect.
  fs::create_directories(tmp / "n" / "runs" / "adis16355-gm-0123abcd");
  const Result again = sinsim(common, tmp);
  INFO(again.err);
  CHECK(again.exitCode == 0);
  fs::remove_all(tmp);
}

TEST_CASE("sinsim mc: killed (SIGKILL) or interrupted (SIGINT) mid-way, --resume gives identical files") {
  const fs::path tmp = tempDir("kill");
  const fs::path sc = writeScenario(tmp);
  // One thread and 160 runs of the AR(5) model (~1 s): the first chunk of 8 runs appears long
  // before the end.
  const std::string common = "mc '" + sc.string() + "' --runs 160 --seed 9 --threads 1 --model '" +
                             sourceDir() + "/scenarios/adis16355-ar5.yaml'";
  const Result full = sinsim(common + " -o '" + (tmp / "full").string() + "'", tmp);
  REQUIRE(full.exitCode == 0);

  for (int sig : {SIGKILL, SIGINT}) {
    const fs::path out = tmp / (sig == SIGKILL ? "killed" : "interrupted");
    const pid_t pid = spawn(common + " -o '" + out.string() + "'", tmp);
    const int status = interruptAfterFirstChunk(pid, out, sig);
    INFO("signal " << sig << ", stderr: " << slurp(tmp / "bg.err"));
    if (sig == SIGKILL) {
      REQUIRE(WIFSIGNALED(status));
    } else {
      // Ctrl-C: the running chunk is dropped, the process says how to continue and exits 130.
      REQUIRE(WIFEXITED(status));
      CHECK(WEXITSTATUS(status) == 130);
      CHECK(slurp(tmp / "bg.err").find("--resume") != std::string::npos);
    }
    REQUIRE_FALSE(fs::exists(out / "stats.csv"));  // really stopped mid-way
    REQUIRE(anyChunk(out));
    const Result res = sinsim(common + " --resume -o '" + out.string() + "'", tmp);
    INFO(res.err);
    REQUIRE(res.exitCode == 0);
    requireSameFolders(tmp / "full", out);
  }
  fs::remove_all(tmp);
}

TEST_CASE("sinsim mc: checkpoints are protected: no silent overwrite, no resume of another batch") {
  const fs::path tmp = tempDir("refuse");
  const fs::path sc = writeScenario(tmp);
  const std::string out = " -o '" + (tmp / "o").string() + "'";
  const std::string base = "mc '" + sc.string() + "' --runs 8 --model '" + sourceDir() +
                           "/scenarios/adis16355-gm.yaml'";
  REQUIRE(sinsim(base + " --seed 1" + out, tmp).exitCode == 0);
  const Result again = sinsim(base + " --seed 1" + out, tmp);
  CHECK(again.exitCode == 1);
  CHECK(again.err.find("pass --resume") != std::string::npos);
  const Result other = sinsim(base + " --seed 2 --resume" + out, tmp);
  CHECK(other.exitCode == 1);
  CHECK(other.err.find("other inputs") != std::string::npos);
  // Bad input: nothing is created.
  const Result bad = sinsim("mc '" + sc.string() + "' --runs 0 -o '" + (tmp / "x").string() + "'", tmp);
  CHECK(bad.exitCode == 2);  // a bad command line, as --runs -1
  CHECK(bad.err.find("--runs: expected at least 1 run per model, got 0") != std::string::npos);
  CHECK_FALSE(fs::exists(tmp / "x"));
  const Result badTime = sinsim(base + " --times 999 -o '" + (tmp / "y").string() + "'", tmp);
  CHECK(badTime.exitCode == 1);
  CHECK(badTime.err.find("outside the run") != std::string::npos);
  CHECK_FALSE(fs::exists(tmp / "y"));
  // One output epoch named twice would be counted twice in every table and test.
  const Result twice = sinsim(base + " --times \"30,0.5 min\" -o '" + (tmp / "y").string() + "'", tmp);
  CHECK(twice.exitCode == 1);
  CHECK(twice.err.find("--times: times 1 and 2 (30 s, 30 s) fall on the same output epoch") != std::string::npos);
  CHECK_FALSE(fs::exists(tmp / "y"));
  fs::remove_all(tmp);
}

TEST_CASE("sinsim mc: a progress line on a terminal, none when stderr is a file") {
  const fs::path tmp = tempDir("progress");
  const fs::path sc = writeScenario(tmp);
  // 2400 runs on one thread: several seconds even on an idle machine (480 took under 1 s), past
  // the line's first second of silence (cli/terminal.hpp).
  const std::string args = "mc '" + sc.string() + "' --runs 2400 --threads 1 --model '" + sourceDir() +
                           "/scenarios/adis16355-gm.yaml'";
  const Result plain = sinsim(args + " -o '" + (tmp / "a").string() + "'", tmp);
  REQUIRE(plain.exitCode == 0);
  CHECK(plain.err.find("sinsim mc: runs") == std::string::npos);
  // util-linux `script` gives the command a pseudo-terminal (part of every Debian base system).
  REQUIRE(fs::exists("/usr/bin/script"));
  const std::string cmd = "/usr/bin/script -qec \"'" + sinsimPath() + "' " + args + " -o '" +
                          (tmp / "b").string() + "'\" /dev/null > '" + (tmp / "pty.out").string() + "'";
  REQUIRE(std::system(cmd.c_str()) == 0);
  const std::string out = slurp(tmp / "pty.out");
  CHECK(out.find("sinsim mc: runs ") != std::string::npos);  // runs done
  CHECK(out.find("/2400 (") != std::string::npos);           // of how many
  CHECK(out.find("/s, ") != std::string::npos);              // rate
  CHECK(out.find("s left") != std::string::npos);            // time left
  fs::remove_all(tmp);
}
