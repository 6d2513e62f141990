// The vertical channel policies against the closed forms of the linearised height error, at rest
// at 45° N with the closed-form static IMU of the true position.
#include <catch2/catch.hpp>

#include <cstdio>

#include "common/error.hpp"
#include "nav_test_support.hpp"

using namespace navtest;

namespace {

// -∂g_D/∂h at (lat, 0) from GeographicLib (central difference over ±1 m: truncation ~1e-18,
// rounding ~1e-15 of the 3e-6 s^-2 result). Independent of LocalEarth.
double verticalGradient(const Earth& earth, double lat) {
  return -(earth.gravity_n(lat, 1.0).z() - earth.gravity_n(lat, -1.0).z()) / 2.0;
}

}  // namespace

TEST_CASE("free vertical channel: a height error grows as cosh(omega_v t)") {
  // Linearised: δḧ = ω_v² δh with ω_v² = -∂g_D/∂h (≈ 2g/R), δh(0) = δh0, δḣ(0) = 0 →
  // δh = δh0 cosh(ω_v t). Neglected: the Coriolis coupling of δv_D into the east channel and
  // back, 4Ω² cos²φ / ω_v² ≈ 0.35 % of ω_v², which changes cosh(ω_v t) at ω_v t ≈ 2 by
  // ≈ ω_v t tanh(ω_v t)·0.17 % ≈ 0.35 %; the horizontal Schuler loop it excites is bounded.
  // Tolerance 0.5 % (measured 0.085 %). Also the textbook ω_v = sqrt(2g/R) (R = sqrt(MN)): the true gradient of normal
  // gravity is 2g/R (1 + f + m - 2f sin²φ) ≈ 0.3 % steeper, giving ≈ 0.3 % more growth: 2 %.
  const Earth earth;
  const double lat = 45.0 * kDeg, dh0 = 1.0, duration = 1200.0;
  NavState s0;
  s0.lat = lat;
  s0.h = dh0;  // truth at h = 0
  s0.q_nb = quatFromEuler(Vec3(0.1, 0.2, 0.3));
  Strapdown ins(earth, s0, {VerticalChannel::Free, 100.0});
  const double dt = 0.01;
  ImuSample imu = staticSample(earth, lat, 0.0, s0.q_nb, dt);
  const double wv = std::sqrt(verticalGradient(earth, lat));
  double M = 0.0, N = 0.0;
  earth.radii(lat, M, N);
  const double wv2gR = std::sqrt(2.0 * earth.gravity_n(lat, 0.0).z() / std::sqrt(M * N));
  double worst = 0.0, worstTextbook = 0.0;
  const long n = std::lround(duration / dt);
  for (long k = 1; k <= n; ++k) {
    imu.t = k * dt;
    ins.update(imu);
    if (k % 1000 == 0) {
      const double dh = ins.state().h;
      const double ref = dh0 * std::cosh(wv * imu.t);
      worst = std::max(worst, std::abs(dh / ref - 1.0));
      const double refTextbook = dh0 * std::cosh(wv2gR * imu.t);
      worstTextbook = std::max(worstTextbook, std::abs(dh / refTextbook - 1.0));
    }
  }
  std::printf("free vertical channel: omega_v = %.5g 1/s (sqrt(2g/R) = %.5g), h(%.0f s) = %.4f m, "
              "worst relative deviation from cosh %.3g %% (textbook omega: %.3g %%)\n",
              wv, wv2gR, duration, ins.state().h, 100.0 * worst, 100.0 * worstTextbook);
  CHECK(ins.state().h > 3.0 * dh0);  // it did grow (cosh(2.1) ≈ 4.1)
  CHECK(worst < 0.005);
  CHECK(worstTextbook < 0.02);
}

