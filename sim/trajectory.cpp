#include "sim/trajectory.hpp"

#include <cmath>

#include "nav/attitude.hpp"

namespace sinsim::sim {

nav::Vec3 bodyRateFromEulerRates(const nav::Vec3& e, const nav::Vec3& r) {
  const double sf = std::sin(e.x()), cf = std::cos(e.x());
  const double st = std::sin(e.y()), ct = std::cos(e.y());
  return nav::Vec3(r.x() - r.z() * st,             //
                   r.y() * cf + r.z() * sf * ct,   //
                   -r.y() * sf + r.z() * cf * ct);
}

Trajectory::Trajectory(const nav::Earth& earth, MotionProfile motion)
    : earth_(earth), motion_(std::move(motion)) {}

nav::Vec3 Trajectory::positionRate(const nav::Vec3& v_n, double lat, double h) const {
  double M = 0.0, N = 0.0;
  earth_.radii(lat, M, N);
  return nav::Vec3(v_n.x() / (M + h), v_n.y() / ((N + h) * std::cos(lat)), -v_n.z());
}

Kinematics Trajectory::at(double t, double lat, double lon, double h) const {
  const MotionPoint m = motion_.at(t);
  Kinematics k;
  k.t = t;
  k.lat = lat;
  k.lon = lon;
  k.h = h;
  k.v_n = m.v_n;
  k.a_n = m.a_n;
  k.euler = m.euler;
  k.q_nb = nav::quatFromEuler(m.euler);
  k.omega_nb_b = bodyRateFromEulerRates(m.euler, m.eulerRate);

  double M = 0.0, N = 0.0;
  earth_.radii(lat, M, N);
  k.posRate = nav::Vec3(m.v_n.x() / (M + h), m.v_n.y() / ((N + h) * std::cos(lat)), -m.v_n.z());
  const nav::Vec3 omega_en_n = nav::Earth::omega_en_n(M, N, h, std::tan(lat), m.v_n);
  const nav::Vec3 omega_ie_n = earth_.omega_ie_n(lat);
  k.g_n = earth_.gravity_n(lat, h);

  const nav::Mat3 C_bn = k.q_nb.toRotationMatrix().transpose();
  k.omega_ib_b = k.omega_nb_b + C_bn * (omega_ie_n + omega_en_n);
  const nav::Vec3 f_n = m.a_n + (2.0 * omega_ie_n + omega_en_n).cross(m.v_n) - k.g_n;
  k.f_b = C_bn * f_n;
  return k;
}

}  // namespace sinsim::sim
