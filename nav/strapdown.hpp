// NED local-level strapdown mechanization on WGS-84 driven by IMU increments.
// (Implementation and its equation references: strapdown.cpp.)
#pragma once

#include <cmath>

#include "nav/earth.hpp"
#include "nav/types.hpp"

namespace sinsim::nav {

/// How the (unstable) vertical channel is handled.
enum class VerticalChannel {
  Free,    ///< pure inertial: height error grows as physics says (≈ e^{t·sqrt(2g/R)})
  Held,    ///< height and vertical velocity set to the reference each step (ideal altimeter)
  Damped,  ///< second-order baro-inertial loop on the reference height (time constant below)
};

struct StrapdownOptions {
  VerticalChannel vertical = VerticalChannel::Free;
  double dampingTimeConstant = 100.0;  // [s] for VerticalChannel::Damped, > 0
};

class Strapdown {
 public:
  Strapdown(const Earth& earth, const NavState& initial, const StrapdownOptions& options = {});

  /// Advances the state over one IMU interval. hRef [m] is the reference height at the end of
  /// the interval, used by the Held and Damped vertical channels (ignored for Free).
  void update(const ImuSample& imu, double hRef = NAN);

  const NavState& state() const { return state_; }

 private:
  const Earth& earth_;
  NavState state_;
  StrapdownOptions options_;
  // previous interval's increments, for the two-sample coning and sculling corrections
  Vec3 prevDtheta_b_ = Vec3::Zero();
  Vec3 prevDv_b_ = Vec3::Zero();
  bool havePrev_ = false;
  double vdLoopState_ = 0.0;  // damped-channel integrator [m/s^2]
};

}  // namespace sinsim::nav
