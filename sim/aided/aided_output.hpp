// CSV rows of an aided run (docs/aided.md): filter.csv (the navigation errors beside the filter's
// 1-sigma, NEES and NIS at every GNSS clock epoch) and imu.csv (ideal and measured IMU, as rates
// and as increments). Units are in the headers.
#pragma once

#include <cstdio>

#include "nav/types.hpp"
#include "sim/aided/aided_navigation.hpp"

namespace sinsim::sim::aided {

void writeFilterHeader(std::FILE* f);
/// One row per epoch that has a filter view (fe.sigma set: the GNSS clock epochs).
void writeFilterRow(std::FILE* f, const FilterEpoch& fe);

void writeImuHeader(std::FILE* f);
/// t, then ideal and measured rates [rad/s], [m/s^2] (increment / dt) and increments [rad], [m/s].
void writeImuRow(std::FILE* f, const nav::ImuSample& ideal, const nav::ImuSample& measured);

}  // namespace sinsim::sim::aided
