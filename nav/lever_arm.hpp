// Lever-arm kinematics: where a point fixed in the body (a GNSS antenna) is, and how fast it moves
// relative to the Earth, from the reference point's state.
#pragma once

#include "nav/earth.hpp"
#include "nav/types.hpp"

namespace sinsim::nav {

/// What the body's rotation adds to the velocity relative to the Earth of the body point at lever_b
/// [m] (body axes), in NED [m/s]: C_nb (ω_eb_b × l), ω_eb_b = ω_ib_b − C_bn ω_ie_n; the point moves
/// at v_n plus this (Groves 2013, sec. 14.2.3). omega_ib_b: the body's inertial rate [rad/s].
inline Vec3 leverArmVelocity(const Earth& earth, const NavState& s, const Vec3& omega_ib_b,
                             const Vec3& lever_b) {
  const Vec3 omega_eb_b = omega_ib_b - s.q_nb.conjugate() * earth.omega_ie_n(s.lat);
  return s.q_nb * omega_eb_b.cross(lever_b);
}

}  // namespace sinsim::nav
