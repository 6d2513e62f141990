// A measured static record as a Monte Carlo participant: the static scenario it was recorded in,
// the attitude levelled from its data, and its replay (RecordSource, sim/imu_source.hpp) through
// exactly the same navigation loop (and initial-bias removal) as the models' runs.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "errormodels/stats/record.hpp"
#include "nav/strapdown.hpp"
#include "nav/types.hpp"
#include "sim/montecarlo.hpp"
#include "sim/reference.hpp"
#include "sim/scenario.hpp"

namespace sinsim::sim {

/// Roll and pitch [rad] of an IMU at rest from the mean specific force of its first n samples:
/// at rest f_b = C_bn (0, 0, −g), so roll = atan2(−f_y, −f_z), pitch = atan2(f_x, √(f_y² + f_z²))
/// (Titterton & Weston 2004 §10.2, coarse levelling). Returns (roll, pitch, yaw).
nav::Vec3 levelAttitude(const errormodels::Record& record, std::size_t n, double yaw);

/// Where and how a static record was taken, and how much of it to use (sinsim mc --measured).
struct MeasuredOptions {
  std::string path;                   // CSV (or .gz) with gx, gy, gz, ax, ay, az
  errormodels::RecordOptions record;  // units, rate, irregular time
  double lat = 0.0, lon = 0.0;        // [rad]
  double h = 0.0;                     // [m] above the WGS-84 ellipsoid
  /// Roll, pitch, yaw [rad]; unset: levelled from the mean specific force over
  /// max(bias window, 1 s), yaw = heading.
  std::optional<nav::Vec3> attitude;
  double heading = 0.0;                 // [rad]
  std::optional<double> biasWindow;     // [s]; unset: min(60 s, 10 % of the used record)
  std::string biasWindowOption = "--bias-window";  // its name in messages (diagnose: --nav-bias-window)
  double skip = 0.0;                    // [s] dropped from the start (a warm-up)
  std::optional<double> duration;       // [s] used after the skip; unset: all
  nav::StrapdownOptions strapdown{nav::VerticalChannel::Held, 100.0};
  double outputRate = 1.0;              // [Hz] statistics epochs
};

/// The record (warm-up dropped) and the static scenario it defines.
struct MeasuredSetup {
  errormodels::Record record;
  Scenario scenario;   // at rest for the whole epochs of the record used, no error model
  double biasWindow;   // [s]
  std::string identity;  // text that identifies the scenario for checkpoint resume checks
};

/// Loads and checks the record and builds its static scenario (a typed value: no YAML round
/// trip). Throws InputError naming the file for a record without the six IMU columns, a skip
/// that leaves nothing, a record shorter than one output epoch, or an invalid place.
MeasuredSetup prepareMeasured(const MeasuredOptions& options);

/// The same for a record already loaded (options.path and options.record unused; messages name
/// record.source): `sinsim diagnose --nav` replays the record it diagnosed.
MeasuredSetup measuredSetup(errormodels::Record record, const MeasuredOptions& options);

/// A vehicle at rest at start (lat, lon, h, roll, pitch, heading) for `duration` [s], IMU at
/// imuRate, statistics at outputRate [Hz]. Throws InputError for values a scenario file could
/// not hold (latitude beyond ±89°, rates that do not divide, non-positive duration).
Scenario staticScenario(const std::string& name, const MotionStart& start, double imuRate,
                        double outputRate, const nav::StrapdownOptions& strapdown,
                        double duration);

/// The record navigated along ref (built from setup.scenario): its errors at every output epoch.
McMeasured navigateMeasured(const MeasuredSetup& setup, const Reference& ref,
                            const NavigateOptions& options);

}  // namespace sinsim::sim
