// The WGS-84 Earth as the navigation equations need it: radii of curvature, normal gravity with
// height, Earth rate and transport rate in NED. All geodesy is GeographicLib's (Ellipsoid,
// NormalGravity); nothing here re-derives a formula.
#pragma once

#include <cmath>

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
  Vec3 omega_ie_n(double lat) const { return omega_ie_n(std::sin(lat), std::cos(lat)); }
  /// The same from precomputed sin(lat), cos(lat) (the mechanization's inner loop).
  Vec3 omega_ie_n(double sinLat, double cosLat) const {
    return Vec3(omega_ * cosLat, 0.0, -omega_ * sinLat);
  }
  /// Transport rate of the NED frame for velocity v_n [m/s] at lat [rad], h [m] (Titterton &
  /// Weston 2004, eq. 3.72): [vE/(N+h), -vN/(M+h), -vE tan(lat)/(N+h)] [rad/s].
  Vec3 omega_en_n(double lat, double h, const Vec3& v_n) const;
  /// The same from precomputed radii M, N [m] and tan(lat) (the mechanization's inner loop).
  static Vec3 omega_en_n(double M, double N, double h, double tanLat, const Vec3& v_n) {
    return Vec3(v_n.y() / (N + h), -v_n.x() / (M + h), -v_n.y() * tanLat / (N + h));
  }

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

/// GeographicLib's normal gravity near a moving anchor point, for inner loops that cannot afford a
/// NormalGravity::Gravity call (~150 ns) every step. Inside the box |lat - lat0| ≤ kMaxDlat,
/// |h - h0| ≤ kMaxDh the value is the first-order Taylor expansion g(lat0, h0) + ∂g/∂lat Δlat +
/// ∂g/∂h Δh, the derivatives being central differences of GeographicLib; outside it the anchor
/// moves to the query point (5 GeographicLib calls). Nothing is re-derived: every number comes
/// from NormalGravity. Truncation (the omitted second-order terms; magnitudes from the leading
/// terms of normal gravity, γ ≈ γ_e (1 + 0.0053 sin² lat)(1 - 2h/a + 3h²/a²)):
///   ½ ∂²γ/∂h² Δh²     ≈ ½ (6γ/a²) (20 m)²        ≈ 3e-10 m/s²,
///   ½ ∂²γ/∂lat² Δlat² ≤ ½ (0.104 m/s²)(2e-5)²   ≈ 2e-11 m/s²,
/// and the northward component's are smaller still — below 1e-9 m/s², i.e. < 1 mm of Schuler-bounded
/// horizontal error (δx ≈ δg/ω_s², ω_s² ≈ 1.5e-6 s^-2). Longitude does not enter normal gravity.
class LocalGravity {
 public:
  static constexpr double kMaxDlat = 2e-5;  // [rad], ≈ 130 m
  static constexpr double kMaxDh = 20.0;    // [m]

  explicit LocalGravity(const Earth& earth) : earth_(&earth) {}

  /// Normal gravity in NED [m/s^2] at lat [rad], h [m]; moves the anchor if the point is outside
  /// the validity box (or on the first call).
  const Vec3& at(double lat, double h) {
    if (!(std::abs(lat - lat0_) <= kMaxDlat && std::abs(h - h0_) <= kMaxDh)) reanchor(lat, h);
    g_n_ = g0_n_ + dg_dlat_ * (lat - lat0_) + dg_dh_ * (h - h0_);
    return g_n_;
  }
  /// ∂g_n/∂h at the anchor [1/s^2] (its down component is ≈ -2g/R).
  const Vec3& dgdh() const { return dg_dh_; }
  /// Number of anchor moves so far (for benchmarks and tests).
  long reanchorCount() const { return reanchors_; }

 private:
  void reanchor(double lat, double h);

  const Earth* earth_;
  double lat0_ = NAN, h0_ = NAN;
  Vec3 g0_n_ = Vec3::Zero(), dg_dlat_ = Vec3::Zero(), dg_dh_ = Vec3::Zero(), g_n_ = Vec3::Zero();
  long reanchors_ = 0;
};

}  // namespace sinsim::nav
