// One simulation run: scenario → trajectory → ideal IMU → (copy) → sensor errors → strapdown →
// errors vs truth → decimated outputs and a summary.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <cmath>
#include <string>

#include "nav/types.hpp"
#include "sim/nav_loop.hpp"
#include "sim/aided/aided_navigation.hpp"
#include "sim/scenario.hpp"

namespace sinsim::sim {


/// Navigation error of one epoch: nav minus truth.
struct NavError {
  double t = 0.0;                          // [s]
  nav::Vec3 pos_n = nav::Vec3::Zero();     // north, east, down [m] (radii at the true position)
  nav::Vec3 vel_n = nav::Vec3::Zero();     // [m/s]
  nav::Vec3 euler = nav::Vec3::Zero();     // roll, pitch, yaw differences, wrapped [rad]
  double horizontal() const { return std::hypot(pos_n.x(), pos_n.y()); }  // [m]
  double vertical() const { return std::abs(pos_n.z()); }                 // [m]
};

/// nav minus truth at the same epoch. Position in local NED metres: δN = δlat (M + h),
/// δE = δlon (N + h) cos lat, δD = −δh with M, N at the true latitude (small-difference form,
/// exact to O(δ²/R), < 1 µm for errors below 100 m). Attitude as wrapped Euler differences
/// (meaningless near pitch ±90°, where the Euler angles themselves are).
NavError navError(const nav::Earth& earth, const nav::NavState& nav, const nav::NavState& truth);

/// Throws NumericalError ("the navigation error became non-finite at t = ...") unless every
/// component is finite and within `bound` (mc stores floats: 3.4e38).
void requireFiniteError(const NavError& e, double bound = std::numeric_limits<double>::infinity());

struct RunOptions {
  /// Output folder; empty: compute only, write nothing. Created (with parents) only after the
  /// scenario, the model and its instantiation have been validated.
  std::string outDir;
  /// Overrides the scenario's seed (`--seed`). Default when neither gives one: 0.
  std::optional<std::uint64_t> seed;
  /// Overrides the scenario's error model (`--model`): "none" or a model file path.
  std::optional<std::string> model;
  /// Monte Carlo run index (the realisation of the error model), 0 for a single run.
  std::uint64_t runIndex = 0;
  /// Initial-bias removal window [s] (NavLoopOptions::biasWindow); 0: none.
  double biasWindow = 0.0;
  /// Aiding filter plugged into the navigation loop (not owned); nullptr: pure inertial.
  NavAiding* aiding = nullptr;
  /// Called with the error of every output row (t = 0 and every 1/outputRate s), in time order,
  /// whether or not files are written: for statistics without CSV round trips.
  std::function<void(const NavError&)> onRow;
  /// Also write imu.csv: ideal and measured IMU, as rates and as increments (large: one row per
  /// IMU interval).
  bool writeImu = false;
  /// Also write the run's HTML report here (sim/run_report.hpp: track, errors against time);
  /// empty: none. Its folder must exist (or be outDir).
  std::string htmlPath;
};

struct RunSummary {
  std::string scenario;     // name
  std::string model;        // source of the error model ("none", a path, "inline")
  std::uint64_t seed = 0;
  double duration = 0.0;    // [s]
  long long imuSamples = 0;
  double distance = 0.0;    // path length travelled [m]
  NavError final;           // at the last epoch
  double maxHorizontal = 0.0, maxHorizontalTime = 0.0;  // over every IMU epoch [m], [s]
  double maxVertical = 0.0, maxVerticalTime = 0.0;      // [m], [s]
  double rmsHorizontal = 0.0, rmsVertical = 0.0;        // over the output rows [m]
  std::vector<aided::OutageResult> outages;  // aided runs: per GNSS outage window
  std::string filter;  // aided runs: what the filter used of its model (filterSummaryLine)
  std::vector<std::string> warnings;  // what the user should know about the result (printed)
  double wallTime = 0.0;    // [s]
  std::string outDir;       // "" when nothing was written
  std::vector<std::string> files;  // the files written into outDir, in order
  std::string report;       // the HTML report written (RunOptions::htmlPath), "" for none
};

/// Runs the scenario. Throws InputError (ConfigError for a bad model file) before anything is
/// written; output files are written to temporaries and renamed into outDir at the end, so a
/// failure never leaves half-written outputs. Memory does not grow with the duration.
RunSummary run(const Scenario& scenario, const RunOptions& options = {});

/// One line for terminals: "car: 1800 s, 21.4 km, final horizontal error 3.1 mm (max 4.0 mm),
/// vertical 1.2 mm".
std::string summaryLine(const RunSummary& s);

}  // namespace sinsim::sim
