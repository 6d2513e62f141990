#include "nav/ins_error_model.hpp"

#include <cmath>

#include "nav/attitude.hpp"

namespace sinsim::nav {

Mat9 insErrorDynamics(const Earth& earth, const InsErrorPoint& p, VerticalChannel vertical,
                      double k1, double k2) {
  double M = 0.0, N = 0.0;
  earth.radii(p.lat, M, N);
  const double Mh = M + p.h, Nh = N + p.h;
  const double sL = std::sin(p.lat), cL = std::cos(p.lat), tL = sL / cL;
  const double vN = p.v_n.x(), vE = p.v_n.y(), vD = p.v_n.z();
  const double W = earth.rate();
  const Vec3 w_ie = earth.omega_ie_n(sL, cL);
  const Vec3 w_en = Earth::omega_en_n(M, N, p.h, tL, p.v_n);

  // Partial derivatives of the Earth and transport rates (T&W eq. 3.72) with respect to the
  // states: δlat = δN/(M+h), δh = −δD.
  Mat3 dWie_dr = Mat3::Zero();  // ∂ω_ie/∂δr
  dWie_dr.col(0) = Vec3(-W * sL, 0.0, -W * cL) / Mh;
  Mat3 dWen_dr = Mat3::Zero();  // ∂ω_en/∂δr
  dWen_dr(2, 0) = -vE / (cL * cL * Nh * Mh);
  dWen_dr.col(2) = Vec3(vE / (Nh * Nh), -vN / (Mh * Mh), -vE * tL / (Nh * Nh));
  Mat3 dWen_dv = Mat3::Zero();  // ∂ω_en/∂δv
  dWen_dv(0, 1) = 1.0 / Nh;
  dWen_dv(1, 0) = -1.0 / Mh;
  dWen_dv(2, 1) = -tL / Nh;

  Mat9 F = Mat9::Zero();
  // Position: derivative of δN = (M+h)δlat and δE = (N+h)cos(lat)δlon along the motion
  // (Shin 2005, eq. 2.44).
  F(0, 0) = -vD / Mh;
  F(0, 2) = vN / Mh;
  F(1, 0) = vE * tL / Mh;
  F(1, 1) = -(vD / Nh + vN * tL / Mh);
  F(1, 2) = vE / Nh;
  F.block<3, 3>(kPos, kVel).setIdentity();

  // Velocity (T&W eq. 12.10 in NED): specific-force rotation, Coriolis and transport.
  const Mat3 vx = skew(p.v_n);
  F.block<3, 3>(kVel, kPos) = vx * (2.0 * dWie_dr + dWen_dr);
  F.block<3, 3>(kVel, kVel) = -skew(2.0 * w_ie + w_en) + vx * dWen_dv;
  F.block<3, 3>(kVel, kAtt) = skew(p.f_n);
  // Free-air gradient: g_D(h + δh) ≈ g_D − (2g/R)δh with δh = −δD; R the Gaussian mean radius.
  const double g = earth.gravity_n(p.lat, p.h).z();
  F(kVel + 2, kPos + 2) += 2.0 * g / (std::sqrt(M * N) + p.h);

  // Attitude (T&W eq. 12.6): ψ̇ = −ω_in × ψ + δω_in.
  F.block<3, 3>(kAtt, kPos) = dWie_dr + dWen_dr;
  F.block<3, 3>(kAtt, kVel) = dWen_dv;
  F.block<3, 3>(kAtt, kAtt) = -skew(w_ie + w_en);

  switch (vertical) {
    case VerticalChannel::Free: break;
    case VerticalChannel::Damped:
      // ḣ = −v_D − k1(h − h_ref), v̇_D = a_D + k2(h − h_ref) (strapdown.hpp) with δh = −δD.
      F(kPos + 2, kPos + 2) -= k1;
      F(kVel + 2, kPos + 2) -= k2;
      break;
    case VerticalChannel::Held:
      F.row(kPos + 2).setZero();
      F.row(kVel + 2).setZero();
      F.col(kPos + 2).setZero();
      F.col(kVel + 2).setZero();
      break;
  }
  return F;
}

Mat93 gyroErrorInput(const Mat3& C_nb) {
  Mat93 G = Mat93::Zero();
  G.block<3, 3>(kAtt, 0) = -C_nb;
  return G;
}

Mat93 accelErrorInput(const Mat3& C_nb, VerticalChannel vertical) {
  Mat93 G = Mat93::Zero();
  G.block<3, 3>(kVel, 0) = C_nb;
  if (vertical == VerticalChannel::Held) G.row(kVel + 2).setZero();
  return G;
}

}  // namespace sinsim::nav