TEST_CASE("damped vertical channel: critically damped decay with the set time constant") {
  // Gains k1 = 2/τ, k2 = 1/τ² + ω_v² make the linearised error obey (d/dt + 1/τ)² δh = 0. With
  // δh(0) = δh0, δv_D(0) = 0: δḣ(0) = -k1 δh0, so δh = δh0 (1 - t/τ) e^{-t/τ}. Forward-Euler loop
  // terms: error O(dt/τ) = 1e-4 relative; the Coriolis coupling (above) shifts ω_v² by 0.35 %,
  // i.e. k2 τ² by 1e-5. Tolerance: 1e-3 of δh0 at every second.
  const Earth earth;
  const double lat = 45.0 * kDeg, dh0 = 10.0, tau = 50.0;
  NavState s0;
  s0.lat = lat;
  s0.h = 100.0 + dh0;  // truth and reference at 100 m
  Strapdown ins(earth, s0, {VerticalChannel::Damped, tau});
  CHECK(ins.dampingGainK1() == Approx(2.0 / tau).epsilon(1e-15));
  const double wv2 = verticalGradient(earth, lat);
  CHECK(ins.dampingGainK2() == Approx(1.0 / (tau * tau) + wv2).epsilon(1e-3));
  const double dt = 0.01;
  ImuSample imu = staticSample(earth, lat, 100.0, s0.q_nb, dt);
  double worst = 0.0;
  const long n = std::lround(20.0 * tau / dt);
  for (long k = 1; k <= n; ++k) {
    imu.t = k * dt;
    ins.update(imu, 100.0);
    if (k % 100 == 0) {
      const double ref = dh0 * (1.0 - imu.t / tau) * std::exp(-imu.t / tau);
      worst = std::max(worst, std::abs((ins.state().h - 100.0) - ref));
    }
  }
  std::printf("damped vertical channel (tau = %.0f s): worst deviation from the closed form %.3g m "
              "(%.2g of the initial error), final error %.3g m\n",
              tau, worst, worst / dh0, ins.state().h - 100.0);
  CHECK(worst < 1e-3 * dh0);
  // Converged: the closed form is down to (1 - 20) e^{-20} δh0 ≈ 4e-7 m; what is left is the
  // Coriolis loop the transient excited: δv_E ≈ 2Ω cos φ δh0 (a Schuler oscillation the vertical
  // loop cannot damp) feeds back a vertical acceleration 2Ω cos φ δv_E, which the loop holds at
  // δh ≈ that / k2 ≤ (2Ω cos φ τ)² δh0 ≈ 2.7e-4 m, and δv_D = -k1 δh.
  const double floor = std::pow(2.0 * earth.rate() * std::cos(lat) * tau, 2) * dh0;
  CHECK(std::abs(ins.state().h - 100.0) < floor);
  CHECK(std::abs(ins.state().v_n.z()) < ins.dampingGainK1() * floor);
}

TEST_CASE("held vertical channel follows the reference height and its rate") {
  // hRef(t) = H sin(ωt): h must equal hRef exactly and v_D = -ḣRef up to the three-point
  // backward difference's error (dt²/3)|h'''| ≤ (dt²/3) H ω³ ≈ 1.3e-5 m/s for H = 50 m,
  // ω = 0.2 rad/s, dt = 0.01 s; asserted with a factor 2 for the O(dt³) remainder.
  const Earth earth;
  const double lat = 30.0 * kDeg, H = 50.0, w = 0.2, dt = 0.01;
  NavState s0;
  s0.lat = lat;
  Strapdown ins(earth, s0, {VerticalChannel::Held, 100.0});
  ImuSample imu = staticSample(earth, lat, 0.0, s0.q_nb, dt);
  double worstV = 0.0;
  for (long k = 1; k <= 2000; ++k) {
    imu.t = k * dt;
    const double href = H * std::sin(w * imu.t);
    ins.update(imu, href);
    CHECK(ins.state().h == href);
    const double vD = -H * w * std::cos(w * imu.t);
    if (k >= 2) worstV = std::max(worstV, std::abs(ins.state().v_n.z() - vD));
  }
  CHECK(worstV < 2.0 * H * w * w * w * dt * dt / 3.0);
}

