// `bias`: a constant offset of the sensor output, fixed and/or drawn once per run (turn-on bias).
//   value: 10 deg/h      fixed part (default 0)
//   sigma: 5 deg/h       standard deviation of the turn-on part, N(0, sigma²) once per run
#include "errormodels/effect.hpp"

namespace sinsim::errormodels {
namespace {

class BiasState final : public AxisErrorState {
 public:
  BiasState(int axis, double b) : AxisErrorState(axis), b_(b) {}
  double integral(const Interval& iv) override { return b_ * iv.dt; }

 private:
  double b_;  // [signal]
};

class Bias final : public Effect {
 public:
  Bias(double value, double sigma) : value_(value), sigma_(sigma) {}
  std::unique_ptr<EffectState> instantiate(const InstanceContext& ctx) const override {
    double b = value_;
    if (sigma_ > 0) b += sigma_ * ctx.stream().next();
    return std::make_unique<BiasState>(ctx.site->axis, b);
  }

 private:
  double value_, sigma_;  // [signal]
};

}  // namespace

std::unique_ptr<Effect> parseEffect_bias(const ConfigNode& node, const EffectSite& site) {
  node.allowKeys({"type", "enabled", "value", "sigma"});
  if (!node.has("value") && !node.has("sigma"))
    node.error("missing parameter: give value and/or sigma (e.g. value: 10 " + site.signalUnit() +
               ")");
  double value = node.quantity("value", site.signal(), 0.0);
  double sigma = node.quantity("sigma", site.signal(), 0.0);
  if (!(sigma >= 0)) node["sigma"].error("must be zero or positive");
  return std::make_unique<Bias>(value, sigma);
}

}  // namespace sinsim::errormodels
