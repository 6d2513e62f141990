// The filter sensor model the aided tests share: per axis a bias, a Gauss-Markov and a random walk
// (9 + 27 states) with white noise, at a MEMS grade (gyro 0.15 deg/sqrt(h) white, 10 deg/h bias,
// 20 deg/h GM of 200 s, 3 deg/h/sqrt(h) walk; accelerometer 0.1 m/s/sqrt(h) white, 0.01 m/s^2 bias,
// 0.02 m/s^2 GM, 1e-5 m/s^2/sqrt(s) walk).
#pragma once

#include "common/constants.hpp"
#include "sim/aided/error_state_filter.hpp"
#include "sim/aided/sensor_states.hpp"

namespace aidedtest {

/// accelGmTau [s]: the accelerometer GM's correlation time (a short one exercises the fast path).
inline sinsim::sim::aided::FilterSensorModel biasGmWalkModel(double accelGmTau) {
  using namespace sinsim::sim::aided;
  const double d = sinsim::kRadPerDeg;
  FilterSensorModel m;
  for (int i = 0; i < 3; ++i) {
    m.gyro[i].whiteDensity = 0.15 * d / 60.0;
    m.gyro[i].blocks = {biasState(10 * d / 3600), gaussMarkovState(20 * d / 3600, 200),
                        randomWalkState(3 * d / 3600 / 60)};
    m.accel[i].whiteDensity = 0.1 / 60.0;
    m.accel[i].blocks = {biasState(0.01), gaussMarkovState(0.02, accelGmTau),
                         randomWalkState(1e-5)};
  }
  return m;
}

}  // namespace aidedtest
