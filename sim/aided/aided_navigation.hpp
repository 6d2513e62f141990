// Aided navigation around one strapdown: the run's initial errors, coarse alignment, GNSS fixes
// simulated from the truth (white noise, lever arm, outages) and the closed-loop error-state
// filter. For each IMU interval the navigation loop asks compensate() for the sample the strapdown
// integrates and then calls afterInterval with it; what it leaves in the strapdown is the
// navigation solution.
//
// Known errors of the filter's model (misalignment, g-sensitivity, ramp, ...; known_errors.hpp)
// are removed from every measured sample first, as an INS's calibration would.
// Closed loop: the filter's sensor-error estimate is removed from each measured increment before
// the strapdown integrates it (first order in dt: dθ −= b̂_g dt + ŝ_g ∘ dθ, dv −= b̂_a dt + ŝ_a ∘ dv,
// ŝ the scale-factor estimates), as an INS compensates its IMU, and each update's δr, δv, ψ are
// fed back through Strapdown::correct and zeroed in the filter.
//
// Random streams (errormodels/random.hpp), keyed by (seed, run): stream id (2, 0) the initial
// errors, (2, 1) GNSS position noise, (2, 2) GNSS velocity noise. The IMU's own streams (sensor
// 0, 1) are untouched, so a run with and without aiding sees the same IMU errors.
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/constants.hpp"
#include "errormodels/imu_model.hpp"
#include "errormodels/random.hpp"
#include "nav/earth.hpp"
#include "nav/strapdown.hpp"
#include "sim/aided/aiding_config.hpp"
#include "sim/aided/error_state_filter.hpp"
#include "sim/aided/known_errors.hpp"
#include "sim/aided/linearity_limits.hpp"

namespace sinsim::sim::aided {

/// One outage's outcome: the largest horizontal error over the IMU epochs inside the window and
/// the filter's horizontal 1-sigma sqrt(P_NN + P_EE) predicted at the first filter step at or
/// after it, before that step's fix (for a maximum at the window's last IMU epoch: the fix at its
/// end, one interval later; a run that ends between steps: the last step's). NaN for a window the
/// filter never ran in (inside the alignment).
struct OutageResult {
  TimeWindow window;
  double maxHorizontal = NAN;        // [m]
  double sigmaHorizontal = NAN;      // [m]
  double t = NAN;                    // when the maximum occurred [s]
};

/// The filter's view at one epoch, against the truth.
struct FilterEpoch {
  double t = 0.0;                                  // [s]
  bool filtered = false;                           // a GNSS clock epoch: the fields below are set
  Eigen::Matrix<double, 9, 1> error;               // nav − truth: δr_n [m], δv_n [m/s], ψ [rad]
  Eigen::Matrix<double, 9, 1> sigma;               // filter 1-sigma of the same
  double nees = NAN;                               // errorᵀ P⁻¹ error over the nav states (neesDof)
  double nis = NAN;                                // of the update at this epoch (NaN: none)
  int nisDof = 0;                                  // its degrees of freedom (3 or 6)
  bool aiding = false;                             // a fix was used at this epoch
  bool outage = false;                             // inside an outage window
};

/// The navigation states the NEES sums over: all 9, or 7 with a held vertical channel, whose
/// down position and velocity the strapdown holds at the truth (no error for the filter to own:
/// their variances stay at the prior and would pull the NEES below its band).
int neesDof(nav::VerticalChannel vertical);


/// What every run of the scenario should warn about, from its aiding and true start (static when
/// it aligns): no GNSS fix used (noFixWarning); a filter attitude 1-sigma at the start beyond
/// kMaxStartAttitudeSigma — from
/// initial_errors.attitude, or from the coarse alignment as the filter's own model predicts it
/// (ErrorStateFilter::startAfterAlignment; a gyro too poor to gyrocompass). Empty without a filter.
std::vector<std::string> startWarnings(const nav::Earth& earth, const AidingConfig& config,
                                       const nav::StrapdownOptions& strapdownOptions,
                                       const nav::NavState& start);

class AidedNavigation {
 public:
  /// earth must outlive the object; strapdownOptions as the strapdown runs (vertical channel;
  /// its damping gains are read from the strapdown at each step).
  AidedNavigation(const nav::Earth& earth, const AidingConfig& config, FilterSensorModel model,
                  const nav::StrapdownOptions& strapdownOptions, const errormodels::StreamKey& key);

