// The record-channel table (channels.hpp).
#include "errormodels/channels.hpp"

namespace sinsim::errormodels {

std::optional<int> findChannel(const std::string& name) {
  for (int c = 0; c < int(kRecordChannels.size()); ++c)
    if (name == kRecordChannels[c].name) return c;
  return std::nullopt;
}

const std::vector<double>& channelData(const Record& r, int c) {
  const Channel& ch = kRecordChannels.at(c);
  return ch.sensor == Sensor::gyro ? r.gyro[ch.axis] : r.accel[ch.axis];
}

std::string otherChannels(const Record& r, int c, const char* sep) {
  std::string out;
  for (int k = 0; k < int(kRecordChannels.size()); ++k)
    if (k != c && !channelData(r, k).empty()) out += (out.empty() ? "" : sep) + std::string(kRecordChannels[k].name);
  return out;
}

}  // namespace sinsim::errormodels
