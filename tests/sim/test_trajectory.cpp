// The trajectory generator and the ideal IMU against truth from outside the code: closed forms
// of a stationary IMU, GeographicLib geodesics and rhumb lines, the analytic integrals of the
// smooth-step profiles, numerical derivatives, and hand-derived jerk bounds.
#include <GeographicLib/Geodesic.hpp>
#include <GeographicLib/NormalGravity.hpp>
#include <GeographicLib/Rhumb.hpp>
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "common/constants.hpp"
#include "nav/earth.hpp"
#include "sim/ideal_imu.hpp"
#include "sim/scenario.hpp"
#include "sim/trajectory.hpp"

using namespace sinsim;
using nav::Vec3;

namespace {
constexpr double kDeg = kPi / 180.0;
constexpr double kOmegaWgs84 = 7.292115e-5;  // [rad/s] WGS-84 Earth rate (NIMA TR8350.2 3.2.4)

// C_nb = Rz(yaw) Ry(pitch) Rx(roll), composed here from Eigen's elementary rotations.
nav::Mat3 dcmZyx(double roll, double pitch, double yaw) {
  return (Eigen::AngleAxisd(yaw, Vec3::UnitZ()) * Eigen::AngleAxisd(pitch, Vec3::UnitY()) *
          Eigen::AngleAxisd(roll, Vec3::UnitX()))
      .toRotationMatrix();
}
}  // namespace

TEST_CASE("static IMU equals the closed form -C_bn g_n and C_bn omega_ie_n") {
  const double lat = 45.0, h = 250.0, roll = 2.0, pitch = -3.0, yaw = 30.0;  // [deg, m]
  const sim::Scenario sc = sim::parseScenario(R"(
start: {latitude: 45 deg, longitude: 7 deg, height: 250 m,
        attitude: {roll: 2 deg, pitch: -3 deg, yaw: 30 deg}}
imu_rate: 100 Hz
segments: [{type: static, duration: 10 s}]
)", "static.yaml");
  const nav::Earth earth;
  const sim::Trajectory traj(earth, sc.motion());
  sim::IdealImu imu(traj, sc.imuRate);

  // Truth from outside: GeographicLib's normal gravity (northward γy, upward γz) and the WGS-84
  // Earth rate; f_b = -C_bn g_n, ω_ib_b = C_bn Ω [cos φ, 0, -sin φ] (Titterton & Weston 3.71).
  double gy = 0.0, gz = 0.0;
  GeographicLib::NormalGravity::WGS84().Gravity(lat, h, gy, gz);
  const Vec3 g_n(gy, 0.0, -gz);
  const nav::Mat3 C_bn = dcmZyx(roll * kDeg, pitch * kDeg, yaw * kDeg).transpose();
  const Vec3 f_b = -C_bn * g_n;
  const Vec3 w_b = C_bn * Vec3(kOmegaWgs84 * std::cos(lat * kDeg), 0.0,
                               -kOmegaWgs84 * std::sin(lat * kDeg));
  REQUIRE(imu.sampleCount() == 1000);
  double worstF = 0.0, worstW = 0.0;
  while (!imu.done()) {
    const nav::ImuSample s = imu.next();
    worstF = std::max(worstF, (s.dv_b / s.dt - f_b).norm() / f_b.norm());
    worstW = std::max(worstW, (s.dtheta_b / s.dt - w_b).norm() / w_b.norm());
    // at rest the position is not integrated at all: exactly the start
    REQUIRE(imu.truth().lat == sc.start.lat);
    REQUIRE(imu.truth().h == sc.start.h);
  }
  // A constant integrand summed with the RK4 weights in double precision: relative error a few
  // ulp (≈ 1e-15); 1e-12 leaves room for the trigonometry of C_bn and nothing else.
  CHECK(worstF < 1e-12);
  CHECK(worstW < 1e-12);
  // The rates interface agrees with the increments.
  const sim::Kinematics k = imu.rates();
  CHECK((k.f_b - f_b).norm() / f_b.norm() < 1e-12);
  CHECK((k.omega_ib_b - w_b).norm() / w_b.norm() < 1e-12);
}

