// Coning and sculling in an inertially fixed setting, with exact increments of closed-form
// motions, through the same two-sample kernels the mechanization uses (strapdown.hpp).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

#include "nav_test_support.hpp"

using namespace navtest;

namespace {

// Classical coning, half-angle β at frequency Ω: q_ib(t) = [cos(β/2), sin(β/2)(0, cos Ωt, sin Ωt)]
// (a rotation by β about an axis spinning in the y-z plane). Its body rate, from ω = 2 q* ⊗ q̇:
// ω_b = (-2Ω sin²(β/2), -Ω sin β sin Ωt, Ω sin β cos Ωt), so the increments integrate exactly:
// Δθ = (-2Ω sin²(β/2) h, sin β (cos Ωt_k - cos Ωt_{k-1}), sin β (sin Ωt_k - sin Ωt_{k-1})).
struct Coning {
  double beta, Omega;
  Quat q(double t) const {
    const double s = std::sin(0.5 * beta);
    return Quat(std::cos(0.5 * beta), 0.0, s * std::cos(Omega * t), s * std::sin(Omega * t));
  }
  Vec3 dtheta(double t0, double t1) const {
    const double sb = std::sin(beta), s = std::sin(0.5 * beta);
    return Vec3(-2.0 * Omega * s * s * (t1 - t0),
                sb * (std::cos(Omega * t1) - std::cos(Omega * t0)),
                sb * (std::sin(Omega * t1) - std::sin(Omega * t0)));
  }
};

double coningError(const Coning& c, double h, long steps, bool useConing) {
  // The coning is under way before t = 0: (-h, 0] supplies the first "previous" increment
  // (a cold start would add a one-off (1/3) sin²β sin²(x/2) sin x ≈ 1.6e-6 rad, 5 % of the
  // 60 s residual).
  Quat q = c.q(0.0);
  Vec3 prev = c.dtheta(-h, 0.0);
  for (long k = 1; k <= steps; ++k) {
    const Vec3 dth = c.dtheta((k - 1) * h, k * h);
    const Vec3 phi = useConing ? rotationVectorTwoSample(prev, dth) : dth;
    q = (q * quatFromRotationVector(phi)).normalized();
    prev = dth;
  }
  return attitudeError(q, c.q(steps * h));
}

}  // namespace

TEST_CASE("coning: two-sample correction against the closed-form attitude") {
  // β = 0.1 rad at 2 Hz, 100 Hz increments (Ωh = 0.126), 60 s.
  const Coning c{0.1, 2.0 * kPi * 2.0};
  const double h = 0.01;
  const long steps = 6000;
  const double with = coningError(c, h, steps, true);
  const double without = coningError(c, h, steps, false);
  // Leading-order drift per step (expand the exact coning increment ½ sin²β (Ωh - sin Ωh) and the
  // algorithm's (1/12)(Δθ_{k-1} × Δθ_k)_x = (1/3) sin²β sin²(Ωh/2) sin Ωh in x = Ωh):
  //   without the correction: sin²β x³/12;   with it: sin²β x⁵/60.
  // Both accumulate linearly along the cone axis. Tolerance 3 %: the next terms are O(x²) ≈ 1.6 %
  // and O(β²) ≈ 1 % relative (measured agreement is better than 1 %).
  const double x = c.Omega * h, sb2 = std::pow(std::sin(c.beta), 2);
  const double predWithout = steps * sb2 * std::pow(x, 3) / 12.0;
  const double predWith = steps * sb2 * std::pow(x, 5) / 60.0;
  std::printf("coning 60 s: error with correction %.3g rad (predicted %.3g), without %.3g rad "
              "(predicted %.3g)\n",
              with, predWith, without, predWithout);
  CHECK(without == Approx(predWithout).epsilon(0.03));
  CHECK(with == Approx(predWith).epsilon(0.03));
  CHECK(with < without / 100.0);
}

TEST_CASE("coning: first step (one-sample form) and zero rotation are exact") {
  // A constant-axis rotation has no coning: any number of steps must be exact to rounding.
  const Vec3 w(0.3, -0.2, 0.5);  // [rad/s]
  const double h = 0.01;
  Quat q = Quat::Identity();
  Vec3 prev = Vec3::Zero();
  for (int k = 0; k < 1000; ++k) {
    q = q * quatFromRotationVector(rotationVectorTwoSample(prev, w * h));
    prev = w * h;
  }
  // 1000 quaternion products: ~1000 ε of rounding.
  CHECK(attitudeError(q, quatFromRotationVector(w * 10.0)) < 1e-12);
  CHECK(rotationVectorTwoSample(Vec3::Zero(), Vec3::Zero()) == Vec3::Zero());
}