  /// The navigation's start: the true start plus this run's initial errors.
  nav::NavState initialState(const nav::NavState& truth) const;

  /// One IMU interval: `measured` has just been integrated by `strapdown`; `ideal` is what a
  /// perfect IMU delivered over it and truth the true state at the interval's end (GNSS is
  /// simulated from them). Returns the epoch's filter view.
  FilterEpoch afterInterval(const nav::ImuSample& measured, const nav::ImuSample& ideal,
                            const nav::NavState& truth, nav::Strapdown& strapdown);
  /// The sample the strapdown integrates: `measured` less the filter model's known errors (from
  /// the first sample on, alignment included) and less the filter's current sensor-error estimate
  /// (the continuous blocks'; not before the alignment ends, without a filter, or while nothing is
  /// estimated). `temperature` [K]: the sensor's over the interval (NaN: none; a known temperature
  /// effect then needs it: refused by the scenario reader). afterInterval is then called with the
  /// returned sample.
  nav::ImuSample compensate(const nav::ImuSample& measured, double temperature = NAN);

  const std::vector<OutageResult>& outages() const { return outages_; }
  const ErrorStateFilter& filter() const { return filter_; }

 private:
  // compensate() with the known g-sensitivity of the specific force's increment dv [m/s].
  nav::ImuSample compensate(const nav::ImuSample& measured, const nav::Vec3& dv, double temperature);
  void propagateStep(nav::Strapdown& sd);
  // The outage windows' maxima, after the interval ending at truth.t (`epoch`: its filter view).
  void trackOutage(const nav::NavState& truth, const nav::Strapdown& sd, const FilterEpoch& epoch);
  void align(const nav::ImuSample& measured, const nav::NavState& truth, nav::Strapdown& sd);
  // rateNav, rateTrue: the last interval's mean body rates [rad/s], the navigation's (compensated)
  // and the truth's; a velocity fix's lever-arm term needs them.
  void fix(const nav::NavState& truth, const nav::Vec3& rateNav, const nav::Vec3& rateTrue,
           nav::Strapdown& sd, FilterEpoch& out);

  const nav::Earth* earth_;
  AidingConfig config_;
  ErrorStateFilter filter_;
  KnownErrors known_;  // the filter model's known errors (known_errors.hpp)
  nav::StrapdownOptions sdOptions_;
  Eigen::Matrix<double, 9, 1> initialError_;  // drawn once: δr_n, δv_n, roll/pitch/yaw
  errormodels::NormalStream posNoise_, velNoise_;
  // alignment: sums of the measured increments over the static start
  nav::Vec3 sumDtheta_ = nav::Vec3::Zero(), sumDv_ = nav::Vec3::Zero();
  double sumDt_ = 0.0;
  bool aligned_ = false;
  nav::NavState alignAnchor_;  // position and velocity held during alignment
  // linearisation point accumulated since the last propagation (means over the step)
  nav::InsErrorPoint sum_;
  ScaleInput sumScale_;  // Σ C_nb diag(dθ_b), Σ C_nb diag(dv_b) (with scale-factor states only)
  double stepTime_ = 0.0;
  long long fixIndex_ = 0;  // next GNSS epoch number (t = k / rate)
  std::vector<OutageResult> outages_;
  // The outage whose maximum came between filter steps: its sigma is the next step's prediction.
  std::optional<std::size_t> pendingSigma_;
};

/// The 9 navigation errors nav − truth in the filter's states: δr_n [m] (radii at the truth),
/// δv_n, and ψ from Ĉ_nb C_nbᵀ ≈ I − [ψ×].
Eigen::Matrix<double, 9, 1> navErrorStates(const nav::Earth& earth, const nav::NavState& nav,
                                           const nav::NavState& truth);

}  // namespace sinsim::sim::aided
