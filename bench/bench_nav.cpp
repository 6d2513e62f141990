// Strapdown update() throughput. items_processed = IMU steps; the README quotes steps/s.
//
// Input: one full level turn at constant speed and rate, tabulated once before timing with the
// specific force and angular rate a vehicle at the turn's centre latitude would sense
// (f_n = v̇_n + (2ω_ie + ω_en) × v_n - g_n, ω_ib_b = ψ̇ z + C_bn ω_in_n), then replayed cyclically.
// The solution is restarted every 10^5 steps (≈ 17 min of 100 Hz data) so it never wanders off.
// Every part of a dynamic step runs: coning and sculling terms, the LocalEarth expansion and its
// re-anchoring as the vehicle moves (every ≈ 640 m or 50 m of height).
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "common/constants.hpp"
#include "nav/attitude.hpp"
#include "nav/earth.hpp"
#include "nav/strapdown.hpp"

using namespace sinsim::nav;

namespace {


std::vector<ImuSample> levelTurn(const Earth& earth, double lat, double h, double speed,
                                 double yawRate, double dt) {
  const long n = std::lround(2.0 * sinsim::kPi / yawRate / dt);
  std::vector<ImuSample> out(n);
  double M = 0.0, N = 0.0;
  earth.radii(lat, M, N);
  const Vec3 g_n = earth.gravity_n(lat, h), w_ie = earth.omega_ie_n(lat);
  for (long k = 0; k < n; ++k) {
    const double psi = (k + 0.5) * yawRate * dt;  // midpoint of the interval
    const Vec3 v_n(speed * std::cos(psi), speed * std::sin(psi), 0.0);
    const Vec3 vdot_n = yawRate * Vec3(-v_n.y(), v_n.x(), 0.0);
    const Vec3 w_en = Earth::omega_en_n(M, N, h, std::tan(lat), v_n);
    const Vec3 f_n = vdot_n + (2.0 * w_ie + w_en).cross(v_n) - g_n;
    const Mat3 C_bn = Eigen::AngleAxisd(-psi, Vec3::UnitZ()).toRotationMatrix();
    out[k].dt = dt;
    out[k].dv_b = C_bn * f_n * dt;
    out[k].dtheta_b = (Vec3(0.0, 0.0, yawRate) + C_bn * (w_ie + w_en)) * dt;
  }
  return out;
}

void runTurn(benchmark::State& st, double speed, double yawRate, VerticalChannel vc) {
  const Earth earth;
  const double dt = 0.01, lat = 0.7, h = 300.0;  // [s], [rad], [m]
  const std::vector<ImuSample> table = levelTurn(earth, lat, h, speed, yawRate, dt);
  NavState s0;
  s0.lat = lat;
  s0.lon = 0.2;
  s0.h = h;
  s0.v_n = Vec3(speed, 0.0, 0.0);
  StrapdownOptions opt;
  opt.vertical = vc;
  Strapdown ins(earth, s0, opt);
  long steps = 0, sinceRestart = 0;
  std::size_t i = 0;
  for (auto _ : st) {
    ins.update(table[i], h);
    if (++i == table.size()) i = 0;
    if (++sinceRestart == 100000) {
      benchmark::DoNotOptimize(ins.state());
      ins = Strapdown(earth, s0, opt);
      sinceRestart = 0;
      i = 0;
    }
    ++steps;
  }
  benchmark::DoNotOptimize(ins.state());
  st.SetItemsProcessed(steps);
}

// Car: 20 m/s, 0.05 rad/s turn (400 m radius). Aircraft: 250 m/s, 0.05 rad/s (5 km radius).
void BM_StrapdownCar(benchmark::State& st) { runTurn(st, 20.0, 0.05, VerticalChannel::Held); }
void BM_StrapdownAircraft(benchmark::State& st) {
  runTurn(st, 250.0, 0.05, VerticalChannel::Held);
}
void BM_StrapdownAircraftFree(benchmark::State& st) {
  runTurn(st, 250.0, 0.05, VerticalChannel::Free);
}
void BM_StrapdownAircraftDamped(benchmark::State& st) {
  runTurn(st, 250.0, 0.05, VerticalChannel::Damped);
}

// The GeographicLib calls LocalEarth avoids in the inner loop, for comparison.
void BM_GeographicLibGravity(benchmark::State& st) {
  const Earth earth;
  double lat = 0.7;
  for (auto _ : st) {
    lat += 1e-9;
    benchmark::DoNotOptimize(earth.gravity_n(lat, 300.0));
  }
  st.SetItemsProcessed(st.iterations());
}

void BM_GeographicLibRadii(benchmark::State& st) {
  const Earth earth;
  double lat = 0.7, M = 0.0, N = 0.0;
  for (auto _ : st) {
    lat += 1e-9;
    earth.radii(lat, M, N);
    benchmark::DoNotOptimize(M);
    benchmark::DoNotOptimize(N);
  }
  st.SetItemsProcessed(st.iterations());
}

}  // namespace

BENCHMARK(BM_StrapdownCar);
BENCHMARK(BM_StrapdownAircraft);
BENCHMARK(BM_StrapdownAircraftFree);
BENCHMARK(BM_StrapdownAircraftDamped);
BENCHMARK(BM_GeographicLibGravity);
BENCHMARK(BM_GeographicLibRadii);
BENCHMARK_MAIN();
