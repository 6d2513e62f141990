// A sampled (AR) sensor process seen by a filter whose step holds many of its samples
// (sim/aided/step_aggregation.hpp), against truths computed outside it:
//  1) closed forms from the AR autocovariance r(k) (Yule-Walker, errormodels/ar_model.hpp): the
//     variance of any weighted sum of N consecutive samples of a stationary AR is wᵀ R w with
//     R_ij = r(|i − j|); for the plain sum, Σ_{|k|<N} (N − |k|) r(k) (Box, Jenkins & Reinsel
//     2008, §2.1); its covariance with the state after the step is Σ_n w_n r(|m − i − n|);
//  2) the filter's propagation over a 1 s step against the joint system (INS errors + AR
//     states) propagated sample by sample at the AR's rate with Van Loan's matrix exponential.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "common/constants.hpp"
#include "errormodels/ar_model.hpp"
#include "nav/earth.hpp"
#include "sim/aided/discretize.hpp"
#include "sim/aided/error_state_filter.hpp"
#include "sim/aided/step_aggregation.hpp"

using namespace sinsim::sim::aided;

using sinsim::kRadPerDeg;

namespace {

// The moment weights of sample n of N in μ_k = ∫_0^1 (1 − σ)^k/k! y dσ (y held over 1/N):
// [((N − n)/N)^(k+1) − ((N − n − 1)/N)^(k+1)] / (k+1)!.
double weight(int k, int n, int N) {
  double f = 1.0;
  for (int i = 2; i <= k + 1; ++i) f *= i;
  return (std::pow(double(N - n) / N, k + 1) - std::pow(double(N - n - 1) / N, k + 1)) / f;
}

struct Case {
  const char* name;
  std::vector<double> a;
  int N;
};

}  // namespace

TEST_CASE("AR step aggregation: moments' variances and cross-covariances equal the closed forms") {
  const std::vector<Case> cases = {
      // seed paper's gyro x AR(5) (scenarios/adis16355-ar5.yaml) over a 1 s step at 1 kHz
      {"ADIS gyro x AR(5), N = 1000", {-1.0327, -0.34341, 0.037895, 0.19732, 0.14724}, 1000},
      // the accelerometer's, whose poles are faster, over 100 samples
      {"ADIS accel x AR(5), N = 100", {-0.51552, -0.068261, -0.047218, -0.049565, -0.13655}, 100},
      // a pole 1e-3 from the unit circle (correlation of 1000 samples, the step's length)
      {"AR(2) poles 0.999, 0.5, N = 1000", {-1.499, 0.4995}, 1000},
      {"AR(1) one sample", {-0.9}, 1},
  };
  const double sigmaE = 0.7, rate = 1000.0;
  for (const Case& c : cases) {
    INFO(c.name);
    const int p = static_cast<int>(c.a.size()), N = c.N;
    const StateBlock b = arState(c.a, sigmaE, rate);
    const StepAggregation g = aggregateBlock(b, N / rate);
    REQUIRE(g.samples == N);
    const std::vector<double> r = sinsim::errormodels::ar::autocovariance(c.a, sigmaE, N + p);
    auto rr = [&r](int k) { return r[std::abs(k)]; };
    // Stationary start: the total is the initial state's part plus the step's noise part.
    const Eigen::MatrixXd muVar = g.PhiMu * b.P0 * g.PhiMu.transpose() + g.QdMuMu;
    const Eigen::MatrixXd muA = g.PhiMu * b.P0 * g.Phi.transpose() + g.QdMuA;
    const Eigen::MatrixXd aVar = g.Phi * b.P0 * g.Phi.transpose() + g.Qd;
    // Rounding only on both sides: sums of N² and N terms of one sign pattern (worst cancellation
    // at the near-unit pole, where r(k) ~ r(0) for all k: ~N ulp); 1e-9 relative leaves 1e4× room.
    constexpr double tol = 1e-9;

    // The plain sum of the N samples: N μ_0.
    double sumVar = 0.0;
    for (int k = -(N - 1); k <= N - 1; ++k) sumVar += (N - std::abs(k)) * rr(k);
    CHECK(std::abs(double(N) * N * muVar(0, 0) - sumVar) <= tol * sumVar);

    for (int k1 : {0, 1, 2, 5})
      for (int k2 : {0, 1, 3}) {
        double wRw = 0.0, norm = 0.0;
        for (int i = 0; i < N; ++i)
          for (int j = 0; j < N; ++j) {
            wRw += weight(k1, i, N) * weight(k2, j, N) * rr(i - j);
            norm += std::abs(weight(k1, i, N) * weight(k2, j, N) * rr(i - j));
          }
        INFO("k1 = " << k1 << ", k2 = " << k2);
        CHECK(std::abs(muVar(k1, k2) - wRw) <= tol * norm);
      }
    // With the state after the step, a[m] = (y[N], …, y[N − p + 1]).
    for (int k : {0, 1, 4})
      for (int i = 0; i < p; ++i) {
        double cross = 0.0, norm = 0.0;
        for (int n = 0; n < N; ++n) {
          cross += weight(k, n, N) * rr(N - i - n);
          norm += std::abs(weight(k, n, N) * rr(N - i - n));
        }
        INFO("k = " << k << ", i = " << i);
        CHECK(std::abs(muA(k, i) - cross) <= tol * norm);
      }
    // The state itself stays stationary.
    CHECK((aVar - b.P0).norm() <= tol * b.P0.norm());
  }
  CHECK_THROWS(aggregateBlock(gaussMarkovState(1.0, 1.0), 1.0));  // continuous: no samples
}

