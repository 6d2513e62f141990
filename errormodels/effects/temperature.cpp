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

std::unique_ptr<Effect> parseEffect_temperature(const ConfigNode& node, const EffectSite& site) {
  node.allowKeys({"type", "enabled", "T0", "coefficients"});
  double T0 = node.quantity("T0", Dimension::temperature());
  ConfigNode cn = node.require("coefficients");
  std::vector<double> c;
  bool ok = std::isfinite(T0);
  if (cn.exists()) {
    auto items = cn.items();
    if (cn.isSequence() && items.empty()) cn.error("expected at least one coefficient");
    for (std::size_t k = 0; k < items.size(); ++k) {
      Dimension d = site.signal() / Dimension::temperature().pow(int(k) + 1);
      auto v = items[k].asQuantity(d);
      ok = ok && v.has_value();
      c.push_back(v.value_or(NAN));
    }
    ok = ok && !items.empty();
  } else {
    ok = false;
  }
  if (!ok) return nullptr;
  return std::make_unique<Temperature>(T0, std::move(c));
}

}  // namespace sinsim::errormodels
