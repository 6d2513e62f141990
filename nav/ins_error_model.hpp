// Linearised error dynamics of the NED strapdown mechanization (nav/strapdown.hpp), the model an
// error-state (GNSS/INS) Kalman filter propagates. Filter-independent: no noise statistics, no
// sensor states — only how position, velocity and attitude errors evolve and how a body-frame
// gyro or accelerometer error enters them.
//
// States (9), all in the local NED frame at the navigated position:
//   δr_n = [δN, δE, δD]     position error [m]: δN = (M+h) δlat, δE = (N+h) cos(lat) δlon, δD = −δh
//   δv_n                    velocity error (navigated − true) [m/s]
//   ψ                       attitude error ("phi-angle", small rotation of the navigated frame):
//                           Ĉ_nb = (I − [ψ×]) C_nb  [rad]
// Error equations (Titterton & Weston 2004, §12.3.1, eqs. 12.6–12.16 in phi-angle form; Shin 2005,
// "Estimation techniques for low-cost inertial navigation", UCGE 20219, eqs. 2.44–2.50):
//   δṙ_n = F_rr δr_n + δv_n
//   δv̇_n = f_n × ψ + C_nb δf_b − (2ω_ie + ω_en) × δv_n + v_n × (2δω_ie + δω_en) + δg_n
//   ψ̇    = −ω_in × ψ + δω_in − C_nb δω_ib_b
// with δω_ie, δω_en the changes of the Earth and transport rates with δr_n and δv_n and δg_n the
// vertical gravity gradient 2g/R δD (free-air gradient; the horizontal gradients, g/R, are two
// orders below it and left out). The damped vertical channel of the strapdown adds its loop
// (δḊ −= k1 δD, δv̇_D −= k2 δD); the held channel pins δD and δv_D (their rows are zero).
#pragma once

#include <Eigen/Core>

#include "nav/earth.hpp"
#include "nav/strapdown.hpp"
#include "nav/types.hpp"

namespace sinsim::nav {

using Mat9 = Eigen::Matrix<double, 9, 9>;
using Mat93 = Eigen::Matrix<double, 9, 3>;

/// Index of the first state of each 3-vector in the 9-state vector.
enum InsErrorIndex { kPos = 0, kVel = 3, kAtt = 6 };

/// Where the error dynamics are linearised: the navigation solution and the specific force.
struct InsErrorPoint {
  double lat = 0.0;            // [rad]
  double h = 0.0;              // [m]
  Vec3 v_n = Vec3::Zero();     // [m/s]
  Vec3 f_n = Vec3::Zero();     // specific force in NED [m/s^2]
  Mat3 C_nb = Mat3::Identity();
};

/// Continuous-time system matrix F (9×9) of the error states above at `p`; `vertical` selects the
/// vertical channel as the strapdown runs it (k1 [1/s], k2 [1/s^2] its damping gains, used for
/// VerticalChannel::Damped only).
Mat9 insErrorDynamics(const Earth& earth, const InsErrorPoint& p, VerticalChannel vertical,
                      double k1 = 0.0, double k2 = 0.0);

/// How a gyro error δω_ib_b [rad/s] enters: rows of ψ get −C_nb (9×3, other rows zero).
Mat93 gyroErrorInput(const Mat3& C_nb);
/// How an accelerometer error δf_b [m/s^2] enters: rows of δv_n get C_nb; zero in the rows of the
/// held vertical channel's δv_D when `vertical` is Held.
Mat93 accelErrorInput(const Mat3& C_nb, VerticalChannel vertical);

}  // namespace sinsim::nav
