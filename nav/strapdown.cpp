// NED strapdown mechanization, one IMU interval (t_{k-1}, t_k] per update().
//
// Step order (Savage 1998 two-speed structure; PSINS insupdate ordering):
//   1. extrapolate velocity and position to the interval midpoint t_{k-½};
//   2. Earth quantities once, at that midpoint: radii M, N (GeographicLib Ellipsoid), normal
//      gravity g_n (GeographicLib NormalGravity via LocalGravity), ω_ie^n, ω_en^n, ζ = ω_in^n h;
//   3. body-frame increments: coning-corrected rotation vector φ and the rotation- and
//      sculling-corrected specific-force increment Δv_SF^b (strapdown.hpp);
//   4. velocity: v_k = v_{k-1} + (I - ½ζ×) C_nb(k-1) Δv_SF^b + [g - (2ω_ie + ω_en) × v]_{k-½} h;
//   5. position: trapezoid on (v_{k-1} + v_k)/2 with the midpoint radii; vertical channel policy;
//   6. attitude: q_nb(k) = q(-ζ) ⊗ q_nb(k-1) ⊗ q(φ), renormalised.
// Local truncation of steps 4-6 is O(h³) for smooth motion, and the two-sample coning/sculling
// terms are exact for rates and specific forces linear in time over two intervals.
#include "nav/strapdown.hpp"

#include <string>

#include "common/constants.hpp"
#include "common/error.hpp"

