#include "sim/nav_loop.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/error.hpp"
#include "common/limits.hpp"

namespace sinsim::sim {

const nav::Earth& sharedEarth() {
  static const nav::Earth earth;
  return earth;
}

const char* verticalName(nav::VerticalChannel v) {
  switch (v) {
    case nav::VerticalChannel::Free: return "free";
    case nav::VerticalChannel::Held: return "held";
    case nav::VerticalChannel::Damped: return "damped";
  }
  return "?";
}

nav::VerticalChannel verticalChannel(const std::string& name, const std::string& what) {
  for (auto v : {nav::VerticalChannel::Free, nav::VerticalChannel::Held, nav::VerticalChannel::Damped})
    if (name == verticalName(v)) return v;
  throw InputError(what + ": \"" + name + "\" is not one of: free, held, damped");
}

namespace {

// The mean error rates (measured − ideal) over the head [rad/s], [m/s^2].
struct Bias {
  nav::Vec3 gyro = nav::Vec3::Zero();
  nav::Vec3 accel = nav::Vec3::Zero();
};

Bias meanBias(const std::vector<ImuEpoch>& head) {
  Bias b;
  double T = 0.0;  // [s]
  for (const ImuEpoch& e : head) {
    b.gyro += e.measured.dtheta_b - e.ideal.dtheta_b;
    b.accel += e.measured.dv_b - e.ideal.dv_b;
    T += e.ideal.dt;
  }
  b.gyro /= T;
  b.accel /= T;
  return b;
}

}  // namespace

bool navigate(ImuSource& source, const NavLoopOptions& opt, const EpochSink& sink) {
  const nav::Earth& earth = sharedEarth();
  // The truth's height is the held / damped channels' first reference (an initial height error
  // is the navigated state's, not the reference's).
  nav::Strapdown strapdown(earth, opt.aiding ? opt.aiding->start(source.initial()) : source.initial(),
                           opt.strapdown, source.initial().h);
  ImuEpoch e;
  e.hasTruth = true;
  e.truth = source.initial();
  e.hTrue = e.truth.h;
  sink(e, strapdown.state());

  // Initial bias removal: the head of the run is read first, its mean error rate estimated, then
  // replayed.
  std::vector<ImuEpoch> head;
  Bias bias;
  if (!(opt.biasWindow >= 0.0))  // NaN or negative: the Python module read them as 0
    throw InputError("the bias window (--bias-window) must be >= 0 s, got " + limits::fmt(opt.biasWindow));
  const bool removeBias = opt.biasWindow > 0.0;
  if (removeBias) {
    // In floating point first: llround of 1e308 s × rate overflows.
    const double samples = opt.biasWindow * source.rate();
    if (!(samples <= double(source.sampleCount()) + 0.5))
      throw InputError("the bias window (--bias-window) of " + limits::fmt(opt.biasWindow) +
                       " s is longer than the run (" +
                       limits::fmt(double(source.sampleCount()) / source.rate()) + " s)");
    const long long nb = std::llround(samples);
    if (nb <= 0)
      throw InputError("the bias window (--bias-window) of " + limits::fmt(opt.biasWindow) +
                       " s is shorter than one IMU interval");
    head.resize(std::size_t(nb));
    for (ImuEpoch& h : head)
      if (!source.next(h)) throw NumericalError("IMU source ended inside the bias window");
    bias = meanBias(head);
  }

  for (std::size_t k = 0;; ++k) {
    if (k < head.size()) {
      e = head[k];
    } else if (!source.next(e)) {
      break;
    }
    if (removeBias) {
      e.measured.dtheta_b -= bias.gyro * e.measured.dt;
      e.measured.dv_b -= bias.accel * e.measured.dt;
    }
    if (opt.aiding) {
      const nav::ImuSample integrated = opt.aiding->compensate(e);
      strapdown.update(integrated, e.hTrue);
      opt.aiding->epoch(e, integrated, strapdown);
    } else {
      strapdown.update(e.measured, e.hTrue);
    }
    sink(e, strapdown.state());
    // Every 1024 samples (a relaxed load: nothing against a strapdown step), so that Ctrl-C stops
    // a run within ~30 ms; every 65536 took 1.5 s on an aided run and missed a short run's whole.
    if (opt.cancel && (k & 0x3ff) == 0x3ff && opt.cancel->load(std::memory_order_relaxed))
      return false;
  }
  return !(opt.cancel && opt.cancel->load(std::memory_order_relaxed));  // one shorter than 1024 too
}

}  // namespace sinsim::sim
