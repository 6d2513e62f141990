// The filter's block-wise propagation and its O(n² m) Joseph update against the dense forms they
// replace (which test_filter_math checks against closed forms, Simpson and the DARE): the
// navigation rows of the block series against Van Loan's exponential of the whole system, the
// block prediction against Φ P Φᵀ + Qd with the whole Φ, the update against the textbook
// (I − K H) P (I − K H)ᵀ + K R Kᵀ.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <vector>

#include "common/constants.hpp"
#include "nav/earth.hpp"
#include "nav/ins_error_model.hpp"
#include "sim/aided/block_series.hpp"
#include "sim/aided/discretize.hpp"
#include "sim/aided/error_state_filter.hpp"
#include "sim/aided/kalman.hpp"
#include "sim/aided/sensor_states.hpp"
#include "filter_model_support.hpp"

using namespace sinsim::sim::aided;
namespace nav = sinsim::nav;
using sinsim::kRadPerDeg;

namespace {

nav::InsErrorPoint movingTiltedPoint() {
  nav::InsErrorPoint p;
  p.lat = 0.8;
  p.h = 500.0;
  p.v_n = nav::Vec3(12.0, -5.0, 0.3);
  p.f_n = nav::Vec3(1.5, -2.0, -9.81);
  p.C_nb = Eigen::AngleAxisd(0.7, nav::Vec3(0.2, -0.3, 1.0).normalized()).toRotationMatrix();
  return p;
}

// A continuous block of two states (a second-order Gauss-Markov: ẍ + 2ζω ẋ + ω² x = w), so that
// the series' general (matrix) block path is exercised as well as the scalar one.
StateBlock secondOrderGm(double omega, double zeta, double q) {
  StateBlock b;
  b.name = "second_order_gm";
  b.size = 2;
  b.F = Eigen::MatrixXd::Zero(2, 2);
  b.F << 0.0, 1.0, -omega * omega, -2.0 * zeta * omega;
  b.Qc = Eigen::MatrixXd::Zero(2, 2);
  b.Qc(1, 1) = q;
  b.c = Eigen::RowVectorXd::Zero(2);
  b.c(0) = 1.0;
  b.P0 = Eigen::MatrixXd::Identity(2, 2) * 1e-8;
  b.x0 = Eigen::VectorXd::Zero(2);
  return b;
}

FilterSensorModel mixedModel(double fastTau) {
  FilterSensorModel m = aidedtest::biasGmWalkModel(fastTau);
  m.accel[1].blocks.push_back(secondOrderGm(0.3, 0.2, 1e-6));
  m.gyro[2].blocks.push_back(arState({-0.9, 0.2}, 1e-4, 100.0));  // sampled: spliced in
  return m;
}

// The worst difference of two n × n covariances (or Φs), each entry in its own states' scale.
double scaledWorst(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, const Eigen::VectorXd& scale,
                   bool transition) {
  double worst = 0.0;
  for (Eigen::Index i = 0; i < a.rows(); ++i)
    for (Eigen::Index j = 0; j < a.cols(); ++j) {
      const double unit = transition ? scale(i) / scale(j) : scale(i) * scale(j);
      worst = std::max(worst, std::abs(a(i, j) - b(i, j)) / unit);
    }
  return worst;
}

}  // namespace

