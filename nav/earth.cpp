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

Vec3 Earth::omega_en_n(double lat, double h, const Vec3& v_n) const {
  double M = 0.0, N = 0.0;
  radii(lat, M, N);
  return omega_en_n(M, N, h, std::tan(lat), v_n);
}

double Earth::schulerFrequency(double lat) const {
  double M = 0.0, N = 0.0;
  radii(lat, M, N);
  return std::sqrt(-gravity_n(lat, 0.0).z() / std::sqrt(M * N));
}

}  // namespace sinsim::nav

namespace sinsim::nav {

void LocalGravity::reanchor(double lat, double h) {
  // Central differences: steps keep the truncation (f''' δ²/6) and the rounding (≈ 1e-15 g/δ)
  // of each derivative far below what the expansion box needs (see earth.hpp).
  constexpr double dLat = 1e-5;  // [rad]
  constexpr double dH = 10.0;    // [m]
  lat0_ = lat;
  h0_ = h;
  g0_n_ = earth_->gravity_n(lat, h);
  dg_dlat_ = (earth_->gravity_n(lat + dLat, h) - earth_->gravity_n(lat - dLat, h)) / (2.0 * dLat);
  dg_dh_ = (earth_->gravity_n(lat, h + dH) - earth_->gravity_n(lat, h - dH)) / (2.0 * dH);
  ++reanchors_;
}

}  // namespace sinsim::nav
