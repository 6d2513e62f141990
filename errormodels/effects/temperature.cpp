// `temperature`: bias as a polynomial in the sensor temperature T (from the scenario's or synth's
// temperature profile), b(T) = c1 (T - T0) + c2 (T - T0)² + ...
//   T0: 25 degC
//   coefficients: [0.01 deg/s/degC, 1e-4 deg/s/degC^2]    c1, c2, ... (the constant term is `bias`)
#include "errormodels/effect.hpp"

namespace sinsim::errormodels {
namespace {

class TemperatureState final : public AxisErrorState {
 public:
  TemperatureState(int axis, double T0, const std::vector<double>& c)
      : AxisErrorState(axis), T0_(T0), c_(c) {}
  double integral(const Interval& iv) override {
    const double x = iv.temperature - T0_;  // [K]
    double b = 0.0;                         // Horner: ((cn x + cn-1) x + ... + c1) x
    for (auto it = c_.rbegin(); it != c_.rend(); ++it) b = (b + *it) * x;
    return b * iv.dt;
  }

 private:
  double T0_;
  std::vector<double> c_;
};

class Temperature final : public Effect {
 public:
  Temperature(double T0, std::vector<double> c) : T0_(T0), c_(std::move(c)) {}
  bool needsTemperature() const override { return true; }
  std::unique_ptr<EffectState> instantiate(const InstanceContext& ctx) const override {
    return std::make_unique<TemperatureState>(ctx.site->axis, T0_, c_);
  }

 private:
  double T0_;              // [K]
  std::vector<double> c_;  // [signal / K^k]
};

}  // namespace

const std::vector<ParamSchema>& paramsOf_temperature() {
  static DimRule perDegree = [] {
    DimRule d = signal();
    d.perItemTemperature = true;
    return d;
  }();
  static const std::vector<ParamSchema> p = {
      param("T0", ParamKind::quantity, fixed(Dimension::temperature())).positive().printed(8)
          .doc("reference temperature"),
      param("coefficients", ParamKind::list, perDegree)
          .doc("c1, c2, ...: signal/degC, signal/degC^2, ... (the constant term is `bias`)")};
  return p;
}

std::unique_ptr<Effect> buildEffect_temperature(const EffectSpec& spec, const EffectSite&,
                                                SpecProblems&) {
  return std::make_unique<Temperature>(valueOr(spec, "T0", NAN), valuesOf(spec, "coefficients"));
}

}  // namespace sinsim::errormodels
