// Shared by the consistency tests (test_consistency.cpp, test_scale_factor_consistency.cpp): the
// ideal IMU of a drive precomputed once, and the aiding both use (random initial errors, GNSS
// position at 1 Hz with a lever arm, one outage, the filter on).
#pragma once

#include <vector>

#include "common/constants.hpp"
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

}  // namespace sinsim::test
