// The aided-navigation keys of a scenario, typed and in SI (docs/aided.md):
//   initial_errors   the navigation's start minus the truth: position, velocity, attitude, each a
//                    fixed value or a sigma drawn per run
//   alignment        coarse alignment (leveling + gyrocompassing) over the first static seconds
//   gnss             position (and velocity) fixes from the truth with white noise, a lever arm,
//                    outages as time windows
//   filter           the filter's own sensor model, a file or inline (may differ from the truth
//                    `errors:`), converted to filter states at reading
// Read once by the scenario reader (parseAiding); nothing below re-reads YAML.
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "common/config.hpp"
#include "errormodels/imu_model.hpp"
#include "nav/types.hpp"
#include "sim/aided/error_state_filter.hpp"

namespace sinsim::sim::aided {

/// A 3-vector that is either a fixed value or a standard deviation of a zero-mean draw.
struct ValueOrSigma {
  nav::Vec3 value = nav::Vec3::Zero();  // used when !random
  nav::Vec3 sigma = nav::Vec3::Zero();  // used when random
  bool random = false;
  /// Its 1-sigma size (|value| for a fixed value): what a filter should start with.
  nav::Vec3 spread() const { return random ? sigma : value.cwiseAbs(); }
};

struct InitialErrors {
  ValueOrSigma position;  // north, east, down [m]
  ValueOrSigma velocity;  // NED [m/s]
  ValueOrSigma attitude;  // roll, pitch, yaw [rad]
  bool any() const;
};

struct AlignmentConfig {
  double duration = 0.0;  // [s] of the static start averaged; 0: no alignment
};

struct TimeWindow {
  double start = 0.0, end = 0.0;  // [s]
  /// A window given past the scenario's end is stored ending there and holds its last epoch too.
  bool toTheEnd = false;
  bool contains(double t) const { return t >= start && (toTheEnd || t < end); }
};

/// The longest filter propagation step [s]: between GNSS fixes further apart (a rate below 1 Hz,
/// or an outage) the filter still propagates this often, so that its error dynamics, linearised
/// at the step's mean attitude and specific force, follow the motion.
constexpr double kMaxPropagationStep = 1.0;

/// The longest GNSS lever arm accepted [m].
constexpr double kMaxLeverArm = 1000.0;
/// The finest GNSS fix sigma accepted, 1 mm (position) and 1 mm/s (velocity): RTK is ~1 cm, and a
/// blind probe's 1e-9 m broke the filter's covariance without a word (NEES mean 1e12; at 1 mm one
/// spike epoch, at 1 cm consistent): finer, the update reaches the rounding of the solution.
constexpr double kMinFixSigma = 1e-3;

struct GnssConfig {
  bool enabled = false;
  double rate = 1.0;                                // [Hz]
  std::optional<nav::Vec3> positionSigma;           // north, east, down [m]; none: velocity only
  std::optional<nav::Vec3> velocitySigma;           // NED [m/s]; none: position only
  nav::Vec3 leverArm_b = nav::Vec3::Zero();         // antenna in body axes [m]
  std::vector<TimeWindow> outages;                  // sorted, no fixes inside
  double runEnd = NAN;                              // [s] the scenario's end as read (NaN: unknown)
  bool inOutage(double t) const;
};

/// A warning when no fix falls after the alignment (`alignEnd` [s]), outside every outage and up
/// to the scenario's end (GNSS at 0.001 Hz in a 10-min run; one outage over the whole run, GNSS
/// "off" on purpose); empty otherwise.
std::string noFixWarning(const GnssConfig& g, double alignEnd);

struct FilterConfig {
  bool enabled = false;
  std::string model;           // the model file's path (resolved against the scenario), or "inline"
  FilterSensorModel sensors;   // its sensor-error states (filter_model.hpp)
  // its known errors, compensated (known_errors.hpp): added and linear; the IMU rate [Hz]
  errormodels::ImuErrorModel knownAdded = errormodels::ImuErrorModel::none();
  errormodels::ImuErrorModel knownLinear = errormodels::ImuErrorModel::none();
  std::vector<std::string> knownLabels;  // the known effects as the file places them (knownLabels)
  double imuRate = 0.0;
};

struct AidingConfig {
  InitialErrors initialErrors;
  AlignmentConfig alignment;
  GnssConfig gnss;
  FilterConfig filter;
  /// True when nothing differs from a free-inertial run from the true state.
  bool inert() const { return !initialErrors.any() && alignment.duration == 0.0 && !gnss.enabled &&
                              !filter.enabled; }
};

/// Reads initial_errors, alignment, gnss and filter from a scenario's root map; problems are
/// recorded in the file's diagnostics with their line and key path. `baseDir` resolves a relative
/// filter model path; `duration` [s] is the scenario's, to check outage windows against;
/// `imuRate` [Hz] its IMU rate (a filter model's per-sample rounding is white noise at it);
/// `hasTemperature`: the scenario gives the sensor's temperature (a filter model's temperature
/// polynomial is compensated at it, and refused without it).
AidingConfig parseAiding(const ConfigNode& root, const std::string& baseDir, double duration,
                         double imuRate, bool hasTemperature);

/// The root keys parseAiding reads (for the scenario's allowKeys).
const std::vector<std::string>& aidingKeys();

}  // namespace sinsim::sim::aided
