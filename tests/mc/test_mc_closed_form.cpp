// Monte Carlo variances against the closed forms of a stationary INS driven by white noise, for
// t much shorter than the Schuler period (84 min), within the χ² bound of N runs.
//
// Accelerometer white noise of density q^(1/2) on the north axis: δv_N = ∫w dt, so
//   σ_v²(t) = q t,   σ_p²(t) = q t³/3                          (random walk and its integral)
// Gyro white noise of density n on the north axis (angle random walk): the tilt about north
// φ_N = ∫w dt and the east velocity error δv̇_E = −g φ_N (the level error projects gravity), so
//   σ_roll²(t) = n² t,   σ_vE²(t) = g² n² t³/3.
// The neglected couplings scale with (ω_s t)² = (t/806 s)² ≤ 2.2 % at t = 120 s for the
// Schuler feedback in σ_vE, which enters the variance at ≈ (ω_s t)²/5 ≈ 0.5 %, and the trapezoid
// position sum differs from the continuous integral by 1/(4n²) relative — both far inside the
// χ² intervals below.
//
// Bound: with N runs, (N − 1) s²/σ² ~ χ²(N − 1) for Gaussian errors (the errors are linear in the
// Gaussian noise). Each check asserts the 99.9 % two-sided interval
// [χ²_{0.0005}(N−1), χ²_{0.9995}(N−1)]/(N − 1) for s²/σ² — for N = 1000 that is [0.857, 1.154].
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "errormodels/stats/special.hpp"
#include "helpers.hpp"
#include "sim/montecarlo.hpp"
#include "sim/scenario.hpp"

using namespace sinsim;

namespace {

const char* kStatic = R"(name: chi2
start: {latitude: 45 deg, longitude: 7 deg, height: 250 m, heading: 0 deg}
imu_rate: 100 Hz
output_rate: 1 Hz
vertical: held
segments:
  - {type: static, duration: 120 s}
)";

double sampleVariance(const std::vector<float>& errors, std::uint64_t runs, std::size_t epochs,
                      std::size_t e, int field) {
  const std::size_t perRun = epochs * sim::kErrorFields;
  double s = 0, s2 = 0;
  for (std::uint64_t k = 0; k < runs; ++k) s += errors[k * perRun + e * sim::kErrorFields + field];
  const double mean = s / double(runs);
  for (std::uint64_t k = 0; k < runs; ++k) {
    const double d = errors[k * perRun + e * sim::kErrorFields + field] - mean;
    s2 += d * d;
  }
  return s2 / double(runs - 1);
}

}  // namespace

