// CSV rows of an aided run (docs/aided.md): filter.csv (the navigation errors beside the filter's
// 1-sigma, NEES and NIS at every GNSS clock epoch) and imu.csv (ideal and measured IMU, as rates
// and as increments). Units are in the headers. A value that does not exist (the NIS of an epoch
// without a fix) is an empty field, never "nan".
#pragma once

#include <cstdio>

#include "nav/types.hpp"
#include "sim/aided/aided_navigation.hpp"

namespace sinsim::sim::aided {

/// ",<v in printf format fmt>", or "," alone when v is not finite (no value): no NaN or inf
/// reaches a CSV file.
void writeCsvNumber(std::FILE* f, const char* fmt, double v);

void writeFilterHeader(std::FILE* f);
/// One row per epoch that has a filter view (fe.sigma set: the GNSS clock epochs); nis is empty
/// (and nis_dof 0) at an epoch without a fix.
void writeFilterRow(std::FILE* f, const FilterEpoch& fe);

void writeImuHeader(std::FILE* f);
/// t, then ideal and measured rates [rad/s], [m/s^2] (increment / dt) and increments [rad], [m/s].
void writeImuRow(std::FILE* f, const nav::ImuSample& ideal, const nav::ImuSample& measured);

}  // namespace sinsim::sim::aided
