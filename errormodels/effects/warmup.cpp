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

const std::vector<ParamSchema>& paramsOf_warmup() {
  static const std::vector<ParamSchema> p = {
      param("amplitude", ParamKind::quantity, signal()).doc("bias offset at switch-on"),
      param("tau", ParamKind::quantity, fixed(Dimension::time())).positive().printed(6)
          .doc("settling time constant")};
  return p;
}

std::unique_ptr<Effect> buildEffect_warmup(const EffectSpec& spec, const EffectSite&,
                                           SpecProblems&) {
  return std::make_unique<Warmup>(valueOr(spec, "amplitude", NAN), valueOr(spec, "tau", NAN));
}

}  // namespace sinsim::errormodels
