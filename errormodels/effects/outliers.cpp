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

const std::vector<ParamSchema>& paramsOf_outliers() {
  static const std::vector<ParamSchema> p = {
      param("rate", ParamKind::quantity, fixed(Dimension::frequency())).positive().printed(6)
          .doc("mean number of outliers per second"),
      param("amplitude", ParamKind::quantity, signal()).positive()
          .doc("size of each outlier (random sign)")};
  return p;
}

std::unique_ptr<Effect> buildEffect_outliers(const EffectSpec& spec, const EffectSite&,
                                             SpecProblems&) {
  return std::make_unique<Outliers>(valueOr(spec, "rate", NAN), valueOr(spec, "amplitude", NAN));
}

double outliersWhiteDensityOf(const EffectSpec& spec, double imuRate) {
  const double p = valueOr(spec, "rate", NAN) / imuRate;
  return std::sqrt(p / imuRate) * valueOr(spec, "amplitude", NAN);
}

}  // namespace sinsim::errormodels
