// The six channels of an IMU record, the one table: name (the CSV column and the `--axes` name),
// sensor and axis, in record order gx gy gz ax ay az. Used by the identify pipeline and the
// diagnosis; their display units come from the model writer (displayUnit in model_io.hpp).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "errormodels/model_spec.hpp"
#include "errormodels/stats/record.hpp"

namespace sinsim::errormodels {

struct Channel {
  const char* name;  ///< "gx" .. "az"
  Sensor sensor;
  int axis;          ///< 0, 1, 2 for x, y, z
};

inline constexpr std::array<Channel, 6> kRecordChannels{{{"gx", Sensor::gyro, 0},
                                                         {"gy", Sensor::gyro, 1},
                                                         {"gz", Sensor::gyro, 2},
                                                         {"ax", Sensor::accel, 0},
                                                         {"ay", Sensor::accel, 1},
                                                         {"az", Sensor::accel, 2}}};

/// "gx, gy, gz, ax, ay, az", for messages.
inline constexpr const char* kChannelList = "gx, gy, gz, ax, ay, az";

/// Index 0..5 of a channel name, or nullopt for an unknown name.
std::optional<int> findChannel(const std::string& name);
/// The samples of channel c (0..5) of a record [SI]; empty when the record lacks the column.
const std::vector<double>& channelData(const Record& r, int c);
/// The record's channels other than c that hold data, joined by `sep` ("gx,gy,ax"): the hint
/// that leaves channel c out (`--axes`, `--channels`).
std::string otherChannels(const Record& r, int c, const char* sep);

}  // namespace sinsim::errormodels
