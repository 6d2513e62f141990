// The continuous kinematics of a scenario on the WGS-84 Earth: the analytic motion
// (sim/motion.hpp) plus a position, giving every rate an ideal IMU and the navigation equations
// need. Nothing here samples or differences positions: all derivatives are analytic.
#pragma once

#include "nav/earth.hpp"
#include "nav/types.hpp"
#include "sim/motion.hpp"

namespace sinsim::sim {

/// Everything about the vehicle at one instant and one position.
struct Kinematics {
  double t = 0.0;                      // [s]
  double lat = 0.0, lon = 0.0, h = 0.0;  // geodetic [rad, rad, m]
  nav::Vec3 v_n = nav::Vec3::Zero();   // velocity w.r.t. Earth, NED [m/s]
  nav::Vec3 a_n = nav::Vec3::Zero();   // d(v_n)/dt [m/s^2]
  nav::Quat q_nb = nav::Quat::Identity();  // attitude body → NED
  nav::Vec3 euler = nav::Vec3::Zero();     // roll, pitch, yaw [rad] (yaw not wrapped)
  nav::Vec3 omega_nb_b = nav::Vec3::Zero();  // body rate w.r.t. NED, in body [rad/s]
  nav::Vec3 omega_ib_b = nav::Vec3::Zero();  // what a perfect gyro triad measures [rad/s]
  nav::Vec3 f_b = nav::Vec3::Zero();         // what a perfect accelerometer triad measures [m/s^2]
  nav::Vec3 g_n = nav::Vec3::Zero();         // normal gravity, NED [m/s^2]
  nav::Vec3 posRate = nav::Vec3::Zero();     // (lat', lon', h') [rad/s, rad/s, m/s]
};

/// The scenario's motion placed on the Earth. Stateless: evaluate at any (t, position).
class Trajectory {
 public:
  /// earth must outlive the trajectory.
  Trajectory(const nav::Earth& earth, MotionProfile motion);

  /// Kinematics at time t [s] and position (lat [rad], lon [rad], h [m]):
  ///   v_n = s [cos γ cos ψ, cos γ sin ψ, −sin γ]
  ///   lat' = vN/(M + h), lon' = vE/((N + h) cos lat), h' = −vD      (Titterton & Weston 3.79)
  ///   ω_nb^b from the ZYX Euler rates                              (Titterton & Weston 3.52)
  ///   ω_ib^b = ω_nb^b + C_bn (ω_ie^n + ω_en^n)
  ///   f^n = v̇_n + (2 ω_ie^n + ω_en^n) × v_n − g^n,  f^b = C_bn f^n  (Titterton & Weston 3.71)
  /// with radii, normal gravity (incl. its north component) and Earth rate from nav::Earth.
  Kinematics at(double t, double lat, double lon, double h) const;

  /// Position rate only (cheaper), same equations as at().
  nav::Vec3 positionRate(const nav::Vec3& v_n, double lat, double h) const;

  const MotionProfile& motion() const { return motion_; }
  const nav::Earth& earth() const { return earth_; }
  double duration() const { return motion_.duration(); }

 private:
  const nav::Earth& earth_;
  MotionProfile motion_;
};

/// ω_nb^b [rad/s] from ZYX Euler angles (roll φ, pitch θ, yaw ψ) [rad] and their rates [rad/s]:
/// [φ̇ − ψ̇ sin θ,  θ̇ cos φ + ψ̇ sin φ cos θ,  −θ̇ sin φ + ψ̇ cos φ cos θ] (Titterton & Weston 3.52).
nav::Vec3 bodyRateFromEulerRates(const nav::Vec3& euler, const nav::Vec3& eulerRate);

}  // namespace sinsim::sim