TEST_CASE("constant-heading cruise follows GeographicLib's rhumb line") {
  // At h = 0 and constant NED heading the path is the rhumb line (loxodrome) of that azimuth.
  const sim::Scenario sc = sim::parseScenario(R"(
start: {latitude: 40 deg, longitude: -3 deg, height: 0 m, heading: 60 deg, speed: 30 m/s}
imu_rate: 100 Hz
segments: [{type: cruise, duration: 1000 s}]
)", "rhumb.yaml");
  const nav::Earth earth;
  const sim::Trajectory traj(earth, sc.motion());
  sim::IdealImu imu(traj, sc.imuRate);
  while (!imu.done()) imu.next();
  double lat2 = 0.0, lon2 = 0.0;
  GeographicLib::Rhumb::WGS84().Direct(40.0, -3.0, 60.0, 30.0 * 1000.0, lat2, lon2);
  const double M = earth.meridianRadius(lat2 * kDeg), N = earth.primeVerticalRadius(lat2 * kDeg);
  const double dN = (imu.truth().lat - lat2 * kDeg) * M;
  const double dE = (imu.truth().lon - lon2 * kDeg) * N * std::cos(lat2 * kDeg);
  INFO("rhumb end point differs by north " << dN << " m, east " << dE << " m");
  // RK4 truncation is negligible here (position rates vary on the scale R/v ≈ 2e5 s); what is
  // left is rounding: 1e5 steps each adding ≤ ½ ulp(0.7 rad) ≈ 5.6e-17 rad ≈ 0.36 nm, at worst
  // 36 µm if every rounding had the same sign. GeographicLib's Rhumb is exact to ~nm.
  CHECK(std::hypot(dN, dE) < 36e-6);
  CHECK(std::abs(imu.truth().h) < 1e-12);
}

TEST_CASE("accelerate-cruise-stop along a meridian covers the closed-form distance") {
  // Heading north: a meridian is a geodesic. Distance = ∫ s dt = 0.5·50·100 (∫S(u)du = 1/2) +
  // 50·1000 + 0.5·50·100 = 55000 m exactly; GeographicLib's geodesic inverse measures it.
  const sim::Scenario sc = sim::parseScenario(R"(
start: {latitude: 10 deg, longitude: 20 deg, heading: 0 deg}
imu_rate: 100 Hz
segments:
  - {type: accelerate, speed: 50 m/s, duration: 100 s}
  - {type: cruise, duration: 1000 s}
  - {type: decelerate, speed: 0 m/s, duration: 100 s}
  - {type: static, duration: 5 s}
)", "meridian.yaml");
  const nav::Earth earth;
  const sim::Trajectory traj(earth, sc.motion());
  sim::IdealImu imu(traj, sc.imuRate);
  while (!imu.done()) imu.next();
  const nav::NavState& end = imu.truth();
  double s12 = 0.0;
  GeographicLib::Geodesic::WGS84().Inverse(10.0, 20.0, end.lat / kDeg, end.lon / kDeg, s12);
  INFO("distance " << s12 << " m");
  // rounding bound as for the rhumb line, 120500 steps: ≤ 45 µm
  CHECK(std::abs(s12 - 55000.0) < 45e-6);
  CHECK(end.lon == sc.start.lon);  // vE = 0 exactly: the longitude never moves
  CHECK(end.v_n.norm() == 0.0);
}

TEST_CASE("climb and descend reach the planned heights") {
  // h(t) = h0 + Δh S(u): the ODE h' = s sin γ with γ = asin(ḣ/s) must reproduce the plan.
  const sim::Scenario sc = sim::parseScenario(R"(
start: {latitude: -33 deg, longitude: 151 deg, height: 20 m, heading: 135 deg, speed: 100 m/s}
imu_rate: 200 Hz
segments:
  - {type: climb, height_change: 500 m, duration: 100 s}
  - {type: turn, heading_change: 90 deg, bank: 30 deg}
  - {type: descend, height: 120 m, duration: 60 s}
)", "climb.yaml");
  const nav::Earth earth;
  const sim::Trajectory traj(earth, sc.motion());
  sim::IdealImu imu(traj, sc.imuRate);
  double worst = 0.0;
  const double tClimbEnd = 100.0;
  while (!imu.done()) {
    imu.next();
    if (std::abs(imu.truth().t - tClimbEnd) < 1e-9) CHECK(std::abs(imu.truth().h - 520.0) < 1e-8);
    worst = std::max(worst, std::abs(imu.truth().h - traj.motion().at(imu.truth().t).plannedHeight));
  }
  // Simpson on 1 − cos(2πu) with h/T = 2.5e-5 is exact to ~(2πh/T)^4/180 relative ≈ 3e-19;
  // rounding over 4e4 steps of a 500 m value (ulp 1e-13) stays below 1e-8 m.
  CHECK(worst < 1e-8);
  CHECK(std::abs(imu.truth().h - 120.0) < 1e-8);
}

