// The sensor temperature over a run or a record, the one type for the scenario (`temperature:`)
// and for `sinsim synth --temperature`: absent, a constant, a linear ramp, or a table read from a
// CSV file. The value handed to ImuCorruptor::corrupt at each interval's midpoint.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "common/config.hpp"

namespace sinsim::sim {

struct TemperatureProfile {
  bool present = false;
  double start = NAN;  ///< temperature at t = 0 [K]
  double rate = 0.0;   ///< linear ramp [K/s]
  /// A table instead of start + rate t (when not empty): times [s], strictly increasing, and
  /// temperatures [K], interpolated linearly and held constant outside the time span.
  std::vector<double> times, kelvins;

  /// Temperature at time t [s] [K]; NaN when absent.
  double at(double t) const;
};

/// The scenario's `temperature:` node: "25 degC", {start, end} (a ramp over `duration` [s]) or
/// {start, rate}. Problems are recorded on the node (file, line, key); absent node: not present.
TemperatureProfile readTemperature(const ConfigNode& node, double duration);

/// `--temperature` text for a record of `duration` [s]: a constant "25 degC", a ramp over the
/// whole record "20 degC..45 degC", or a CSV file with header t,temp (s, degC). InputError naming
/// the option, file and row otherwise.
TemperatureProfile temperatureFromText(const std::string& spec, double duration);

}  // namespace sinsim::sim
