// Error-free IMU on smooth manoeuvring trajectories over WGS-84: the mechanization's truncation
// alone must keep the horizontal error below 1 cm over 30 min at 100 Hz (the simulator's
// requirement; gnss-ins-sim ends 28 m off on its 965 s drive).
//
// Truth is built here independently of the mechanization: speed, Euler angles (yaw, pitch, roll)
// are sums of sinusoids with analytic derivatives; velocity is along the body x axis
// (v_n = s [cos ψ cos θ, sin ψ cos θ, -sin θ]); position is integrated from it by classical
// RK4 (local error ~ h⁵ (v/R) ω⁴ < 1e-16 rad per step); specific force and body rate follow from
// the navigation equations (Titterton & Weston 2004 eqs. 3.69, 3.36):
//   f_n = v̇_n + (2 ω_ie + ω_en) × v_n - g_n,   ω_ib_b = ω_nb_b + C_bn (ω_ie + ω_en),
// with ω_nb_b from the ZYX Euler rates, and the IMU increments are their integrals over each
// interval by 3-point Gauss-Legendre quadrature (error ~ h⁷ f⁽⁶⁾/2e6: rounding level here).
#include <catch2/catch.hpp>

#include <cstdio>
#include <vector>

#include "nav_test_support.hpp"

using namespace navtest;

namespace {

/// c0 + c1 t + Σ a sin(w t + p), with its derivative.
struct Signal {
  double c0 = 0.0, c1 = 0.0;
  std::vector<Eigen::Vector3d> terms;  // (a, w, p)
  double value(double t) const {
    double v = c0 + c1 * t;
    for (const auto& s : terms) v += s.x() * std::sin(s.y() * t + s.z());
    return v;
  }
  double rate(double t) const {
    double v = c1;
    for (const auto& s : terms) v += s.x() * s.y() * std::cos(s.y() * t + s.z());
    return v;
  }
};

struct Profile {
  Signal speed, yaw, pitch, roll;  // [m/s], [rad]
};

struct Position {
  double lat, lon, h;
};

class Truth {
 public:
  Truth(const Earth& earth, const Profile& p) : earth_(earth), p_(p) {}

