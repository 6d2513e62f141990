// The loosely coupled GNSS/INS error-state Kalman filter: the 9 INS error states of
// nav/ins_error_model.hpp followed by the sensor-error states of the filter's OWN sensor model
// (sensor_states.hpp; it may differ from the truth model by design). Closed loop: after each
// update the caller takes the navigation correction (and the states are zeroed) and compensates
// the IMU with the sensor-error estimate.
//
// Propagation is exact for the error dynamics held constant over the step: Φ and Qd of the
// continuous part (INS errors, white noise, bias / random-walk / Gauss-Markov states) from their
// series summed to rounding (discretize.hpp; Van Loan's matrix exponential where the series is not
// safe); the sampled (AR) blocks, whose samples are much shorter than the step, by their exact
// aggregation over the step's samples (step_aggregation.hpp) spliced in.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "nav/earth.hpp"
#include "nav/ins_error_model.hpp"
#include "sim/aided/block_series.hpp"
#include "sim/aided/kalman.hpp"
#include "sim/aided/sensor_states.hpp"
#include "sim/aided/step_aggregation.hpp"

namespace sinsim::sim::aided {

/// The error processes of one sensor axis as the filter models them.
struct SensorAxisModel {
  double whiteDensity = 0.0;       // white-noise density [signal/sqrt(Hz)]; 0: none
  std::vector<StateBlock> blocks;  // state-carrying processes, summed
};

/// The filter's IMU model: gyro axes in [rad/s], accelerometer axes in [m/s^2].
struct FilterSensorModel {
  SensorAxisModel gyro[3], accel[3];
  int stateCount() const;
};

/// How the scale-factor states enter over a step: the means over the step of C_nb diag(ω_ib_b)
/// [rad/s] and C_nb diag(f_b) [m/s^2] from the measured (compensated) signals, so that a gyro
/// scale error s_i enters ψ through −(column i) s_i and an accelerometer one δv through
/// (column i) s_i, as a bias enters through C_nb's column (Titterton & Weston 2004, §12.3.3:
/// δω_ib_b = diag(ω_ib_b) s_g, δf_b = diag(f_b) s_a). The mean of the product over the step is
/// the exact average input of a constant s (the rest of the linearisation is held at the step's
/// means likewise). Zero (no rotation, no force) when the filter has no scale-factor states.
struct ScaleInput {
  nav::Mat3 C_omega = nav::Mat3::Zero();  // [rad/s]
  nav::Mat3 C_f = nav::Mat3::Zero();      // [m/s^2]
};

struct FilterOptions {
  nav::VerticalChannel vertical = nav::VerticalChannel::Free;
  double k1 = 0.0, k2 = 0.0;  // damped vertical channel gains [1/s], [1/s^2]
  /// Initial 1-sigma of δr_n [m], δv_n [m/s], ψ [rad].
  Eigen::Matrix<double, 9, 1> sigma0 = Eigen::Matrix<double, 9, 1>::Zero();
};

class ErrorStateFilter {
 public:
  /// The earth must outlive the filter.
  ErrorStateFilter(const nav::Earth& earth, FilterSensorModel model, const FilterOptions& options);

  int size() const { return static_cast<int>(x_.size()); }
  const Eigen::VectorXd& x() const { return x_; }
  const Eigen::MatrixXd& P() const { return P_; }
  /// Current estimates of the gyro [rad/s] and accelerometer [m/s^2] errors, per body axis, that
  /// the caller compensates the IMU with: the continuous blocks' (bias, random walk, GM). A
  /// sampled (ar) block is not compensated; its predicted effect on the INS errors over each step
  /// is left in x's navigation part by propagate.
  const nav::Vec3& gyroError() const { return gyroEstimate_; }
  const nav::Vec3& accelError() const { return accelEstimate_; }
  /// Current scale-factor estimates per body axis [-] (zero without scale-factor states): the
  /// caller removes s_i u_i from each measured increment u_i as it removes the biases.
  const nav::Vec3& gyroScale() const { return gyroScaleEstimate_; }
  const nav::Vec3& accelScale() const { return accelScaleEstimate_; }
  /// Whether the model has scale-factor states (and propagate needs a ScaleInput).
  bool hasScaleStates() const { return hasScale_; }

  /// The damped vertical channel's gains as the strapdown runs them [1/s], [1/s^2].
  void setVerticalGains(double k1, double k2) {
    options_.k1 = k1;
    options_.k2 = k2;
  }
  /// Propagates x and P over T [s] with the error dynamics linearised at p. Closed loop: the
  /// navigation part of x is the predicted effect of the sampled blocks' estimates only (zero
  /// without them); the caller compensates the IMU with gyroError/accelError for the rest and
  /// feeds the navigation part back with takeNavCorrection.
  /// s: the step's scale-factor inputs (ignored without scale-factor states).
  void propagate(const nav::InsErrorPoint& p, double T, const ScaleInput& s = ScaleInput());
  /// Continuous system (F, Qc) at p (and s), for tests and for callers that discretise themselves.
  void continuousModel(const nav::InsErrorPoint& p, Eigen::MatrixXd& F, Eigen::MatrixXd& Qc,
                       const ScaleInput& s = ScaleInput()) const;

