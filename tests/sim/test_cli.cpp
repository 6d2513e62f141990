// `sinsim run` as a user calls it: exit codes, messages naming file, line and key path, and no
// output files for bad input.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace {

struct Result {
  int exitCode = -1;
  std::string out, err;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Runs `sinsim <args>` in folder `cwd`, capturing stdout and stderr.
Result sinsim(const std::string& args, const fs::path& tmp, const std::string& cwd = ".") {
  const std::string cmd = "cd '" + cwd + "' && '" + std::string(SINSIM_BINARY_DIR) +
                          "/sinsim' " + args + " > '" + (tmp / "stdout").string() + "' 2> '" +
                          (tmp / "stderr").string() + "'";
  const int status = std::system(cmd.c_str());
  Result r;
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(tmp / "stdout");
  r.err = slurp(tmp / "stderr");
  return r;
}

fs::path tempDir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() /
                     ("sinsim_test_cli_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

const std::string kFixtures = std::string(SINSIM_SOURCE_DIR) + "/tests/sim/fixtures/";

}  // namespace

TEST_CASE("sinsim run: bad scenarios exit 1 naming file, line and key, and write nothing") {
  const fs::path tmp = tempDir("bad");
  struct Case {
    const char* file;
    const char* located;  // "<line>: <key path>: <start of the message>"
  };
  const Case cases[] = {
      {"bad_unknown_key.yaml", ":6: start.headin: unknown key (did you mean \"heading\"?"},
      {"bad_missing_start.yaml", ":2: start: missing key"},
      {"bad_negative_duration.yaml", ":6: segments[1].duration: expected a positive duration"},
      {"bad_unit.yaml", ":6: segments[0].speed: expected a value in m/s"},
      {"bad_segment_type.yaml", ":5: segments[1].type: unknown segment type \"hover\" (known: "},
  };
  for (const Case& c : cases) {
    const fs::path out = tmp / "out";
    const Result r = sinsim("run '" + kFixtures + c.file + "' -o '" + out.string() + "'", tmp);
    INFO(c.file << "\nstderr: " << r.err);
    CHECK(r.exitCode == 1);
    CHECK(r.err.find(kFixtures + c.file + c.located) != std::string::npos);
    CHECK_FALSE(fs::exists(out));
  }
  fs::remove_all(tmp);
}

TEST_CASE("sinsim run and mc: a flight over the pole stops where it reaches 89 deg, naming the file") {
  // The start is inside ±89°; the motion leaves it after 1.1° of northing (the NED frame is
  // singular at the poles): 250 m/s north from 88.9° reaches 89° at about 44.7 s.
  const fs::path tmp = tempDir("pole");
  const fs::path scenario = tmp / "pole.yaml";
  std::ofstream(scenario) << R"(name: pole
start: {latitude: 88.9 deg, longitude: 10 deg, height: 10000 m, heading: 0 deg, speed: 250 m/s}
imu_rate: 100 Hz
output_rate: 1 Hz
vertical: held
errors: none
segments:
  - {type: cruise, duration: 120 s}
)";
  for (const std::string command : {"run", "mc"}) {
    const fs::path out = tmp / ("out-" + command);
    const Result r = sinsim(command + " '" + scenario.string() + "' -o '" + out.string() + "'" +
                                (command == "mc" ? " --runs 2 --model none" : ""),
                            tmp);
    INFO(command << " stderr: " << r.err);
    CHECK(r.exitCode == 1);
    CHECK(r.err.find(scenario.string() + ": the trajectory reaches latitude 89") != std::string::npos);
    CHECK(r.err.find(" s: the navigation frame (NED) is singular at the poles") != std::string::npos);
    CHECK_FALSE(fs::exists(out));
  }
  fs::remove_all(tmp);
}

