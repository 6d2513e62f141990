// Coarse alignment against its closed-form error limits (Titterton & Weston 2004, §10.2.1):
// tilt ≈ δf_h / g for an accelerometer bias, heading ≈ δω_E / (Ω cos L) for a gyro bias along the
// level east axis. Two latitudes, an attitude with roll, pitch and a heading away from north.
#include <catch2/catch.hpp>

#include <cmath>

#include "common/constants.hpp"
#include "nav/alignment.hpp"
#include "nav/attitude.hpp"
#include "nav/earth.hpp"

using namespace sinsim::nav;

using sinsim::kRadPerDeg;

namespace {

struct Truth {
  Mat3 C_nb;
  Vec3 f_b, w_b;
};

Truth stationary(const Earth& earth, double lat, const Vec3& rpy) {
  Truth t;
  t.C_nb = dcmFromEuler(rpy);
  t.f_b = -t.C_nb.transpose() * earth.gravity_n(lat, 0.0);
  t.w_b = t.C_nb.transpose() * earth.omega_ie_n(lat);
  return t;
}

// Small rotation ψ with Ĉ = (I − [ψ×]) C, from Ĉ Cᵀ.
Vec3 attitudeError(const Quat& q_est, const Mat3& C_true) {
  const Mat3 E = q_est.toRotationMatrix() * C_true.transpose();  // ≈ I − [ψ×]
  return Vec3(E(1, 2) - E(2, 1), E(2, 0) - E(0, 2), E(0, 1) - E(1, 0)) * 0.5;
}
}  // namespace

TEST_CASE("coarse alignment: exact without sensor errors, closed-form errors with biases") {
  const Earth earth;
  const Vec3 rpy(2.0 * kRadPerDeg, -3.0 * kRadPerDeg, 130.0 * kRadPerDeg);
  for (double latDeg : {10.0, 60.0}) {
    const double lat = latDeg * kRadPerDeg;
    const Truth t = stationary(earth, lat, rpy);
    const double g = earth.gravity_n(lat, 0.0).norm();

    // No error: rounding only (atan2 of exact signals).
    CHECK(attitudeError(coarseAlignment(t.f_b, t.w_b), t.C_nb).norm() <= 1e-12);

    // Accelerometer bias 1 mg on every axis: the horizontal part of the bias, in NED, divided by
    // the measured vertical g − δf_D is the tilt (the neglected terms are ~ (δf/g)² ≈ 1e-6
    // relative, hence 1e-5).
    const Vec3 ba(1e-3 * g, -1e-3 * g, 1e-3 * g);
    const Vec3 psiA = attitudeError(coarseAlignment(t.f_b + ba, t.w_b), t.C_nb);
    const Vec3 ba_n = t.C_nb * ba;
    const double tilt = std::hypot(psiA.x(), psiA.y());
    const double tiltExpect = std::hypot(ba_n.x(), ba_n.y()) / (g - ba_n.z());
    CHECK(std::abs(tilt - tiltExpect) <= 1e-5 * tiltExpect);

    // Gyro bias 0.1 deg/h: heading error = east component / (Ω cos L) to first order; the next
    // term is relative O(ε), ε = |δω| / (Ω cos L) (the north component changes the horizontal
    // rate's magnitude): ε = 0.007 at 10°, 0.013 at 60°; the bound is 2ε.
    const Vec3 bg = Vec3(0.3, -0.4, 0.1).normalized() * 0.1 * kRadPerDeg / 3600.0;
    const Vec3 psiG = attitudeError(coarseAlignment(t.f_b, t.w_b + bg), t.C_nb);
    const double bgEast = (t.C_nb * bg).y();
    const double headExpect = std::abs(bgEast) / (earth.rate() * std::cos(lat));
    const double eps = bg.norm() / (earth.rate() * std::cos(lat));
    CHECK(std::abs(std::abs(psiG.z()) - headExpect) <= 2.0 * eps * headExpect);
    CHECK(std::hypot(psiG.x(), psiG.y()) <= 1e-12);  // a gyro bias does not tilt
  }
}

TEST_CASE("coarse alignment refuses signals it cannot align on") {
  CHECK_THROWS(coarseAlignment(Vec3::Zero(), Vec3(1e-5, 0, 0)));
  CHECK_THROWS(coarseAlignment(Vec3(0, 0, -9.8), Vec3(0, 0, 7e-5)));  // at a pole: no north
  CHECK_THROWS(coarseAlignment(Vec3(0, 0, NAN), Vec3(1e-5, 0, 0)));
}

TEST_CASE("coarse alignment: the linear error map against the alignment itself") {
  // ψ = J [C_nb δf_b; C_nb δω_b] (coarseAlignmentSensitivity) against the ψ that coarseAlignment
  // actually makes from perturbed signals, for errors on every axis at once (so that the tilt's
  // coupling into heading, −ψ_N tan L, is exercised: 1.7x at 60°). Errors of 10 µg and
  // 0.001 deg/h keep the second-order terms (the ratios δf/g = 1e-5 and δω/(Ω cos L) ≤ 1.3e-4)
  // below 1e-3 of ψ, the tolerance.
  const Earth earth;
  const double omega = earth.omega_ie_n(0.0).norm();
  const Vec3 rpy(-4.0 * kRadPerDeg, 7.0 * kRadPerDeg, -60.0 * kRadPerDeg);
  const double dg = 1e-5 * 9.8, dw = 1e-3 * kRadPerDeg / 3600.0;
  const Vec3 dirs[] = {Vec3(1, -2, 0.5), Vec3(-1, 0.3, 2), Vec3(0.2, 1, -1)};
  for (double latDeg : {10.0, 60.0})
    for (const Vec3& d : dirs) {
      const double lat = latDeg * kRadPerDeg;
      const Truth t = stationary(earth, lat, rpy);
      const double g = earth.gravity_n(lat, 0.0).norm();
      const Vec3 df = dg * d.normalized(), dwb = dw * Vec3(d.z(), d.x(), -d.y()).normalized();
      const Vec3 psi = attitudeError(coarseAlignment(t.f_b + df, t.w_b + dwb), t.C_nb);
      Eigen::Matrix<double, 6, 1> e;
      e << t.C_nb * df, t.C_nb * dwb;
      const Vec3 expect = coarseAlignmentSensitivity(lat, g, omega) * e;
      INFO("lat " << latDeg << " psi " << psi.transpose() << " expected " << expect.transpose());
      CHECK((psi - expect).norm() <= 1e-3 * expect.norm());
    }
}
