#include "sim/filter_summary.hpp"

#include <string>
#include <vector>

namespace sinsim::sim {

std::string filterSummaryLine(const aided::FilterConfig& f) {
  std::string line = "filter: 9 navigation + " + std::to_string(f.sensors.stateCount()) +
                     " sensor states from " + f.model;
  for (std::size_t i = 0; i < f.knownLabels.size(); ++i)
    line += (i == 0 ? "; compensated as known: " : ", ") + f.knownLabels[i];
  return line;
}

nlohmann::json filterSummaryJson(const aided::FilterConfig& f) {
  static const char* kAxes = "xyz";
  nlohmann::json states = nlohmann::json::object(), white = nlohmann::json::object();
  for (int s = 0; s < 2; ++s)
    for (int i = 0; i < 3; ++i) {
      const aided::SensorAxisModel& m = s == 0 ? f.sensors.gyro[i] : f.sensors.accel[i];
      const std::string axis = std::string(s == 0 ? "gyro." : "accel.") + kAxes[i];
      nlohmann::json blocks = nlohmann::json::array();
      for (const aided::StateBlock& b : m.blocks) blocks.push_back({{"process", b.name}, {"states", b.size}});
      states[axis] = blocks;
      white[axis] = m.whiteDensity;
    }
  return {{"model", f.model},
          {"navigation_states", 9},
          {"sensor_states", f.sensors.stateCount()},
          {"states_per_axis", states},
          {"white_density_si", white},
          {"white_density_unit", "rad/sqrt(s) (gyro), m/s/sqrt(s) (accel)"},
          {"compensated_known_errors", f.knownLabels}};
}

}  // namespace sinsim::sim