  /// Position fix: dz = (INS antenna position − GNSS position) in NED [m]; leverArm_n = C_nb l_b
  /// [m] (the antenna seen from the IMU, NED); sigma [m] per axis.
  Innovation updatePosition(const nav::Vec3& dz, const nav::Vec3& leverArm_n,
                            const nav::Vec3& sigma);
  /// Velocity fix: dz = the antenna's INS velocity − GNSS velocity in NED [m/s]; armVelocity_n the
  /// INS's lever-arm term C_nb (ω_eb × l) (nav/lever_arm.hpp), zero without a lever arm.
  Innovation updateVelocity(const nav::Vec3& dz, const nav::Vec3& armVelocity_n,
                            const nav::Vec3& sigma);

  /// The attitude after a coarse alignment over a static window of T [s] (alignment_prior.cpp):
  /// ψ's mean, covariance and cross-covariance with the sensor states from the filter's own
  /// model through the alignment's linear error map J (nav::coarseAlignmentSensitivity). The
  /// window's mean sensor error of each block is its end value times a window gain plus an
  /// independent part (white noise N²/T; a walk's or a Gauss-Markov's path over the window; a
  /// sampled block's whole mean), rotated to NED by the aligned C_nb; f_b and omega_b are the
  /// window's mean measured signals (the scale states' inputs). The walks' states are aged by the
  /// window (variance + K² T): the filter starts at its end.
  void startAfterAlignment(const Eigen::Matrix<double, 3, 6>& J, const nav::Mat3& C_nb,
                           const nav::Vec3& f_b, const nav::Vec3& omega_b, double T);

  /// Closed-loop feedback: returns the estimated δr_n, δv_n, ψ and zeroes them in x (their
  /// covariance is unchanged: the correction is a known shift).
  Eigen::Matrix<double, 9, 1> takeNavCorrection();

 private:
  // Each placed block holds its own copy of the model's block (no pointer into model_: a copied
  // or moved filter stays valid on its own).
  struct Placed { int axis; int offset; StateBlock block; };  // axis 0-2 gyro, 3-5 accel
  nav::Vec3 sensorError(int firstAxis, bool scale) const;
  /// Input columns of each body axis: rows 0-2 of the gyro's, 3-5 of the accelerometer's errors
  /// into the INS errors; for a scale block the ScaleInput's columns.
  struct AxisInputs {
    nav::Mat93 Gg, Ga, Sg, Sa;
    Eigen::Matrix<double, 9, 1> column(const Placed& pl) const;
  };
  AxisInputs axisInputsAt(const nav::InsErrorPoint& p, const ScaleInput& s) const;
  nav::Mat9 whiteNoiseInput(const nav::Mat93& Gg, const nav::Mat93& Ga) const;
  void refreshSensorEstimates();  // after every change of x's sensor part
  const StepAggregation& aggregation(std::size_t placedIndex, double T);
  /// The continuous blocks' own Φ_b, Qd_b over T (constant per model and step: computed once).
  const std::vector<DiscreteSystem>& continuousBlocks(double T);
  /// Φ's navigation rows and blocks and the whole Qd of the continuous part over T at p.
  void discretizeContinuous(const nav::InsErrorPoint& p, const ScaleInput& s, double T,
                            BlockTransition& Phi, Eigen::MatrixXd& Qd);
  void spliceDiscrete(std::size_t placedIndex, const Eigen::Matrix<double, 9, 9>& A,
                      const Eigen::Matrix<double, 9, 1>& g, double T, BlockTransition& Phi,
                      Eigen::MatrixXd& Qd, Eigen::Matrix<double, 9, 1>& navMean);

  const nav::Earth* earth_;
  FilterSensorModel model_;
  FilterOptions options_;
  std::vector<Placed> placed_;
  std::vector<std::vector<StepAggregation>> aggregations_;  // per placed block, per step length
  std::vector<InputBlock> inputs_;         // the continuous placed blocks (g set per step)
  std::vector<std::size_t> inputPlaced_;   // their indices in placed_
  struct BlockCache {
    double T;
    std::vector<DiscreteSystem> blocks;  // per inputs_ entry
  };
  std::vector<BlockCache> blockCache_;  // the last few step lengths
  // propagate's work space, kept between steps so that a step allocates (almost) nothing
  BlockTransition phi_;
  Eigen::MatrixXd qd_;
  Eigen::Matrix<double, 9, Eigen::Dynamic> qdN_;
  Eigen::VectorXd x_;
  Eigen::MatrixXd P_;
  nav::Vec3 gyroEstimate_ = nav::Vec3::Zero(), accelEstimate_ = nav::Vec3::Zero();
  nav::Vec3 gyroScaleEstimate_ = nav::Vec3::Zero(), accelScaleEstimate_ = nav::Vec3::Zero();
  bool hasScale_ = false;
};

}  // namespace sinsim::sim::aided
