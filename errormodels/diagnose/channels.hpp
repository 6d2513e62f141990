// The six channels of a record as the diagnosis names them (gx..az), their display units, and the
// number formatting of findings and tables.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "errormodels/stats/record.hpp"

namespace sinsim::errormodels::diagnose::detail {

extern const std::array<const char*, 6> kChannels;  // gx gy gz ax ay az
int channelIndex(const std::string& name);           // InputError for an unknown name
inline bool isGyro(int c) { return c < 3; }
inline const char* sensorName(int c) { return c < 3 ? "gyro" : "accel"; }
inline const char* axisName(int c) { static const char* n[3] = {"x", "y", "z"}; return n[c % 3]; }
const std::vector<double>& channelData(const Record& r, int c);

/// Display units of the model files and reports (the same as fit/model_writer).
struct Units {
  const char* level;      // signal
  const char* walk;       // signal / sqrt(time)
  const char* increment;  // signal * time
  const char* slope;      // signal / time
  const char* perKelvin;  // signal / degC
  const char* perKelvin2; // signal / degC^2
};
const Units& unitsFor(int channel);
/// "<value in unit> <unit>", 6 significant digits.
std::string quantity(double si, const char* unit);
/// v with `digits` significant digits (%g).
std::string num(double v, int digits = 4);

}  // namespace sinsim::errormodels::diagnose::detail
