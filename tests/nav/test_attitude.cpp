// Attitude math at the awkward points (Sophus-style: θ = 0, 1e-5, near and at π; pitch at and near
// ±90°), against Eigen's independent AngleAxis/Quaternion code and against the defining identities.
// Tolerances: every quantity here is O(1) and computed by a handful of operations, so errors are a
// few ulp (2.2e-16 each); 1e-14 allows ~50 ulp, far below any real formula error (a wrong series
// coefficient at θ = 1e-4 shows up at 1e-13 and above; a wrong branch at O(1)).
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "common/constants.hpp"
#include "nav/attitude.hpp"

using namespace sinsim::nav;

namespace {
using sinsim::kPi;
constexpr double kTol = 1e-14;

// Quaternions q and -q are the same rotation.
double quatDistance(const Quat& a, const Quat& b) {
  return std::min((a.coeffs() - b.coeffs()).norm(), (a.coeffs() + b.coeffs()).norm());
}

std::vector<Vec3> axes() {
  return {Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ(), Vec3(1, 2, -3).normalized(),
          Vec3(-0.3, 0.1, 0.9).normalized()};
}
}  // namespace

TEST_CASE("rotation vector to quaternion matches Eigen::AngleAxis") {
  // 0.05 rad is where the series gives way to trigonometry: both sides of it.
  const std::vector<double> angles = {0.0, 1e-12, 1e-8, 1e-5,       1e-4,        0.05 - 1e-12,
                                      0.05, 0.3,  1.0,  3.0,        kPi - 1e-6,  kPi - 1e-12,
                                      kPi};
  for (const Vec3& u : axes()) {
    for (double th : angles) {
      const Quat q = quatFromRotationVector(th * u);
      const Quat ref(Eigen::AngleAxisd(th, u));
      INFO("theta = " << th << ", axis = " << u.transpose());
      CHECK(quatDistance(q, ref) < kTol);
      CHECK(std::abs(q.norm() - 1.0) < kTol);
      // q(φ) - 1 keeps full relative precision in its scalar part (-2 sin²(θ/4) exactly).
      const Quat dq = quatDeltaFromRotationVector(th * u);
      const double s4 = std::sin(0.25 * th);
      CHECK(std::abs(dq.w() + 2.0 * s4 * s4) <= 1e-15 * 2.0 * s4 * s4);
      CHECK((dq.vec() - q.vec()).norm() == 0.0);
    }
  }
  // Exactly zero: identity, bit for bit.
  const Quat q0 = quatFromRotationVector(Vec3::Zero());
  CHECK(q0.w() == 1.0);
  CHECK(q0.vec() == Vec3::Zero());
}

TEST_CASE("quaternion to rotation vector round trip including 180 degrees") {
  for (const Vec3& u : axes()) {
    for (double th : {0.0, 1e-12, 1e-5, 0.5, 2.0, kPi - 1e-6, kPi - 1e-9}) {
      const Vec3 phi = th * u;
      INFO("theta = " << th);
      // |φ| < π: the rotation vector is unique.
      CHECK((rotationVectorFromQuat(quatFromRotationVector(phi)) - phi).norm() < kTol);
      // Both signs of the quaternion give the same rotation vector.
      const Quat q(Eigen::AngleAxisd(th, u));
      const Quat mq(-q.w(), -q.x(), -q.y(), -q.z());
      CHECK((rotationVectorFromQuat(mq) - phi).norm() < kTol);
    }
    // At exactly π, φ and -φ are the same rotation: either is right, with |φ| = π.
    const Vec3 phi = kPi * u;
    const Vec3 back = rotationVectorFromQuat(Quat(Eigen::AngleAxisd(kPi, u)));
    CHECK(std::min((back - phi).norm(), (back + phi).norm()) < kTol);
    CHECK(std::abs(back.norm() - kPi) < kTol);
  }
  // A rotation vector from a quaternion reproduces that rotation (Eigen's conversion as judge).
  const Quat q = Quat(0.1, -0.7, 0.2, 0.3).normalized();
  const Vec3 phi = rotationVectorFromQuat(q);
  CHECK(quatDistance(Quat(Eigen::AngleAxisd(phi.norm(), phi.normalized())), q) < kTol);
}