TEST_CASE("strapdown refuses bad input with InputError") {
  const Earth earth;
  NavState s0;
  s0.lat = 0.5;
  ImuSample imu;
  imu.t = 0.01;
  imu.dt = 0.01;
  {
    Strapdown ins(earth, s0);
    ImuSample bad = imu;
    bad.dt = 0.0;
    CHECK_THROWS_AS(ins.update(bad), sinsim::InputError);
    bad.dt = NAN;
    CHECK_THROWS_AS(ins.update(bad), sinsim::InputError);
    CHECK_NOTHROW(ins.update(imu));  // NaN hRef is fine for the free channel
  }
  {
    Strapdown ins(earth, s0, {VerticalChannel::Held, 100.0});
    CHECK_THROWS_AS(ins.update(imu), sinsim::InputError);  // needs hRef
  }
  CHECK_THROWS_AS(Strapdown(earth, s0, {VerticalChannel::Damped, 0.0}), sinsim::InputError);
  CHECK_THROWS_AS(Strapdown(earth, s0, {VerticalChannel::Damped, NAN}), sinsim::InputError);
  NavState bad = s0;
  bad.lat = 2.0;
  CHECK_THROWS_AS(Strapdown(earth, bad), sinsim::InputError);
  bad = s0;
  bad.v_n.x() = NAN;
  CHECK_THROWS_AS(Strapdown(earth, bad), sinsim::InputError);
}

TEST_CASE("held vertical channel: an initial height error or a filter's height correction moves no horizontal channel") {
  // At rest with the exact static IMU the navigated state must stay at the truth. The held
  // channel sets the height to the reference; its vertical velocity must come from the references
  // alone. Differenced against the state's own height, a 500 m initial error is a one-step
  // v_D of 5e4 m/s at 100 Hz, whose Coriolis term 2 Ω cos φ v_D dt kicks v_E by 5.6 cm/s at 40° N
  // and a Schuler oscillation of ~45 m follows (the defect this test guards).
  const Earth earth;
  const double lat = 40.0 * kDeg, href = 600.0, dt = 0.01;
  NavState s0;
  s0.lat = lat;
  s0.h = href + 500.0;
  Strapdown ins(earth, s0, {VerticalChannel::Held, 100.0}, href);
  const ImuSample imu0 = staticSample(earth, lat, href, s0.q_nb, dt);
  ImuSample imu = imu0;
  double worstV = 0.0, worstLat = 0.0, worstLon = 0.0;
  for (long k = 1; k <= 60000; ++k) {
    imu.t = k * dt;
    if (k == 30000) ins.correct(Vec3(0.0, 0.0, 7.0), Vec3(0.0, 0.0, 2.0), Vec3::Zero());
    ins.update(imu, href);
    CHECK(ins.state().h == href);
    worstV = std::max(worstV, ins.state().v_n.norm());
    worstLat = std::max(worstLat, std::abs(ins.state().lat - lat));
    worstLon = std::max(worstLon, std::abs(ins.state().lon));
  }
  double M = 0.0, N = 0.0;
  earth.radii(lat, M, N);
  std::printf("held channel, 500 m initial height error and a 7 m correction: worst |v| %.3g m/s, "
              "north %.3g m, east %.3g m over 600 s\n",
              worstV, worstLat * M, worstLon * N * std::cos(lat));
  CHECK(worstV < 1e-6);
  CHECK(worstLat * M < 1e-4);
  CHECK(worstLon * N * std::cos(lat) < 1e-4);
  // The correction's horizontal parts are applied, the vertical ones are not.
  ins.correct(Vec3(0.0, 0.0, 3.0), Vec3(0.5, -0.25, 1.0), Vec3::Zero());
  CHECK(ins.state().h == href);
  CHECK(ins.state().v_n.x() == Approx(-0.5).margin(1e-6));
  CHECK(ins.state().v_n.y() == Approx(0.25).margin(1e-6));
  CHECK(std::abs(ins.state().v_n.z()) < 1e-6);
}
