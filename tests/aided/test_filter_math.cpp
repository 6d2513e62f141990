// The filter's building blocks against truths computed outside them: the discrete algebraic
// Riccati equation iterated in closed form, and the one-step prediction variance of an AR process.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <random>

#include "common/constants.hpp"
#include "errormodels/ar_model.hpp"
#include "nav/earth.hpp"
#include "sim/aided/discretize.hpp"
#include "sim/aided/error_state_filter.hpp"
#include "sim/aided/kalman.hpp"
#include "sim/aided/sensor_states.hpp"
#include "filter_model_support.hpp"

using namespace sinsim::sim::aided;

using sinsim::kRadPerDeg;

namespace {

// Transition of (p, v, b) over t for ṗ = v, v̇ = b + w_a, ḃ = −b/τ + w_b, in closed form.
Eigen::Matrix3d phiClosed(double t, double tau) {
  const double e = std::exp(-t / tau);
  Eigen::Matrix3d P;
  P << 1, t, tau * (t - tau * (1 - e)),
       0, 1, tau * (1 - e),
       0, 0, e;
  return P;
}

}  // namespace

TEST_CASE("single-axis static GNSS position fixes: steady covariance solves the DARE") {
  // One axis at rest: position, velocity and a Gauss-Markov accelerometer bias, white
  // accelerometer noise, position fixes every T. The filter path (Van Loan + Joseph update) is
  // compared with the discrete algebraic Riccati equation iterated independently: Φ in closed
  // form, Qd by composite Simpson quadrature of ∫ Φ(s) Qc Φ(s)ᵀ ds, and the textbook (I − KH)P
  // update.
  const double T = 1.0, tau = 300.0, Na = 0.002, sigmaB = 5e-3, sigmaR = 1.5;
  const StateBlock gm = gaussMarkovState(sigmaB, tau);
  Eigen::MatrixXd F = Eigen::MatrixXd::Zero(3, 3), Qc = Eigen::MatrixXd::Zero(3, 3);
  F(0, 1) = 1.0;
  F(1, 2) = 1.0;  // the bias state's c = 1 drives v̇
  F(2, 2) = gm.F(0, 0);
  Qc(1, 1) = Na * Na;
  Qc(2, 2) = gm.Qc(0, 0);
  const DiscreteSystem d = vanLoan(F, Qc, T);

  // Independent Φ and Qd.
  const Eigen::Matrix3d Phi = phiClosed(T, tau);
  const Eigen::Matrix3d Qc3 = Qc;
  const int n = 4000;  // Simpson error ∝ (T/n)^4 · max|f''''| ≪ 1e-12 relative here
  Eigen::Matrix3d Qd = Eigen::Matrix3d::Zero();
  for (int i = 0; i <= n; ++i) {
    const double s = T * i / n, w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    const Eigen::Matrix3d Ps = phiClosed(s, tau);
    Qd += w * Ps * Qc3 * Ps.transpose();
  }
  Qd *= T / (3.0 * n);
  // Scaling and squaring loses a few digits (forward error ~ squarings · u · ‖A‖, ~2e-12 here);
  // 1e-10 is far below what moves P by the 1e-6 checked at the end.
  CHECK((d.Phi - Eigen::MatrixXd(Phi)).norm() <= 1e-10 * Phi.norm());
  CHECK((d.Qd - Eigen::MatrixXd(Qd)).norm() <= 1e-9 * Qd.norm());

  // DARE by fixed-point iteration of the a-priori covariance (converges geometrically; 20000
  // steps are thousands of the slowest time constant τ/T = 300).
  Eigen::RowVector3d H(1, 0, 0);
  Eigen::Matrix3d Pm = Eigen::Matrix3d::Identity() * 1e2;
  for (int k = 0; k < 20000; ++k) {
    const double S = H * Pm * H.transpose() + sigmaR * sigmaR;
    const Eigen::Vector3d K = Pm * H.transpose() / S;
    const Eigen::Matrix3d Pp = (Eigen::Matrix3d::Identity() - K * H) * Pm;
    Pm = Phi * Pp * Phi.transpose() + Qd;
  }
  // Filter path from a different start (to show the limit does not depend on it).
  Eigen::VectorXd x = Eigen::VectorXd::Zero(3);
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(3, 3);
  P(0, 0) = 25.0;
  P(1, 1) = 1.0;
  P(2, 2) = sigmaB * sigmaB;
  Eigen::VectorXd z(1);
  z(0) = 0.0;
  Eigen::MatrixXd Hd = H, R = Eigen::MatrixXd::Constant(1, 1, sigmaR * sigmaR);
  for (int k = 0; k < 20000; ++k) {
    kalmanPredict(x, P, d.Phi, d.Qd);
    kalmanUpdate(x, P, z, Hd, R);
  }
  kalmanPredict(x, P, d.Phi, d.Qd);
  // 1e-6 relative: the brief's bound; the two paths differ only by rounding and by Qd's
  // quadrature error (< 1e-9 relative, above).
  CHECK(std::abs(P(0, 0) - Pm(0, 0)) <= 1e-6 * Pm(0, 0));
  CHECK(std::abs(P(1, 1) - Pm(1, 1)) <= 1e-6 * Pm(1, 1));
  CHECK(std::abs(P(2, 2) - Pm(2, 2)) <= 1e-6 * Pm(2, 2));
}

