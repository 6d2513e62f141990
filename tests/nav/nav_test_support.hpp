// Shared pieces of the nav tests: the closed-form ideal IMU of a vehicle at rest on the Earth and
// the position error in metres.
#pragma once

#include <cmath>

#include "common/constants.hpp"
#include "nav/attitude.hpp"
#include "nav/earth.hpp"
#include "nav/strapdown.hpp"
#include "nav/types.hpp"

namespace navtest {

using namespace sinsim::nav;

using sinsim::kPi;
constexpr double kDeg = kPi / 180.0;

/// Ideal increments of a body at rest on the Earth (Titterton & Weston 2004 §3.5: at rest the
/// specific force balances normal gravity and the body turns with the Earth):
/// f_b = -C_bn g_n, ω_ib_b = C_bn ω_ie_n, both constant, so Δv = f_b dt and Δθ = ω_ib_b dt exactly.
inline ImuSample staticSample(const Earth& earth, double lat, double h, const Quat& q_nb,
                              double dt) {
  const Mat3 C_bn = q_nb.toRotationMatrix().transpose();
  ImuSample s;
  s.dt = dt;
  s.dv_b = -C_bn * earth.gravity_n(lat, h) * dt;
  s.dtheta_b = C_bn * earth.omega_ie_n(lat) * dt;
  return s;
}

/// North, east, down position error [m] of `s` relative to (lat, lon, h) (local, first order).
inline Vec3 positionError(const Earth& earth, const NavState& s, double lat, double lon,
                          double h) {
  double M = 0.0, N = 0.0;
  earth.radii(lat, M, N);
  return Vec3((s.lat - lat) * (M + h), wrapAngle(s.lon - lon) * (N + h) * std::cos(lat),
              -(s.h - h));
}

/// Angle [rad] of the rotation between two attitudes.
inline double attitudeError(const Quat& a, const Quat& b) {
  return rotationVectorFromQuat(a.conjugate() * b).norm();
}

}  // namespace navtest