TEST_CASE("AR filter propagation over 1 s equals the joint system stepped at the AR's rate") {
  // Independent route: the INS errors and the AR(5) gyro-x states as one system, stepped over each
  // 1 ms sample with Van Loan's exponential of [[F, g c], [0, 0]] (the sample held), then the AR
  // recursion, 1000 times. The filter does the step at once (series in F T, moments of the AR).
  const std::vector<double> a = {-1.0327, -0.34341, 0.037895, 0.19732, 0.14724};
  const double sigmaE = 0.020539 * kRadPerDeg, rate = 1000.0, T = 1.0;
  FilterSensorModel m;
  m.gyro[0].blocks = {arState(a, sigmaE, rate)};
  m.accel[1].blocks = {arState({-0.6, 0.1}, 3e-3, rate)};  // a second block, another axis
  FilterOptions opt;
  opt.sigma0 << 3, 3, 5, 0.1, 0.1, 0.2, 0.005, 0.005, 0.03;
  const sinsim::nav::Earth earth;
  ErrorStateFilter filter(earth, m, opt);
  const int n = filter.size();
  REQUIRE(n == 9 + 5 + 2);
  sinsim::nav::InsErrorPoint pt;
  pt.lat = 0.8;
  pt.h = 500.0;
  pt.v_n = sinsim::nav::Vec3(12.0, -5.0, 0.3);
  pt.f_n = sinsim::nav::Vec3(1.5, -2.0, -9.81);
  pt.C_nb = Eigen::AngleAxisd(0.7, sinsim::nav::Vec3(0.2, -0.3, 1.0).normalized()).toRotationMatrix();

  // The joint per-sample system.
  Eigen::MatrixXd F, Qc;
  filter.continuousModel(pt, F, Qc);  // INS errors only: sampled blocks are not in F
  REQUIRE(F.block(0, 9, 9, n - 9).isZero());
  const sinsim::nav::Mat93 Gg = sinsim::nav::gyroErrorInput(pt.C_nb);
  const sinsim::nav::Mat93 Ga = sinsim::nav::accelErrorInput(pt.C_nb, opt.vertical);
  Eigen::MatrixXd Fh = F;
  Fh.block(0, 9, 9, 1) = Gg.col(0);   // y of the gyro-x block (its first state)
  Fh.block(0, 14, 9, 1) = Ga.col(1);  // y of the accel-y block
  for (int i = 9; i < n; ++i) Fh(i, i) = 0.0;
  const DiscreteSystem h = vanLoan(Fh, Eigen::MatrixXd::Zero(n, n), 1.0 / rate);
  Eigen::MatrixXd Phi1 = h.Phi;  // the held sample's effect on the INS errors, then the AR step
  Eigen::MatrixXd Ar = Eigen::MatrixXd::Zero(n, n);
  Ar.topLeftCorner(9, 9).setIdentity();
  Ar.block(9, 9, 5, 5) = m.gyro[0].blocks[0].A;
  Ar.block(14, 14, 2, 2) = m.accel[1].blocks[0].A;
  Phi1.bottomRightCorner(n - 9, n - 9).setIdentity();
  Phi1 = (Ar * Phi1).eval();
  Eigen::MatrixXd Q1 = Eigen::MatrixXd::Zero(n, n);
  Q1(9, 9) = sigmaE * sigmaE;
  Q1(14, 14) = 3e-3 * 3e-3;
  Eigen::MatrixXd P = filter.P();
  for (int k = 0; k < 1000; ++k) P = (Phi1 * P * Phi1.transpose() + Q1).eval();

  filter.propagate(pt, T);
  const Eigen::MatrixXd& Pf = filter.P();
  // Entry by entry in the states' own scale sqrt(P_ii P_jj): the sample-by-sample route adds
  // 1000 rounded products (~1e-13), Van Loan's Padé ~1e-13 per sample; 1e-9 is far below any
  // modelling difference (the held-sample approximation this replaces is off by O(1)).
  double worst = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      worst = std::max(worst, std::abs(Pf(i, j) - P(i, j)) / std::sqrt(P(i, i) * P(j, j)));
  INFO("worst scaled difference " << worst);
  CHECK(worst < 1e-9);
}
