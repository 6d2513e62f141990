// The six channels of a record as the diagnosis names them (gx..az) — views of the one channel
// table (errormodels/channels.hpp) — their display units (the model writer's, displayUnit), and
// the number formatting of findings and tables.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "errormodels/channels.hpp"
#include "errormodels/stats/record.hpp"

namespace sinsim::errormodels::diagnose::detail {

/// gx gy gz ax ay az: the names of kRecordChannels.
inline constexpr std::array<const char*, 6> kChannels{
    kRecordChannels[0].name, kRecordChannels[1].name, kRecordChannels[2].name,
    kRecordChannels[3].name, kRecordChannels[4].name, kRecordChannels[5].name};
// InputError for an unknown name, led by `where` (the option that named it)
int channelIndex(const std::string& name, const std::string& where = "--channels");
inline bool isGyro(int c) { return kRecordChannels[c].sensor == Sensor::gyro; }
inline const char* sensorName(int c) { return errormodels::sensorName(kRecordChannels[c].sensor); }
inline const char* axisName(int c) {
  static const char* n[3] = {"x", "y", "z"};
  return n[kRecordChannels[c].axis];
}
using errormodels::channelData;

/// Display units of the model files and reports: displayUnit (model_io.hpp) of each quantity.
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
