// How the tests read the real ADIS16405 records (../shared/data/adis16405, 100 Hz, 10 000 s each,
// gyros in deg/s, accelerometers in g; SMAC-Group imudata, University of Calgary, CC BY-NC-SA 4.0).
#pragma once

#include <optional>
#include <string>

#include "errormodels/stats/record.hpp"

namespace sinsim::test {

/// The directory of the records (with a trailing slash).
inline std::string adisDir() { return std::string(SINSIM_SHARED_DIR) + "/data/adis16405/"; }

/// The records' rate and units, `skip` [s] discarded at the start, then `duration` [s] kept.
inline errormodels::RecordOptions adisOptions(double skip = 0.0, std::optional<double> duration = {}) {
  errormodels::RecordOptions ro;
  ro.rate_hz = 100.0;
  ro.gyro_unit = "deg/s";
  ro.accel_unit = "g";
  ro.skip_s = skip;
  ro.duration_s = duration;
  return ro;
}

}  // namespace sinsim::test
