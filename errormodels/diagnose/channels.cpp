// Channel names, display units and number formatting of the diagnosis (channels.hpp).
#include "errormodels/diagnose/channels.hpp"

#include <cstdio>

#include "common/error.hpp"
#include "common/units.hpp"
#include "common/number_text.hpp"
#include "errormodels/model_io.hpp"

namespace sinsim::errormodels::diagnose::detail {

int channelIndex(const std::string& name, const std::string& where) {
  if (const auto c = findChannel(name)) return *c;
  throw InputError(where + ": unknown channel \"" + name + "\" (known: " + kChannelList + ")");
}

namespace {
// The six units of a sensor, kept alive for the const char* of Units.
struct SensorUnits {
  std::array<std::string, 6> text;
  Units units;
  explicit SensorUnits(Sensor s) {
    const Dimension sig = s == Sensor::gyro ? Dimension::angularRate() : Dimension::acceleration();
    const Dimension t = Dimension::time(), T = Dimension::temperature();
    const Dimension dims[6] = {sig, sig / t.sqrt(), sig * t, sig / t, sig / T, sig / T.pow(2)};
    for (int i = 0; i < 6; ++i) text[i] = displayUnit(dims[i], s);
    units = {text[0].c_str(), text[1].c_str(), text[2].c_str(),
             text[3].c_str(), text[4].c_str(), text[5].c_str()};
  }
  SensorUnits(const SensorUnits&) = delete;  // units points into text
};
}  // namespace

const Units& unitsFor(int channel) {
  static const SensorUnits gyro(Sensor::gyro), accel(Sensor::accel);
  return isGyro(channel) ? gyro.units : accel.units;
}

std::string quantity(double si, const char* unit) {
  const double f = parseUnit(unit).si;
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.6g %s", si / f, unit);
  return buf;
}

std::string num(double v, int digits) {
  return significant(v, digits);
}

}  // namespace sinsim::errormodels::diagnose::detail
