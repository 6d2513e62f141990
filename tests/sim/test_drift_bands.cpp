// The drift-band kernel (sim/drift_bands.hpp) against closed forms of a static INS.
//
// Constant errors (deterministic, exact up to the midpoint rule, relative O((ω_s dt)²) ≈ 1e-8):
//  - accelerometer bias b north: δp_N(T) = b (1 − cos ω_s T)/ω_s², without Schuler b T²/2;
//  - gyro bias ω east: δψ_E = −ω t, δv̇_N = g ψ_E: δp_N(T) = −g ω (ω_s T − sin ω_s T)/ω_s³,
//    without Schuler −g ω T³/6 (Titterton & Weston 2004 §12.2);
//  - a constant lives in the remainder band only (its Haar details are 0), and a bias window
//    removes it entirely.
// White accelerometer noise of density √q through a bias window W (no Schuler):
//   δp = ∫ (T − t) (w(t) − w̄_W) dt,  Var δp = q [T³/3 − T² (T − W/2) + T⁴/(4W)],
// checked over N realisations inside the 99.9 % χ²(N − 1) interval of the sample variance.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "errormodels/stats/special.hpp"
#include "sim/drift_bands.hpp"

using namespace sinsim;

namespace {

sim::ErrorSignal zeros(std::size_t n, double rate) {
  sim::ErrorSignal x;
  x.rate = rate;
  for (int a = 0; a < 3; ++a) x.gyro[a].assign(n, 0.0), x.accel[a].assign(n, 0.0);
  return x;
}

std::array<double, 2> total(const std::vector<std::array<double, 2>>& bands) {
  std::array<double, 2> s{0.0, 0.0};
  for (const auto& b : bands) s[0] += b[0], s[1] += b[1];
  return s;
}

}  // namespace

TEST_CASE("drift bands: constant accelerometer and gyro biases give the static INS closed forms") {
  const double rate = 50.0, T = 600.0;
  const auto n = std::size_t(rate * T);
  const double b = 1e-3, w = 1e-5, g = 9.8;  // [m/s²], [rad/s], [m/s²]
  sim::DriftKernel k;
  k.g = g;
  for (double ws : {0.0, 1.2e-3}) {  // no Schuler; ω_s ≈ 1/806 s (ω_s T = 0.72)
    k.schuler = ws;
    auto x = zeros(n, rate);
    x.accel[0].assign(n, b);
    const auto ba = sim::driftByBand(x, k);
    const double pa = ws > 0 ? b * (1 - std::cos(ws * T)) / (ws * ws) : b * T * T / 2;
    CHECK(total(ba)[0] == Approx(pa).epsilon(1e-7));
    CHECK(std::abs(total(ba)[1]) < 1e-9 * std::abs(pa));
    CHECK(std::abs(ba.back()[0] - pa) < 1e-9 * std::abs(pa));  // all in the remainder
    x = zeros(n, rate);
    x.gyro[1].assign(n, w);
    const auto bg = sim::driftByBand(x, k);
    const double pg = ws > 0 ? -g * w * (ws * T - std::sin(ws * T)) / (ws * ws * ws)
                             : -g * w * T * T * T / 6;
    CHECK(total(bg)[0] == Approx(pg).epsilon(1e-6));
    // A bias window removes a constant from every band.
    k.biasWindow = 30.0;
    CHECK(std::abs(total(sim::driftByBand(x, k))[0]) < 1e-9 * std::abs(pg));
    k.biasWindow = 0.0;
  }
  CHECK(sim::driftBandTaus(n, rate).size() == 15);  // 2^14 = 16384 ≤ 30000 < 2^15
}

TEST_CASE("drift bands: white accelerometer noise through a bias window, variance in the chi2 bound") {
  const double rate = 20.0, T = 300.0, W = 30.0, sq = 0.01;  // √q [m/s/√s]
  const auto n = std::size_t(rate * T);
  sim::DriftKernel k;
  k.biasWindow = W;
  const double var = sq * sq * (T * T * T / 3 - T * T * (T - W / 2) + T * T * T * T / (4 * W));
  std::mt19937_64 rng(20241124);  // the test's one stream
  std::normal_distribution<double> normal(0.0, sq * std::sqrt(rate));  // per-sample sd of density √q
  const int runs = 600;
  double s2 = 0.0, s = 0.0;
  for (int r = 0; r < runs; ++r) {
    auto x = zeros(n, rate);
    for (auto& v : x.accel[0]) v = normal(rng);
    const double p = total(sim::driftByBand(x, k))[0];
    s += p;
    s2 += p * p;
  }
  const double sample = (s2 - s * s / runs) / (runs - 1);
  const double lo = errormodels::chiSquareQuantile(0.0005, runs - 1) / (runs - 1);
  const double hi = errormodels::chiSquareQuantile(0.9995, runs - 1) / (runs - 1);
  // The midpoint sum differs from the integral by O(1/(T rate)²) relative: far inside.
  CHECK(sample / var > lo);
  CHECK(sample / var < hi);
}

TEST_CASE("drift bands: the driving band is the fewest adjacent bands holding half") {
  using P = std::pair<std::size_t, std::size_t>;
  // helper-18's shares (tau 20, 41, 82, 164 s): two adjacent bands hold 60 %; the three from
  // 20 s to 82 s (72 %, the 10 % between counted) were reported before.
  CHECK(sim::drivingBands({0.21, 0.10, 0.41, 0.19, 0.09}) == P{2, 3});
  CHECK(sim::drivingBands({0.1, 0.6, 0.3}) == P{1, 1});           // one band alone
  CHECK(sim::drivingBands({0.2, 0.2, 0.2, 0.2, 0.2}) == P{0, 2});  // three, the first of equals
  CHECK(sim::drivingBands({0.45, 0.02, 0.49}) == P{1, 2});  // of two pairs, the larger
  CHECK(sim::drivingBands({}) == P{0, 0});
}