TEST_CASE("block series: the navigation rows equal Van Loan's exponential of the whole system") {
  // 9 INS errors + scalar blocks (bias, GM, random walk) + a two-state block, at a moving tilted
  // point, T = 1 s and 0.2 s. Van Loan's Padé scaling and squaring has a forward error ~1e-12 of
  // the largest entries; each entry is compared in its states' own scale (metres to rad/s span
  // 12 orders), to 1e-9 as the existing series-vs-Van-Loan test.
  const nav::Earth earth;
  const FilterSensorModel m = mixedModel(300.0);
  ErrorStateFilter filter(earth, m, FilterOptions{});
  const nav::InsErrorPoint p = movingTiltedPoint();
  Eigen::MatrixXd F, Qc;
  filter.continuousModel(p, F, Qc);
  const int n = int(F.rows());
  // The blocks as the filter hands them to the series: each continuous block's columns in F.
  std::vector<InputBlock> blocks;
  for (int o = 9; o < n;) {
    int s = 1;
    while (o + s < n && F.block(o, o + s, 1, 1).norm() != 0.0) ++s;  // the 2-state block's F(0,1)
    if (F.block(0, o, 9, 1).isZero()) {  // a sampled block: not in the continuous model
      o += s;
      continue;
    }
    InputBlock b;
    b.column = o;
    b.g = F.block(0, o, 9, 1);
    b.c = Eigen::RowVectorXd::Zero(s);
    b.c(0) = 1.0;
    b.F = F.block(o, o, s, s);
    b.Qc = Qc.block(o, o, s, s);
    blocks.push_back(b);
    o += s;
  }
  REQUIRE(blocks.size() == 19);  // 18 scalar + the two-state block
  for (double T : {1.0, 0.2}) {
    Eigen::MatrixXd Fc = F, Qcc = Qc;  // only the continuous states: the sampled ones are spliced
    const DiscreteSystem ref = vanLoan(Fc, Qcc, T);
    Eigen::Matrix<double, 9, Eigen::Dynamic> PhiN(9, n), QdN(9, n);
    PhiN.setZero();
    QdN.setZero();
    REQUIRE(navigationRowSeries(F.topLeftCorner<9, 9>(), Qc.topLeftCorner<9, 9>(), blocks, n, T,
                                PhiN, QdN));
    Eigen::VectorXd scale = ref.Qd.diagonal().cwiseSqrt();
    for (Eigen::Index i = 0; i < n; ++i)
      if (!(scale(i) > 0.0)) scale(i) = 1.0;  // bias and sampled states: no noise over T
    Eigen::MatrixXd a = ref.Phi, b = ref.Qd;
    a.topRows(9) = PhiN;
    b.topRows(9) = QdN;
    const double worstPhi = scaledWorst(a, ref.Phi, scale, true);
    const double worstQ = scaledWorst(b, ref.Qd, scale, false);
    INFO("T = " << T << ": worst scaled difference Phi " << worstPhi << ", Qd " << worstQ);
    CHECK(worstPhi < 1e-9);
    CHECK(worstQ < 1e-9);
  }
  // A process too fast for one series step is refused (the filter then discretises the whole).
  std::vector<InputBlock> fast = blocks;
  fast[1].F(0, 0) = -1.0 / 0.003;
  Eigen::Matrix<double, 9, Eigen::Dynamic> PhiN(9, n), QdN(9, n);
  CHECK_FALSE(navigationRowSeries(F.topLeftCorner<9, 9>(), Qc.topLeftCorner<9, 9>(), fast, n, 1.0,
                                  PhiN, QdN));
  // Non-finite input (a NaN in A, an infinite input column) is refused as well: the whole-system
  // path reports it, the series never returns NaN rows as converged.
  Eigen::Matrix<double, 9, 9> Anan = F.topLeftCorner<9, 9>();
  Anan(3, 7) = NAN;
  CHECK_FALSE(navigationRowSeries(Anan, Qc.topLeftCorner<9, 9>(), blocks, n, 1.0, PhiN, QdN));
  std::vector<InputBlock> infinite = blocks;
  infinite[0].g[6] = INFINITY;
  CHECK_FALSE(navigationRowSeries(F.topLeftCorner<9, 9>(), Qc.topLeftCorner<9, 9>(), infinite, n,
                                  1.0, PhiN, QdN));
}