TEST_CASE("sculling: two-sample correction against the Bessel-function closed form") {
  // Body rocking about x, θ(t) = A sin Ωt, with specific force B sin Ωt along body y, in phase.
  // In the inertial frame f_z = B sin Ωt sin(A sin Ωt), whose mean over a period is B J1(A) (the
  // Jacobi-Anger expansion), f_y has mean 0 — so after n whole periods v = (0, 0, n T B J1(A)).
  // Increments are exact: Δθ_x = A (sin Ωt_k - sin Ωt_{k-1}), Δv_y = (B/Ω)(cos Ωt_{k-1} -
  // cos Ωt_k). The rotation is about a fixed axis, so the attitude is exact and the test isolates
  // the velocity increment.
  const double A = 0.01, B = 10.0, Omega = 2.0 * kPi * 2.0, h = 0.01;  // 2 Hz rocking, 100 Hz
  const long periods = 120, perPeriod = 50, steps = periods * perPeriod;
  const double T = 2.0 * kPi / Omega;
  const double truth = periods * T * B * std::cyl_bessel_j(1.0, A);

  auto dtheta = [&](double t0, double t1) {
    return Vec3(A * (std::sin(Omega * t1) - std::sin(Omega * t0)), 0.0, 0.0);
  };
  auto dvel = [&](double t0, double t1) {
    return Vec3(0.0, (B / Omega) * (std::cos(Omega * t0) - std::cos(Omega * t1)), 0.0);
  };
  auto run = [&](bool sculling) {
    // The motion is under way before t = 0: the increments of (-h, 0] are the first "previous"
    // ones, so every step uses the two-sample form. (Starting from rest-like zero previous
    // increments instead costs a one-off (1/6) A sin x (B/Ω)(1 - cos x) ≈ 1.3e-6 m/s here, the
    // size of the whole 60 s two-sample residual.)
    Vec3 v = Vec3::Zero(), prevTh = dtheta(-h, 0.0), prevDv = dvel(-h, 0.0);
    for (long k = 1; k <= steps; ++k) {
      const double t0 = (k - 1) * h, t1 = k * h;
      const Vec3 dth = dtheta(t0, t1), dv = dvel(t0, t1);
      const Vec3 dvSF = sculling ? specificForceIncrementTwoSample(prevTh, prevDv, dth, dv) : dv;
      const Mat3 C_ib =
          Eigen::AngleAxisd(A * std::sin(Omega * t0), Vec3::UnitX()).toRotationMatrix();
      v += C_ib * dvSF;
      prevTh = dth;
      prevDv = dv;
    }
    return v;
  };
  const Vec3 full = run(true), none = run(false);
  // Predicted relative errors (averaging each step's error over the phase — exact on a grid of
  // 50 points per period — to first order in A; derivation by computer algebra, the sympy script
  // is in the comment below): uncompensated -(1 - sin x/x) ≈ -x²/6; two-sample
  // (8 sin x - sin 2x - 6x)/(6x) ≈ -x⁴/30, x = Ωh. The neglected O(A²) parts are
  // ~ (x²A²/48)/(x⁴/30) ≈ 0.4 % of the two-sample error at A = 0.01, the x⁶ terms 0.5 %:
  // tolerance 2 %.
  //   a,x,A,B=symbols(...); th=A sin; dv_k=B(cos a - cos(a+x)); exact=∫_0^x th(a+τ)B sin(a+τ)dτ;
  //   alg=th(a)dv_k + ½dθ_k dv_k + (1/12)(dθ_p dv_k - dv_p dθ_k); average (alg-exact) over a.
  const double x = Omega * h;
  const double predNone = -(1.0 - std::sin(x) / x);
  const double predFull = (8.0 * std::sin(x) - std::sin(2.0 * x) - 6.0 * x) / (6.0 * x);
  const double relNone = (none.z() - truth) / truth;
  const double relFull = (full.z() - truth) / truth;
  std::printf("sculling 60 s: truth v_z = %.6f m/s; relative error two-sample %.4g (predicted "
              "%.4g), uncompensated %.4g (predicted %.4g)\n",
              truth, relFull, predFull, relNone, predNone);
  CHECK(relNone == Approx(predNone).epsilon(0.02));
  CHECK(relFull == Approx(predFull).epsilon(0.02));
  CHECK(std::abs(relFull) < std::abs(relNone) / 100.0);
  // f_y averages to zero; the y velocity is rounding only.
  CHECK(std::abs(full.y()) < 1e-12);
}
