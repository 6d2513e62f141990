#include "nav/attitude.hpp"

#include <cmath>

#include "common/constants.hpp"

namespace sinsim::nav {

Mat3 skew(const Vec3& a) {
  Mat3 S;
  S << 0.0, -a.z(), a.y(),  //
      a.z(), 0.0, -a.x(),   //
      -a.y(), a.x(), 0.0;
  return S;
}

namespace {
// cos(θ/2) - 1 and sin(θ/2)/θ. Below θ = 0.05 rad (θ² < 2.5e-3) by their Maclaurin series in
// x = θ² through x⁴; the first omitted terms, x⁵/3715891200 and x⁵/81749606400, are < 3e-23
// there, i.e. below 1e-19 relative. Above, by trigonometry, with cos(θ/2) - 1 = -2 sin²(θ/4) to
// keep its relative precision.
void halfAngleTerms(double th2, double& cm1, double& s) {
  if (th2 < 2.5e-3) {
    const double x = th2;
    cm1 = x * (-1.0 / 8.0 + x * (1.0 / 384.0 + x * (-1.0 / 46080.0 + x * (1.0 / 10321920.0))));
    s = 0.5 + x * (-1.0 / 48.0 + x * (1.0 / 3840.0 + x * (-1.0 / 645120.0 + x / 185794560.0)));
  } else {
    const double th = std::sqrt(th2);
    const double s4 = std::sin(0.25 * th);
    cm1 = -2.0 * s4 * s4;
    s = std::sin(0.5 * th) / th;
  }
}
}  // namespace

Quat quatFromRotationVector(const Vec3& phi) {
  double cm1, s;
  halfAngleTerms(phi.squaredNorm(), cm1, s);
  return Quat(1.0 + cm1, s * phi.x(), s * phi.y(), s * phi.z());
}

Quat quatDeltaFromRotationVector(const Vec3& phi) {
  double cm1, s;
  halfAngleTerms(phi.squaredNorm(), cm1, s);
  return Quat(cm1, s * phi.x(), s * phi.y(), s * phi.z());
}

Vec3 rotationVectorFromQuat(const Quat& qin) {
  Quat q = qin.w() < 0.0 ? Quat(-qin.w(), -qin.x(), -qin.y(), -qin.z()) : qin;
  const Vec3 v = q.vec();
  const double sn = v.norm();  // sin(θ/2)
  // θ = 2 atan2(|v|, w) is well conditioned everywhere, including θ → π (w → 0).
  const double th = 2.0 * std::atan2(sn, q.w());
  if (sn < 1e-12) return 2.0 * v / q.w();  // θ ≈ 2|v|/w to first order, exact for θ = 0
  return v * (th / sn);
}

Vec3 eulerFromDcm(const Mat3& C) {
  // C_nb = Rz(ψ)Ry(θ)Rx(φ): C(2,0) = -sin θ, C(1,0) = sin ψ cos θ, C(0,0) = cos ψ cos θ,
  // C(2,1) = sin φ cos θ, C(2,2) = cos φ cos θ (Titterton & Weston 2004, eq. 3.47).
  // Yaw first, from the first column; then roll and pitch from R = Rz(-ψ) C = Ry(θ)Rx(φ), whose
  // entries R(1,1) = cos φ, R(1,2) = -sin φ, R(0,0) = cos θ ≥ 0 are O(1) at every pitch. Near
  // ±90° pitch ψ is ill-conditioned, but any error in it passes into φ as the one combination
  // ψ ∓ φ that C defines, so Rz(ψ)Ry(θ)Rx(φ) reproduces C to rounding at every attitude.
  double yaw;
  const double cp = std::hypot(C(0, 0), C(1, 0));  // cos θ ≥ 0
  const bool locked = cp < 1e-14;
  if (locked) {
    // Gimbal lock (at the rounding level): only ψ ∓ φ is defined; put it all in yaw, roll = 0.
    // At θ = +90°: C(0,1) = sin(φ - ψ), C(1,1) = cos(φ - ψ); at θ = -90°: C(0,1) = -sin(φ + ψ),
    // C(1,1) = cos(φ + ψ). So atan2(-C(0,1), C(1,1)) = ψ ∓ φ.
    yaw = std::atan2(-C(0, 1), C(1, 1));
  } else {
    yaw = std::atan2(C(1, 0), C(0, 0));
  }
  const double cy = std::cos(yaw), sy = std::sin(yaw);
  const double R00 = cy * C(0, 0) + sy * C(1, 0);
  const double R11 = -sy * C(0, 1) + cy * C(1, 1);
  const double R12 = -sy * C(0, 2) + cy * C(1, 2);
  const double roll = locked ? 0.0 : std::atan2(-R12, R11);
  const double pitch = std::atan2(-C(2, 0), R00);
  return Vec3(wrapAngle(roll), pitch, wrapAngle(yaw));
}

Vec3 eulerFromQuat(const Quat& q_nb) { return eulerFromDcm(q_nb.toRotationMatrix()); }

Mat3 dcmFromEuler(const Vec3& rpy) { return quatFromEuler(rpy).toRotationMatrix(); }

Quat quatFromEuler(const Vec3& rpy) {
  const Quat qz(Eigen::AngleAxisd(rpy.z(), Vec3::UnitZ()));
  const Quat qy(Eigen::AngleAxisd(rpy.y(), Vec3::UnitY()));
  const Quat qx(Eigen::AngleAxisd(rpy.x(), Vec3::UnitX()));
  return qz * qy * qx;
}

double wrapAngle(double a) {
  a = std::remainder(a, 2.0 * kPi);  // in [-π, π]
  return a <= -kPi ? a + 2.0 * kPi : a;
}

}  // namespace sinsim::nav
