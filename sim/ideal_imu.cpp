#include "sim/ideal_imu.hpp"

#include <algorithm>
#include <cmath>

#include "common/error.hpp"
#include "common/limits.hpp"
#include "nav/attitude.hpp"

namespace sinsim::sim {

IdealImu::IdealImu(const Trajectory& trajectory, double imuRate, double maxSubstep)
    : trajectory_(trajectory), rate_(imuRate) {
  if (!(std::isfinite(imuRate) && imuRate > 0.0))
    throw InputError("IMU rate must be a positive frequency");
  if (!(std::isfinite(maxSubstep) && maxSubstep > 0.0))
    throw InputError("integration substep must be a positive time");
  dt_ = 1.0 / imuRate;
  maxSubstep_ = maxSubstep;
  // Checked in floating point before the integer conversion: llround of 1e308 is undefined.
  if (limits::tooManySamples(trajectory.duration(), imuRate))
    throw InputError("a " + limits::fmt(trajectory.duration()) + " s trajectory at " +
                     limits::fmt(imuRate) + " Hz is more than " +
                     limits::fmt(limits::kMaxSamples) + " IMU samples (docs/limits.md)");
  count_ = std::llround(trajectory.duration() * imuRate);

  const MotionStart& s = trajectory.motion().start();
  const MotionPoint m = trajectory.motion().at(0.0);
  truth_.t = 0.0;
  truth_.lat = s.lat;
  truth_.lon = s.lon;
  truth_.h = s.h;
  truth_.v_n = m.v_n;
  truth_.q_nb = nav::quatFromEuler(m.euler);
}

Kinematics IdealImu::rates() const {
  return trajectory_.at(truth_.t, truth_.lat, truth_.lon, truth_.h);
}

nav::ImuSample IdealImu::next() {
  nav::ImuSample out;
  const double tStart = static_cast<double>(k_) * dt_;
  const double tEnd = static_cast<double>(k_ + 1) * dt_;  // k·dt, not a running sum: no drift
  nav::Vec3 p(truth_.lat, truth_.lon, truth_.h);
  nav::Vec3 dtheta = nav::Vec3::Zero(), dv = nav::Vec3::Zero();
  const Trajectory& tr = trajectory_;
  const MotionProfile& motion = tr.motion();
  // Pieces between knots (segment boundaries, excursion turning points) inside the interval:
  // the integrand is analytic on each, and RK4 keeps its O(h^5) local error.
  double a = tStart;
  while (a < tEnd) {
    const double knot = motion.nextKnot(a);
    // a knot closer than 1e-9 s to the interval end is taken as the end (rounding of k·dt)
    const double b = knot < tEnd - 1e-9 ? knot : tEnd;
    const int n = std::max(1, static_cast<int>(std::ceil((b - a) / maxSubstep_ - 1e-9)));
    const double h = (b - a) / n;
    for (int i = 0; i < n; ++i) {
      const double t = a + i * h;
      // Classical RK4 (Butcher tableau 0, ½, ½, 1; weights 1/6, 1/3, 1/3, 1/6).
      const Kinematics k1 = tr.at(t, p.x(), p.y(), p.z());
      const nav::Vec3 p2 = p + 0.5 * h * k1.posRate;
      const Kinematics k2 = tr.at(t + 0.5 * h, p2.x(), p2.y(), p2.z());
      const nav::Vec3 p3 = p + 0.5 * h * k2.posRate;
      const Kinematics k3 = tr.at(t + 0.5 * h, p3.x(), p3.y(), p3.z());
      const nav::Vec3 p4 = p + h * k3.posRate;
      const Kinematics k4 = tr.at(t + h, p4.x(), p4.y(), p4.z());
      p += h / 6.0 * (k1.posRate + 2.0 * (k2.posRate + k3.posRate) + k4.posRate);
      dtheta += h / 6.0 * (k1.omega_ib_b + 2.0 * (k2.omega_ib_b + k3.omega_ib_b) + k4.omega_ib_b);
      dv += h / 6.0 * (k1.f_b + 2.0 * (k2.f_b + k3.f_b) + k4.f_b);
    }
    a = b;
  }
  // The NED frame (lon' = vE / ((N + h) cos lat)) is singular at the poles: the start is
  // checked against the same limit (scenario.cpp), the motion here.
  if (!(std::abs(p.x()) <= limits::kMaxLatitude))
    throw MotionError("the trajectory reaches latitude " + limits::fmt(p.x() * kDegPerRad, 9) +
                     " deg at t = " + limits::fmt(tEnd, 9) +
                     " s: the navigation frame (NED) is singular at the poles; keep the motion "
                     "within ±89 deg (docs/limits.md)");
  ++k_;
  const MotionPoint m = motion.at(tEnd);
  truth_.t = tEnd;
  truth_.lat = p.x();
  truth_.lon = p.y();
  truth_.h = p.z();
  truth_.v_n = m.v_n;
  truth_.q_nb = nav::quatFromEuler(m.euler);

  out.t = tEnd;
  out.dt = tEnd - tStart;
  out.dtheta_b = dtheta;
  out.dv_b = dv;
  return out;
}

}  // namespace sinsim::sim
