// A measured static record as a Monte Carlo participant: the static scenario it was recorded in,
// the attitude levelled from its data, and a corruptor that replays it in place of the ideal IMU,
// so that it runs through exactly the same navigation (and initial-bias removal) as the models.
#pragma once

#include <cstddef>
#include <string>

#include "errormodels/imu_model.hpp"
#include "errormodels/stats/record.hpp"
#include "nav/types.hpp"

namespace sinsim::sim {

/// Roll and pitch [rad] of an IMU at rest from the mean specific force of its first n samples:
/// at rest f_b = C_bn (0, 0, −g), so roll = atan2(−f_y, −f_z), pitch = atan2(f_x, √(f_y² + f_z²))
/// (Titterton & Weston 2004 §10.2, coarse levelling). Returns (roll, pitch, yaw).
nav::Vec3 levelAttitude(const errormodels::Record& record, std::size_t n, double yaw);

/// Scenario text of a vehicle at rest at (lat, lon [rad], h [m]) with attitude rpy [rad] for
/// duration [s], IMU at imuRate, statistics at outputRate [Hz], vertical channel `vertical`.
std::string staticScenarioYaml(const std::string& name, double lat, double lon, double h,
                               const nav::Vec3& rpy, double imuRate, double outputRate,
                               const std::string& vertical, double duration);

/// Replaces the ideal increments of sample k (ending at t = (k + 1)/rate) by the record's rates
/// times dt. The record must outlive the replay and hold every sample asked for.
class RecordReplay final : public errormodels::ImuCorruptor {
 public:
  RecordReplay(const errormodels::Record& record, double rate) : rec_(record), rate_(rate) {}
  void corrupt(nav::ImuSample& sample, double temperature) override;

 private:
  const errormodels::Record& rec_;
  double rate_;  // [Hz]
};

}  // namespace sinsim::sim
