// The one navigation loop of sinsim: IMU intervals from an ImuSource → (initial-bias removal) →
// strapdown → (aiding) → every epoch handed to the caller with its truth. `run`, `mc` and
// `mc --measured` all navigate through it; they differ only in their source and in what they do
// with the epochs (CSV rows, error statistics, checkpoint floats).
#pragma once

#include <atomic>
#include <functional>
#include <string>

#include "nav/earth.hpp"
#include "nav/strapdown.hpp"
#include "sim/imu_source.hpp"

namespace sinsim::sim {

/// The aiding hook (issue: GNSS/INS). start() chooses where the navigation starts (the
/// truth plus a run's initial errors); compensate() gives the sample the strapdown integrates for
/// an interval (the measured one — after the bias window's correction — less a filter's sensor
/// estimate); epoch() is called once per interval, after the strapdown has integrated that sample
/// and before the epoch is reported, with the interval (ideal and measured sample, truth where the
/// source knows it), the integrated sample and the strapdown. A filter predicts with the
/// integrated sample, may simulate its aiding measurements from e.truth (check e.hasTruth) and
/// corrects the navigation through the strapdown's interface; what it leaves in the strapdown is
/// what the epoch reports. Its own outputs (filter.csv) are its business: the loop knows nothing
/// of them.
class NavAiding {
 public:
  virtual ~NavAiding() = default;
  /// Where the navigation starts, given the true start (initial errors); default: the truth.
  virtual nav::NavState start(const nav::NavState& truth) { return truth; }
  /// The sample the strapdown integrates for interval e; default: e.measured.
  virtual nav::ImuSample compensate(const ImuEpoch& e) { return e.measured; }
  virtual void epoch(const ImuEpoch& e, const nav::ImuSample& integrated,
                     nav::Strapdown& strapdown) = 0;
};

struct NavLoopOptions {
  nav::StrapdownOptions strapdown;  // vertical channel (free, held, damped with its τ)
  /// > 0: remove the initial bias as a user does with a static record: the mean of
  /// (measured − ideal) increments over the first biasWindow seconds, per axis, divided by its
  /// duration, is subtracted from every sample (the ideal signal holds the known Earth rate and
  /// gravity) [s]. 0: nothing removed.
  double biasWindow = 0.0;
  NavAiding* aiding = nullptr;               // not owned; nullptr: pure inertial
  const std::atomic<bool>* cancel = nullptr; // checked every 1024 intervals and at the end
};

/// Called for epoch 0 (the start: e.index == 0, no sample, e.truth = the initial state) and after
/// every interval, in time order, with the navigation state at e's end.
using EpochSink = std::function<void(const ImuEpoch& e, const nav::NavState& nav)>;

/// Navigates `source` from its true initial state (or where the aiding says it starts) with the
/// WGS-84 earth. Returns false when
/// `cancel` became true (the sink has then seen only part of the run). Throws InputError for a
/// bias window shorter than one IMU interval.
bool navigate(ImuSource& source, const NavLoopOptions& options, const EpochSink& sink);

/// "free", "held", "damped" (as a scenario's `vertical:` writes them).
const char* verticalName(nav::VerticalChannel v);
/// The channel named `name`; InputError "<what>: ..." listing the names otherwise.
nav::VerticalChannel verticalChannel(const std::string& name, const std::string& what);

/// The WGS-84 Earth shared by every run (GeographicLib objects are immutable once built).
const nav::Earth& sharedEarth();

}  // namespace sinsim::sim
