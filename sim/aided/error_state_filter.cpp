#include "sim/aided/error_state_filter.hpp"

#include <cmath>
#include <string>

#include "common/error.hpp"
#include "nav/attitude.hpp"
#include "sim/aided/step_aggregation.hpp"

namespace sinsim::sim::aided {

int FilterSensorModel::stateCount() const {
  int n = 0;
  for (int i = 0; i < 3; ++i)
    for (const auto* axis : {&gyro[i], &accel[i]})
      for (const StateBlock& b : axis->blocks) n += b.size;
  return n;
}

ErrorStateFilter::ErrorStateFilter(const nav::Earth& earth, FilterSensorModel model,
                                   const FilterOptions& options)
    : earth_(&earth), model_(std::move(model)), options_(options) {
  const int n = 9 + model_.stateCount();
  x_ = Eigen::VectorXd::Zero(n);
  P_ = Eigen::MatrixXd::Zero(n, n);
  P_.topLeftCorner<9, 9>() = options_.sigma0.array().square().matrix().asDiagonal();
  int offset = 9;
  for (int axis = 0; axis < 6; ++axis) {
    const SensorAxisModel& m = axis < 3 ? model_.gyro[axis] : model_.accel[axis - 3];
    for (const StateBlock& b : m.blocks) {
      placed_.push_back({axis, offset, b});
      hasScale_ = hasScale_ || b.scale;
      P_.block(offset, offset, b.size, b.size) = b.P0;
      x_.segment(offset, b.size) = b.x0;
      if (!b.discrete) {
        inputs_.push_back({offset, Eigen::Matrix<double, 9, 1>::Zero(), b.c, b.F, b.Qc});
        inputPlaced_.push_back(placed_.size() - 1);
      }
      offset += b.size;
      aggregations_.emplace_back();
    }
  }
  refreshSensorEstimates();
}

void ErrorStateFilter::refreshSensorEstimates() {
  gyroEstimate_ = sensorError(0, false);
  accelEstimate_ = sensorError(3, false);
  if (!hasScale_) return;
  gyroScaleEstimate_ = sensorError(0, true);
  accelScaleEstimate_ = sensorError(3, true);
}

// The continuous blocks' estimate of the axes firstAxis..firstAxis+2: the additive error (scale
// false) or the scale factor (scale true).
nav::Vec3 ErrorStateFilter::sensorError(int firstAxis, bool scale) const {
  nav::Vec3 e = nav::Vec3::Zero();
  for (const Placed& p : placed_)
    if (!p.block.discrete && p.block.scale == scale && p.axis >= firstAxis && p.axis < firstAxis + 3)
      e[p.axis - firstAxis] += p.block.c.dot(x_.segment(p.offset, p.block.size));
  return e;
}

ErrorStateFilter::AxisInputs ErrorStateFilter::axisInputsAt(const nav::InsErrorPoint& p,
                                                            const ScaleInput& s) const {
  AxisInputs in;
  in.Gg = nav::gyroErrorInput(p.C_nb);
  in.Ga = nav::accelErrorInput(p.C_nb, options_.vertical);
  // A scale error s_i is the bias ω_i s_i (f_i s_i): the same input with C_nb diag(u) for C_nb.
  in.Sg = nav::gyroErrorInput(s.C_omega);
  in.Sa = nav::accelErrorInput(s.C_f, options_.vertical);
  return in;
}

Eigen::Matrix<double, 9, 1> ErrorStateFilter::AxisInputs::column(const Placed& pl) const {
  if (pl.block.scale) return pl.axis < 3 ? Sg.col(pl.axis) : Sa.col(pl.axis - 3);
  return pl.axis < 3 ? Gg.col(pl.axis) : Ga.col(pl.axis - 3);
}

// White sensor noise enters the INS errors directly: Q_n = G_g diag(N_g²) G_gᵀ + G_a diag(N_a²) G_aᵀ.
nav::Mat9 ErrorStateFilter::whiteNoiseInput(const nav::Mat93& Gg, const nav::Mat93& Ga) const {
  nav::Vec3 Ng2, Na2;
  for (int i = 0; i < 3; ++i) {
    Ng2[i] = model_.gyro[i].whiteDensity * model_.gyro[i].whiteDensity;
    Na2[i] = model_.accel[i].whiteDensity * model_.accel[i].whiteDensity;
  }
  return Gg * Ng2.asDiagonal() * Gg.transpose() + Ga * Na2.asDiagonal() * Ga.transpose();
}

void ErrorStateFilter::continuousModel(const nav::InsErrorPoint& p, Eigen::MatrixXd& F,
                                       Eigen::MatrixXd& Qc, const ScaleInput& s) const {
  const int n = size();
  F = Eigen::MatrixXd::Zero(n, n);
  Qc = Eigen::MatrixXd::Zero(n, n);
  F.topLeftCorner<9, 9>() =
      nav::insErrorDynamics(*earth_, p, options_.vertical, options_.k1, options_.k2);
  const AxisInputs in = axisInputsAt(p, s);
  Qc.topLeftCorner<9, 9>() = whiteNoiseInput(in.Gg, in.Ga);
  for (const Placed& pl : placed_) {
    const StateBlock& b = pl.block;
    const Eigen::Matrix<double, 9, 1> g = in.column(pl);
    if (b.discrete) continue;  // sampled processes: aggregated over the step (propagate)
    F.block(0, pl.offset, 9, b.size) = g * b.c;  // the sensor error c x drives the INS errors
    F.block(pl.offset, pl.offset, b.size, b.size) = b.F;
    Qc.block(pl.offset, pl.offset, b.size, b.size) = b.Qc;
  }
}

const StepAggregation& ErrorStateFilter::aggregation(std::size_t placedIndex, double T) {
  const StateBlock& b = placed_[placedIndex].block;
  const int m = samplesPerStep(b, T);
  std::vector<StepAggregation>& cache = aggregations_[placedIndex];
  for (const StepAggregation& g : cache)
    if (g.samples == m) return g;
  cache.push_back(aggregateBlock(b, T));
  return cache.back();
}

const std::vector<DiscreteSystem>& ErrorStateFilter::continuousBlocks(double T) {
  for (const BlockCache& c : blockCache_)
    if (c.T == T) return c.blocks;
  // A step length not seen before (the GNSS clock's steps are all equal but the first and any
  // after an alignment): a few are kept, the oldest replaced.
  constexpr std::size_t kKept = 4;
  if (blockCache_.size() == kKept) blockCache_.erase(blockCache_.begin());
  BlockCache c{T, {}};
  for (const InputBlock& b : inputs_) c.blocks.push_back(discretize(b.F, b.Qc, T));
  blockCache_.push_back(std::move(c));
  return blockCache_.back().blocks;
}

void ErrorStateFilter::discretizeContinuous(const nav::InsErrorPoint& p, const ScaleInput& s,
                                            double T, BlockTransition& Phi, Eigen::MatrixXd& Qd) {
  const int n = size();
  const nav::Mat9 A = nav::insErrorDynamics(*earth_, p, options_.vertical, options_.k1, options_.k2);
  const AxisInputs in = axisInputsAt(p, s);
  const nav::Mat9 Qn = whiteNoiseInput(in.Gg, in.Ga);
  for (std::size_t i = 0; i < inputs_.size(); ++i) inputs_[i].g = in.column(placed_[inputPlaced_[i]]);
  Phi.nav.setZero(9, n);
  qdN_.setZero(9, n);
  if (Phi.block.size() != placed_.size()) {
    Phi.offset.clear();
    Phi.block.clear();
    for (const Placed& pl : placed_) {
      Phi.offset.push_back(pl.offset);
      Phi.block.emplace_back(pl.block.size, pl.block.size);
    }
  }
  for (Eigen::MatrixXd& b : Phi.block) b.setIdentity();
  Qd.setZero(n, n);
  const Eigen::Matrix<double, 9, Eigen::Dynamic>& QdN = qdN_;
  if (navigationRowSeries(A, Qn, inputs_, n, T, Phi.nav, qdN_)) {
    const std::vector<DiscreteSystem>& own = continuousBlocks(T);
    for (std::size_t i = 0; i < inputs_.size(); ++i) {
      const int o = inputs_[i].column;
      Phi.block[inputPlaced_[i]] = own[i].Phi;
      Qd.block(o, o, own[i].Qd.rows(), own[i].Qd.cols()) = own[i].Qd;
    }
    Qd.topRows<9>() = QdN;
    Qd.leftCols<9>() = QdN.transpose();
    return;
  }
  // A process too fast for one series step: the whole system, halving and doubling.
  Eigen::MatrixXd F, Qc;
  continuousModel(p, F, Qc, s);
  const DiscreteSystem d = discretize(F, Qc, T);
  Phi.nav = d.Phi.topRows<9>();
  for (std::size_t i = 0; i < placed_.size(); ++i) {
    const int o = placed_[i].offset, sz = placed_[i].block.size;
    Phi.block[i] = d.Phi.block(o, o, sz, sz);
  }
  Qd = d.Qd;
}

// A discrete block's exact Φ and Qd over T (step_aggregation.hpp): the INS errors see it through
// T Σ_k (A T)^k g μ_k, g its input column, A the INS error dynamics.
void ErrorStateFilter::spliceDiscrete(std::size_t placedIndex, const Eigen::Matrix<double, 9, 9>& A,
                                      const Eigen::Matrix<double, 9, 1>& g, double T,
                                      BlockTransition& Phi, Eigen::MatrixXd& Qd,
                                      Eigen::Matrix<double, 9, 1>& navMean) {
  const Placed& pl = placed_[placedIndex];
  const StepAggregation& agg = aggregation(placedIndex, T);
  const int K = agg.order, o = pl.offset, p = pl.block.size;
  const Eigen::Matrix<double, 9, 9> FT = A * T;
  Eigen::Matrix<double, 9, Eigen::Dynamic> U(9, K + 1);  // u_k = (F T)^k g
  U.col(0) = g;
  for (int k = 1; k <= K; ++k) U.col(k) = FT * U.col(k - 1);
  // |μ_k| <= max|y| / (k+1)!: the last term must be below rounding of the largest.
  double largest = 0.0, inv = 1.0;
  for (int k = 0; k <= K; ++k) {
    inv /= (k + 1);
    largest = std::max(largest, U.col(k).lpNorm<Eigen::Infinity>() * inv);
  }
  if (!(U.col(K).lpNorm<Eigen::Infinity>() * inv <= 0x1p-53 * largest))
    throw InputError("filter: the step of " + std::to_string(T) +
                     " s is too long for the series of a sampled sensor process (ar); use a "
                     "higher GNSS rate");
  const Eigen::MatrixXd PhiNa = T * U * agg.PhiMu;  // 9 × p
  navMean += PhiNa * x_.segment(o, p);
  Phi.nav.block(0, o, 9, p) = PhiNa;
  Phi.block[placedIndex] = agg.Phi;
  const Eigen::MatrixXd QNa = T * U * agg.QdMuA;
  Qd.block(0, o, 9, p) = QNa;
  Qd.block(o, 0, p, 9) = QNa.transpose();
  Qd.block(o, o, p, p) = agg.Qd;
  Qd.topLeftCorner<9, 9>() += (T * T) * U * agg.QdMuMu * U.transpose();
}

void ErrorStateFilter::propagate(const nav::InsErrorPoint& p, double T, const ScaleInput& s) {
  BlockTransition& Phi = phi_;
  Eigen::MatrixXd& Qd = qd_;
  discretizeContinuous(p, s, T, Phi, Qd);
  Eigen::Matrix<double, 9, 1> navMean = Eigen::Matrix<double, 9, 1>::Zero();
  const nav::Mat93 Gg = nav::gyroErrorInput(p.C_nb);
  const nav::Mat93 Ga = nav::accelErrorInput(p.C_nb, options_.vertical);
  bool anyDiscrete = false;
  nav::Mat9 A;
  for (std::size_t i = 0; i < placed_.size(); ++i) {
    const Placed& pl = placed_[i];
    if (!pl.block.discrete) continue;
    if (!anyDiscrete)
      A = nav::insErrorDynamics(*earth_, p, options_.vertical, options_.k1, options_.k2);
    anyDiscrete = true;
    const Eigen::Matrix<double, 9, 1> g = pl.axis < 3 ? Gg.col(pl.axis) : Ga.col(pl.axis - 3);
    spliceDiscrete(i, A, g, T, Phi, Qd, navMean);
  }
  kalmanPredict(x_, P_, Phi, Qd);
  // Closed loop: the caller removes the continuous blocks' estimate from the IMU, so the drift
  // Φ_ns x_s the open-loop prediction adds to the navigation errors never happens. A sampled
  // block's estimate decays within its correlation time, far inside the step, and is not
  // compensated: its predicted effect stays in the navigation states for the caller to feed back.
  x_.head<9>() = navMean;
  refreshSensorEstimates();
}

Innovation ErrorStateFilter::updatePosition(const nav::Vec3& dz, const nav::Vec3& leverArm_n,
                                            const nav::Vec3& sigma) {
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(3, size());
  H.block<3, 3>(0, nav::kPos).setIdentity();
  // Ĉ_nb l = (I − [ψ×]) C_nb l = C_nb l + (C_nb l) × ψ
  H.block<3, 3>(0, nav::kAtt) = nav::skew(leverArm_n);
  const Eigen::MatrixXd R = sigma.array().square().matrix().asDiagonal();
  Innovation in = kalmanUpdate(x_, P_, dz, H, R);
  refreshSensorEstimates();
  return in;
}

Innovation ErrorStateFilter::updateVelocity(const nav::Vec3& dz, const nav::Vec3& armVelocity_n,
                                            const nav::Vec3& sigma) {
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(3, size());
  H.block<3, 3>(0, nav::kVel).setIdentity();
  // The lever-arm term Ĉ_nb (ω × l) through the attitude error, as the position's lever arm; its
  // part through the gyro error, C_nb (δω × l), is left out: ≤ |δω| |l|, 5e-5 m/s for 10 deg/h at
  // 1 m, against velocity fixes of centimetres per second.
  H.block<3, 3>(0, nav::kAtt) = nav::skew(armVelocity_n);
  const Eigen::MatrixXd R = sigma.array().square().matrix().asDiagonal();
  Innovation in = kalmanUpdate(x_, P_, dz, H, R);
  refreshSensorEstimates();
  return in;
}

Eigen::Matrix<double, 9, 1> ErrorStateFilter::takeNavCorrection() {
  Eigen::Matrix<double, 9, 1> c = x_.head<9>();
  x_.head<9>().setZero();
  return c;
}

}  // namespace sinsim::sim::aided
