// The lever-arm velocity term C_nb (ω_eb × l) (nav/lever_arm.hpp) against closed forms: a level body
// turning on the spot moves an antenna ahead of it sideways at r |l|, and a body at rest on the
// rotating Earth (its gyros see the Earth rate only) moves it not at all, at any attitude.
#include <catch2/catch.hpp>

#include <cmath>

#include "nav/attitude.hpp"
#include "nav/earth.hpp"
#include "nav/lever_arm.hpp"

using namespace sinsim::nav;

TEST_CASE("lever-arm velocity: a level body turning on the spot, an antenna ahead of it") {
  const Earth earth;
  for (double heading : {0.0, 0.7, 2.0, -2.5}) {
    NavState s;
    s.lat = 0.8;
    s.q_nb = Quat(Eigen::AngleAxisd(heading, Vec3::UnitZ()));
    const double r = 0.3;  // yaw rate [rad/s] about body z (down): a right turn
    // The gyros see the turn plus the Earth rate in body axes.
    const Vec3 omega_ib_b = Vec3(0, 0, r) + s.q_nb.conjugate() * earth.omega_ie_n(s.lat);
    const Vec3 v = leverArmVelocity(earth, s, omega_ib_b, Vec3(2.0, 0, 0));
    // 2 m ahead along the heading, moving to the right of it at r · 2 m.
    const Vec3 expected = 2.0 * r * Vec3(-std::sin(heading), std::cos(heading), 0);
    CHECK((v - expected).norm() < 1e-15);
  }
}

TEST_CASE("lever-arm velocity: a body at rest on the Earth, any attitude and antenna, none") {
  const Earth earth;
  NavState s;
  s.lat = -0.6;
  s.q_nb = Quat(Eigen::AngleAxisd(0.4, Vec3(1, -2, 0.5).normalized()));
  const Vec3 omega_ib_b = s.q_nb.conjugate() * earth.omega_ie_n(s.lat);
  CHECK(leverArmVelocity(earth, s, omega_ib_b, Vec3(0.5, -0.2, -1.0)).norm() < 1e-20);
  // ... while counting the Earth rate as the body's own would move it by Ω |l| sin(angle).
  CHECK(leverArmVelocity(earth, s, Vec3::Zero(), Vec3(0.5, -0.2, -1.0)).norm() > 1e-5);
}
