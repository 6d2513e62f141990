// `warmup`: exponential settling after switch-on, e(t) = A exp(-t/tau), t the scenario time [s].
//   amplitude: 0.1 deg/s       error at t = 0
//   tau: 5 min                 settling time constant
// ∫ e dt = A tau [exp(-t0/tau) - exp(-t1/tau)] = A tau exp(-t0/tau) (1 - exp(-dt/tau)).
#include "errormodels/effect.hpp"

namespace sinsim::errormodels {
namespace {

class WarmupState final : public AxisErrorState {
 public:
  WarmupState(int axis, double A, double tau) : AxisErrorState(axis), a_(A), tau_(tau) {}
  double integral(const Interval& iv) override {
    return a_ * tau_ * std::exp(-iv.t0 / tau_) * -std::expm1(-iv.dt / tau_);
  }

 private:
  double a_, tau_;
};

class Warmup final : public Effect {
 public:
  Warmup(double A, double tau) : a_(A), tau_(tau) {}
  std::unique_ptr<EffectState> instantiate(const InstanceContext& ctx) const override {
    return std::make_unique<WarmupState>(ctx.site->axis, a_, tau_);
  }

 private:
  double a_, tau_;
};

}  // namespace

std::unique_ptr<Effect> parseEffect_warmup(const ConfigNode& node, const EffectSite& site) {
  node.allowKeys({"type", "enabled", "amplitude", "tau"});
  double A = node.quantity("amplitude", site.signal());
  double tau = positiveQuantity(node, "tau", Dimension::time());
  if (!(std::isfinite(A) && std::isfinite(tau))) return nullptr;
  return std::make_unique<Warmup>(A, tau);
}

}  // namespace sinsim::errormodels
