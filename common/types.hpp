// Base vocabulary shared by every layer: 3-vectors, rotation matrices, quaternions and one IMU
// output interval. Lives in common/ so that nav/ (mechanization) and errormodels/ (sensor
// corruption) speak the same types without depending on each other.
// Frames: n = local-level NED, b = body (x fwd, y right, z down); C_nb/q_nb rotate body → nav.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace sinsim {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;  // Hamilton, q_nb maps body vectors to nav: v_n = q_nb * v_b

/// One IMU output interval (t - dt, t]: integrated angular rate and specific force, as a real
/// strapdown IMU delivers them (not the rotation vector: coning is the mechanization's job).
struct ImuSample {
  double t = 0.0;                // end of the interval [s]
  double dt = 0.0;               // interval length [s]
  Vec3 dtheta_b = Vec3::Zero();  // ∫ omega_ib_b dt [rad]
  Vec3 dv_b = Vec3::Zero();      // ∫ f_b dt [m/s]
};

}  // namespace sinsim