TEST_CASE("Euler angles to DCM and back") {
  const double d = kPi / 180.0;
  // Yaw sweeps all quadrants including ±180°, roll too; pitch away from ±90°.
  for (double roll : {-179.0, -90.0, -30.0, 0.0, 45.0, 120.0, 180.0}) {
    for (double pitch : {-89.0, -45.0, 0.0, 10.0, 60.0, 89.9}) {
      for (double yaw : {-170.0, -90.0, 0.0, 1e-9, 30.0, 135.0, 180.0}) {
        const Vec3 rpy(roll * d, pitch * d, yaw * d);
        const Mat3 C = dcmFromEuler(rpy);
        // DCM by the textbook product Rz(ψ)Ry(θ)Rx(φ) (independent of quatFromEuler).
        const Mat3 Cref = (Eigen::AngleAxisd(rpy.z(), Vec3::UnitZ()) *
                           Eigen::AngleAxisd(rpy.y(), Vec3::UnitY()) *
                           Eigen::AngleAxisd(rpy.x(), Vec3::UnitX()))
                              .toRotationMatrix();
        INFO("rpy [deg] = " << roll << ", " << pitch << ", " << yaw);
        CHECK((C - Cref).norm() < kTol);
        const Vec3 back = eulerFromDcm(C);
        // Compare angles modulo 2π (±180° are the same angle). Roll and yaw come from DCM
        // entries scaled by cos θ, so their error is ≈ ε / cos θ (5.7e-12 at 89.9°).
        const double tol = 1e-14 + 1e-14 / std::cos(rpy.y());
        for (int i = 0; i < 3; ++i) CHECK(std::abs(wrapAngle(back[i] - rpy[i])) < tol);
        CHECK(back.x() > -kPi);
        CHECK(back.x() <= kPi);
        CHECK(back.z() > -kPi);
        CHECK(back.z() <= kPi);
        CHECK((eulerFromQuat(quatFromEuler(rpy)) - back).norm() < tol);
      }
    }
  }
}

TEST_CASE("Euler angles at and near gimbal lock reproduce the DCM") {
  const double d = kPi / 180.0;
  // At pitch ±90° only yaw ∓ roll is observable; near it roll and yaw are ill-conditioned
  // individually (error ~ ε/cos θ), but the DCM rebuilt from the returned angles must equal the
  // input to rounding.
  for (double sign : {1.0, -1.0}) {
    for (double offset : {0.0, 1e-15, 1e-12, 1e-9, 1e-7, 1e-5, 1e-3}) {
      for (double roll : {0.0, 25.0, -140.0}) {
        for (double yaw : {0.0, 70.0, -100.0}) {
          const Vec3 rpy(roll * d, sign * (kPi / 2 - offset), yaw * d);
          const Mat3 C = dcmFromEuler(rpy);
          const Vec3 back = eulerFromDcm(C);
          INFO("pitch = " << rpy.y() << ", roll = " << roll << ", yaw = " << yaw);
          CHECK((dcmFromEuler(back) - C).norm() < kTol);
          // Pitch is atan2(sin θ, cos θ) with cos θ taken from the first column (absolute error
          // a few ε), so it stays accurate to a few ε even at the lock.
          CHECK(std::abs(back.y() - rpy.y()) < 1e-13);
          if (offset == 0.0) {
            CHECK(back.x() == 0.0);  // documented convention at the lock: roll = 0
            CHECK(std::abs(wrapAngle(back.z() - (rpy.z() - sign * rpy.x()))) < 1e-12);
          }
        }
      }
    }
  }
}

TEST_CASE("wrapAngle maps into the half-open interval from -pi to pi") {
  CHECK(wrapAngle(0.0) == 0.0);
  CHECK(wrapAngle(kPi) == kPi);
  CHECK(wrapAngle(-kPi) == kPi);
  CHECK(wrapAngle(3 * kPi) == Approx(kPi).epsilon(1e-15));
  CHECK(wrapAngle(-3 * kPi) == Approx(kPi).epsilon(1e-15));
  CHECK(wrapAngle(2 * kPi) == Approx(0.0).margin(1e-15));
  CHECK(wrapAngle(kPi + 1e-9) == Approx(-kPi + 1e-9).epsilon(1e-15));
  CHECK(wrapAngle(-kPi - 1e-9) == Approx(kPi - 1e-9).epsilon(1e-15));
  CHECK(wrapAngle(7.0) == Approx(7.0 - 2 * kPi).epsilon(1e-15));
  CHECK(wrapAngle(-1000.0) == Approx(-1000.0 + 159 * 2 * kPi).epsilon(1e-13));
  for (double a = -20.0; a < 20.0; a += 0.37) {
    const double w = wrapAngle(a);
    CHECK(w > -kPi);
    CHECK(w <= kPi);
    CHECK(std::abs(std::remainder(w - a, 2 * kPi)) < 1e-14);
  }
}

TEST_CASE("skew is the cross product") {
  const Vec3 a(1.5, -2.0, 0.25), b(-0.5, 3.0, 7.0);
  CHECK((skew(a) * b - a.cross(b)).norm() == 0.0);
  CHECK((skew(a) + skew(a).transpose()).norm() == 0.0);
}
