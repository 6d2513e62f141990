#include "nav/earth.hpp"

#include <cmath>

#include "common/constants.hpp"

namespace sinsim::nav {

Earth::Earth()
    : gravity_(GeographicLib::NormalGravity::WGS84()),
      ellipsoid_(gravity_.EquatorialRadius(), gravity_.Flattening()),
      omega_(gravity_.AngularVelocity()) {}

double Earth::meridianRadius(double lat) const {
  return ellipsoid_.MeridionalCurvatureRadius(lat * kDegPerRad);
}

double Earth::primeVerticalRadius(double lat) const {
  return ellipsoid_.TransverseCurvatureRadius(lat * kDegPerRad);
}

void Earth::radii(double lat, double& M, double& N) const {
  M = meridianRadius(lat);
  N = primeVerticalRadius(lat);
}

Vec3 Earth::gravity_n(double lat, double h) const {
  double gammay = 0.0, gammaz = 0.0;  // northward and upward components [m/s^2]
  gravity_.Gravity(lat * kDegPerRad, h, gammay, gammaz);
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
  return std::sqrt(gravity_n(lat, 0.0).z() / std::sqrt(M * N));  // g_n.z() > 0: NED down
}

}  // namespace sinsim::nav

namespace sinsim::nav {

void LocalEarth::reanchor(double lat, double h) {
  // Difference steps equal to the box: the rounding of a second difference, ≈ 1e-16·value·(Δ/δ)²,
  // then stays at the 1e-16 level of the value, and the truncation of the differences (f'''' δ²/12
  // relative to f'') is of the same order as the expansion's own third-order remainder.
  constexpr double dLat = kMaxDlat;  // [rad]
  constexpr double dH = kMaxDh;      // [m]
  lat0_ = lat;
  h0_ = h;
  sin0_ = std::sin(lat);
  cos0_ = std::cos(lat);
  double Mp, Np, Mm, Nm;
  earth_->radii(lat, M0_, N0_);
  earth_->radii(lat + dLat, Mp, Np);
  earth_->radii(lat - dLat, Mm, Nm);
  dM_ = (Mp - Mm) / (2.0 * dLat);
  d2M_ = (Mp - 2.0 * M0_ + Mm) / (dLat * dLat);
  dN_ = (Np - Nm) / (2.0 * dLat);
  d2N_ = (Np - 2.0 * N0_ + Nm) / (dLat * dLat);
  g0_n_ = earth_->gravity_n(lat, h);
  const Vec3 gLp = earth_->gravity_n(lat + dLat, h), gLm = earth_->gravity_n(lat - dLat, h);
  const Vec3 gHp = earth_->gravity_n(lat, h + dH), gHm = earth_->gravity_n(lat, h - dH);
  const Vec3 gLpHp = earth_->gravity_n(lat + dLat, h + dH);
  dg_dlat_ = (gLp - gLm) / (2.0 * dLat);
  d2g_dlat2_ = (gLp - 2.0 * g0_n_ + gLm) / (dLat * dLat);
  dg_dh_ = (gHp - gHm) / (2.0 * dH);
  d2g_dh2_ = (gHp - 2.0 * g0_n_ + gHm) / (dH * dH);
  d2g_dlatdh_ = (gLpHp - gLp - gHp + g0_n_) / (dLat * dH);
  ++reanchors_;
}

}  // namespace sinsim::nav
