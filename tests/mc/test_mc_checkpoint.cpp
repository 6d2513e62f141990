// Checkpoint integrity and folder ownership (issue 15): damaged checkpoints are detected by their
// CRC-32, reported and recomputed to the bytes of an uninterrupted batch; a second writer is
// refused (flock), also for `run`; temporaries of a killed process are removed by the next run;
// a file size limit (ulimit -f) gives a message naming the file instead of a silent SIGXFSZ death.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include "helpers.hpp"

using namespace mctest;

namespace {

const char* kScenario = R"(name: ck
start: {latitude: 48 deg, longitude: 11 deg, height: 500 m, heading: 90 deg}
imu_rate: 100 Hz
output_rate: 1 Hz
segments:
  - {type: static, duration: 5 s}
  - {type: accelerate, speed: 15 m/s, duration: 10 s}
  - {type: turn, heading_change: 90 deg, duration: 15 s}
)";

fs::path writeScenario(const fs::path& dir) {
  const fs::path p = dir / "ck.yaml";
  std::ofstream(p) << kScenario;
  return p;
}

std::string model(const char* name) { return " --model '" + sourceDir() + "/scenarios/" + name + "'"; }

std::vector<fs::path> chunks(const fs::path& dir) {
  std::vector<fs::path> r;
  for (const auto& e : fs::recursive_directory_iterator(dir / "runs"))
    if (e.path().extension() == ".bin") r.push_back(e.path());
  std::sort(r.begin(), r.end());
  return r;
}

void overwrite(const fs::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary | std::ios::trunc) << bytes;
}

// An flock on dir held by this process: another sinsim for sinsim's purposes.
struct HeldLock {
  int fd;
  explicit HeldLock(const fs::path& dir) : fd(::open(dir.c_str(), O_RDONLY | O_DIRECTORY)) {
    REQUIRE(fd >= 0);
    REQUIRE(::flock(fd, LOCK_EX | LOCK_NB) == 0);
  }
  ~HeldLock() { ::close(fd); }
};

}  // namespace

TEST_CASE("sinsim mc: damaged checkpoints are detected, reported and recomputed to identical files") {
  const fs::path tmp = tempDir("crc");
  const fs::path sc = writeScenario(tmp);
  // 40 runs: 5 chunks of 8.
  const std::string common = "mc '" + sc.string() + "' --runs 40 --seed 3 --threads 1" +
                             model("adis16355-gm.yaml");
  REQUIRE(sinsim(common + " -o '" + (tmp / "full").string() + "'", tmp).exitCode == 0);
  fs::copy(tmp / "full", tmp / "hit", fs::copy_options::recursive);
  for (const char* f : {"stats.csv", "summary.json", "report.html"}) fs::remove(tmp / "hit" / f);
  const auto c = chunks(tmp / "hit");
  REQUIRE(c.size() == 5);
  // 0: one bit of the payload (an error value: used as is, it shifts the statistics);
  // 1: one bit of the header's input fingerprint (must not pass for "another batch");
  // 2: truncated to half; 3: zeroed at full length; 4: untouched.
  std::string b0 = slurp(c[0]);
  b0[48 + 1001] ^= 0x10;
  overwrite(c[0], b0);
  std::string b1 = slurp(c[1]);
  b1[8] ^= 0x01;
  overwrite(c[1], b1);
  const std::string b2 = slurp(c[2]);
  overwrite(c[2], b2.substr(0, b2.size() / 2));
  overwrite(c[3], std::string(slurp(c[3]).size(), '\0'));

  const Result r = sinsim(common + " --resume -o '" + (tmp / "hit").string() + "'", tmp);
  INFO(r.err);
  REQUIRE(r.exitCode == 0);
  CHECK(r.err.find("4 damaged checkpoint(s)") != std::string::npos);
  for (int i = 0; i < 4; ++i) CHECK(r.err.find(c[std::size_t(i)].filename().string()) != std::string::npos);
  CHECK(r.out.find("32 runs computed, 8 resumed from checkpoints") != std::string::npos);
  // Every file, checkpoints included, as the uninterrupted batch wrote it.
  const auto fa = listFiles(tmp / "full"), fb = listFiles(tmp / "hit");
  REQUIRE(fa == fb);
  for (const auto& f : fa) {
    INFO(f);
    CHECK(slurp(tmp / "full" / f) == slurp(tmp / "hit" / f));
  }
  fs::remove_all(tmp);
}

TEST_CASE("sinsim mc and run: a second writer into a folder is refused, even with --resume") {
  const fs::path tmp = tempDir("lock");
  const fs::path sc = writeScenario(tmp);
  const fs::path out = tmp / "o";
  // A real concurrent batch: ~1 s of work on one thread; the second starts once a chunk exists.
  const std::string args = "mc '" + sc.string() + "' --runs 160 --seed 9 --threads 1" +
                           model("adis16355-ar5.yaml") + " -o '" + out.string() + "'";
  const pid_t first = spawn(args, tmp);
  const auto start = std::chrono::steady_clock::now();
  int status = 0;
  bool ended = false;
  while (!anyChunk(out) && !(ended = ::waitpid(first, &status, WNOHANG) == first) &&
         std::chrono::steady_clock::now() - start < std::chrono::seconds(60))
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  REQUIRE_FALSE(ended);
  const Result second = sinsim(args + " --resume", tmp);
  ::kill(first, SIGKILL);
  ::waitpid(first, &status, 0);
  CHECK(second.exitCode == 1);
  CHECK(second.err.find("another sinsim process is writing into") != std::string::npos);
  // The lock dies with its holder: the folder resumes.
  CHECK(sinsim(args + " --resume", tmp).exitCode == 0);

  // `run` takes the same lock.
  fs::create_directories(tmp / "r");
  {
    HeldLock held(tmp / "r");
    const Result r = sinsim("run '" + sc.string() + "' -o '" + (tmp / "r").string() + "'", tmp);
    CHECK(r.exitCode == 1);
    CHECK(r.err.find("another sinsim process") != std::string::npos);
    CHECK_FALSE(fs::exists(tmp / "r" / "errors.csv"));
  }
  CHECK(sinsim("run '" + sc.string() + "' -o '" + (tmp / "r").string() + "'", tmp).exitCode == 0);
  fs::remove_all(tmp);
}