TEST_CASE("sinsim run: a good scenario, overrides, and a bad model or option") {
  const fs::path tmp = tempDir("good");
  const std::string scenario = "'" + kFixtures + "good_short.yaml'";
  Result r = sinsim("run " + scenario + " -o '" + (tmp / "a").string() + "' --seed 5 --model none",
                    tmp);
  INFO("stdout: " << r.out << "\nstderr: " << r.err);
  CHECK(r.exitCode == 0);
  CHECK(r.out.find((tmp / "a").string()) != std::string::npos);
  CHECK(r.out.find("final horizontal error") != std::string::npos);
  for (const char* f : {"truth.csv", "nav.csv", "errors.csv", "summary.json"})
    CHECK(fs::is_regular_file(tmp / "a" / f));
  CHECK(slurp(tmp / "a" / "summary.json").find("\"seed\": 5") != std::string::npos);

  r = sinsim("run " + scenario + " -o '" + (tmp / "b").string() + "' --model no_such.yaml", tmp);
  CHECK(r.exitCode == 1);
  CHECK(r.err.find("no_such.yaml") != std::string::npos);
  CHECK_FALSE(fs::exists(tmp / "b"));

  r = sinsim("run " + scenario + " --seed minus-one", tmp);
  CHECK(r.exitCode == 2);  // command-line error (CLI11)
  // An option value sinsim reads itself is a bad command line too (it exited 1).
  for (const char* bad : {"5 m", "-1 s", "nan"}) {
    r = sinsim("run " + scenario + " --bias-window '" + bad + "' -o '" + (tmp / "bw").string() + "'", tmp);
    INFO(bad << ": " << r.err);
    CHECK(r.exitCode == 2);
    CHECK(r.err.find("--bias-window: ") != std::string::npos);
    CHECK_FALSE(fs::exists(tmp / "bw"));
  }

  // A negative count is no huge one: CLI11 alone read "-5" as 2^64 - 5.
  for (const char* args : {"mc SC --runs -5", "mc SC --runs=-5", "mc SC --runs 2 --stop-after -1",
                           "diagnose rec.csv --model m.yaml --realisations -4",
                           "diagnose rec.csv --model m.yaml --nav-runs=-3"}) {
    std::string a = args;
    const std::size_t at = a.find("SC");
    if (at != std::string::npos) a.replace(at, 2, scenario);
    r = sinsim(a + " -o '" + (tmp / "c").string() + "'", tmp);
    INFO(a << "\nstderr: " << r.err);
    CHECK(r.exitCode == 2);
    CHECK(r.err.find("expected a whole number (digits only), got \"-") != std::string::npos);
    CHECK(r.err.find("18446744073709551611") == std::string::npos);
    CHECK_FALSE(fs::exists(tmp / "c"));
  }
  fs::remove_all(tmp);
}

TEST_CASE("sinsim run without arguments runs the default scenario into out/<name>") {
  // From a folder that is not the checkout: the default scenario is found via the source tree.
  const fs::path tmp = tempDir("default");
  const Result r = sinsim("run", tmp, tmp.string());
  INFO("stdout: " << r.out << "\nstderr: " << r.err);
  CHECK(r.exitCode == 0);
  CHECK(r.out.find("scenarios/car.yaml") != std::string::npos);
  CHECK(r.out.find("car: ") != std::string::npos);
  CHECK(fs::is_regular_file(tmp / "out" / "car" / "errors.csv"));
  fs::remove_all(tmp);
}

TEST_CASE("sinsim run --html: a report with the track, the errors and the attitude errors") {
  const fs::path tmp = tempDir("html");
  const std::string scenario = "'" + kFixtures + "good_short.yaml'";
  const std::string model = "'" + std::string(SINSIM_SOURCE_DIR) + "/scenarios/adis16355-gm.yaml'";
  Result r = sinsim("run " + scenario + " -o '" + (tmp / "a").string() + "' --model " + model +
                        " --html '" + (tmp / "a" / "report.html").string() + "'",
                    tmp);
  INFO("stdout: " << r.out << "\nstderr: " << r.err);
  REQUIRE(r.exitCode == 0);
  CHECK(r.out.find("report: " + (tmp / "a" / "report.html").string()) != std::string::npos);
  const std::string html = slurp(tmp / "a" / "report.html");
  for (const char* s : {"Track: truth and navigation", "Position error (navigation − truth)",
                        "Attitude error (navigation − truth)", "After ", " travelled, the navigation is "})
    CHECK(html.find(s) != std::string::npos);
  std::size_t svgs = 0;
  for (std::size_t at = html.find("<svg"); at != std::string::npos; at = html.find("<svg", at + 1))
    ++svgs;
  CHECK(svgs >= 3);
  CHECK(html.find("e+0") == std::string::npos);  // lengths in mm/m/km, not exponents

  // A report into a missing folder: refused before anything is written.
  r = sinsim("run " + scenario + " -o '" + (tmp / "b").string() + "' --html '" +
                 (tmp / "nowhere" / "r.html").string() + "'",
             tmp);
  CHECK(r.exitCode == 1);
  CHECK(r.err.find("nowhere") != std::string::npos);
  CHECK_FALSE(fs::exists(tmp / "b"));

  // A report over the run's own truth.csv (it was written over it, exit 0), or onto a folder or an
  // input (refused after the run, its outputs left behind): refused before, no folder left.
  for (const std::string& page : {(tmp / "c" / "truth.csv").string(), tmp.string(),
                                   kFixtures + "good_short.yaml"}) {
    r = sinsim("run " + scenario + " -o '" + (tmp / "c").string() + "' --html '" + page + "'", tmp);
    INFO(page << "\nstderr: " << r.err);
    CHECK(r.exitCode == 1);
    CHECK(r.err.find(page) != std::string::npos);
    CHECK_FALSE(fs::exists(tmp / "c"));
  }
  fs::remove_all(tmp);
}

