#include "sim/reference.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sim/ideal_imu.hpp"
#include "sim/nav_loop.hpp"
#include "sim/run.hpp"
#include "sim/scenario_aiding.hpp"
#include "sim/trajectory.hpp"

namespace sinsim::sim {

std::size_t Reference::bytes() const {
  return samples.size() * sizeof(nav::ImuSample) + hRef.size() * sizeof(double) +
         (truth.size() + truthAll.size()) * sizeof(nav::NavState);
}

std::size_t Reference::runFloats() const {
  std::size_t n = epochs() * kErrorFields;
  if (!aiding.inert())
    n += epochs() * kAidedEpochFields + aiding.gnss.outages.size() * kOutageFields;
  return n;
}

Reference buildReference(const Scenario& sc) {
  Reference r;
  r.name = sc.name;
  r.imuRate = sc.imuRate;
  r.outputRate = sc.outputRate;
  r.decimation = sc.decimation();
  r.strapdown = sc.strapdown;
  r.temperature = sc.temperature;
  r.aiding = sc.aiding;
  const bool aided = !sc.aiding.inert();
  const Trajectory trajectory(sharedEarth(), sc.motion());
  IdealImu imu(trajectory, sc.imuRate);
  r.initial = imu.truth();
  r.samples.reserve(std::size_t(imu.sampleCount()));
  r.hRef.reserve(std::size_t(imu.sampleCount()));
  r.truth.reserve(std::size_t(imu.sampleCount() / r.decimation + 1));
  r.truth.push_back(imu.truth());
  if (aided) r.truthAll.reserve(std::size_t(imu.sampleCount()));
  while (!imu.done()) {
    r.samples.push_back(imu.next());
    r.hRef.push_back(imu.truth().h);
    if (aided) r.truthAll.push_back(imu.truth());
    if (imu.index() % r.decimation == 0) r.truth.push_back(imu.truth());
  }
  return r;
}

namespace {

/// One epoch's errors as floats. A value no float holds (NaN, inf, beyond 3.4e38) stops the batch
/// with the time it happened, as `run` stops: `mc` wrote "CEP -nan" and exit 0.
void store(float* row, const NavError& e) {
  requireFiniteError(e, double(std::numeric_limits<float>::max()));
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

bool navigateErrors(ImuSource& source, const Reference& ref, const NavigateOptions& options,
                    float* out, const std::atomic<bool>* cancel, NavAiding* aiding) {
  NavLoopOptions loop;
  loop.strapdown = ref.strapdown;
  loop.biasWindow = options.biasWindow;
  loop.cancel = cancel;
  loop.aiding = aiding;
  const nav::Earth& earth = sharedEarth();
  const auto dec = ref.decimation;
  return navigate(source, loop, [&](const ImuEpoch& e, const nav::NavState& nav) {
    if (e.index % dec == 0)
      store(out + std::size_t(e.index / dec) * kErrorFields, navError(earth, nav, e.truth));
  });
}

bool navigateRealisation(const Reference& ref, errormodels::ImuCorruptor* corruptor,
                         const NavigateOptions& options, float* out,
                         const std::atomic<bool>* cancel, const errormodels::StreamKey& key) {
  ReferenceSource source(ref, corruptor);
  if (ref.aiding.inert()) return navigateErrors(source, ref, options, out, cancel);
  ScenarioAiding aiding(sharedEarth(), ref.aiding, ref.strapdown, key);
  float* view = out + ref.epochs() * kErrorFields;
  std::fill(view, out + ref.runFloats(), NAN);
  aiding.recordEpochs(view, std::size_t(ref.decimation));
  if (!navigateErrors(source, ref, options, out, cancel, &aiding)) return false;
  float* outages = view + ref.epochs() * kAidedEpochFields;
  for (const aided::OutageResult& o : aiding.aided().outages()) {
    outages[kOutageMaxHorizontal] = float(o.maxHorizontal);
    outages[kOutageSigmaHorizontal] = float(o.sigmaHorizontal);
    outages += kOutageFields;
  }
  return true;
}

}  // namespace sinsim::sim