TEST_CASE("sinsim run and mc: temporaries of a killed process are removed, nothing else") {
  const fs::path tmp = tempDir("stale");
  const fs::path sc = writeScenario(tmp);
  const fs::path r = tmp / "r";
  fs::create_directories(r);
  overwrite(r / ".errors.csv.tmp.4242", "half a file");  // as OutputFiles names them
  overwrite(r / "notes.tmp.txt", "the user's");
  REQUIRE(sinsim("run '" + sc.string() + "' -o '" + r.string() + "'", tmp).exitCode == 0);
  CHECK_FALSE(fs::exists(r / ".errors.csv.tmp.4242"));
  CHECK(fs::exists(r / "notes.tmp.txt"));
  CHECK(fs::exists(r / "errors.csv"));

  const fs::path m = tmp / "m";
  const std::string args = "mc '" + sc.string() + "' --runs 16 --threads 1" +
                           model("adis16355-gm.yaml") + " -o '" + m.string() + "'";
  CHECK(sinsim(args + " --stop-after 8", tmp).exitCode == 130);
  const auto c = chunks(m);
  REQUIRE(c.size() == 1);
  const fs::path stale = c[0].parent_path() / "r000000008.bin.tmp.4242.77";  // as the store names them
  overwrite(stale, "half a chunk");
  REQUIRE(sinsim(args + " --resume", tmp).exitCode == 0);
  CHECK_FALSE(fs::exists(stale));
  CHECK(chunks(m).size() == 2);
  fs::remove_all(tmp);
}

TEST_CASE("sinsim run and mc: a file size limit (ulimit -f) gives a message naming the file") {
  const fs::path tmp = tempDir("fsize");
  const fs::path sc = writeScenario(tmp);
  // Limits in blocks of 512 bytes (POSIX sh): a checkpoint of 8 runs × 31 epochs × 36 bytes
  // (8.9 kB) exceeds 8 blocks; truth.csv (31 rows of ~110 bytes) exceeds 2.
  auto limited = [&](const std::string& blocks, const std::string& args) {
    const std::string cmd = "ulimit -f " + blocks + "; exec '" + sinsimPath() + "' " + args + " > '" +
                            (tmp / "stdout").string() + "' 2> '" + (tmp / "stderr").string() + "'";
    const int st = std::system(("sh -c \"" + cmd + "\"").c_str());
    Result r;
    r.exitCode = WIFEXITED(st) ? WEXITSTATUS(st) : -1;  // -1: killed by a signal
    r.err = slurp(tmp / "stderr");
    return r;
  };
  const Result mc = limited("8", "mc '" + sc.string() + "' --runs 8 --threads 1" +
                            model("adis16355-gm.yaml") + " -o '" + (tmp / "m").string() + "'");
  INFO(mc.err);
  CHECK(mc.exitCode == 1);
  CHECK(mc.err.find("r000000000.bin") != std::string::npos);
  CHECK(mc.err.find("File too large") != std::string::npos);
  CHECK(mc.err.find("ulimit -f") != std::string::npos);
  const Result run = limited("2", "run '" + sc.string() + "' -o '" + (tmp / "r").string() + "'");
  INFO(run.err);
  CHECK(run.exitCode == 1);
  CHECK(run.err.find("truth.csv: File too large") != std::string::npos);
  CHECK_FALSE(fs::exists(tmp / "r"));  // no half-written output: the folder it made is gone
  fs::remove_all(tmp);
}

TEST_CASE("sinsim mc: errors no float holds stop the batch, and its new folder is removed") {
  // White noise of 1e11 rad/sqrt(s) (inside the model limit of 1e12): the navigation error
  // passes 3.4e38 m within a second. Before, the batch wrote "CEP -nan" and "-nan" rows, exit 0.
  const fs::path tmp = tempDir("nonfinite");
  const fs::path sc = writeScenario(tmp);
  std::ofstream(tmp / "huge.yaml") << "gyro: {all: [{type: white, density: 1e11 rad/sqrt(s)}]}\n";
  for (const char* threads : {"1", "2"}) {
    const Result r = sinsim("mc '" + sc.string() + "' --runs 4 --threads " + threads + " --model '" +
                                (tmp / "huge.yaml").string() + "' -o '" + (tmp / "m").string() + "'",
                            tmp);
    INFO(r.err);
    CHECK(r.exitCode == 1);
    CHECK(r.err.find("the navigation error became non-finite at t = ") != std::string::npos);
    CHECK_FALSE(fs::exists(tmp / "m"));  // no checkpoint folder: the rerun needs no --resume
  }
  // A folder the user made keeps what it held.
  fs::create_directories(tmp / "mine");
  std::ofstream(tmp / "mine" / "notes.txt") << "mine\n";
  const Result r = sinsim("mc '" + sc.string() + "' --runs 4 --threads 1 --model '" + (tmp / "huge.yaml").string() +
                              "' -o '" + (tmp / "mine").string() + "'",
                          tmp);
  CHECK(r.exitCode == 1);
  CHECK(slurp(tmp / "mine" / "notes.txt") == "mine\n");
  CHECK_FALSE(fs::exists(tmp / "mine" / "runs"));
  fs::remove_all(tmp);
}