TEST_CASE("velocity equals the numerical derivative of the integrated positions") {
  const sim::Scenario sc = sim::parseScenario(R"(
start: {latitude: 60 deg, longitude: 0 deg, height: 100 m, heading: 10 deg, speed: 5 m/s}
imu_rate: 1000 Hz
segments:
  - {type: accelerate, speed: 40 m/s, duration: 6 s}
  - {type: turn, heading_change: -120 deg, duration: 8 s, bank: auto}
  - {type: climb, height_change: 30 m, duration: 6 s}
)", "deriv.yaml");
  const nav::Earth earth;
  const sim::Trajectory traj(earth, sc.motion());
  sim::IdealImu imu(traj, sc.imuRate);
  std::vector<nav::NavState> states{imu.truth()};
  while (!imu.done()) {
    imu.next();
    states.push_back(imu.truth());
  }
  const double dt = imu.dt();
  double worst = 0.0;
  for (std::size_t k = 1; k + 1 < states.size(); ++k) {
    const nav::NavState &a = states[k - 1], &b = states[k], &c = states[k + 1];
    const double M = earth.meridianRadius(b.lat), N = earth.primeVerticalRadius(b.lat);
    const Vec3 v((c.lat - a.lat) / (2 * dt) * (M + b.h),
                 (c.lon - a.lon) / (2 * dt) * (N + b.h) * std::cos(b.lat), -(c.h - a.h) / (2 * dt));
    worst = std::max(worst, (v - b.v_n).norm());
  }
  INFO("worst |v - central difference| = " << worst << " m/s");
  // Central difference: truncation dt²/6·|d³x/dt³| ≤ 1e-6/6·(jerk ≲ 5 m/s³) ≈ 1e-6 m/s;
  // rounding ulp(lat)·R/(2 dt) ≈ 1.1e-16·6.4e6/2e-3 ≈ 3.6e-7 m/s. 1e-5 m/s is 3× their sum.
  CHECK(worst < 1e-5);
}

TEST_CASE("Euler-rate body rate matches the derivative of the attitude") {
  // ω_nb^b from Titterton & Weston 3.52 against skew(ω) = C_bn dC_nb/dt by central differences.
  const Vec3 e(0.4, -1.2, 2.5), r(0.3, -0.7, 1.1);
  const double d = 1e-6;
  const nav::Mat3 C0 = dcmZyx(e.x(), e.y(), e.z());
  const Vec3 ep = e + d * r, em = e - d * r;
  const nav::Mat3 Cdot = (dcmZyx(ep.x(), ep.y(), ep.z()) - dcmZyx(em.x(), em.y(), em.z())) / (2 * d);
  const nav::Mat3 W = C0.transpose() * Cdot;
  const Vec3 w(W(2, 1), W(0, 2), W(1, 0));
  // truncation d²|ω|³/6 ≈ 3e-13, rounding 1e-16/1e-6 = 1e-10
  CHECK((sim::bodyRateFromEulerRates(e, r) - w).norm() < 1e-9);
}

