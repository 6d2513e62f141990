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

const std::vector<ParamSchema>& paramsOf_ramp() {
  static const std::vector<ParamSchema> p = {
      param("slope", ParamKind::quantity, signal(Dimension::frequency()))
          .doc("rate of change of the bias (deg/h^2, m/s^3)")};
  return p;
}

std::unique_ptr<Effect> buildEffect_ramp(const EffectSpec& spec, const EffectSite&, SpecProblems&) {
  return std::make_unique<Ramp>(valueOr(spec, "slope", NAN));
}

}  // namespace sinsim::errormodels
