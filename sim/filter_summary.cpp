#include "sim/filter_summary.hpp"

#include <string>

namespace sinsim::sim {

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
  nlohmann::json known = nlohmann::json::array();
  for (const errormodels::ImuErrorModel* m : {&f.knownAdded, &f.knownLinear})
    for (const std::string& name : m->effectNames()) known.push_back(name);
  return {{"model", f.model},
          {"navigation_states", 9},
          {"sensor_states", f.sensors.stateCount()},
          {"states_per_axis", states},
          {"white_density_si", white},
          {"white_density_unit", "rad/sqrt(s) (gyro), m/s/sqrt(s) (accel)"},
          {"compensated_known_errors", known}};
}

}  // namespace sinsim::sim
