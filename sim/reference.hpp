// The part of a simulation that is the same for every realisation of the sensor errors: the ideal
// IMU samples and the truth. A Monte Carlo batch computes it once and shares it read-only across
// runs and threads (the trajectory generator makes ~0.8 M samples/s, far too slow to redo per
// run), then navigates each realisation along it.
#pragma once

#include <atomic>
#include <cstddef>
#include <vector>

#include "errormodels/imu_model.hpp"
#include "nav/earth.hpp"
#include "nav/strapdown.hpp"
#include "nav/types.hpp"
#include "sim/imu_source.hpp"
#include "sim/nav_loop.hpp"
#include "sim/scenario.hpp"

namespace sinsim::sim {

/// Fields of one output epoch of a realisation, nav − truth (see navError in run.hpp).
enum ErrorField : int {
  kNorth = 0, kEast, kDown,  // [m]
  kVn, kVe, kVd,             // [m/s]
  kRoll, kPitch, kYaw,       // wrapped Euler differences [rad]
  kErrorFields
};

/// An aided run's filter view, stored after its errors (runFloats): per output epoch
/// kAidedEpochFields floats, then per outage window kOutageFields floats. NaN where the epoch had
/// no filter step (alignment, or an output epoch between GNSS ticks) or no update.
enum AidedEpochField : int {
  kNees = 0,   // (nav − truth)ᵀ P⁻¹ (nav − truth) over the aided::neesDof navigation states
  kNis,        // of the epoch's GNSS update
  kNisDof,     // its degrees of freedom (3: position, 6: position and velocity)
  kEpochClass, // 0 none, 1 aiding (a fix used), 2 outage
  kAidedEpochFields
};
enum OutageField : int {
  kOutageMaxHorizontal = 0,  // the largest horizontal error inside the window [m]
  kOutageSigmaHorizontal,    // the filter's horizontal 1-sigma at that moment [m]
  kOutageFields
};

struct Reference {
  std::string name;                  // scenario name
  double imuRate = 0.0;              // [Hz]
  double outputRate = 0.0;           // [Hz]
  long long decimation = 1;          // IMU samples per output epoch
  nav::StrapdownOptions strapdown;
  TemperatureProfile temperature;
  nav::NavState initial;             // truth at t = 0 (the navigation starts from it)
  std::vector<nav::ImuSample> samples;  // ideal increments, interval k = (t_k − dt, t_k]
  std::vector<double> hRef;             // true height at the end of interval k [m]
  std::vector<nav::NavState> truth;     // truth at output epoch e (sample e·decimation; e = 0: t = 0)
  /// The scenario's aiding (initial errors, alignment, GNSS, filter; docs/aided.md). When not
  /// inert, every realisation navigates with it (its random streams keyed by the run's key) and
  /// truthAll holds the truth at the end of every interval k (GNSS fixes are simulated from it).
  aided::AidingConfig aiding;
  std::vector<nav::NavState> truthAll;

  std::size_t epochs() const { return truth.size(); }
  /// Floats one realisation stores: epochs() × kErrorFields errors, and when aided its filter view
  /// (epochs() × kAidedEpochFields, then outages × kOutageFields).
  std::size_t runFloats() const;
  double epochTime(std::size_t e) const { return truth[e].t; }  // [s]
  /// Bytes held (the samples dominate: 72 per IMU sample, 88 more when aided).
  std::size_t bytes() const;
};

/// Generates the ideal IMU and truth of a scenario (sim/ideal_imu.hpp) once.
Reference buildReference(const Scenario& scenario);

/// How a realisation's increments are prepared before the strapdown.
struct NavigateOptions {
  /// > 0: remove the initial bias as a user does with a static record: the mean of
  /// (measured − ideal) increments over the first biasWindow seconds [s], per axis, divided by its
  /// duration, is subtracted from every sample (the ideal signal holds the known Earth rate and
  /// gravity). 0: nothing removed.
  double biasWindow = 0.0;
};

/// Navigates `source` (one whose output epochs are the reference's: a ReferenceSource or a
/// RecordSource of ref) through the navigation loop (sim/nav_loop.hpp) and writes the error at
/// every output epoch to out[e · kErrorFields + field] (epochs() × kErrorFields floats), with the
/// aiding hook `aiding` (nullptr: free inertial). Returns false, leaving out partly written, when
/// `cancel` becomes true (checked every 65536 samples).
bool navigateErrors(ImuSource& source, const Reference& ref, const NavigateOptions& options,
                    float* out, const std::atomic<bool>* cancel = nullptr,
                    NavAiding* aiding = nullptr);

/// Navigates one realisation along the reference: `corruptor` (nullptr: the perfect IMU) turns
/// each ideal sample into a measured one, the strapdown integrates it from the true initial
/// state, and the error at every output epoch is written to out[e · kErrorFields + field]
/// (ref.runFloats() floats in all). An aided reference (ref.aiding not inert) navigates with its
/// initial errors, alignment and GNSS/INS filter, whose random streams are keyed by `key` (the
/// corruptor's key: run k of a batch is {seed, k}), and writes the filter's view after the
/// errors (AidedEpochField, OutageField). Returns false, leaving out partly written,
/// when `cancel` becomes true (checked every 65536 samples).
bool navigateRealisation(const Reference& ref, errormodels::ImuCorruptor* corruptor,
                         const NavigateOptions& options, float* out,
                         const std::atomic<bool>* cancel = nullptr,
                         const errormodels::StreamKey& key = {});

}  // namespace sinsim::sim