TEST_CASE("specific force and angular rate have no jumps beyond the jerk bounds") {
  const sim::Scenario sc = sim::parseScenario(R"(
start: {latitude: 30 deg, longitude: 100 deg, height: 0 m}
imu_rate: 100 Hz
segments:
  - {type: accelerate, speed: 20 m/s, duration: 10 s}
  - {type: turn, heading_change: 90 deg, duration: 10 s}
  - {type: climb, height_change: 20 m, duration: 20 s}
  - {type: pitch, angle: 10 deg, duration: 5 s}
  - {type: roll, angle: 10 deg, duration: 5 s}
  - {type: decelerate, speed: 0 m/s, duration: 10 s}
)", "smooth.yaml");
  const nav::Earth earth;
  const sim::Trajectory traj(earth, sc.motion());
  sim::IdealImu imu(traj, sc.imuRate);
  // Hand-derived bounds (|ḟ_b| ≤ |ȧ_n| + |ω_nb|·|f| + Earth/transport terms < 1e-3 m/s³):
  //   |f| ≤ g + peak acceleration ≤ 9.8 + 6.3 = 16.1 m/s² (turn: s·2Δψ/T = 20·π/10 = 6.3)
  //   accelerate: |ȧ| ≤ 2πΔs/T² = 1.26;  turn: s(2πΔψ/T² + (2Δψ/T)²) = 3.95, |ω| ≤ 0.314;
  //   climb: 2πΔh/T² = 0.31 plus s·γ̇² ≈ 0.01, |γ̇| ≤ 2π·0.1/20 = 0.031;
  //   pitch/roll excursion of A = 10° in T = 5 s: |ω| ≤ 4A/T = 0.14 rad/s, |ω̇| ≤ 8πA/T² = 0.18.
  // Jerk J per segment [m/s³] and angular acceleration bound [rad/s²]:
  struct Bound { double t1, jerk, angAcc; };
  const std::vector<Bound> bounds{{10, 1.26 + 1e-3, 1e-3},
                                  {20, 3.95 + 0.314 * 16.1, 2 * kPi * (kPi / 2) / 100 + 1e-3},
                                  {40, 0.32 + 0.031 * 16.1, 2 * kPi * 0.1 / 400 + 0.01},
                                  {45, 0.14 * 16.1, 0.18 + 1e-3},
                                  {50, 0.14 * 16.1, 0.18 + 1e-3},
                                  {60, 1.26 + 1e-3, 1e-3}};
  auto boundAt = [&](double t) {
    for (const auto& b : bounds)
      if (t <= b.t1 + 1e-9) return b;
    return bounds.back();
  };
  nav::ImuSample prev = imu.next();
  double worstRatioF = 0.0, worstRatioW = 0.0;
  while (!imu.done()) {
    const nav::ImuSample s = imu.next();
    // consecutive interval means differ by ≤ dt·max|ḟ| over the two intervals
    const Bound b1 = boundAt(prev.t - prev.dt), b2 = boundAt(s.t);
    const double J = std::max(b1.jerk, b2.jerk), A = std::max(b1.angAcc, b2.angAcc);
    const double jumpF = (s.dv_b / s.dt - prev.dv_b / prev.dt).norm();
    const double jumpW = (s.dtheta_b / s.dt - prev.dtheta_b / prev.dt).norm();
    worstRatioF = std::max(worstRatioF, jumpF / (s.dt * J));
    worstRatioW = std::max(worstRatioW, jumpW / (s.dt * A));
    prev = s;
  }
  INFO("largest jump / bound: specific force " << worstRatioF << ", angular rate " << worstRatioW);
  CHECK(worstRatioF <= 1.0);
  CHECK(worstRatioW <= 1.0);
}

TEST_CASE("increments converge: 10 ms and 0.5 ms integration steps agree to RK4's bound") {
  // The limit h → 0 is the exact integral; RK4 between knots has local error
  // h^5/2880·max|x⁗| (Simpson's rule for the pure quadratures). Fastest motion here: the pitch
  // excursion of A = 15° in T = 4 s, ω ≈ 4A/T = 0.26 rad/s with derivatives growing by
  // 2π/(T/2) = π s^-1 each: |ω⁗| ≈ 0.26·π^4 ≈ 25 rad/s^5 → 1e-10/2880·25 ≈ 9e-13 rad per
  // 10 ms step; the specific force turns with it, |f⁗| ≈ g·|ω⁗| ≈ 250 → 9e-12 m/s.
  // Bounds: 3× these. A step across a knot (segment boundary, excursion turning point, here at
  // odd instants to land inside IMU intervals) drops to O(h²) there: 4e-6 m/s, 2e-6 rad measured
  // with the knots ignored.
  const sim::Scenario sc = sim::parseScenario(R"(
start: {latitude: 10 deg, longitude: 10 deg, height: 1000 m, speed: 80 m/s}
imu_rate: 100 Hz
segments:
  - {type: accelerate, speed: 100 m/s, duration: 4.005 s}
  - {type: turn, heading_change: 60 deg, bank: auto, duration: 10.003 s}
  - {type: climb, height_change: 200 m, duration: 20 s}
  - {type: pitch, angle: 15 deg, duration: 4.0071 s}
  - {type: roll, angle: -30 deg, duration: 4 s}
  - {type: descend, height: 1000 m, duration: 20.002 s}
)", "knots.yaml");
  const nav::Earth earth;
  const sim::Trajectory traj(earth, sc.motion());
  sim::IdealImu coarse(traj, sc.imuRate, 0.01), fine(traj, sc.imuRate, 0.0005);
  double worstV = 0.0, worstT = 0.0;
  while (!coarse.done()) {
    const nav::ImuSample a = coarse.next(), b = fine.next();
    worstV = std::max(worstV, (a.dv_b - b.dv_b).norm());
    worstT = std::max(worstT, (a.dtheta_b - b.dtheta_b).norm());
  }
  INFO("largest differences: dv " << worstV << " m/s, dtheta " << worstT << " rad");
  CHECK(worstV < 3e-11);
  CHECK(worstT < 3e-12);
}
