// `mpirun -np 2 sinsim mc` (MPI build only): the runs are split across two ranks and the output
// files are bit-identical to a single-process run; an interrupted MPI batch resumes without MPI.
#include <catch2/catch.hpp>

#include "helpers.hpp"

using namespace mctest;

namespace {

const char* kScenario = R"(name: mpi-short
start: {latitude: 48 deg, longitude: 11 deg, height: 500 m, heading: 90 deg}
imu_rate: 100 Hz
output_rate: 1 Hz
vertical: held
segments:
  - {type: static, duration: 5 s}
  - {type: accelerate, speed: 15 m/s, duration: 8 s}
  - {type: turn, heading_change: 90 deg, duration: 8 s}
)";

void requireSameFolders(const fs::path& a, const fs::path& b) {
  const auto fa = listFiles(a), fb = listFiles(b);
  REQUIRE(fa == fb);
  REQUIRE(!fa.empty());
  for (const auto& f : fa) {
    INFO(f);
    CHECK(slurp(a / f) == slurp(b / f));
  }
}

}  // namespace

TEST_CASE("mpirun -np 2 sinsim mc writes the files of a single-process run") {
  const fs::path tmp = tempDir("mpi");
  const fs::path sc = tmp / "short.yaml";
  std::ofstream(sc) << kScenario;
  const std::string args = " mc '" + sc.string() + "' --runs 40 --seed 3 --budget --times 10,21 --model '" +
                           sourceDir() + "/scenarios/adis16355-ar5.yaml' --model '" + sourceDir() +
                           "/scenarios/adis16355-gm.yaml'";
  const Result single = sinsim(args + " --threads 2 -o '" + (tmp / "single").string() + "'", tmp);
  INFO(single.err);
  REQUIRE(single.exitCode == 0);
  // As root Open MPI needs --allow-run-as-root; --oversubscribe lets 2 ranks start on any machine.
  const std::string mpi = std::string("'") + SINSIM_MPIEXEC + "' --allow-run-as-root --oversubscribe -np 2 '" +
                          sinsimPath() + "'" + args + " -o '" + (tmp / "mpi").string() + "' > '" +
                          (tmp / "mpi.out").string() + "' 2> '" + (tmp / "mpi.err").string() + "'";
  const int status = std::system(mpi.c_str());
  INFO(slurp(tmp / "mpi.err"));
  REQUIRE(WIFEXITED(status));
  REQUIRE(WEXITSTATUS(status) == 0);
  CHECK(slurp(tmp / "mpi.out").find("2 MPI ranks") != std::string::npos);
  requireSameFolders(tmp / "single", tmp / "mpi");
  fs::remove_all(tmp);
}
