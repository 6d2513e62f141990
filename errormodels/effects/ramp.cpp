// `ramp`: a bias growing linearly with scenario time t [s], e(t) = R t (IEEE 952 "rate ramp").
//   slope: 10 deg/h/h
// ∫ e dt = R (t1² - t0²)/2 = R dt (t0 + t1)/2.
#include "errormodels/effect.hpp"

namespace sinsim::errormodels {
namespace {

class RampState final : public AxisErrorState {
 public:
  RampState(int axis, double R) : AxisErrorState(axis), r_(R) {}
  double integral(const Interval& iv) override { return r_ * iv.dt * 0.5 * (iv.t0 + iv.t1); }

 private:
  double r_;  // [signal/s]
};

class Ramp final : public Effect {
 public:
  explicit Ramp(double R) : r_(R) {}
  std::unique_ptr<EffectState> instantiate(const InstanceContext& ctx) const override {
    return std::make_unique<RampState>(ctx.site->axis, r_);
  }

 private:
  double r_;
};

}  // namespace

std::unique_ptr<Effect> parseEffect_ramp(const ConfigNode& node, const EffectSite& site) {
  node.allowKeys({"type", "enabled", "slope"});
  double R = node.quantity("slope", site.signal() / Dimension::time());
  if (!std::isfinite(R)) return nullptr;
  return std::make_unique<Ramp>(R);
}

}  // namespace sinsim::errormodels
