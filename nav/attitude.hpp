// Attitude math: rotation vectors, quaternions, DCMs and ZYX Euler angles (yaw ψ, pitch θ,
// roll φ; C_nb = Rz(ψ) Ry(θ) Rx(φ)). Every function is exact at zero rotation (series below a
// small-angle threshold) and at 180° (no division by sin θ/2 near π).
#pragma once

#include "nav/types.hpp"

namespace sinsim::nav {

/// Skew-symmetric (cross-product) matrix: skew(a) b = a × b.
Mat3 skew(const Vec3& a);

/// Quaternion of the rotation by rotation vector phi [rad] (Savage 2000, eq. 7.1.2.2-3).
Quat quatFromRotationVector(const Vec3& phi);
/// Rotation vector [rad] of a unit quaternion, |phi| ≤ π.
Vec3 rotationVectorFromQuat(const Quat& q);

/// Euler angles (roll φ, pitch θ, yaw ψ) [rad] of C_nb; yaw in (-π, π]. At pitch ±90° roll and
/// yaw are not separable; roll is set to 0 and yaw absorbs the combination.
Vec3 eulerFromQuat(const Quat& q_nb);
Vec3 eulerFromDcm(const Mat3& C_nb);
/// C_nb / q_nb from Euler angles (roll, pitch, yaw) [rad].
Mat3 dcmFromEuler(const Vec3& rpy);
Quat quatFromEuler(const Vec3& rpy);

/// Angle wrapped to (-π, π] [rad].
double wrapAngle(double a);

}  // namespace sinsim::nav
