// `sinsim analyze` end to end on a record with known statistics: white noise of per-sample σ at
// rate fs has Allan deviation σ/sqrt(fs·τ) (IEEE Std 952-1997 Annex C: N/sqrt(τ), N = σ/sqrt(fs))
// and a flat one-sided PSD 2σ²/fs. Bad input: exit 1, message with file and line, no output.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "test_support.hpp"

namespace fs = std::filesystem;

using sinsim::test::slurp;

TEST_CASE("sinsim analyze: white noise gives the closed-form Allan deviation and PSD", "[cli]") {
  const fs::path dir = sinsim::test::freshTempDir("sinsim_test_analyze_cli");
  const double fs_hz = 100.0, sigma = 0.1;  // [Hz], [rad/s] per sample
  const int n = 60000;                      // 10 min
  {
    std::ofstream f(dir / "white.csv");
    f << "gx\n";
    std::mt19937_64 rng(11);
    std::normal_distribution<double> g(0.0, sigma);
    f.precision(17);
    for (int i = 0; i < n; ++i) f << g(rng) << "\n";
  }
  const fs::path err = dir / "stderr.txt";
  const fs::path js = dir / "a.json", html = dir / "a.html";
  REQUIRE(sinsim::test::runSinsim("analyze " + (dir / "white.csv").string() + " --rate 100 --json-full --json " + js.string() +
                  " --html " + html.string(),
              err) == 0);
  const nlohmann::json j = nlohmann::json::parse(slurp(js));
  const auto& allan = j["channels"]["gx"]["allan"];
  bool sawOneSecond = false;
  for (std::size_t i = 0; i < allan["tau_s"].size(); ++i) {
    const double tau = allan["tau_s"][i];
    if (std::abs(tau - 1.28) > 1e-9) continue;  // octave grid: m = 128
    sawOneSecond = true;
    const double truth = sigma / std::sqrt(fs_hz * tau);
    const double edf = allan["edf"][i];
    // The estimate's relative sd is ≈ 1/sqrt(2·edf) (χ² with edf dof); 5 sd cannot fail by chance
    // (p < 1e-6) and still catches a wrong √τ or rate scaling (a factor ≥ 1.4).
    CHECK(std::abs(double(allan["adev"][i]) / truth - 1.0) < 5.0 / std::sqrt(2.0 * edf));
  }
  CHECK(sawOneSecond);
  const auto& psd = j["channels"]["gx"]["psd"];
  double mean = 0.0;
  std::size_t bins = 0;
  for (std::size_t k = 1; k + 1 < psd["psd"].size(); ++k, ++bins) mean += double(psd["psd"][k]);
  mean /= double(bins);
  // Mean over ~2000 bins of ~28 averaged segments: relative sd well under 1 %; 3 % is > 5 sd.
  CHECK(mean == Approx(2.0 * sigma * sigma / fs_hz).epsilon(0.03));
  const std::string page = slurp(html);
  CHECK(page.find("<svg") != std::string::npos);
  CHECK(page.find("Allan deviation gx") != std::string::npos);
  // Datasheet units and the noise terms read off: white noise of sigma = 0.1 rad/s at 100 Hz is
  // N = sigma/sqrt(fs) = 0.01 rad/sqrt(s) = 34.38 deg/sqrt(h) (x 180/pi x 60), read at the
  // shortest tau to ~0.3 % (edf ~ 60000): "34.3" to "34.5".
  CHECK(page.find("σ(τ) [deg/h]") != std::string::npos);
  CHECK(page.find("white noise N = 34.") != std::string::npos);
  CHECK(page.find("deg/sqrt(h) (ARW)") != std::string::npos);

  // By default the JSON is compact: every ACF lag and PSD bin below index 64, then about 32 per
  // decade, and the last one.
  const fs::path js3 = dir / "c.json";
  REQUIRE(sinsim::test::runSinsim("analyze " + (dir / "white.csv").string() + " --rate 100 --json " + js3.string(),
                                  err) == 0);
  const nlohmann::json c = nlohmann::json::parse(slurp(js3));
  for (const char* part : {"acf", "psd"}) {
    const auto& full = j["channels"]["gx"][part][std::string(part) == "acf" ? "lag_s" : "f_hz"];
    const auto& kept = c["channels"]["gx"][part][std::string(part) == "acf" ? "lag_s" : "f_hz"];
    INFO(part << ": " << full.size() << " values, " << kept.size() << " kept");
    REQUIRE(full.size() > 200);
    CHECK(kept.size() <= 64 + 32.0 * std::log10(double(full.size()) / 64.0) + 2);
    CHECK(kept.size() >= 64 + 32.0 * std::log10(double(full.size()) / 64.0) - 2);
    CHECK(double(kept.back()) == double(full.back()));
    CHECK(double(kept[63]) == double(full[63]));
  }

  // Bad input: text in data line 3 (file line 4) -> exit 1, file:line named, no output written.
  {
    std::ofstream f(dir / "bad.csv");
    f << "gx\n0.1\n0.2\nabc\n0.3\n";
  }
  const fs::path js2 = dir / "b.json", html2 = dir / "b.html";
  CHECK(sinsim::test::runSinsim("analyze " + (dir / "bad.csv").string() + " --rate 100 --json " + js2.string() +
                " --html " + html2.string(),
            err) == 1);
  CHECK(slurp(err).find("bad.csv:4") != std::string::npos);
  CHECK_FALSE(fs::exists(js2));
  CHECK_FALSE(fs::exists(html2));
  // No output file asked for: a summary on the terminal, in datasheet units. White noise of
  // per-sample sigma at fs: N = sigma / sqrt(fs) [rad/sqrt(s)] = that * 180/pi * 60 deg/sqrt(h),
  // read at tau = 10 ms from ~60000 terms (relative sd ~0.4 %; 3 % is > 5 sd).
  const fs::path out = dir / "summary.txt";
  REQUIRE(std::system((std::string(SINSIM_BINARY_DIR) + "/sinsim analyze " + (dir / "white.csv").string() +
                       " --rate 100 > " + out.string() + " 2> " + err.string())
                          .c_str()) == 0);
  const std::string summary = slurp(out);
  const auto row = summary.find("\ngx ");
  REQUIRE(row != std::string::npos);
  std::istringstream cells(summary.substr(row + 1));
  std::string name, meanV, meanU, sdV, sdU, nV, nU;
  cells >> name >> meanV >> meanU >> sdV >> sdU >> nV >> nU;
  CHECK(nU == "deg/sqrt(h)");
  CHECK(std::stod(nV) == Approx(sigma / std::sqrt(fs_hz) * 180.0 / M_PI * 60.0).epsilon(0.03));
  CHECK(std::stod(sdV) == Approx(sigma * 180.0 / M_PI * 3600.0).epsilon(0.03));
  fs::remove_all(dir);
}
