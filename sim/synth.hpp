// A static IMU record with a known error model, as a real IMU at rest would give it (sinsim
// synth): test data with known truth for the identification path.
//
// CSV, header `t,gx,gy,gz,ax,ay,az,temp`: t [s] (end of each interval), gx..gz [rad/s] and
// ax..az [m/s^2] = measured increments / dt in body axes (x fwd, y right, z down), temp [degC].
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "errormodels/imu_model.hpp"
#include "nav/types.hpp"
#include "sim/temperature.hpp"

namespace sinsim::sim {

struct StaticRecordSpec {
  double rate = 0.0;      // [Hz] > 0
  double duration = 0.0;  // [s] > 0
  errormodels::StreamKey key;  // seed and run index of the random streams
  double lat = 0.0;       // geodetic latitude [rad], |lat| ≤ π/2
  double h = 0.0;         // height above the ellipsoid [m]
  nav::Vec3 rpy = nav::Vec3::Zero();  // roll, pitch, yaw of the body in NED [rad]
};

/// Writes the record to `path` (via a hidden temporary in its folder, renamed at the end: never a
/// half-written file). At rest on the rotating Earth: ω_ib^b = C_bn ω_ie^n, f^b = −C_bn g^n
/// (normal gravity, GeographicLib via nav::Earth), then `model` corrupts each interval at the
/// mid-interval temperature. Returns the number of samples, round(duration · rate).
long long writeStaticRecord(const errormodels::ImuErrorModel& model, const StaticRecordSpec& spec,
                            const TemperatureProfile& temperature, const std::string& path);

}  // namespace sinsim::sim
