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
/// q(phi) minus the identity quaternion, i.e. (cos(θ/2) - 1, sin(θ/2)/θ · phi), with the scalar
/// part computed as -2 sin²(θ/4) (or its series) so that it keeps full relative precision for
/// small θ. For updates of the form q ← q + Δq that must leave q bit-identical when successive
/// rotations cancel.
Quat quatDeltaFromRotationVector(const Vec3& phi);
/// Rotation vector [rad] of a unit quaternion, |phi| ≤ π.
Vec3 rotationVectorFromQuat(const Quat& q);

/// Euler angles (roll φ, pitch θ, yaw ψ) [rad] of C_nb; roll, yaw in (-π, π], pitch in
/// [-π/2, π/2]. At pitch ±90° roll and yaw are not separable; roll is set to 0 and yaw absorbs
/// the combination. At every attitude dcmFromEuler(eulerFromDcm(C)) reproduces C to rounding.
Vec3 eulerFromQuat(const Quat& q_nb);
Vec3 eulerFromDcm(const Mat3& C_nb);
/// C_nb / q_nb from Euler angles (roll, pitch, yaw) [rad].
Mat3 dcmFromEuler(const Vec3& rpy);
Quat quatFromEuler(const Vec3& rpy);

/// Angle wrapped to (-π, π] [rad].
double wrapAngle(double a);

}  // namespace sinsim::nav
