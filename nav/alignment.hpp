// Coarse alignment of a stationary strapdown IMU: leveling from the mean specific force and
// gyrocompassing from the mean angular rate (Titterton & Weston 2004, §10.2.1; Groves 2013,
// §5.6.2). Deterministic: the caller averages the samples of its static segment.
//
// Error limits (first order, T&W eqs. 10.6–10.8): a body accelerometer bias δf tilts the solution
// by ≈ δf / g, and a gyro bias δω along the level east axis turns the heading by
// ≈ δω / (Ω cos lat) (plus the tilt's coupling, tilt · tan lat) — gyrocompassing fails at the poles.
#pragma once

#include "nav/types.hpp"

namespace sinsim::nav {

/// Attitude q_nb of a stationary IMU from its mean specific force f_b [m/s^2] (≈ −g up the body's
/// local vertical) and mean angular rate omega_ib_b [rad/s] (≈ the Earth rate). Roll and pitch
/// level f_b; yaw points the leveled horizontal Earth rate north. Throws InputError when the
/// specific force is not finite or zero, or when the horizontal rate is zero (at a pole, or no
/// rate signal).
Quat coarseAlignment(const Vec3& f_b, const Vec3& omega_ib_b);

/// The first-order attitude error of coarseAlignment at latitude lat [rad] under gravity g
/// [m/s^2] and Earth rate omega [rad/s]: ψ = J [δf_n; δω_n], ψ the phi-angle of the aligned
/// attitude (Ĉ = (I − [ψ×]) C, NED), δf_n and δω_n the errors of the mean specific force and rate
/// in NED [m/s^2, rad/s] (C_nb times the body errors). Leveling: ψ_N = δf_E / g, ψ_E = −δf_N / g;
/// gyrocompassing: ψ_D = δω_E / (Ω cos L) − ψ_N tan L (T&W §10.2.1).
Eigen::Matrix<double, 3, 6> coarseAlignmentSensitivity(double lat, double g, double omega);

}  // namespace sinsim::nav
