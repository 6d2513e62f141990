// `quantization`: the output register's least significant bit, applied last (after every other
// effect), per axis.
//   lsb: 0.07326 deg/s     an LSB of a RATE output: each interval's increment is rounded to
//                          lsb·dt, and by default nothing is carried (a rate-output sensor simply
//                          rounds each sample, and the rounding errors do accumulate)
//   lsb: 0.001 deg         an LSB of an INCREMENT output (deg, rad, m/s): by default the remainder
//                          is carried to the next interval, as an integrating IMU does, so the sum
//                          of output increments never drifts from the true sum by more than lsb/2
//   carry: true|false      overrides the default
// Carry: q[k] = lsb·round((u[k] + r[k-1]) / lsb), r[k] = u[k] + r[k-1] - q[k]  (|r| ≤ lsb/2), so
// Σq = Σu - r[n] (Savage 2000, §3.5 on integrating-output quantization).
#include "errormodels/effect.hpp"

namespace sinsim::errormodels {
namespace {

class QuantizationState final : public EffectState {
 public:
  QuantizationState(int axis, double lsb, bool isRate, bool carry)
      : axis_(axis), lsb_(lsb), isRate_(isRate), carry_(carry) {}
  void apply(Vec3& u, const Interval& iv) override {
    const double step = isRate_ ? lsb_ * iv.dt : lsb_;
    const double x = u[axis_] + (carry_ ? rest_ : 0.0);
    const double q = step * std::nearbyint(x / step);
    rest_ = x - q;
    u[axis_] = q;
  }

 private:
  int axis_;
  double lsb_;
  bool isRate_, carry_;
  double rest_ = 0.0;
};

class Quantization final : public Effect {
 public:
  Quantization(double lsb, bool isRate, bool carry) : lsb_(lsb), isRate_(isRate), carry_(carry) {}
  Stage stage() const override { return Stage::output; }
  std::unique_ptr<EffectState> instantiate(const InstanceContext& ctx) const override {
    return std::make_unique<QuantizationState>(ctx.site->axis, lsb_, isRate_, carry_);
  }

 private:
  double lsb_;
  bool isRate_, carry_;
};

}  // namespace

std::unique_ptr<Effect> parseEffect_quantization(const ConfigNode& node, const EffectSite& site) {
  node.allowKeys({"type", "enabled", "lsb", "carry"});
  ConfigNode c = node.require("lsb");
  if (!c.exists()) return nullptr;
  auto text = c.asString();
  if (!text) return nullptr;
  const Dimension incrementDim = site.signal() * Dimension::time();
  Quantity q;
  try {
    q = parseQuantity(*text);
  } catch (const InputError& e) {
    c.error(e.what());
    return nullptr;
  }
  const bool isRate = q.dim == site.signal();
  if (!isRate && q.dim != incrementDim) {
    c.error("expected an LSB of the rate output (" + exampleUnit(site.signal()) +
            ") or of the increment output (" + exampleUnit(incrementDim) + "), got \"" + *text +
            "\"");
    return nullptr;
  }
  if (!(q.si > 0)) {
    c.error("must be positive");
    return nullptr;
  }
  bool carry = node.boolean("carry", !isRate);
  return std::make_unique<Quantization>(q.si, isRate, carry);
}

}  // namespace sinsim::errormodels
