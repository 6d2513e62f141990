// Shared by the consistency tests (test_consistency.cpp, test_scale_factor_consistency.cpp): the
// ideal IMU of a drive precomputed once, and the aiding both use (random initial errors, GNSS
// position at 1 Hz with a lever arm, one outage, the filter on).
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "common/constants.hpp"
#include "errormodels/imu_model.hpp"
#include "sim/aided/aided_navigation.hpp"
#include "sim/aided/aiding_config.hpp"
#include "sim/ideal_imu.hpp"
#include "sim/scenario.hpp"
#include "sim/trajectory.hpp"

namespace sinsim::test {

struct IdealDrive {
  std::vector<nav::ImuSample> samples;
  std::vector<nav::NavState> truth;  // truth[k] at the end of samples[k]
  nav::NavState start;
};

inline IdealDrive idealDrive(const sim::Scenario& sc, const nav::Earth& earth) {
  const sim::Trajectory traj(earth, sc.motion());
  sim::IdealImu imu(traj, sc.imuRate);
  IdealDrive d;
  d.start = imu.truth();
  while (!imu.done()) {
    d.samples.push_back(imu.next());
    d.truth.push_back(imu.truth());
  }
  return d;
}

/// Initial errors (2, 2, 3 m; 0.05 m/s; 0.3°, 0.3°, 2°) drawn per run, GNSS position (1, 1, 2 m)
/// at 1 Hz with a lever arm, an outage [outageStart, outageEnd] [s], the filter on.
inline sim::aided::AidingConfig consistencyAiding(double outageStart, double outageEnd) {
  sim::aided::AidingConfig cfg;
  cfg.initialErrors.position.random = true;
  cfg.initialErrors.position.sigma = nav::Vec3(2, 2, 3);
  cfg.initialErrors.velocity.random = true;
  cfg.initialErrors.velocity.sigma = nav::Vec3::Constant(0.05);
  cfg.initialErrors.attitude.random = true;
  cfg.initialErrors.attitude.sigma = nav::Vec3(0.3, 0.3, 2.0) * kRadPerDeg;
  cfg.gnss.enabled = true;
  cfg.gnss.rate = 1.0;
  cfg.gnss.positionSigma = nav::Vec3(1.0, 1.0, 2.0);
  cfg.gnss.leverArm_b = nav::Vec3(0.5, -0.2, -1.0);
  cfg.gnss.outages = {{outageStart, outageEnd}};
  cfg.filter.enabled = true;
  return cfg;
}

/// The consistency tests' drive: 20 s static, accelerate, a turn, cruise (150 s, 45° N).
constexpr const char* kConsistencyDrive = R"(
name: consistency
start: {latitude: 45 deg, longitude: 7 deg, height: 300 m, heading: 30 deg}
imu_rate: 100 Hz
vertical: free
segments:
  - {type: static, duration: 20 s}
  - {type: accelerate, speed: 15 m/s, duration: 15 s}
  - {type: cruise, duration: 20 s}
  - {type: turn, heading_change: 90 deg, duration: 15 s}
  - {type: cruise, duration: 80 s}
)";

/// Whether the mean of R independent χ²(d) values lies in its two-sided 99 % band,
/// d ± 2.5758 sqrt(2d/R) (normal approximation of χ²(dR)/R; Bar-Shalom, Li & Kirubarajan 2001,
/// §5.4.2).
inline bool inChiSquareBand(double mean, int dof, int runs) {
  const double half = 2.5758 * std::sqrt(2.0 * dof / runs);
  return mean > dof - half && mean < dof + half;
}

/// R runs of a drive: run r's IMU corrupted by `truth` under the key (seed, r), navigated with
/// the aiding `cfg` and the filter's model; onEpoch(r, FilterEpoch) after every IMU interval.
template <class OnEpoch>
void aidedRuns(const sim::Scenario& sc, const IdealDrive& drive, const nav::Earth& earth,
               const errormodels::ImuErrorModel& truth, const sim::aided::AidingConfig& cfg,
               const sim::aided::FilterSensorModel& filter, int runs, std::uint64_t seed,
               OnEpoch&& onEpoch) {
  for (int r = 0; r < runs; ++r) {
    const errormodels::StreamKey key{seed, static_cast<std::uint64_t>(r)};
    auto corruptor = truth.instantiate(sc.imuRate, key);
    sim::aided::AidedNavigation aided(earth, cfg, filter, sc.strapdown, key);
    nav::Strapdown sd(earth, aided.initialState(drive.start), sc.strapdown);
    for (std::size_t k = 0; k < drive.samples.size(); ++k) {
      nav::ImuSample m = drive.samples[k];
      corruptor->corrupt(m, NAN);
      const nav::ImuSample u = aided.compensate(m);
      sd.update(u, drive.truth[k].h);
      onEpoch(r, aided.afterInterval(u, drive.samples[k], drive.truth[k], sd));
    }
  }
}

}  // namespace sinsim::test
