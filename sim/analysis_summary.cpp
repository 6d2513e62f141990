// The terminal summary of `sinsim analyze` (analysis.hpp): per channel the mean, sd and the noise
// terms read off the Allan curve in datasheet units.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/constants.hpp"
#include "sim/analysis.hpp"

namespace sinsim::sim {

// How far the shortest tau's slope may be from white noise's −½ before N is read elsewhere, and
// how near an octave's slope must be to count as white noise's there.
constexpr double kWhiteSlopeTolerance = 0.1;
constexpr double kWhiteSlopeFound = 0.05;

NoiseTerms readNoiseTerms(const errormodels::AllanCurve& a) {
  NoiseTerms t;
  if (a.size() == 0) return t;
  t.N = a.dev.front() * std::sqrt(a.tau.front());
  t.tauN = a.tau.front();
  const auto k = std::size_t(std::min_element(a.dev.begin(), a.dev.end()) - a.dev.begin());
  // The slope over an octave from point i (the curve's points may be dense: neighbours' slopes
  // scatter), and the end point of that octave.
  auto octaveEnd = [&](std::size_t i) {
    std::size_t j = i + 1;
    while (j + 1 < a.size() && a.tau[j] < 2.0 * a.tau[i]) ++j;
    return j;
  };
  auto slope = [&](std::size_t i) {
    const std::size_t j = octaveEnd(i);
    return std::log(a.dev[j] / a.dev[i]) / std::log(a.tau[j] / a.tau[i]);
  };
  auto positive = [&](std::size_t i) { return a.dev[i] > 0 && a.dev[octaveEnd(i)] > 0; };
  if (a.size() > 1 && positive(0)) t.shortSlope = slope(0);
  if (std::fabs(t.shortSlope + 0.5) > kWhiteSlopeTolerance) {
    // The first octave, from the short end up to the Allan minimum, whose slope is white noise's;
    // else the one nearest it.
    std::size_t best = 0;
    for (std::size_t i = 1; i < k && octaveEnd(i) <= k; ++i) {
      if (!positive(i)) continue;
      if (std::fabs(slope(i) + 0.5) < std::fabs(slope(best) + 0.5)) best = i;
      if (std::fabs(slope(i) + 0.5) <= kWhiteSlopeFound) break;
    }
    if (best > 0) {
      const std::size_t j = octaveEnd(best);
      t.tauN = std::sqrt(a.tau[best] * a.tau[j]);
      t.N = std::sqrt(a.dev[best] * a.dev[j]) * std::sqrt(t.tauN);
    }
  }
  t.B = a.dev[k] / 0.664;
  t.tauB = a.tau[k];
  t.bStillFalling = a.size() > 1 && k + 1 == a.size();
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
      "channel  mean            sd              white N (at tau)               bias instability B = Allan minimum / 0.664 (at tau)\n";
  char line[256];
  for (const ChannelStats& c : stats) {
    // Datasheet units: deg/h and deg/sqrt(h) for gyros, ug and m/s/sqrt(h) for accelerometers.
    const DatasheetUnits u = datasheetUnits(c.name[0] == 'g');
    const NoiseTerms t = readNoiseTerms(c.allan);
    std::string N = "-", B = "-";
    if (c.allan.size() > 0 && !c.constant) {
      std::snprintf(line, sizeof line, "%.4g %s at %.3g s", t.N * u.density, u.densityUnit.c_str(), t.tauN);
      N = line;
      std::snprintf(line, sizeof line, t.bStillFalling ? "<= %.4g %s at %.3g s (still falling)" : "%.4g %s at %.3g s",
                    t.B * u.level, u.levelUnit.c_str(), t.tauB);
      B = line;
    }
    char mean[64], sd[64];
    // No exponent: a 1 g accelerometer mean reads -1016130 ug, not -1.01613e+06 ug.
    const double m = c.mean * u.level, d = c.sd * u.level;
    std::snprintf(mean, sizeof mean, std::fabs(m) >= 1e5 ? "%.0f %s" : "%.6g %s", m, u.levelUnit.c_str());
    std::snprintf(sd, sizeof sd, std::fabs(d) >= 1e4 ? "%.0f %s" : "%.4g %s", d, u.levelUnit.c_str());
    std::snprintf(line, sizeof line, "%-8s %-15s %-15s %-30s %s\n", c.name.c_str(), mean, sd,
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
    const NoiseTerms t = readNoiseTerms(c.allan);
    if (!c.constant && c.allan.size() > 0 && t.tauN > c.allan.tau.front()) {
      const bool filtered = t.shortSlope > -0.5;
      std::snprintf(value, sizeof value, "slope %.2f; N read at %.3g s", t.shortSlope, t.tauN);
      out.push_back("channel " + c.name + ": the Allan deviation at the shortest tau is not white noise's (" + value +
                    ", where the slope is nearest -1/2): " +
                    (filtered ? "a low-pass filter in the sensor (or a correlated noise) under-reads the white noise there"
                              : "quantization or another fast noise over-reads the white noise there"));
    }
    if (!c.constant) continue;
    std::snprintf(value, sizeof value, "%.9g %s", c.mean, c.unit_si.c_str());
    out.push_back("channel " + c.name + " is constant (" + value +
                  " at every sample): a dead or unconnected sensor? Its sd, PSD and Allan deviation are zero");
  }
  return out;
}

}  // namespace sinsim::sim
