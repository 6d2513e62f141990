#include "sim/aided/error_state_filter.hpp"

#include "nav/attitude.hpp"

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
      placed_.push_back({axis, offset, &b});
      P_.block(offset, offset, b.size, b.size) = b.P0;
      x_.segment(offset, b.size) = b.x0;
      offset += b.size;
    }
  }
}

nav::Vec3 ErrorStateFilter::sensorError(int firstAxis) const {
  nav::Vec3 e = nav::Vec3::Zero();
  for (const Placed& p : placed_)
    if (p.axis >= firstAxis && p.axis < firstAxis + 3)
      e[p.axis - firstAxis] += p.block->c.dot(x_.segment(p.offset, p.block->size));
  return e;
}

void ErrorStateFilter::continuousModel(const nav::InsErrorPoint& p, Eigen::MatrixXd& F,
                                       Eigen::MatrixXd& Qc) const {
  const int n = size();
  F = Eigen::MatrixXd::Zero(n, n);
  Qc = Eigen::MatrixXd::Zero(n, n);
  F.topLeftCorner<9, 9>() =
      nav::insErrorDynamics(*earth_, p, options_.vertical, options_.k1, options_.k2);
  const nav::Mat93 Gg = nav::gyroErrorInput(p.C_nb);
  const nav::Mat93 Ga = nav::accelErrorInput(p.C_nb, options_.vertical);
  // White sensor noise enters the INS errors directly: Qc += G diag(N²) Gᵀ.
  nav::Vec3 Ng2, Na2;
  for (int i = 0; i < 3; ++i) {
    Ng2[i] = model_.gyro[i].whiteDensity * model_.gyro[i].whiteDensity;
    Na2[i] = model_.accel[i].whiteDensity * model_.accel[i].whiteDensity;
  }
  Qc.topLeftCorner<9, 9>() =
      Gg * Ng2.asDiagonal() * Gg.transpose() + Ga * Na2.asDiagonal() * Ga.transpose();
  for (const Placed& pl : placed_) {
    const StateBlock& b = *pl.block;
    const auto g = pl.axis < 3 ? Gg.col(pl.axis) : Ga.col(pl.axis - 3);
    F.block(0, pl.offset, 9, b.size) = g * b.c;  // the sensor error c x drives the INS errors
    if (!b.discrete) {  // discrete blocks are held over the step (their A^m is spliced in later)
      F.block(pl.offset, pl.offset, b.size, b.size) = b.F;
      Qc.block(pl.offset, pl.offset, b.size, b.size) = b.Qc;
    }
  }
}

void ErrorStateFilter::propagate(const nav::InsErrorPoint& p, double T) {
  Eigen::MatrixXd F, Qc;
  continuousModel(p, F, Qc);
  DiscreteSystem d = discretize(F, Qc, T);
  for (const Placed& pl : placed_) {
    if (!pl.block->discrete) continue;
    const DiscreteSystem s = discretizeBlock(*pl.block, T);
    d.Phi.block(pl.offset, pl.offset, pl.block->size, pl.block->size) = s.Phi;
    d.Qd.block(pl.offset, pl.offset, pl.block->size, pl.block->size) = s.Qd;
  }
  kalmanPredict(x_, P_, d.Phi, d.Qd);
  // Closed loop: the caller removes the sensor-error estimate from the IMU, so the drift Φ_ns x_s
  // the open-loop prediction adds to the navigation errors never happens; their mean stays zero.
  x_.head<9>().setZero();
}

Innovation ErrorStateFilter::updatePosition(const nav::Vec3& dz, const nav::Vec3& leverArm_n,
                                            const nav::Vec3& sigma) {
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(3, size());
  H.block<3, 3>(0, nav::kPos).setIdentity();
  // Ĉ_nb l = (I − [ψ×]) C_nb l = C_nb l + (C_nb l) × ψ
  H.block<3, 3>(0, nav::kAtt) = nav::skew(leverArm_n);
  const Eigen::MatrixXd R = sigma.array().square().matrix().asDiagonal();
  return kalmanUpdate(x_, P_, dz, H, R);
}

Innovation ErrorStateFilter::updateVelocity(const nav::Vec3& dz, const nav::Vec3& sigma) {
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(3, size());
  H.block<3, 3>(0, nav::kVel).setIdentity();
  const Eigen::MatrixXd R = sigma.array().square().matrix().asDiagonal();
  return kalmanUpdate(x_, P_, dz, H, R);
}

Eigen::Matrix<double, 9, 1> ErrorStateFilter::takeNavCorrection() {
  Eigen::Matrix<double, 9, 1> c = x_.head<9>();
  x_.head<9>().setZero();
  return c;
}

}  // namespace sinsim::sim::aided