TEST_CASE("AR(p) states that are the truth AR process predict with the closed-form variance") {
  // Seed paper's gyro x AR(5) (scenarios/adis16355-ar5.yaml). Once p past samples are known
  // exactly, the one-step prediction error of an AR(p) is its driving noise: variance σ_e²; over
  // two steps it is σ_e² (1 + ψ1²) with ψ1 = −a1 (Box, Jenkins & Reinsel 2008, eq. 5.1.16).
  const std::vector<double> a = {-1.0327, -0.34341, 0.037895, 0.19732, 0.14724};
  const double sigmaE = 0.020539 * kRadPerDeg, rate = 1000.0;
  const StateBlock b = arState(a, sigmaE, rate);
  const DiscreteSystem one = discretizeBlock(b, 1.0 / rate);
  const DiscreteSystem two = discretizeBlock(b, 2.0 / rate);

  // Truth: the recursion itself, seeded (named stream of this test).
  std::mt19937_64 rng(20261123);
  std::normal_distribution<double> w;
  std::vector<double> y(5, 0.0);  // y[n-1..n-5], warmed up below
  auto step = [&] {
    double v = sigmaE * w(rng);
    for (int i = 0; i < 5; ++i) v -= a[i] * y[i];
    y.insert(y.begin(), v);
    y.pop_back();
    return v;
  };
  for (int i = 0; i < 5000; ++i) step();

  Eigen::VectorXd x = Eigen::VectorXd::Zero(5);
  Eigen::MatrixXd P = b.P0;
  Eigen::MatrixXd H = b.c, R = Eigen::MatrixXd::Constant(1, 1, 0.0);
  Eigen::VectorXd z(1);
  double predVar = 0.0, predMean = 0.0, expectMean = 0.0;
  for (int k = 0; k < 8; ++k) {
    kalmanPredict(x, P, one.Phi, one.Qd);
    predVar = (b.c * P * b.c.transpose())(0, 0);
    predMean = b.c.dot(x);
    expectMean = 0.0;
    for (int i = 0; i < 5; ++i) expectMean -= a[i] * y[i];
    z(0) = step();
    // R = 0 is allowed: S = c P cᵀ > 0 because the prediction always adds σ_e².
    kalmanUpdate(x, P, z, H, R);
  }
  // After ≥ p exact measurements: rounding only (Joseph form keeps P to ~1e-15 relative).
  CHECK(std::abs(predVar - sigmaE * sigmaE) <= 1e-9 * sigmaE * sigmaE);
  CHECK(std::abs(predMean - expectMean) <= 1e-9 * sigmaE);
  Eigen::VectorXd x2 = x;
  Eigen::MatrixXd P2 = P;
  kalmanPredict(x2, P2, two.Phi, two.Qd);
  const double var2 = (b.c * P2 * b.c.transpose())(0, 0);
  CHECK(std::abs(var2 - sigmaE * sigmaE * (1.0 + a[0] * a[0])) <= 1e-9 * var2);
  // The stationary start is the Yule-Walker r(0).
  CHECK(std::abs(b.P0(0, 0) - sigmaE * sigmaE * sinsim::errormodels::ar::varianceGain(a)) <=
        1e-12 * b.P0(0, 0));
}

TEST_CASE("discrete AR blocks refuse a filter step that is not a whole number of samples") {
  const StateBlock b = arState({-0.5}, 1.0, 1000.0);
  CHECK_THROWS(discretizeBlock(b, 0.0015));
  CHECK_NOTHROW(discretizeBlock(b, 0.01));
  CHECK_THROWS(gaussMarkovState(1.0, -1.0));
  CHECK_THROWS(arState({-1.5}, 1.0, 100.0));  // pole at 1.5: unstable
}