  Vec3 v_n(double t) const {
    const double s = p_.speed.value(t), ps = p_.yaw.value(t), th = p_.pitch.value(t);
    return s * Vec3(std::cos(ps) * std::cos(th), std::sin(ps) * std::cos(th), -std::sin(th));
  }
  Vec3 vdot_n(double t) const {
    const double s = p_.speed.value(t), ps = p_.yaw.value(t), th = p_.pitch.value(t);
    const double ds = p_.speed.rate(t), dps = p_.yaw.rate(t), dth = p_.pitch.rate(t);
    const double cp = std::cos(ps), sp = std::sin(ps), ct = std::cos(th), st = std::sin(th);
    return ds * Vec3(cp * ct, sp * ct, -st) +
           s * Vec3(-sp * ct * dps - cp * st * dth, cp * ct * dps - sp * st * dth, -ct * dth);
  }
  Mat3 C_nb(double t) const {
    return (Eigen::AngleAxisd(p_.yaw.value(t), Vec3::UnitZ()) *
            Eigen::AngleAxisd(p_.pitch.value(t), Vec3::UnitY()) *
            Eigen::AngleAxisd(p_.roll.value(t), Vec3::UnitX()))
        .toRotationMatrix();
  }
  /// ω_nb_b from ZYX Euler rates (Titterton & Weston 2004 eq. 3.52 inverted).
  Vec3 omega_nb_b(double t) const {
    const double th = p_.pitch.value(t), ph = p_.roll.value(t);
    const double dps = p_.yaw.rate(t), dth = p_.pitch.rate(t), dph = p_.roll.rate(t);
    return Vec3(dph - dps * std::sin(th),
                dth * std::cos(ph) + dps * std::sin(ph) * std::cos(th),
                -dth * std::sin(ph) + dps * std::cos(ph) * std::cos(th));
  }
  /// d(lat, lon, h)/dt.
  Vec3 posRate(const Position& p, double t) const {
    double M = 0.0, N = 0.0;
    earth_.radii(p.lat, M, N);
    const Vec3 v = v_n(t);
    return Vec3(v.x() / (M + p.h), v.y() / ((N + p.h) * std::cos(p.lat)), -v.z());
  }
  /// One classical RK4 step of the position from t over tau.
  Position step(const Position& p, double t, double tau) const {
    auto add = [](const Position& a, const Vec3& d, double f) {
      return Position{a.lat + f * d.x(), a.lon + f * d.y(), a.h + f * d.z()};
    };
    const Vec3 k1 = posRate(p, t);
    const Vec3 k2 = posRate(add(p, k1, 0.5 * tau), t + 0.5 * tau);
    const Vec3 k3 = posRate(add(p, k2, 0.5 * tau), t + 0.5 * tau);
    const Vec3 k4 = posRate(add(p, k3, tau), t + tau);
    return add(p, k1 + 2.0 * k2 + 2.0 * k3 + k4, tau / 6.0);
  }
  /// Specific force and body rate at time t and position p.
  void sensors(const Position& p, double t, Vec3& f_b, Vec3& w_b) const {
    double M = 0.0, N = 0.0;
    earth_.radii(p.lat, M, N);
    const Vec3 v = v_n(t);
    const Vec3 w_ie = earth_.omega_ie_n(p.lat);
    const Vec3 w_en = Earth::omega_en_n(M, N, p.h, std::tan(p.lat), v);
    const Mat3 C_bn = C_nb(t).transpose();
    f_b = C_bn * (vdot_n(t) + (2.0 * w_ie + w_en).cross(v) - earth_.gravity_n(p.lat, p.h));
    w_b = omega_nb_b(t) + C_bn * (w_ie + w_en);
  }
  /// Increments over (t, t + dt] from position p at t (3-point Gauss-Legendre).
  ImuSample increments(const Position& p, double t, double dt) const {
    static const double x[3] = {0.5 - 0.5 * std::sqrt(0.6), 0.5, 0.5 + 0.5 * std::sqrt(0.6)};
    static const double w[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
    ImuSample s;
    s.t = t + dt;
    s.dt = dt;
    for (int i = 0; i < 3; ++i) {
      const double tau = x[i] * dt;
      Vec3 f, om;
      sensors(step(p, t, tau), t + tau, f, om);
      s.dv_b += w[i] * dt * f;
      s.dtheta_b += w[i] * dt * om;
    }
    return s;
  }

 private:
  const Earth& earth_;
  Profile p_;
};

struct DynResult {
  double horizontal = 0.0, velocity = 0.0, attitude = 0.0, distance = 0.0;
};

DynResult fly(const Profile& prof, double lat0, double h0, double duration, double rate) {
  const Earth earth;
  const Truth truth(earth, prof);
  Position p{lat0, 0.3, h0};
  NavState s0;
  s0.lat = p.lat;
  s0.lon = p.lon;
  s0.h = p.h;
  s0.v_n = truth.v_n(0.0);
  s0.q_nb = Quat(truth.C_nb(0.0));
  Strapdown ins(earth, s0, {VerticalChannel::Held, 100.0});
  const double dt = 1.0 / rate;
  const long n = std::lround(duration * rate);
  DynResult r;
  for (long k = 0; k < n; ++k) {
    const double t = k * dt;
    const ImuSample imu = truth.increments(p, t, dt);
    const Position p1 = truth.step(p, t, dt);
    r.distance += 0.5 * dt * (truth.v_n(t).norm() + truth.v_n(t + dt).norm());
    p = p1;
    ins.update(imu, p.h);
    if ((k + 1) % std::lround(rate) == 0) {
      const Vec3 e = positionError(earth, ins.state(), p.lat, p.lon, p.h);
      r.horizontal = std::max(r.horizontal, e.head<2>().norm());
      r.velocity = std::max(r.velocity, (ins.state().v_n - truth.v_n(t + dt)).head<2>().norm());
      r.attitude =
          std::max(r.attitude, attitudeError(ins.state().q_nb, Quat(truth.C_nb(t + dt))));
    }
  }
  return r;
}

Profile carProfile() {
  Profile p;
  p.speed.c0 = 15.0;
  p.speed.terms = {{5.0, 0.011, 0.0}, {3.0, 0.07, 1.0}};
  p.yaw.c0 = 0.4;
  p.yaw.c1 = 0.002;
  p.yaw.terms = {{1.2, 0.013, 0.0}, {0.5, 0.05, 2.0}, {0.15, 0.2, 0.3}};
  p.pitch.terms = {{0.02, 0.031, 0.0}, {0.005, 0.4, 1.0}};
  p.roll.terms = {{0.03, 0.05, 0.5}, {0.01, 0.9, 0.0}};
  return p;
}

Profile aircraftProfile() {
  Profile p;
  p.speed.c0 = 200.0;
  p.speed.terms = {{30.0, 0.004, 0.0}, {2.0, 0.1, 0.7}};
  p.yaw.c0 = -1.0;
  p.yaw.c1 = 0.003;
  p.yaw.terms = {{1.5, 0.005, 0.3}, {0.2, 0.05, 1.0}};
  p.pitch.terms = {{0.04, 0.008, 0.0}, {0.02, 0.06, 0.4}};
  p.roll.terms = {{0.4, 0.01, 0.0}, {0.1, 0.15, 1.3}};
  return p;
}

}  // namespace

TEST_CASE("Euler-rate body rate agrees with the derivative of the DCM") {
  // Guards the truth generator: C_bn dC_nb/dt = [ω_nb_b ×], central difference over ±1e-5 s
  // (truncation ~ (1e-5)² ω³ ≈ 1e-12, rounding ~ 1e-16/1e-5 = 1e-11).
  const Earth earth;
  const Truth truth(earth, aircraftProfile());
  for (double t : {0.0, 17.3, 401.9}) {
    const double e = 1e-5;
    const Mat3 dC = (truth.C_nb(t + e) - truth.C_nb(t - e)) / (2.0 * e);
    const Mat3 W = truth.C_nb(t).transpose() * dC;
    CHECK((W - skew(truth.omega_nb_b(t))).norm() < 1e-9);
  }
}

TEST_CASE("error-free car drive of 30 min at 100 Hz: horizontal error below 1 cm") {
  const DynResult r = fly(carProfile(), 48.0 * kDeg, 300.0, 1800.0, 100.0);
  std::printf("car 30 min, %.1f km: max horizontal error %.3g m, velocity %.3g m/s, attitude "
              "%.3g rad\n",
              r.distance / 1000.0, r.horizontal, r.velocity, r.attitude);
  CHECK(r.distance > 20000.0);
  CHECK(r.horizontal < 0.01);
}

TEST_CASE("error-free aircraft flight of 30 min at 100 Hz: horizontal error below 1 cm") {
  const DynResult r = fly(aircraftProfile(), -33.0 * kDeg, 3000.0, 1800.0, 100.0);
  std::printf("aircraft 30 min, %.1f km: max horizontal error %.3g m, velocity %.3g m/s, "
              "attitude %.3g rad\n",
              r.distance / 1000.0, r.horizontal, r.velocity, r.attitude);
  CHECK(r.distance > 300000.0);
  CHECK(r.horizontal < 0.01);
}

TEST_CASE("the mechanization's truncation error is second order in the IMU interval") {
  // Local truncation O(h³) per step (midpoint Earth terms, first-order nav-frame rotation,
  // trapezoidal position) gives a global O(h²) error: halving the interval must divide the error
  // by 4. Measured on this profile: 50 Hz 0.72 mm, 100 Hz 0.176 mm (before the second-order
  // rotation compensation term: 7.62 mm and 1.90 mm, also ratio 4). Asserted: ratio 50 → 100 Hz
  // within 4 ± 10 % (a first- or third-order term would give 2 or 8).
  const DynResult r50 = fly(aircraftProfile(), -33.0 * kDeg, 3000.0, 1800.0, 50.0);
  const DynResult r100 = fly(aircraftProfile(), -33.0 * kDeg, 3000.0, 1800.0, 100.0);
  const double ratio = r50.horizontal / r100.horizontal;
  std::printf("aircraft 30 min: horizontal error 50 Hz %.3g m, 100 Hz %.3g m, ratio %.3f\n",
              r50.horizontal, r100.horizontal, ratio);
  CHECK(ratio == Approx(4.0).epsilon(0.1));
}
