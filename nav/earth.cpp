#include "nav/earth.hpp"

#include <cmath>

namespace sinsim::nav {
namespace {
constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;
}

Earth::Earth()
    : gravity_(GeographicLib::NormalGravity::WGS84()),
      ellipsoid_(gravity_.EquatorialRadius(), gravity_.Flattening()),
      omega_(gravity_.AngularVelocity()) {}

double Earth::meridianRadius(double lat) const {
  return ellipsoid_.MeridionalCurvatureRadius(lat * kRadToDeg);
}

double Earth::primeVerticalRadius(double lat) const {
  return ellipsoid_.TransverseCurvatureRadius(lat * kRadToDeg);
}

void Earth::radii(double lat, double& M, double& N) const {
  M = meridianRadius(lat);
  N = primeVerticalRadius(lat);
}

Vec3 Earth::gravity_n(double lat, double h) const {
  double gammay = 0.0, gammaz = 0.0;  // northward and upward components [m/s^2]
  gravity_.Gravity(lat * kRadToDeg, h, gammay, gammaz);
  return Vec3(gammay, 0.0, -gammaz);
}

Vec3 Earth::omega_ie_n(double lat) const {
  return Vec3(omega_ * std::cos(lat), 0.0, -omega_ * std::sin(lat));
}

Vec3 Earth::omega_en_n(double lat, double h, const Vec3& v_n) const {
  double M = 0.0, N = 0.0;
  radii(lat, M, N);
  return Vec3(v_n.y() / (N + h), -v_n.x() / (M + h), -v_n.y() * std::tan(lat) / (N + h));
}

double Earth::schulerFrequency(double lat) const {
  double M = 0.0, N = 0.0;
  radii(lat, M, N);
  return std::sqrt(-gravity_n(lat, 0.0).z() / std::sqrt(M * N));
}

}  // namespace sinsim::nav
