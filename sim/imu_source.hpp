// Where the navigation's IMU samples come from, one interval at a time: a trajectory's ideal IMU
// through a sensor-error corruptor, a precomputed reference (Monte Carlo) through a corruptor, or
// a measured record replayed along a static reference. The ideal and the measured sample are kept
// apart (GTSAM ScenarioRunner: actual vs measured), so the loop can remove an initial bias and an
// aiding filter can see both; the truth travels with them.
#pragma once

#include <cmath>
#include <memory>
#include <vector>

#include "errormodels/imu_model.hpp"
#include "errormodels/stats/record.hpp"
#include "nav/types.hpp"
#include "sim/ideal_imu.hpp"
#include "sim/scenario.hpp"
#include "sim/trajectory.hpp"

namespace sinsim::sim {

struct Reference;

/// One IMU interval k = (t_k − dt, t_k] as the navigation sees it.
struct ImuEpoch {
  long long index = 0;     // epoch number at the interval's end (1 for the first interval)
  nav::ImuSample ideal;    // what a perfect IMU delivers along the truth
  nav::ImuSample measured; // what the sensor reports (== ideal for a perfect IMU)
  double hTrue = 0.0;      // true height at t_k [m] (the reference of the held/damped channel)
  bool hasTruth = false;   // truth below is valid (every epoch, or only at output epochs)
  nav::NavState truth;     // true state at t_k
  double temperature = NAN;  // the sensor's temperature over the interval [K] (NaN: no profile)
};

/// A stream of IMU intervals of equal length dt = 1/rate() from the true initial state.
class ImuSource {
 public:
  virtual ~ImuSource() = default;
  /// True state at t = 0, where the navigation starts.
  virtual const nav::NavState& initial() const = 0;
  virtual double rate() const = 0;          // [Hz]
  virtual long long sampleCount() const = 0;
  /// Fills e with the next interval; false when every interval has been delivered.
  virtual bool next(ImuEpoch& e) = 0;
};

/// A trajectory's ideal IMU (generated on the fly, memory independent of the duration) through
/// `corruptor` (nullptr: a perfect IMU) at the sensor temperature of `temperature`. The truth is
/// known at every epoch. trajectory and corruptor must outlive the source.
class TrajectorySource final : public ImuSource {
 public:
  TrajectorySource(const Trajectory& trajectory, double imuRate,
                   errormodels::ImuCorruptor* corruptor, const TemperatureProfile& temperature);
  const nav::NavState& initial() const override { return initial_; }
  double rate() const override { return rate_; }
  long long sampleCount() const override { return imu_.sampleCount(); }
  bool next(ImuEpoch& e) override;

 private:
  IdealImu imu_;
  double rate_;  // [Hz]
  errormodels::ImuCorruptor* corruptor_;
  TemperatureProfile temperature_;
  nav::NavState initial_;
};

/// A precomputed Reference (sim/reference.hpp) through `corruptor` (nullptr: perfect IMU). The
/// truth is known at the reference's output epochs only (at every epoch for an aided reference).
/// ref and corruptor must outlive it.
class ReferenceSource final : public ImuSource {
 public:
  ReferenceSource(const Reference& ref, errormodels::ImuCorruptor* corruptor);
  const nav::NavState& initial() const override;
  double rate() const override;
  long long sampleCount() const override;
  bool next(ImuEpoch& e) override;

 private:
  // The measured samples of intervals [blockStart_, blockStart_ + measured_.size()), corrupted a
  // block at a time (ImuCorruptor::corruptBlock: one call per effect for the block).
  void corruptNextBlock();

  const Reference& ref_;
  errormodels::ImuCorruptor* corruptor_;
  std::size_t k_ = 0;
  std::size_t blockStart_ = 0;
  std::vector<nav::ImuSample> measured_;
  std::vector<double> temperature_;
};

/// A measured record replayed along a (static) Reference recorded at the record's rate: interval
/// k's measured increments are the record's rates of row k times dt; the ideal sample and the
/// truth are the reference's. The record must hold every interval (InputError otherwise) and
/// outlive the source.
class RecordSource final : public ImuSource {
 public:
  RecordSource(const Reference& ref, const errormodels::Record& record);
  const nav::NavState& initial() const override;
  double rate() const override;
  long long sampleCount() const override;
  bool next(ImuEpoch& e) override;

 private:
  ReferenceSource ideal_;
  const errormodels::Record& record_;
  std::size_t k_ = 0;
};

}  // namespace sinsim::sim