TEST_CASE("block propagation and O(n² m) Joseph update equal the dense forms") {
  // The filter's propagate (block series, cached sensor blocks, AR splice, block prediction) and
  // its position update against the same steps formed densely: Φ and Qd of the whole continuous
  // system by discretize (halving and doubling for the 3 ms GM case, which the filter also takes),
  // the AR block spliced by the filter's own rule is not re-derived here (step_aggregation tests
  // it), so the model for the dense comparison has no sampled block.
  const nav::Earth earth;
  for (double fastTau : {300.0, 0.003}) {
    FilterSensorModel m = mixedModel(fastTau);
    m.gyro[2].blocks.pop_back();  // no sampled block (see above)
    FilterOptions opt;
    opt.sigma0 << 3, 3, 5, 0.1, 0.1, 0.1, 5e-3, 5e-3, 3e-2;
    ErrorStateFilter filter(earth, m, opt);
    const nav::InsErrorPoint p = movingTiltedPoint();
    const int n = filter.size();
    // A full, correlated prior: a few steps of fixes first.
    for (int k = 0; k < 5; ++k) {
      filter.propagate(p, 1.0);
      filter.updatePosition(nav::Vec3(0.5, -0.2, 0.1), nav::Vec3(0.4, 0.1, -0.9), nav::Vec3(1, 1, 2));
      filter.takeNavCorrection();
    }
    Eigen::VectorXd x = filter.x();
    Eigen::MatrixXd P = filter.P();
    Eigen::MatrixXd F, Qc;
    filter.continuousModel(p, F, Qc);
    const DiscreteSystem d = discretize(F, Qc, 1.0);
    kalmanPredict(x, P, d.Phi, d.Qd);
    filter.propagate(p, 1.0);
    const Eigen::VectorXd scale = P.diagonal().cwiseSqrt();
    // Same terms in another order: rounding of sums of up to n terms of Φ P Φᵀ, ~1e-13 relative;
    // 1e-10 leaves room for it, not for a missing or wrong block.
    const double worstP = scaledWorst(filter.P(), P, scale, false);
    INFO("tau = " << fastTau << ": predicted P, worst scaled difference " << worstP);
    CHECK(worstP < 1e-10);
    for (int i = 9; i < n; ++i) CHECK(std::abs(filter.x()(i) - x(i)) <= 1e-10 * scale(i));

    // The update: the textbook Joseph form with the whole (I − K H).
    Eigen::MatrixXd H = Eigen::MatrixXd::Zero(3, n);
    H.block<3, 3>(0, 0).setIdentity();
    const nav::Vec3 lever(0.4, 0.1, -0.9);
    H.block<3, 3>(0, 6) = nav::skew(lever);
    const Eigen::Matrix3d R = nav::Vec3(1, 1, 4).asDiagonal();
    const Eigen::MatrixXd Pm = filter.P();
    const Eigen::MatrixXd K = Pm * H.transpose() * (H * Pm * H.transpose() + R).inverse();
    const Eigen::MatrixXd IKH = Eigen::MatrixXd::Identity(n, n) - K * H;
    const Eigen::MatrixXd Pref = IKH * Pm * IKH.transpose() + K * R * K.transpose();
    filter.updatePosition(nav::Vec3(0.3, 0.7, -1.1), lever, nav::Vec3(1, 1, 2));
    const double worstU = scaledWorst(filter.P(), Pref, Pref.diagonal().cwiseSqrt(), false);
    INFO("updated P, worst scaled difference " << worstU);
    CHECK(worstU < 1e-10);
  }
}

TEST_CASE("a copied filter does not depend on the original") {
  // The filter once held pointers into its own model: a copy pointed into the original's, and
  // dangled once that was gone. Copy, destroy the original (and reuse its memory), then the copy
  // must propagate and update exactly as a filter built fresh from the same model.
  const nav::Earth earth;
  const FilterSensorModel m = mixedModel(300.0);
  FilterOptions opt;
  opt.sigma0 << 3, 3, 5, 0.1, 0.1, 0.1, 5e-3, 5e-3, 3e-2;
  auto original = std::make_unique<ErrorStateFilter>(earth, m, opt);
  ErrorStateFilter copy = *original;
  original.reset();
  std::vector<FilterSensorModel> clutter(4, mixedModel(1.0));  // likely reuses the freed blocks
  ErrorStateFilter fresh(earth, m, opt);
  const nav::InsErrorPoint p = movingTiltedPoint();
  for (ErrorStateFilter* f : {&copy, &fresh}) {
    f->propagate(p, 1.0);
    f->updatePosition(nav::Vec3(0.5, -0.2, 0.1), nav::Vec3(0.4, 0.1, -0.9), nav::Vec3(1, 1, 2));
    f->propagate(p, 1.0);
  }
  CHECK(copy.P() == fresh.P());  // bit for bit: the same model, the same operations
  CHECK(copy.x() == fresh.x());
  CHECK(clutter.size() == 4);
}

