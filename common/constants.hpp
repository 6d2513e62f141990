// Physical constants and unit conversion factors, one definition each. Names say the direction:
// kRadPerDeg multiplies degrees into radians, kDegPerRad radians into degrees (a bare `kDeg`
// has meant either in this tree before). Unit text ("0.2 deg/sqrt(h)") is converted by
// parseQuantity (common/units.hpp), which takes its factors from here.
#pragma once

namespace sinsim {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kRadPerDeg = kPi / 180.0;  // [rad/deg]
inline constexpr double kDegPerRad = 180.0 / kPi;  // [deg/rad]
inline constexpr double kSecondsPerHour = 3600.0;  // [s/h]
/// Standard gravity g_n [m/s²] (3rd CGPM 1901), the "g" of accelerometer specifications.
inline constexpr double kStandardGravity = 9.80665;
/// 0 °C in kelvin [K] (the offset of the Celsius scale).
inline constexpr double kZeroCelsius = 273.15;

/// Degrees → radians.
constexpr double degToRad(double deg) { return deg * kRadPerDeg; }
/// Radians → degrees.
constexpr double radToDeg(double rad) { return rad * kDegPerRad; }

}  // namespace sinsim
