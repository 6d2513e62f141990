// `bias`: a constant offset of the sensor output, fixed and/or drawn once per run (turn-on bias).
//   value: 10 deg/h      fixed part (default 0)
//   sigma: 5 deg/h       standard deviation of the turn-on part, N(0, sigma²) once per run
#include "errormodels/effect.hpp"

namespace sinsim::errormodels {
namespace {

class BiasState final : public DirectAxisErrorState<BiasState> {
 public:
  BiasState(int axis, double b) : DirectAxisErrorState(axis), b_(b) {}
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

const std::vector<ParamSchema>& paramsOf_bias() {
  static const std::vector<ParamSchema> p = {
      param("value", ParamKind::quantity, signal()).optional("0").doc("fixed bias"),
      param("sigma", ParamKind::quantity, signal()).optional("0").nonNegative()
          .doc("standard deviation of the turn-on bias, drawn once per run")};
  return p;
}

std::unique_ptr<Effect> buildEffect_bias(const EffectSpec& spec, const EffectSite& site,
                                         SpecProblems& problems) {
  if (!spec.has("value") && !spec.has("sigma")) {
    problems.add("", "missing parameter: give value and/or sigma (e.g. value: 10 " +
                         site.signalUnit() + ")");
    return nullptr;
  }
  return std::make_unique<Bias>(valueOr(spec, "value", 0.0), valueOr(spec, "sigma", 0.0));
}

}  // namespace sinsim::errormodels