TEST_CASE("scale-factor states: their input columns, and propagate equals Van Loan of the whole "
          "system at a moving point") {
  // A gyro scale error s enters as the rate error diag(ω_ib_b) s and an accelerometer one as
  // diag(f_b) s (Titterton & Weston 2004, §12.3.3), so through the bias inputs with C_nb replaced
  // by the step's mean C_nb diag(u): ψ̇ ∋ −C_nb ω_i s_gi, δv̇ ∋ C_nb f_i s_ai. The columns are
  // built here from that formula, the propagation (block series with the scale blocks as scalar
  // inputs, the bias / GM / random-walk blocks beside them) compared with Φ P Φᵀ + Qd from Van
  // Loan's exponential of the whole continuous system, at T = 1 s and 0.2 s; and with a 3 ms GM
  // (the filter's whole-system path) against discretize of the whole system.
  const nav::Earth earth;
  const nav::InsErrorPoint p = movingTiltedPoint();
  const nav::Vec3 omega_b(0.05, -0.12, 0.35);          // [rad/s] a turning, rolling vehicle
  const nav::Vec3 f_b = p.C_nb.transpose() * p.f_n;     // [m/s^2]
  ScaleInput in;
  in.C_omega = p.C_nb * omega_b.asDiagonal();
  in.C_f = p.C_nb * f_b.asDiagonal();
  for (double fastTau : {300.0, 0.003}) {
    FilterSensorModel m = mixedModel(fastTau);
    m.gyro[2].blocks.pop_back();  // no sampled block (as above)
    for (int i = 0; i < 3; ++i) {
      m.gyro[i].blocks.push_back(scaleFactorState(3000e-6));
      m.accel[i].blocks.push_back(scaleFactorState(1000e-6 * (i + 1)));
    }
    FilterOptions opt;
    opt.sigma0 << 3, 3, 5, 0.1, 0.1, 0.1, 5e-3, 5e-3, 3e-2;
    ErrorStateFilter filter(earth, m, opt);
    REQUIRE(filter.hasScaleStates());
    const int n = filter.size();
    Eigen::MatrixXd F, Qc;
    filter.continuousModel(p, F, Qc, in);
    // The scale states' columns: the last state of each axis's list, in axis order.
    int offset = 9, checked = 0;
    for (int axis = 0; axis < 6; ++axis) {
      const SensorAxisModel& am = axis < 3 ? m.gyro[axis] : m.accel[axis - 3];
      for (const StateBlock& b : am.blocks) {
        if (b.scale) {
          Eigen::Matrix<double, 9, 1> col = Eigen::Matrix<double, 9, 1>::Zero();
          if (axis < 3) col.segment<3>(6) = -p.C_nb.col(axis) * omega_b[axis];
          else col.segment<3>(3) = p.C_nb.col(axis - 3) * f_b[axis - 3];
          CHECK((F.block(0, offset, 9, 1) - col).norm() <= 1e-15 * col.norm());
          CHECK(F.row(offset).isZero());  // a constant
          CHECK(Qc.row(offset).isZero());
          ++checked;
        }
        offset += b.size;
      }
    }
    REQUIRE(checked == 6);
    for (double T : {1.0, 0.2}) {
      for (int k = 0; k < 5; ++k) {  // a full, correlated prior first
        filter.propagate(p, T, in);
        filter.updatePosition(nav::Vec3(0.5, -0.2, 0.1), nav::Vec3(0.4, 0.1, -0.9),
                              nav::Vec3(1, 1, 2));
        filter.takeNavCorrection();
      }
      Eigen::VectorXd x = filter.x();
      Eigen::MatrixXd P = filter.P();
      // Van Loan's exp(−F T) block overflows for the 3 ms GM (e^300): there the reference is
      // discretize's halving and doubling, checked against the closed form in test_filter_math.
      const DiscreteSystem d = fastTau > 1.0 ? vanLoan(F, Qc, T) : discretize(F, Qc, T);
      kalmanPredict(x, P, d.Phi, d.Qd);
      filter.propagate(p, T, in);
      const Eigen::VectorXd scale = P.diagonal().cwiseSqrt();
      // Van Loan's Padé forward error ~1e-12 of the largest entries, each entry compared in its
      // states' own scale as in the block-series test above: 1e-9.
      const double worstP = scaledWorst(filter.P(), P, scale, false);
      INFO("tau = " << fastTau << ", T = " << T << ": predicted P, worst scaled difference "
                    << worstP);
      CHECK(worstP < 1e-9);
      for (int i = 9; i < n; ++i) CHECK(std::abs(filter.x()(i) - x(i)) <= 1e-9 * scale(i));
    }
  }
}

TEST_CASE("scale-factor states without motion: no input, the prior kept") {
  // Zero rate and force (a ScaleInput of zeros, as without motion) couple nothing: the scale
  // states' variance stays at its prior and their covariance with the navigation stays zero.
  const nav::Earth earth;
  FilterSensorModel m;
  for (int i = 0; i < 3; ++i) {
    m.gyro[i].blocks = {biasState(1e-5), scaleFactorState(2000e-6)};
    m.accel[i].blocks = {scaleFactorState(500e-6)};
  }
  FilterOptions opt;
  opt.sigma0 << 3, 3, 5, 0.1, 0.1, 0.1, 5e-3, 5e-3, 3e-2;
  ErrorStateFilter filter(earth, m, opt);
  for (int k = 0; k < 3; ++k) {
    filter.propagate(movingTiltedPoint(), 1.0);
    filter.updatePosition(nav::Vec3(0.5, -0.2, 0.1), nav::Vec3::Zero(), nav::Vec3(1, 1, 2));
  }
  // layout: gyro x bias 9, scale 10; y 11, 12; z 13, 14; accel scale 15, 16, 17
  for (int i : {10, 12, 14, 15, 16, 17}) {
    CHECK(filter.P()(i, i) == (i <= 14 ? 2000e-6 * 2000e-6 : 500e-6 * 500e-6));
    CHECK(filter.P().row(i).head<9>().isZero());
  }
  CHECK(filter.gyroScale().isZero());
}
