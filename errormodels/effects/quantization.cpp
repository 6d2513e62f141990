// `quantization`: the output register's least significant bit, applied last (after every other
// effect), per axis.
//   lsb: 0.07326 deg/s     an LSB of a RATE output: each interval's increment is rounded to
//                          lsb·dt, and by default nothing is carried (a rate-output sensor simply
//                          rounds each sample, and the rounding errors do accumulate)
//   lsb: 0.001 deg         an LSB of an INCREMENT output (deg, rad, m/s): by default the remainder
//                          is carried to the next interval, as an integrating IMU does, so the sum
//                          of output increments never drifts from the true sum by more than lsb/2
//   carry: true|false      overrides the default
//   dithered: true         (optional) the remainder is a fresh uniform draw on ±step/2 each
//                          interval instead of what the rounding left: the textbook model of
//                          rounding a busy input (a dithered ring-laser gyro, a vibrating mount),
//                          output not on a lattice. Carried (an increment LSB): IEEE Std 952's
//                          quantization noise Q and GMWM's QN, Allan variance 3 Q²/τ², Q = step/√12;
//                          not carried (a rate LSB): white noise of variance lsb²/12 per sample.
// Carry: q[k] = lsb·round((u[k] + r[k-1]) / lsb), r[k] = u[k] + r[k-1] - q[k]  (|r| ≤ lsb/2), so
// Σq = Σu - r[n] (Savage 2000, §3.5 on integrating-output quantization). Dithered: the output
// u[k] + r[k-1] - r[k] (carried) or u[k] - r[k], r[k] = step (Φ(z[k]) - 1/2), z[k] from the effect's
// normal stream. On a static record with an LSB coarser than the noise the remainder of real
// rounding is neither uniform nor independent (the output is a pulse train on the lattice), which
// `dithered` does not model: leave it off there.
#include "errormodels/effects/quantization.hpp"

#include "errormodels/effect.hpp"
#include "errormodels/stats/special.hpp"

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

/// The dithered variant: the remainder a uniform draw, independent from interval to interval.
class DitheredQuantizationState final : public EffectState {
 public:
  DitheredQuantizationState(int axis, double lsb, bool isRate, bool carry, NormalStream s)
      : axis_(axis), lsb_(lsb), isRate_(isRate), carry_(carry), s_(s) {}
  void apply(Vec3& u, const Interval& iv) override {
    const double step = isRate_ ? lsb_ * iv.dt : lsb_;
    const double r = step * (normalCdf(s_.next()) - 0.5);
    u[axis_] += (carry_ ? rest_ : 0.0) - r;
    rest_ = r;
  }

 private:
  int axis_;
  double lsb_;
  bool isRate_, carry_;
  NormalStream s_;
  double rest_ = 0.0;
};

class Quantization final : public Effect {
 public:
  Quantization(double lsb, bool isRate, bool carry, bool dithered)
      : lsb_(lsb), isRate_(isRate), carry_(carry), dithered_(dithered) {}
  Stage stage() const override { return Stage::output; }
  std::unique_ptr<EffectState> instantiate(const InstanceContext& ctx) const override {
    if (dithered_)
      return std::make_unique<DitheredQuantizationState>(ctx.site->axis, lsb_, isRate_, carry_, ctx.stream());
    return std::make_unique<QuantizationState>(ctx.site->axis, lsb_, isRate_, carry_);
  }

 private:
  double lsb_;
  bool isRate_, carry_, dithered_;
};

}  // namespace

const std::vector<ParamSchema>& paramsOf_quantization() {
  static const std::vector<ParamSchema> p = {
      param("lsb", ParamKind::quantity, signal()).orDim(signal(Dimension::time())).positive()
          .expect("an LSB of the rate output ({0}) or of the increment output ({1})")
          .doc("output LSB: of the rate output (deg/s, mg) or of the increment output (deg, m/s)"),
      param("carry", ParamKind::flag, fixed(Dimension::none()))
          .optional("yes for an increment LSB, no for a rate LSB")
          .doc("carry the rounding remainder to the next sample"),
      param("dithered", ParamKind::flag, fixed(Dimension::none()))
          .optional("no")
          .doc("the remainder a fresh uniform draw each sample (carried: quantization noise, Allan 3Q^2/tau^2)")};
  return p;
}

QuantizationRule quantizationRule(const EffectSpec& spec, const Dimension& signal) {
  const ParamSpec& lsb = *spec.find("lsb");
  const ParamSpec* carry = spec.find("carry");
  const ParamSpec* dithered = spec.find("dithered");
  QuantizationRule r;
  r.lsb = lsb.values[0];
  r.isRate = lsb.dims[0] == signal;
  r.carry = carry ? carry->flag : !r.isRate;
  r.dithered = dithered && dithered->flag;
  return r;
}

std::unique_ptr<Effect> buildEffect_quantization(const EffectSpec& spec, const EffectSite& site,
                                                 SpecProblems&) {
  const QuantizationRule r = quantizationRule(spec, site.signal());
  return std::make_unique<Quantization>(r.lsb, r.isRate, r.carry, r.dithered);
}

}  // namespace sinsim::errormodels
