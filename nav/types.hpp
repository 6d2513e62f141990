// Navigation types shared by every stage. Frames: n = local-level NED, b = body (x fwd, y right,
// z down), e = ECEF, i = inertial. Names carry frames: C_nb/q_nb rotate body → nav.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace sinsim::nav {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;  // Hamilton, q_nb maps body vectors to nav: v_n = q_nb * v_b

/// Position, velocity and attitude at time t on the WGS-84 ellipsoid.
struct NavState {
  double t = 0.0;    // [s]
  double lat = 0.0;  // geodetic latitude [rad]
  double lon = 0.0;  // longitude [rad]
  double h = 0.0;    // height above the ellipsoid [m]
  Vec3 v_n = Vec3::Zero();     // velocity w.r.t. Earth in NED [m/s]
  Quat q_nb = Quat::Identity();  // attitude body → NED
};

/// One IMU output interval (t - dt, t]: integrated angular rate and specific force, as a real
/// strapdown IMU delivers them (not the rotation vector: coning is the mechanization's job).
struct ImuSample {
  double t = 0.0;                // end of the interval [s]
  double dt = 0.0;               // interval length [s]
  Vec3 dtheta_b = Vec3::Zero();  // ∫ omega_ib_b dt [rad]
  Vec3 dv_b = Vec3::Zero();      // ∫ f_b dt [m/s]
};

}  // namespace sinsim::nav
