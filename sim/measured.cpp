#include "sim/measured.hpp"

#include <cmath>
#include <sstream>

#include "common/error.hpp"

namespace sinsim::sim {

nav::Vec3 levelAttitude(const errormodels::Record& record, std::size_t n, double yaw) {
  n = std::min(n, record.size());
  if (n == 0) throw InputError(record.source + ": no samples to level from");
  double f[3] = {0, 0, 0};  // mean specific force [m/s^2]
  for (int a = 0; a < 3; ++a) {
    for (std::size_t k = 0; k < n; ++k) f[a] += record.accel[a][k];
    f[a] /= double(n);
  }
  return nav::Vec3(std::atan2(-f[1], -f[2]), std::atan2(f[0], std::hypot(f[1], f[2])), yaw);
}

std::string staticScenarioYaml(const std::string& name, double lat, double lon, double h,
                               const nav::Vec3& rpy, double imuRate, double outputRate,
                               const std::string& vertical, double duration) {
  constexpr double kDeg = 180.0 / 3.14159265358979323846;
  std::ostringstream y;
  y.precision(17);
  y << "name: " << name << "\n"
    << "start:\n  latitude: " << lat * kDeg << " deg\n  longitude: " << lon * kDeg << " deg\n"
    << "  height: " << h << " m\n"
    << "  attitude: {roll: " << rpy.x() * kDeg << " deg, pitch: " << rpy.y() * kDeg
    << " deg, yaw: " << rpy.z() * kDeg << " deg}\n"
    << "imu_rate: " << imuRate << " Hz\noutput_rate: " << outputRate << " Hz\n"
    << "vertical: " << vertical << "\nerrors: none\n"
    << "segments:\n  - {type: static, duration: " << duration << " s}\n";
  return y.str();
}

void RecordReplay::corrupt(nav::ImuSample& s, double) {
  const long long k = std::llround(s.t * rate_) - 1;
  if (k < 0 || std::size_t(k) >= rec_.size())
    throw InputError(rec_.source + ": the record has no sample for t = " + std::to_string(s.t) + " s");
  for (int a = 0; a < 3; ++a) {
    s.dtheta_b[a] = rec_.gyro[a][std::size_t(k)] * s.dt;
    s.dv_b[a] = rec_.accel[a][std::size_t(k)] * s.dt;
  }
}

}  // namespace sinsim::sim
