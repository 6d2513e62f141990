// `sinsim fit` end to end: a record written by `sinsim synth` -> model file -> read back by
// ImuErrorModel::load, used by `sinsim synth` and `sinsim run --model`; bad input -> exit 1 with
// file and line, and no model file.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "errormodels/imu_model.hpp"

#include "test_support.hpp"

namespace fs = std::filesystem;

using sinsim::test::slurp;

TEST_CASE("sinsim fit: synth -> fit -> load, synth and run with the model", "[identify][cli]") {
  const fs::path dir = sinsim::test::freshTempDir("sinsim_test_identify_cli");
  const fs::path err = dir / "stderr.txt";
  const std::string preset = std::string(SINSIM_SOURCE_DIR) + "/scenarios/adis16355-ar5.yaml";
  REQUIRE(sinsim::test::runSinsim("synth " + preset + " --rate 1000 --duration 120 --seed 3 -o " + (dir / "s.csv").string(), err) == 0);
  const fs::path model = dir / "m.yaml";
  INFO(slurp(err));
  REQUIRE(sinsim::test::runSinsim("fit " + (dir / "s.csv").string() + " --axes gx,ax --max-order 8 -o " + model.string(), err) == 0);
  REQUIRE(fs::exists(model));
  const std::string text = slurp(model);
  CHECK(text.find("# data: ") != std::string::npos);        // provenance
  CHECK(text.find("order by mdl (AIC") != std::string::npos);  // how the AR order was chosen
  CHECK(text.find("type: ar") != std::string::npos);
  const auto m = sinsim::errormodels::ImuErrorModel::load(model.string());
  CHECK_FALSE(m.empty());
  CHECK(sinsim::test::runSinsim("synth " + model.string() + " --rate 1000 --duration 2 -o " + (dir / "s2.csv").string(), err) == 0);
  CHECK(sinsim::test::runSinsim("run " + std::string(SINSIM_SOURCE_DIR) + "/scenarios/static.yaml --model " +
                model.string() + " -o " + (dir / "run").string(), err) == 0);
  CHECK(fs::exists(dir / "run" / "summary.json"));

  // Bad input: a NaN in data line 5 (file line 6 after the header) -> exit 1, message with
  // file:line, no model file (and no temporary left).
  {
    std::ofstream f(dir / "bad.csv");
    f << "t,gx\n0.01,1\n0.02,2\n0.03,3\n0.04,4\n0.05,nan\n0.06,6\n";
  }
  const fs::path badModel = dir / "bad.yaml";
  CHECK(sinsim::test::runSinsim("fit " + (dir / "bad.csv").string() + " -o " + badModel.string(), err) == 1);
  const std::string msg = slurp(err);
  INFO(msg);
  CHECK(msg.find("bad.csv:6") != std::string::npos);
  CHECK_FALSE(fs::exists(badModel));
  CHECK_FALSE(fs::exists(badModel.string() + ".tmp"));
  // Bad options -> exit 1 before anything is read or written.
  CHECK(sinsim::test::runSinsim("fit " + (dir / "s.csv").string() + " --kind arma -o " + badModel.string(), err) == 1);
  CHECK(slurp(err).find("known: ar, gm, allan, auto") != std::string::npos);
  CHECK_FALSE(fs::exists(badModel));
  CHECK(sinsim::test::runSinsim("fit " + (dir / "s.csv").string() + " --lines all -o " + badModel.string(), err) == 1);
  CHECK(slurp(err).find("--lines: expected fit or warn, got \"all\"") != std::string::npos);
  CHECK_FALSE(fs::exists(badModel));
  // --skip auto is fit's: fit takes it (a record without a settling: nothing more skipped), the
  // other commands refuse it with what to give instead.
  CHECK(sinsim::test::runSinsim("fit " + (dir / "s.csv").string() + " --axes gx --kind gm --skip auto -o " +
                                    (dir / "auto.yaml").string(), err) == 0);
  CHECK(slurp(err).find("--skip auto: no channel starts with a settling") != std::string::npos);
  CHECK(sinsim::test::runSinsim("analyze " + (dir / "s.csv").string() + " --skip auto", err) == 1);
  CHECK(slurp(err).find("--skip auto: only `sinsim fit` finds a settling to skip") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("sinsim fit --skip: the model file says what was skipped", "[identify][cli]") {
  // The CLI cuts the skip in the record reader, which the model's notes did not see: its file said
  // "samples used: 48000" where the Python module's said "(first 12000 samples = 120 s skipped)".
  const fs::path dir = sinsim::test::freshTempDir("sinsim_test_fit_skip");
  const fs::path err = dir / "stderr.txt";
  const std::string preset = std::string(SINSIM_SOURCE_DIR) + "/scenarios/adis16355-ar5.yaml";
  REQUIRE(sinsim::test::runSinsim("synth " + preset + " --rate 100 --duration 600 --seed 3 -o " + (dir / "s.csv").string(), err) == 0);
  REQUIRE(sinsim::test::runSinsim("fit " + (dir / "s.csv").string() + " --axes gx --kind ar --skip \"2 min\" -o " +
                                      (dir / "m.yaml").string(), err) == 0);
  CHECK_THAT(slurp(dir / "m.yaml"), Catch::Contains("samples used: 48000 (first 12000 samples = 120 s skipped)"));
}

TEST_CASE("analyze and diagnose: the record's warnings stand in their JSON and pages", "[identify][cli]") {
  // A gap read with --allow-irregular-time was warned on stderr only: analyze's page and
  // diagnose's JSON and page did not say that the samples either side of it were joined.
  const fs::path dir = sinsim::test::freshTempDir("sinsim_test_record_warnings");
  std::mt19937_64 rng(5);
  std::normal_distribution<double> n(0.0, 1e-3);
  std::ofstream rec(dir / "gap.csv");
  rec << "t,gx\n";
  for (int k = 0; k < 6000; ++k)
    if (k < 3000 || k >= 3050) rec << k * 0.01 << "," << n(rng) << "\n";
  rec.close();
  std::ofstream(dir / "m.yaml") << "gyro:\n  x: [{type: white, density: 1e-4 rad/s/sqrt(Hz)}]\n";
  const std::string r = (dir / "gap.csv").string(), err = (dir / "err").string();
  REQUIRE(sinsim::test::runSinsim("analyze " + r + " --allow-irregular-time --json " + (dir / "a.json").string() +
                                      " --html " + (dir / "a.html").string(), err) == 0);
  REQUIRE(sinsim::test::runSinsim("diagnose " + r + " --allow-irregular-time --model " + (dir / "m.yaml").string() +
                                      " --realisations 8 --json " + (dir / "d.json").string() + " --html " +
                                      (dir / "d.html").string(), err) == 0);
  const std::string said = "1 irregular time step(s) (1 gap(s)), the first at line 3002";
  for (const char* f : {"a.json", "a.html", "d.json", "d.html"}) {
    INFO(f);
    CHECK_THAT(slurp(dir / f), Catch::Contains(said));
  }
  CHECK_THAT(slurp(dir / "d.html"), Catch::Contains("Record warning: " + said));
}