TEST_CASE("series discretisation: the closed form, the 9 + 18-state filter model, fast processes") {
  // 1) The single-axis case above: Φ in closed form, Qd by Simpson quadrature (independent).
  const double T = 1.0, tau = 300.0, Na = 0.002, sigmaB = 5e-3;
  const StateBlock gm = gaussMarkovState(sigmaB, tau);
  Eigen::MatrixXd F = Eigen::MatrixXd::Zero(3, 3), Qc = Eigen::MatrixXd::Zero(3, 3);
  F(0, 1) = 1.0;
  F(1, 2) = 1.0;
  F(2, 2) = gm.F(0, 0);
  Qc(1, 1) = Na * Na;
  Qc(2, 2) = gm.Qc(0, 0);
  const DiscreteSystem s = discretize(F, Qc, T);
  const Eigen::Matrix3d Phi = phiClosed(T, tau);
  const int n = 4000;  // Simpson: error ∝ (T/n)^4, ≪ 1e-12 relative here
  Eigen::Matrix3d Qd = Eigen::Matrix3d::Zero();
  for (int i = 0; i <= n; ++i) {
    const double t = T * i / n, w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    const Eigen::Matrix3d Ps = phiClosed(t, tau);
    Qd += w * Ps * Eigen::Matrix3d(Qc) * Ps.transpose();
  }
  Qd *= T / (3.0 * n);
  // The series is summed to rounding with no cancellation (decaying terms): a few ulp. The
  // closed form's Φ_02 = τ(T − τ(1 − e^(−T/τ))) itself cancels ~5 digits (τ²/T = 9e4 × ulp,
  // ~1e-11), the quadrature's error is ~1e-13: the bounds of the Van Loan check above.
  CHECK((s.Phi - Eigen::MatrixXd(Phi)).norm() <= 1e-10 * Phi.norm());
  CHECK((s.Qd - Eigen::MatrixXd(Qd)).norm() <= 1e-9 * Qd.norm());

  // 2) The filter's own continuous model (9 INS errors + bias, GM, random walk per axis, white
  // noise) at a moving, tilted point: the series equals Van Loan's Padé result per entry, each
  // entry measured against its own diagonal scale sqrt(Q_ii Q_jj) (the states span 12 orders of
  // magnitude: metres to rad/s), to 1e-9 — scaling and squaring's forward error is ~1e-12 of the
  // largest entries, so the looser bound leaves room for it, not for a wrong term.
  const FilterSensorModel m = aidedtest::biasGmWalkModel(300);
  const sinsim::nav::Earth earth;
  ErrorStateFilter filter(earth, m, FilterOptions{});
  sinsim::nav::InsErrorPoint p;
  p.lat = 0.8;
  p.h = 500.0;
  p.v_n = sinsim::nav::Vec3(12.0, -5.0, 0.3);
  p.f_n = sinsim::nav::Vec3(1.5, -2.0, -9.81);
  p.C_nb = Eigen::AngleAxisd(0.7, sinsim::nav::Vec3(0.2, -0.3, 1.0).normalized()).toRotationMatrix();
  Eigen::MatrixXd Ff, Qf;
  filter.continuousModel(p, Ff, Qf);
  REQUIRE(Ff.rows() == 27);
  const DiscreteSystem a = discretize(Ff, Qf, 1.0), b = vanLoan(Ff, Qf, 1.0);
  const Eigen::VectorXd scale = b.Qd.diagonal().cwiseSqrt();
  double worstPhi = 0.0, worstQ = 0.0;
  for (int i = 0; i < 27; ++i)
    for (int j = 0; j < 27; ++j) {
      // Φ_ij maps state j to state i: compare it in units of state i per state j.
      worstPhi = std::max(worstPhi, std::abs(a.Phi(i, j) - b.Phi(i, j)) * scale(j) / scale(i));
      worstQ = std::max(worstQ, std::abs(a.Qd(i, j) - b.Qd(i, j)) / (scale(i) * scale(j)));
    }
  std::printf("series vs Van Loan, 27 states: worst scaled difference Phi %.2e, Qd %.2e\n", worstPhi,
              worstQ);
  CHECK(worstPhi < 1e-9);
  CHECK(worstQ < 1e-9);

  // 3) Fast processes (GM τ = 20 ms and 3 ms: |F_ii| T = 50 and 333, where Van Loan's exp(−F T)
  // is e^333 and overflows): halved steps and doublings against the closed form and Simpson, with
  // n = 200000 (Simpson's error ∝ (T/(n τ))^4 ~ 3e-9 relative at τ = 3 ms, hence 1e-7).
  for (double fastTau : {0.02, 0.003}) {
    Eigen::MatrixXd F2 = F, Qc2 = Qc;
    F2(2, 2) = -1.0 / fastTau;
    Qc2(2, 2) = 2.0 * sigmaB * sigmaB / fastTau;
    const DiscreteSystem c = discretize(F2, Qc2, T);
    const Eigen::Matrix3d Phi2 = phiClosed(T, fastTau);
    const int n2 = 200000;
    Eigen::Matrix3d Qd2 = Eigen::Matrix3d::Zero();
    for (int i = 0; i <= n2; ++i) {
      const double t = T * i / n2, w = (i == 0 || i == n2) ? 1.0 : (i % 2 ? 4.0 : 2.0);
      const Eigen::Matrix3d Ps = phiClosed(t, fastTau);
      Qd2 += w * Ps * Eigen::Matrix3d(Qc2) * Ps.transpose();
    }
    Qd2 *= T / (3.0 * n2);
    INFO("tau = " << fastTau);
    CHECK(c.Phi.allFinite());
    CHECK((c.Phi - Eigen::MatrixXd(Phi2)).norm() <= 1e-10 * Phi2.norm());
    for (int i = 0; i < 3; ++i)  // each entry in its own scale (the bias variance is tiny)
      for (int j = 0; j < 3; ++j)
        CHECK(std::abs(c.Qd(i, j) - Qd2(i, j)) <= 1e-7 * std::sqrt(Qd2(i, i) * Qd2(j, j)));
  }
}
