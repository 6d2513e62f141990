// `sinusoid`: a periodic error, e.g. vibration-induced: e(t) = A sin(2π f t + φ), t the scenario
// time [s] (0 at the start of the run).
//   amplitude: 0.05 deg/s
//   frequency: 12 Hz
//   phase: 30 deg           (optional, default 0)
// Integrated exactly: ∫ e dt = A/(2πf) [cos(2πf t0 + φ) - cos(2πf t1 + φ)].
#include "errormodels/effect.hpp"

namespace sinsim::errormodels {
namespace {

class SinusoidState final : public AxisErrorState {
 public:
  SinusoidState(int axis, double A, double f, double phase)
      : AxisErrorState(axis), A_(A), w_(2.0 * M_PI * f), phase_(phase) {}
  double integral(const Interval& iv) override {
    // cos a - cos b = -2 sin((a+b)/2) sin((a-b)/2): no cancellation for short intervals.
    const double mid = w_ * 0.5 * (iv.t0 + iv.t1) + phase_;
    return A_ / w_ * 2.0 * std::sin(mid) * std::sin(0.5 * w_ * iv.dt);
  }

 private:
  double A_, w_, phase_;
};

class Sinusoid final : public Effect {
 public:
  Sinusoid(double A, double f, double phase) : A_(A), f_(f), phase_(phase) {}
  std::unique_ptr<EffectState> instantiate(const InstanceContext& ctx) const override {
    return std::make_unique<SinusoidState>(ctx.site->axis, A_, f_, phase_);
  }

 private:
  double A_, f_, phase_;
};

}  // namespace

const std::vector<ParamSchema>& paramsOf_sinusoid() {
  static const std::vector<ParamSchema> p = {
      param("amplitude", ParamKind::quantity, signal()).doc("amplitude"),
      param("frequency", ParamKind::quantity, fixed(Dimension::frequency())).positive()
          .doc("frequency"),
      param("phase", ParamKind::quantity, fixed(Dimension::angle())).optional("0 deg")
          .doc("phase at t = 0")};
  return p;
}

std::unique_ptr<Effect> buildEffect_sinusoid(const EffectSpec& spec, const EffectSite&,
                                             SpecProblems&) {
  return std::make_unique<Sinusoid>(valueOr(spec, "amplitude", NAN), valueOr(spec, "frequency", NAN),
                                    valueOr(spec, "phase", 0.0));
}

}  // namespace sinsim::errormodels
