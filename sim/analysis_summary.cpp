// The terminal summary of `sinsim analyze` (analysis.hpp): per channel the mean, sd and the noise
// terms read off the Allan curve in datasheet units.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/constants.hpp"
#include "sim/analysis.hpp"

namespace sinsim::sim {

NoiseTerms readNoiseTerms(const errormodels::AllanCurve& a) {
  NoiseTerms t;
  if (a.size() == 0) return t;
  t.N = a.dev.front() * std::sqrt(a.tau.front());
  const auto k = std::size_t(std::min_element(a.dev.begin(), a.dev.end()) - a.dev.begin());
  t.B = a.dev[k] / 0.664;
  t.tauB = a.tau[k];
  t.K = a.dev.back() * std::sqrt(3.0 / a.tau.back());
  return t;
}

DatasheetUnits datasheetUnits(bool gyro) {
  if (gyro) {
    const double degPerHour = kDegPerRad * 3600.0;  // [deg/h per rad/s]
    // N [rad/s·√s] → deg/√h: ·(180/π)·√3600 / 3600 ·3600 = ·(180/π)·60; K [rad/s/√s] → deg/h/√h.
    return {degPerHour, kDegPerRad * 60.0, degPerHour * 60.0, "deg/h", "deg/sqrt(h)", "deg/h/sqrt(h)"};
  }
  const double ug = 1e6 / kStandardGravity;  // [µg per m/s²]
  return {ug, 60.0, ug * 60.0, "ug", "m/s/sqrt(h)", "ug/sqrt(h)"};
}

std::string analysisSummary(const std::vector<ChannelStats>& stats) {
  std::string out =
      "channel  mean            sd              white N (shortest tau)  Allan minimum (B = min/0.664)\n";
  char line[256];
  for (const ChannelStats& c : stats) {
    // Datasheet units: deg/h and deg/sqrt(h) for gyros, ug and m/s/sqrt(h) for accelerometers.
    const DatasheetUnits u = datasheetUnits(c.name[0] == 'g');
    const NoiseTerms t = readNoiseTerms(c.allan);
    std::string N = "-", B = "-";
    if (c.allan.size() > 0 && !c.constant) {
      std::snprintf(line, sizeof line, "%.4g %s", t.N * u.density, u.densityUnit.c_str());
      N = line;
      std::snprintf(line, sizeof line, "%.4g %s at %.3g s", t.B * u.level, u.levelUnit.c_str(), t.tauB);
      B = line;
    }
    char mean[64], sd[64];
    // No exponent: a 1 g accelerometer mean reads -1016130 ug, not -1.01613e+06 ug.
    const double m = c.mean * u.level, d = c.sd * u.level;
    std::snprintf(mean, sizeof mean, std::fabs(m) >= 1e5 ? "%.0f %s" : "%.6g %s", m, u.levelUnit.c_str());
    std::snprintf(sd, sizeof sd, std::fabs(d) >= 1e4 ? "%.0f %s" : "%.4g %s", d, u.levelUnit.c_str());
    std::snprintf(line, sizeof line, "%-8s %-15s %-15s %-22s %s\n", c.name.c_str(), mean, sd,
                  N.c_str(), B.c_str());
    out += line;
  }
  for (const ChannelStats& c : stats)
    if (c.constant) out += c.name + ": constant at every sample, no noise to read (a dead sensor?)\n";
  return out;
}

std::vector<std::string> analysisWarnings(const std::vector<ChannelStats>& stats) {
  std::vector<std::string> out;
  char value[64];
  for (const ChannelStats& c : stats) {
    if (!c.constant) continue;
    std::snprintf(value, sizeof value, "%.9g %s", c.mean, c.unit_si.c_str());
    out.push_back("channel " + c.name + " is constant (" + value +
                  " at every sample): a dead or unconnected sensor? Its sd, PSD and Allan deviation are zero");
  }
  return out;
}

}  // namespace sinsim::sim
