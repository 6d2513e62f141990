// Navigation types shared by every stage. Frames: n = local-level NED, b = body (x fwd, y right,
// z down), e = ECEF, i = inertial. Names carry frames: C_nb/q_nb rotate body → nav.
#pragma once

#include "common/types.hpp"

namespace sinsim::nav {

// The base vocabulary lives in common/ (shared with errormodels/); nav code keeps its names.
using sinsim::ImuSample;
using sinsim::Mat3;
using sinsim::Quat;
using sinsim::Vec3;

/// Position, velocity and attitude at time t on the WGS-84 ellipsoid.
struct NavState {
  double t = 0.0;    // [s]
  double lat = 0.0;  // geodetic latitude [rad]
  double lon = 0.0;  // longitude [rad]
  double h = 0.0;    // height above the ellipsoid [m]
  Vec3 v_n = Vec3::Zero();     // velocity w.r.t. Earth in NED [m/s]
  Quat q_nb = Quat::Identity();  // attitude body → NED
};

}  // namespace sinsim::nav
