#include "nav/alignment.hpp"

#include <cmath>

#include "common/error.hpp"
#include "nav/attitude.hpp"

namespace sinsim::nav {

Quat coarseAlignment(const Vec3& f_b, const Vec3& omega_ib_b) {
  if (!(f_b.allFinite() && omega_ib_b.allFinite() && f_b.norm() > 0.0))
    throw InputError("coarse alignment: the mean specific force must be finite and non-zero");
  // Stationary: f_b = C_bn [0, 0, −g] (T&W eq. 10.3), so with C_nb = Rz(ψ) Ry(θ) Rx(φ):
  //   f_b = −g [−sin θ, sin φ cos θ, cos φ cos θ].
  const double roll = std::atan2(-f_b.y(), -f_b.z());
  const double pitch = std::atan2(f_b.x(), std::hypot(f_b.y(), f_b.z()));
  // The rate in the leveled (yaw-only) frame: ω_l = Ry(θ) Rx(φ) ω_b = Rz(ψ)ᵀ Ω [cos L, 0, −sin L],
  // whence ψ = atan2(−ω_l,y, ω_l,x) (T&W eq. 10.7).
  const Mat3 C_lb = dcmFromEuler(Vec3(roll, pitch, 0.0));
  const Vec3 w_l = C_lb * omega_ib_b;
  if (!(std::hypot(w_l.x(), w_l.y()) > 0.0))
    throw InputError("coarse alignment: no horizontal Earth rate to gyrocompass on");
  const double yaw = std::atan2(-w_l.y(), w_l.x());
  return quatFromEuler(Vec3(roll, pitch, yaw));
}

Eigen::Matrix<double, 3, 6> coarseAlignmentSensitivity(double lat, double g, double omega) {
  // Ĉ f̃_b = f_n + δf_n − ψ × f_n with f_n = (0, 0, −g): its level components vanish when
  // δf_N + g ψ_E = 0 and δf_E − g ψ_N = 0. Ĉ ω̃_b's east component vanishes when
  // δω_E = ψ_D Ω cos L + ψ_N Ω sin L (ω_n = Ω (cos L, 0, −sin L)).
  Eigen::Matrix<double, 3, 6> J = Eigen::Matrix<double, 3, 6>::Zero();
  J(0, 1) = 1.0 / g;
  J(1, 0) = -1.0 / g;
  J(2, 4) = 1.0 / (omega * std::cos(lat));
  J(2, 1) = -std::tan(lat) / g;
  return J;
}

}  // namespace sinsim::nav