TEST_CASE("white accelerometer and gyro noise: Monte Carlo variances inside the 99.9 % chi2 bound") {
  const auto tmp = mctest::tempDir("chi2");
  const sim::Scenario sc = sim::parseScenario(kStatic, "chi2.yaml");
  const sim::Reference ref = sim::buildReference(sc);
  const double qa = 0.02 * 0.02;   // (m/s/√s)²: 0.02 m/s/√s = 1.2 m/s/√h
  const double ng = 1e-4;          // rad/√s = 0.34 deg/√h
  std::vector<sim::McModel> models{
      {"accel-white", errormodels::ImuErrorModel::fromString(
                          "accel:\n  x: [{type: white, density: 0.02 m/s/sqrt(s)}]\n", "a.yaml"),
       "a"},
      {"gyro-white", errormodels::ImuErrorModel::fromString(
                         "gyro:\n  x: [{type: white, density: 1e-4 rad/sqrt(s)}]\n", "g.yaml"),
       "g"}};
  sim::McOptions opt;
  opt.runs = 1000;
  opt.seed = 20240601;
  opt.outDir = (tmp / "out").string();
  const sim::McResult r = sim::runMonteCarlo(ref, models, opt);
  REQUIRE(r.complete);
  REQUIRE(r.errors.size() == 2);

  const double N = double(opt.runs);
  const double lo = errormodels::chiSquareQuantile(0.0005, N - 1) / (N - 1);
  const double hi = errormodels::chiSquareQuantile(0.9995, N - 1) / (N - 1);
  const double g = 9.806;  // normal gravity at 45° N, 250 m [m/s²] (9.8054; 0.01 % is immaterial)
  std::printf("chi2 bound for s^2/sigma^2, N = %.0f, 99.9 %% two-sided: [%.4f, %.4f]\n", N, lo, hi);
  for (double t : {30.0, 60.0, 120.0}) {
    const std::size_t e = std::size_t(t);  // 1 Hz epochs
    const double rv = sampleVariance(r.errors[0], opt.runs, ref.epochs(), e, sim::kVn) / (qa * t);
    const double rp =
        sampleVariance(r.errors[0], opt.runs, ref.epochs(), e, sim::kNorth) / (qa * t * t * t / 3);
    const double rr = sampleVariance(r.errors[1], opt.runs, ref.epochs(), e, sim::kRoll) / (ng * ng * t);
    const double re = sampleVariance(r.errors[1], opt.runs, ref.epochs(), e, sim::kVe) /
                      (g * g * ng * ng * t * t * t / 3);
    std::printf("t = %5.0f s  s^2/sigma^2: accel vN %.4f  north %.4f | gyro roll %.4f  vE %.4f\n", t,
                rv, rp, rr, re);
    INFO("t = " << t << " s, bound [" << lo << ", " << hi << "]");
    CHECK(rv > lo);
    CHECK(rv < hi);
    CHECK(rp > lo);
    CHECK(rp < hi);
    CHECK(rr > lo);
    CHECK(rr < hi);
    CHECK(re > lo);
    CHECK(re < hi);
  }
  mctest::fs::remove_all(tmp);
}

TEST_CASE("error budget: two independent white noises share the drift as their densities") {
  // Accelerometer white noise on x (north) and y (east), densities q1, q2 = 4 q1: E[h²] = (q1 +
  // q2) t³/3, and switching one off leaves exactly the other's error (the kept effect draws the
  // same numbers), so share_x = Σδ_N²/Σ(δ_N² + δ_E²). Its sampling law: with F ~ F(N, N),
  // share_x = 1/(1 + (q2/q1) F); the 99.9 % two-sided F(1000, 1000) interval is [0.812, 1.232]
  // (F quantiles from the χ² ones would do: ±3.3 σ of ln F with σ = √(4/N)), giving
  // share_x ∈ [0.169, 0.235] around 0.2. The shares must add up to 1 up to the tiny cross-coupling
  // of the two channels through the Earth rate (≪ 1e-3 in 120 s).
  const auto tmp = mctest::tempDir("budget");
  const sim::Scenario sc = sim::parseScenario(kStatic, "budget.yaml");
  const sim::Reference ref = sim::buildReference(sc);
  std::vector<sim::McModel> models{
      {"two-whites",
       errormodels::ImuErrorModel::fromString("accel:\n  x: [{type: white, density: 0.01 m/s/sqrt(s)}]\n"
                                              "  y: [{type: white, density: 0.02 m/s/sqrt(s)}]\n",
                                              "two.yaml"),
       "two"}};
  sim::McOptions opt;
  opt.runs = 1000;
  opt.seed = 3;
  opt.budget = true;
  opt.times = {120};
  opt.outDir = (tmp / "out").string();
  const sim::McResult r = sim::runMonteCarlo(ref, models, opt);
  REQUIRE(r.complete);
  REQUIRE(r.errors.size() == 3);  // full, without x, without y
  const std::string json = mctest::slurp(tmp / "out" / "summary.json");
  const auto j = nlohmann::json::parse(json);
  const auto& effects = j["budget"][0]["at"][0]["effects"];
  REQUIRE(effects.size() == 2);
  const double sx = effects[0]["share"], sy = effects[1]["share"];
  std::printf("budget shares at 120 s: accel x %.4f, accel y %.4f, sum %.6f\n", sx, sy, sx + sy);
  CHECK(std::string(effects[0]["effect"]).find("accel.x") != std::string::npos);
  CHECK(sx > 0.169);
  CHECK(sx < 0.235);
  CHECK(sx + sy == Approx(1.0).margin(1e-3));
  mctest::fs::remove_all(tmp);
}
