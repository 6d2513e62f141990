#include "sim/reference.hpp"

#include <cmath>

#include "common/error.hpp"
#include "sim/ideal_imu.hpp"
#include "sim/run.hpp"
#include "sim/trajectory.hpp"

namespace sinsim::sim {

std::size_t Reference::bytes() const {
  return samples.size() * sizeof(nav::ImuSample) + hRef.size() * sizeof(double) +
         truth.size() * sizeof(nav::NavState);
}

const nav::Earth& sharedEarth() {
  static const nav::Earth earth;
  return earth;
}

Reference buildReference(const Scenario& sc) {
  Reference r;
  r.name = sc.name;
  r.imuRate = sc.imuRate;
  r.outputRate = sc.outputRate;
  r.decimation = sc.decimation();
  r.strapdown = sc.strapdown;
  r.temperature = sc.temperature;
  const Trajectory trajectory(sharedEarth(), sc.motion());
  IdealImu imu(trajectory, sc.imuRate);
  r.initial = imu.truth();
  r.samples.reserve(std::size_t(imu.sampleCount()));
  r.hRef.reserve(std::size_t(imu.sampleCount()));
  r.truth.reserve(std::size_t(imu.sampleCount() / r.decimation + 1));
  r.truth.push_back(imu.truth());
  while (!imu.done()) {
    r.samples.push_back(imu.next());
    r.hRef.push_back(imu.truth().h);
    if (imu.index() % r.decimation == 0) r.truth.push_back(imu.truth());
  }
  return r;
}

namespace {

void store(float* row, const NavError& e) {
  row[kNorth] = float(e.pos_n.x());
  row[kEast] = float(e.pos_n.y());
  row[kDown] = float(e.pos_n.z());
  row[kVn] = float(e.vel_n.x());
  row[kVe] = float(e.vel_n.y());
  row[kVd] = float(e.vel_n.z());
  row[kRoll] = float(e.euler.x());
  row[kPitch] = float(e.euler.y());
  row[kYaw] = float(e.euler.z());
}

}  // namespace

bool navigateRealisation(const Reference& ref, errormodels::ImuCorruptor* corruptor,
                         const NavigateOptions& options, float* out,
                         const std::atomic<bool>* cancel) {
  const nav::Earth& earth = sharedEarth();
  nav::Strapdown strapdown(earth, ref.initial, ref.strapdown);
  store(out, navError(earth, strapdown.state(), ref.truth[0]));
  const std::size_t n = ref.samples.size();
  const auto dec = std::size_t(ref.decimation);

  auto measure = [&](std::size_t k) {
    nav::ImuSample s = ref.samples[k];  // a copy: the ideal sample stays as it is
    if (corruptor) corruptor->corrupt(s, ref.temperature.at(s.t - 0.5 * s.dt));
    return s;
  };

  // Initial bias removal (NavigateOptions::biasWindow): the head of the realisation is measured
  // first, its mean error rate estimated, then replayed.
  std::vector<nav::ImuSample> head;
  nav::Vec3 biasGyro = nav::Vec3::Zero(), biasAccel = nav::Vec3::Zero();  // [rad/s], [m/s^2]
  if (options.biasWindow > 0.0) {
    const auto nb = std::min<std::size_t>(n, std::size_t(std::llround(options.biasWindow * ref.imuRate)));
    if (nb == 0) throw InputError("the bias window is shorter than one IMU interval");
    head.reserve(nb);
    double T = 0.0;
    for (std::size_t k = 0; k < nb; ++k) {
      head.push_back(measure(k));
      biasGyro += head.back().dtheta_b - ref.samples[k].dtheta_b;
      biasAccel += head.back().dv_b - ref.samples[k].dv_b;
      T += ref.samples[k].dt;
    }
    biasGyro /= T;
    biasAccel /= T;
  }

  for (std::size_t k = 0; k < n; ++k) {
    nav::ImuSample s = k < head.size() ? head[k] : measure(k);
    if (options.biasWindow > 0.0) {
      s.dtheta_b -= biasGyro * s.dt;
      s.dv_b -= biasAccel * s.dt;
    }
    strapdown.update(s, ref.hRef[k]);
    if ((k + 1) % dec == 0) {
      const std::size_t e = (k + 1) / dec;
      store(out + e * kErrorFields, navError(earth, strapdown.state(), ref.truth[e]));
    }
    if (cancel && (k & 0xffff) == 0xffff && cancel->load(std::memory_order_relaxed)) return false;
  }
  return true;
}

}  // namespace sinsim::sim
