// The WGS-84 Earth as the navigation equations need it: radii of curvature, normal gravity with
// height, Earth rate and transport rate in NED. All geodesy is GeographicLib's (Ellipsoid,
// NormalGravity); nothing here re-derives a formula.
#pragma once

#include <GeographicLib/Ellipsoid.hpp>
#include <GeographicLib/NormalGravity.hpp>

#include "nav/types.hpp"

namespace sinsim::nav {

class Earth {
 public:
  /// WGS-84 ellipsoid and normal gravity field (GeographicLib::NormalGravity::WGS84()).
  Earth();

  /// Meridian radius of curvature M [m] at geodetic latitude lat [rad].
  double meridianRadius(double lat) const;
  /// Prime-vertical (transverse) radius of curvature N [m] at latitude lat [rad].
  double primeVerticalRadius(double lat) const;
  /// Both radii at once (M, N) [m]; cheaper than two calls.
  void radii(double lat, double& M, double& N) const;

  /// Normal gravity vector (gravitation + centrifugal) in NED [m/s^2] at lat [rad], height h [m].
  /// Above the ellipsoid it has a small northward component; GeographicLib gives both.
  Vec3 gravity_n(double lat, double h) const;

  /// Earth rotation rate Ω [rad/s] (WGS-84, 7.292115e-5).
  double rate() const { return omega_; }
  /// Earth rate in NED: Ω [cos lat, 0, -sin lat] [rad/s].
  Vec3 omega_ie_n(double lat) const;
  /// Transport rate of the NED frame for velocity v_n [m/s] at lat [rad], h [m] (Titterton &
  /// Weston 2004, eq. 3.72): [vE/(N+h), -vN/(M+h), -vE tan(lat)/(N+h)] [rad/s].
  Vec3 omega_en_n(double lat, double h, const Vec3& v_n) const;

  /// Equatorial radius a [m] and flattening f of the ellipsoid.
  double a() const { return ellipsoid_.EquatorialRadius(); }
  double f() const { return ellipsoid_.Flattening(); }
  /// Schuler angular frequency sqrt(g/R) at lat [rad] with R = sqrt(M N) [rad/s].
  double schulerFrequency(double lat) const;

  const GeographicLib::NormalGravity& normalGravity() const { return gravity_; }
  const GeographicLib::Ellipsoid& ellipsoid() const { return ellipsoid_; }

 private:
  const GeographicLib::NormalGravity& gravity_;
  GeographicLib::Ellipsoid ellipsoid_;
  double omega_;
};

}  // namespace sinsim::nav
