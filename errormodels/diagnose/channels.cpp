// Channel names, display units and number formatting of the diagnosis (channels.hpp).
#include "errormodels/diagnose/channels.hpp"

#include <cstdio>

#include "common/error.hpp"
#include "common/units.hpp"

namespace sinsim::errormodels::diagnose::detail {

const std::array<const char*, 6> kChannels = {"gx", "gy", "gz", "ax", "ay", "az"};

int channelIndex(const std::string& name) {
  for (int c = 0; c < 6; ++c)
    if (name == kChannels[c]) return c;
  throw InputError("unknown channel \"" + name + "\" (known: gx, gy, gz, ax, ay, az)");
}

const std::vector<double>& channelData(const Record& r, int c) {
  return c < 3 ? r.gyro[c] : r.accel[c - 3];
}

const Units& unitsFor(int channel) {
  static const Units gyro{"deg/s", "deg/h/sqrt(h)", "deg", "deg/h^2", "deg/s/degC", "deg/s/degC^2"};
  static const Units accel{"mg", "m/s^2/sqrt(h)", "m/s", "m/s^3", "mg/degC", "mg/degC^2"};
  return isGyro(channel) ? gyro : accel;
}

std::string quantity(double si, const char* unit) {
  const double f = parseUnit(unit).si;
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.6g %s", si / f, unit);
  return buf;
}

std::string num(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

}  // namespace sinsim::errormodels::diagnose::detail
