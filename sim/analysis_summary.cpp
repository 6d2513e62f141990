// The terminal summary of `sinsim analyze` (analysis.hpp): per channel the mean, sd and the noise
// terms read off the Allan curve in datasheet units.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/constants.hpp"
#include "sim/analysis.hpp"

namespace sinsim::sim {

std::string analysisSummary(const std::vector<ChannelStats>& stats) {
  std::string out =
      "channel  mean            sd              white N (shortest tau)  Allan minimum (B = min/0.664)\n";
  char line[256];
  for (const ChannelStats& c : stats) {
    const bool gyro = c.name[0] == 'g';
    // Datasheet units: deg/h and deg/sqrt(h) for gyros, ug and m/s/sqrt(h) for accelerometers.
    const double level = gyro ? kDegPerRad * 3600.0 : 1e6 / kStandardGravity;
    const char* levelUnit = gyro ? "deg/h" : "ug";
    const double white = gyro ? kDegPerRad * 60.0 : 60.0;  // [unit sqrt(s)] -> per sqrt(h)
    const char* whiteUnit = gyro ? "deg/sqrt(h)" : "m/s/sqrt(h)";
    const auto& a = c.allan;
    std::string N = "-", B = "-";
    if (a.size() > 0) {
      // White noise from the shortest tau, where it dominates a white-noise-limited sensor:
      // ADEV(tau) sqrt(tau) is N on the -1/2 line (IEEE Std 952, Annex C).
      std::snprintf(line, sizeof line, "%.4g %s", a.dev[0] * std::sqrt(a.tau[0]) * white, whiteUnit);
      N = line;
      const auto k = std::size_t(std::min_element(a.dev.begin(), a.dev.end()) - a.dev.begin());
      std::snprintf(line, sizeof line, "%.4g %s at %.3g s", a.dev[k] / 0.664 * level, levelUnit, a.tau[k]);
      B = line;
    }
    char mean[64], sd[64];
    std::snprintf(mean, sizeof mean, "%.6g %s", c.mean * level, levelUnit);
    std::snprintf(sd, sizeof sd, "%.4g %s", c.sd * level, levelUnit);
    std::snprintf(line, sizeof line, "%-8s %-15s %-15s %-22s %s\n", c.name.c_str(), mean, sd,
                  N.c_str(), B.c_str());
    out += line;
  }
  return out;
}

}  // namespace sinsim::sim