namespace sinsim::nav {
namespace {

bool finiteState(const NavState& s) {
  return std::isfinite(s.t) && std::isfinite(s.lat) && std::isfinite(s.lon) &&
         std::isfinite(s.h) && s.v_n.allFinite() && s.q_nb.coeffs().allFinite() &&
         s.q_nb.norm() > 0.5;
}

}  // namespace

Strapdown::Strapdown(const Earth& earth, const NavState& initial, const StrapdownOptions& options,
                     double hRef0)
    : earth_(&earth), state_(initial), options_(options), local_(earth) {
  if (!finiteState(initial))
    throw InputError("strapdown: initial state must be finite with a non-zero attitude quaternion");
  if (!(std::abs(initial.lat) < 0.5 * kPi))
    throw InputError("strapdown: initial latitude must be strictly between -90° and 90°");
  if (options.vertical == VerticalChannel::Damped &&
      !(std::isfinite(options.dampingTimeConstant) && options.dampingTimeConstant > 0.0))
    throw InputError("strapdown: damping time constant must be a positive number of seconds, got " +
                     std::to_string(options.dampingTimeConstant));
  state_.q_nb.normalize();
  tau_ = options.dampingTimeConstant;
  k1_ = 2.0 / tau_;
  // Gravity minus Coriolis at the start, for the first midpoint extrapolation.
  const EarthPoint& e = local_.at(state_.lat, state_.h);
  const Vec3 w_ie = earth_->omega_ie_n(e.sinLat, e.cosLat);
  const Vec3 w_en = Earth::omega_en_n(e.M, e.N, state_.h, e.sinLat / e.cosLat, state_.v_n);
  gcc_n_ = e.g_n - (2.0 * w_ie + w_en).cross(state_.v_n);
  M_ = e.M;
  hRefPrev_ = std::isfinite(hRef0) ? hRef0 : state_.h;
}

void Strapdown::correct(const Vec3& dr_n, const Vec3& dv_n, const Vec3& psi) {
  if (!(dr_n.allFinite() && dv_n.allFinite() && psi.allFinite()))
    throw InputError("strapdown: a correction must be finite");
  if (!dr_n.isZero()) {  // (the filter's per-interval sensor compensation has no position part)
    double M = 0.0, N = 0.0;
    earth_->radii(state_.lat, M, N);
    state_.lat -= dr_n.x() / (M + state_.h);
    state_.lon -= dr_n.y() / ((N + state_.h) * std::cos(state_.lat));
    // δD = −δh; the held channel's height and v_D are the reference's, whatever the filter says
    if (options_.vertical != VerticalChannel::Held) state_.h += dr_n.z();
  }
  state_.v_n.head<2>() -= dv_n.head<2>();
  if (options_.vertical != VerticalChannel::Held) state_.v_n.z() -= dv_n.z();
  // C_nb = (I + [ψ×]) Ĉ_nb to first order; the exact rotation keeps q_nb a unit quaternion.
  state_.q_nb = (quatFromRotationVector(psi) * state_.q_nb).normalized();
}

double Strapdown::dampingGainK2() const {
  // ω_v² = -∂g_D/∂h from GeographicLib (≈ 2g/R = 3.1e-6 s^-2).
  return 1.0 / (tau_ * tau_) - local_.dgdh().z();
}

void Strapdown::update(const ImuSample& imu, double hRef) {
  const double dt = imu.dt;
  if (!(dt > 0.0 && std::isfinite(dt)))
    throw InputError("strapdown: IMU interval must be positive and finite, got dt = " +
                     std::to_string(dt) + " s at t = " + std::to_string(imu.t) + " s");
  const VerticalChannel vc = options_.vertical;
  if (vc != VerticalChannel::Free && !std::isfinite(hRef))
    throw InputError("strapdown: the held or damped vertical channel needs a finite reference "
                     "height, got " + std::to_string(hRef) + " at t = " + std::to_string(imu.t) +
                     " s");

  const Mat3 C_nb = state_.q_nb.toRotationMatrix();  // C^{n(k-1)}_{b(k-1)}
  const Vec3& v0 = state_.v_n;
  const double h0 = state_.h;

  // 1. Midpoint extrapolation (PSINS insupdate: vn01 = vn + an·h/2, pos01 = pos + Mpv·vn01·h/2),
  //    with the acceleration formed from this interval's Δv and the last gravity/Coriolis.
  Vec3 v_mid = v0 + 0.5 * (C_nb * imu.dv_b + gcc_n_ * dt);
  double h_mid;
  if (vc == VerticalChannel::Held) {
    // The interval's mean vertical velocity, v_D(t_{k-½}) + O(h²), from the references alone: the
    // state's own height may differ from the reference (an initial height error, a filter's
    // correction) and a difference with it would be a one-step vertical velocity of (δh / dt),
    // whose Coriolis term kicks the horizontal channels (500 m at 100 Hz: 5.6 cm/s east at 40° N).
    v_mid.z() = -(hRef - hRefPrev_) / dt;
    h_mid = 0.5 * (hRefPrev_ + hRef);
  } else {
    h_mid = h0 - 0.25 * dt * (v0.z() + v_mid.z());
  }
  const double lat_mid = state_.lat + 0.25 * dt * (v0.x() + v_mid.x()) / (M_ + h0);

  // 2. Earth at the midpoint, once per step (LocalEarth: GeographicLib values, earth.hpp).
  const EarthPoint& e = local_.at(lat_mid, h_mid);
  const double cosLat = e.cosLat;
  const Vec3 w_ie = earth_->omega_ie_n(e.sinLat, cosLat);
  const Vec3 w_en = Earth::omega_en_n(e.M, e.N, h_mid, e.sinLat / cosLat, v_mid);
  const Vec3 zeta = (w_ie + w_en) * dt;  // nav-frame rotation over the interval [rad]
  M_ = e.M;

  // 3. Body-frame increments (two-sample forms; the first step uses the one-sample forms).
  const Vec3 phi_b = rotationVectorTwoSample(prevDtheta_b_, imu.dtheta_b);
  const Vec3 dvSF_b =
      specificForceIncrementTwoSample(prevDtheta_b_, prevDv_b_, imu.dtheta_b, imu.dv_b);

  // 4. Velocity (Savage 1998 Part 2): specific-force increment taken to n(k-1), then to n(k) by
  //    the first-order nav-frame rotation -½ ζ × (·); gravity and Coriolis at the midpoint.
  const Vec3 dvSF_n0 = C_nb * dvSF_b;
  const Vec3 dvSF_n = dvSF_n0 - 0.5 * zeta.cross(dvSF_n0);
  gcc_n_ = e.g_n - (2.0 * w_ie + w_en).cross(v_mid);
  Vec3 v1 = v0 + dvSF_n + gcc_n_ * dt;

  // 5. Position: trapezoid on velocity (PSINS Mpvvn = Mpv·(vn + vn1)/2), radii at the midpoint.
  double h1;
  switch (vc) {
    case VerticalChannel::Free:
      h1 = h0 - 0.5 * dt * (v0.z() + v1.z());
      break;
    case VerticalChannel::Held: {
      h1 = hRef;
      // v_D(t_k) from the reference: three-point (second-order) backward difference when two
      // earlier reference heights exist, else the two-point difference.
      if (std::isfinite(hRefPrev2_) && prevDt_ > 0.0) {
        const double a = prevDt_, b = dt;
        v1.z() = -(hRefPrev2_ * b / (a * (a + b)) - hRefPrev_ * (a + b) / (a * b) +
                   hRef * (a + 2.0 * b) / (b * (a + b)));
      } else {
        v1.z() = -(hRef - hRefPrev_) / dt;
      }
      break;
    }
    case VerticalChannel::Damped: {
      // Second-order baro-inertial loop, forward-Euler on the loop terms (dt/τ ≪ 1):
      // ḣ = -v_D - k1 e, v̇_D = a_D + k2 e, e = h - hRef (gains: strapdown.hpp).
      const double hFree = h0 - 0.5 * dt * (v0.z() + v1.z());
      const double err = hFree - hRef;
      h1 = hFree - k1_ * err * dt;
      v1.z() += dampingGainK2() * err * dt;
      break;
    }
    default:
      h1 = h0;
  }
  const double hm = 0.5 * (h0 + h1);
  state_.lat += 0.5 * dt * (v0.x() + v1.x()) / (e.M + hm);
  state_.lon += 0.5 * dt * (v0.y() + v1.y()) / ((e.N + hm) * cosLat);
  if (std::abs(state_.lon) > kPi) state_.lon = wrapAngle(state_.lon);
  state_.h = h1;
  state_.v_n = v1;

  // 6. Attitude (Savage 1998 Part 1): C^{n(k)}_{b(k)} = C^{n(k)}_{n(k-1)} C^{n(k-1)}_{b(k-1)}
  //    C^{b(k-1)}_{b(k)}; the nav frame turns by +ζ, so C^{n(k)}_{n(k-1)} is the rotation by -ζ.
  //    Written as q + Δq with Δq = α⊗q + q⊗β + α⊗q⊗β, α = q(-ζ) - 1, β = q(φ) - 1, so that
  //    exactly cancelling rotations (a vehicle at rest) leave q bit-identical instead of
  //    accumulating a systematic rounding drift of ~1e-16 rad per step (measured: 1e-10 rad/h).
  {
    const Quat& q = state_.q_nb;
    const Quat alpha = quatDeltaFromRotationVector(-zeta);
    const Quat beta = quatDeltaFromRotationVector(phi_b);
    const Quat qb = q * beta;
    const Eigen::Vector4d dq = (alpha * q).coeffs() + qb.coeffs() + (alpha * qb).coeffs();
    state_.q_nb.coeffs() += dq;
    // First-order renormalisation q ← q (3 - |q|²)/2: exact to O((|q|² - 1)²), leaves a unit
    // quaternion untouched.
    state_.q_nb.coeffs() *= 0.5 * (3.0 - state_.q_nb.squaredNorm());
  }
  state_.t = imu.t;

  prevDtheta_b_ = imu.dtheta_b;
  prevDv_b_ = imu.dv_b;
  prevDt_ = dt;
  if (vc == VerticalChannel::Held) {
    hRefPrev2_ = hRefPrev_;
    hRefPrev_ = hRef;
  }
}

}  // namespace sinsim::nav
