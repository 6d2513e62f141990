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

/// The position-dependent Earth quantities of one navigation step, at one point.
struct EarthPoint {
  double M = 0.0;           // meridian radius of curvature [m]
  double N = 0.0;           // prime-vertical radius of curvature [m]
  double sinLat = 0.0;      // sin(lat)
  double cosLat = 1.0;      // cos(lat)
  Vec3 g_n = Vec3::Zero();  // normal gravity in NED [m/s^2]
};

/// GeographicLib's radii and normal gravity near a moving anchor point, for inner loops that
/// cannot afford NormalGravity::Gravity (~150 ns) and two Ellipsoid radii (~27 ns) every step.
///
/// Inside the box |lat - lat0| ≤ kMaxDlat, |h - h0| ≤ kMaxDh the values are second-order Taylor
/// expansions about the anchor (lat0, h0) whose derivatives are finite differences of
/// GeographicLib values (central for the first and pure second derivatives, forward for the
/// mixed one); outside the box the anchor moves to the query point (6 NormalGravity and 3 radii
/// calls). Nothing is re-derived: every number comes from GeographicLib. sin/cos(lat) come from
/// the anchor's by the angle-addition identity, with sin/cos of |Δlat| ≤ 1e-4 by series.
///
/// Truncation (third-order terms; sizes from γ ≈ γ_e (1 + 0.0053 sin² lat)(1 - 2h/a + 3h²/a²)):
///   gravity: (1/6) ∂³γ/∂h³ Δh³ ≈ (1/6)(24γ/a³)(50 m)³ ≈ 2e-13 m/s², (1/6)(0.2 m/s²) Δlat³ ≈
///   3e-14 m/s²; the mixed third-order terms and the forward-difference error of the mixed
///   derivative are smaller; finite-difference rounding ≈ 1e-16 γ (Δ/δ)² ≤ 1e-15 m/s².
///   radii: (1/6) M‴ Δlat³ ≈ (1/6)(4e5 m)(1e-4)³ ≈ 7e-8 m, i.e. 1e-14 relative.
/// All far below what matters for navigation: 1e-9 m/s² of horizontal gravity error is < 1 mm of
/// Schuler-bounded position error (δx ≈ δg/ω_s², ω_s² ≈ 1.5e-6 s^-2). The unit test compares
/// against GeographicLib directly over the box. Longitude does not enter.
class LocalEarth {
 public:
  static constexpr double kMaxDlat = 1e-4;  // [rad], ≈ 640 m
  static constexpr double kMaxDh = 50.0;    // [m]

  explicit LocalEarth(const Earth& earth) : earth_(&earth) {}

  /// Radii, sin/cos(lat) and normal gravity at lat [rad], h [m]; moves the anchor if the point
  /// is outside the validity box (or on the first call).
  const EarthPoint& at(double lat, double h) {
    double dl = lat - lat0_, dh = h - h0_;
    if (!(std::abs(dl) <= kMaxDlat && std::abs(dh) <= kMaxDh)) {
      reanchor(lat, h);
      dl = 0.0;
      dh = 0.0;
    }
    const double dl2 = dl * dl;
    p_.M = M0_ + dl * (dM_ + 0.5 * dl * d2M_);
    p_.N = N0_ + dl * (dN_ + 0.5 * dl * d2N_);
    // sin/cos(lat0 + dl) by angle addition; the series of cos dl, sin dl are truncated at
    // dl^6/720 and dl^7/5040 (< 2e-27 for |dl| ≤ 1e-4).
    const double cd = 1.0 - dl2 * (0.5 - dl2 / 24.0);
    const double sd = dl * (1.0 - dl2 * (1.0 / 6.0 - dl2 / 120.0));
    p_.sinLat = sin0_ * cd + cos0_ * sd;
    p_.cosLat = cos0_ * cd - sin0_ * sd;
    p_.g_n = g0_n_ + dl * (dg_dlat_ + 0.5 * dl * d2g_dlat2_) +
             dh * (dg_dh_ + 0.5 * dh * d2g_dh2_) + (dl * dh) * d2g_dlatdh_;
    return p_;
  }
  /// ∂g_n/∂h at the anchor [1/s^2] (its down component is ≈ -2g/R).
  const Vec3& dgdh() const { return dg_dh_; }
  /// Number of anchor moves so far (for benchmarks and tests).
  long reanchorCount() const { return reanchors_; }

 private:
  void reanchor(double lat, double h);

  const Earth* earth_;
  double lat0_ = NAN, h0_ = NAN;
  double M0_ = 0.0, dM_ = 0.0, d2M_ = 0.0, N0_ = 0.0, dN_ = 0.0, d2N_ = 0.0;
  double sin0_ = 0.0, cos0_ = 1.0;
  Vec3 g0_n_ = Vec3::Zero(), dg_dlat_ = Vec3::Zero(), d2g_dlat2_ = Vec3::Zero();
  Vec3 dg_dh_ = Vec3::Zero(), d2g_dh2_ = Vec3::Zero(), d2g_dlatdh_ = Vec3::Zero();
  EarthPoint p_;
  long reanchors_ = 0;
};

}  // namespace sinsim::nav