TEST_CASE("sinsim run: an earlier run's imu.csv in the folder is removed, and a duration between "
          "IMU samples is warned") {
  const fs::path tmp = tempDir("stale");
  const std::string scenario = "'" + kFixtures + "good_short.yaml'";
  Result r = sinsim("run " + scenario + " -o '" + (tmp / "a").string() + "' --imu", tmp);
  REQUIRE(r.exitCode == 0);
  REQUIRE(fs::exists(tmp / "a" / "imu.csv"));
  r = sinsim("run " + scenario + " -o '" + (tmp / "a").string() + "'", tmp);
  INFO("stderr: " << r.err);
  CHECK(r.exitCode == 0);
  CHECK(r.err.find("imu.csv in " + (tmp / "a").string() + " was an earlier run's") != std::string::npos);
  CHECK_FALSE(fs::exists(tmp / "a" / "imu.csv"));
  CHECK(fs::exists(tmp / "a" / "truth.csv"));

  {
    std::ofstream s(tmp / "odd.yaml");
    s << "name: odd\nstart: {latitude: 45 deg, longitude: 7 deg}\nimu_rate: 100 Hz\noutput_rate: 100 Hz\n"
         "segments:\n  - {type: accelerate, speed: 10 m/s, duration: 1.005 s}\n";
  }
  r = sinsim("run odd.yaml -o b", tmp, tmp.string());
  INFO("stderr: " << r.err);
  CHECK(r.exitCode == 0);
  CHECK(r.err.find("the segments add up to 1.005 s, not a whole number of IMU intervals (0.01 s): "
                   "the run ends at the nearest sample, 1 s") != std::string::npos);
  fs::remove_all(tmp);
}

TEST_CASE("sinsim diagnose --nav: the verdict on the terminal, in the JSON and the page, refused "
          "for an aided scenario with no output written") {
  const fs::path tmp = tempDir("diagnose_nav");
  {
    std::ofstream m(tmp / "m.yaml");
    m << "gyro:\n  all: [{type: white, density: 1e-4 rad/sqrt(s)}]\n"
         "accel:\n  all: [{type: white, density: 0.002 m/s/sqrt(s)}]\n";
    std::ofstream s(tmp / "rest.yaml");
    s << "name: rest\nstart: {latitude: 45 deg, longitude: 7 deg, height: 250 m, heading: 0 deg}\n"
         "imu_rate: 50 Hz\noutput_rate: 1 Hz\nvertical: held\n"
         "segments:\n  - {type: static, duration: 120 s}\n";
  }
  Result r = sinsim("synth m.yaml --rate 50 --duration \"3 min\" --seed 5 -o rec.csv", tmp, tmp.string());
  REQUIRE(r.exitCode == 0);
  r = sinsim("diagnose rec.csv --model m.yaml --nav rest.yaml --nav-runs 16 --json d.json --html d.html",
             tmp, tmp.string());
  INFO("stdout: " << r.out << "\nstderr: " << r.err);
  REQUIRE(r.exitCode == 0);
  CHECK(r.out.find("Navigation verdict along rest") != std::string::npos);
  CHECK(r.out.find("driven by gyro white") != std::string::npos);
  CHECK(slurp(tmp / "d.json").find("\"navigation\"") != std::string::npos);
  CHECK(slurp(tmp / "d.html").find("Navigation verdict along rest") != std::string::npos);

  // Without --nav the JSON has no verdict (and the diagnosis runs no navigation).
  r = sinsim("diagnose rec.csv --model m.yaml --json plain.json", tmp, tmp.string());
  REQUIRE(r.exitCode == 0);
  CHECK(slurp(tmp / "plain.json").find("\"navigation\"") == std::string::npos);

  // An aided scenario: exit 1, the scenario named, no JSON written.
  r = sinsim("diagnose rec.csv --model m.yaml --nav '" + std::string(SINSIM_SOURCE_DIR) +
                 "/scenarios/car-10min-aided.yaml' --json aided.json",
             tmp, tmp.string());
  CHECK(r.exitCode == 1);
  CHECK(r.err.find("aiding keys") != std::string::npos);
  CHECK_FALSE(fs::exists(tmp / "aided.json"));

  // A bias window longer than the replay: the record and diagnose's own option named (it said
  // run's --bias-window and no file); mc --measured names its option and the record too.
  r = sinsim("diagnose rec.csv --model m.yaml --nav rest.yaml --nav-bias-window \"5 min\" --json long.json",
             tmp, tmp.string());
  CHECK(r.exitCode == 1);
  CHECK(r.err.find("rec.csv: the bias window (--nav-bias-window) of 300 s is longer than the record used (120 s")
        != std::string::npos);
  CHECK_FALSE(fs::exists(tmp / "long.json"));
  r = sinsim("mc --measured rec.csv --model m.yaml --runs 2 --bias-window \"5 min\" -o mcm", tmp, tmp.string());
  CHECK(r.exitCode == 1);
  CHECK(r.err.find("rec.csv: the bias window (--bias-window) of 300 s is longer than the record used (180 s)")
        != std::string::npos);
  CHECK_FALSE(fs::exists(tmp / "mcm"));
  fs::remove_all(tmp);
}
