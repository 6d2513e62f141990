// `outliers`: isolated large samples (bit errors, shocks, bus glitches). In each IMU interval an
// outlier occurs with probability p = rate·dt (a Bernoulli thinning of a Poisson process of the
// given mean rate; p ≤ 1 is required); its value, added to the rate output of that one interval,
// is ±amplitude with a random sign.
//   rate: 0.01 Hz          mean number of outliers per second
//   amplitude: 2 deg/s     size of each outlier (signal)
// Two normals per interval from the effect's stream: z₁ < Φ⁻¹(p) decides the event (P = p
// exactly), the sign of z₂ its sign.
#include "errormodels/effect.hpp"
#include "errormodels/stats/special.hpp"

namespace sinsim::errormodels {
namespace {

class OutliersState final : public AxisErrorState {
 public:
  OutliersState(int axis, double amplitude, double zEvent, NormalStream s)
      : AxisErrorState(axis), a_(amplitude), zEvent_(zEvent), s_(s) {}
  double integral(const Interval& iv) override {
    const double z1 = s_.next(), z2 = s_.next();
    if (!(z1 < zEvent_)) return 0.0;
    return (z2 < 0 ? -a_ : a_) * iv.dt;
  }

 private:
  double a_, zEvent_;
  NormalStream s_;
};

class Outliers final : public Effect {
 public:
  Outliers(double rate, double amplitude) : rate_(rate), a_(amplitude) {}
  std::unique_ptr<EffectState> instantiate(const InstanceContext& ctx) const override {
    const double p = rate_ / ctx.imuRate;
    if (!(p <= 1.0))
      throw InputError(ctx.site->name + ": outlier rate " + std::to_string(rate_) +
                       " Hz exceeds the IMU rate " + std::to_string(ctx.imuRate) + " Hz");
    return std::make_unique<OutliersState>(ctx.site->axis, a_, normalQuantile(p), ctx.stream());
  }

 private:
  double rate_, a_;  // [Hz], [signal]
};

}  // namespace

std::unique_ptr<Effect> parseEffect_outliers(const ConfigNode& node, const EffectSite& site) {
  node.allowKeys({"type", "enabled", "rate", "amplitude"});
  const double rate = positiveQuantity(node, "rate", Dimension::frequency());
  const double a = positiveQuantity(node, "amplitude", site.signal());
  if (!(std::isfinite(rate) && std::isfinite(a))) return nullptr;
  return std::make_unique<Outliers>(rate, a);
}

}  // namespace sinsim::errormodels
