// `bias_instability`: flicker (1/f) bias noise, as a sum of first-order Gauss-Markov processes.
//   B: 10 deg/h                bias-instability coefficient (IEEE Std 952-1997 Annex C: two-sided
//                              PSD B²/(2π f); Allan deviation floor sqrt(2 ln2/π) B ≈ 0.664 B)
//   or floor: 6.64 deg/h       the Allan-deviation floor itself (B = floor / 0.664)
//   tau_range: [1 s, 1000 s]   averaging times over which the Allan floor must hold
//
// Construction: a log-uniform set of GM correlation times with the same variance each has a PSD
// sum ≈ ρ σ² ∫ 2T/(1+(2πfT)²) d(ln T) = ρ σ²/(2f); equal to B²/(2πf) when σ² = B²/(π ρ), with
// ρ = d/ln 10 components per unit of ln T (d per decade). Keshner 1982 ("1/f noise", Proc. IEEE
// 70(3)) gives the same sum-of-relaxations picture. Here d = 2 per decade, at the centres of
// half-decade cells spanning tau_range widened by 10^1.5 on each side: the widening is what makes
// the Allan floor flat up to the ends of tau_range. Computed from the GM closed-form Allan variance,
// the floor then stays within -2.5 %/+1 % of 0.664 B over tau_range (checked in
// tests/errormodels/test_processes.cpp). Outside the widened band the process is what a sum of GMs
// is: random-walk-like (ADEV ∝ τ^+1/2) below the fastest correlation time, and ADEV ∝ τ^-1/2 above
// the slowest (bounded variance).
// Each component is integrated exactly over the IMU intervals (gm_process.hpp).
#include <cmath>

#include "errormodels/flicker_gms.hpp"
#include "errormodels/gm_process.hpp"
#include "errormodels/held_process.hpp"

namespace sinsim::errormodels {
namespace {

class FlickerState final : public AxisErrorState {
 public:
  FlickerState(int axis, double sigma, const std::vector<double>& taus, const InstanceContext& ctx)
      : AxisErrorState(axis) {
    for (std::size_t j = 0; j < taus.size(); ++j)
      gms_.emplace_back(sigma, taus[j], ctx.stream(unsigned(j)));
  }
  double integral(const Interval& iv) override {
    double s = 0.0;
    for (auto& g : gms_) s += g.integral(iv.dt);
    return s;
  }

 private:
  std::vector<ExactGaussMarkov> gms_;
};

class BiasInstability final : public Effect {
 public:
  explicit BiasInstability(const FlickerGms& g) : taus_(g.taus), sigma_(g.sigma) {}
  std::unique_ptr<EffectState> instantiate(const InstanceContext& ctx) const override {
    return std::make_unique<FlickerState>(ctx.site->axis, sigma_, taus_, ctx);
  }

 private:
  std::vector<double> taus_;  // GM correlation times [s]
  double sigma_;              // standard deviation of each component [signal]
};

}  // namespace

const std::vector<ParamSchema>& paramsOf_bias_instability() {
  static const std::vector<ParamSchema> p = {
      param("B", ParamKind::quantity, signal()).oneOf(1).positive()
          .doc("bias-instability coefficient B (Allan deviation floor 0.664 B)"),
      param("floor", ParamKind::quantity, signal()).oneOf(1).positive()
          .doc("or the Allan-deviation floor itself"),
      param("tau_range", ParamKind::list, fixed(Dimension::time())).printed(6)
          .doc("[shortest, longest] averaging time over which the floor holds")};
  return p;
}

namespace {

// The components a spec asks for, or the key and the message of what is wrong with it.
struct ReadComponents {
  FlickerGms gms;
  std::string key, problem;
};

ReadComponents readComponents(const EffectSpec& spec) {
  ReadComponents r;
  const double floorPerB = std::sqrt(2.0 * std::log(2.0) / M_PI);  // ≈ 0.664
  const double B = spec.has("B") ? valueOr(spec, "B", NAN) : valueOr(spec, "floor", NAN) / floorPerB;
  const std::vector<double> range = valuesOf(spec, "tau_range");
  r.key = "tau_range";
  if (range.size() != 2)
    r.problem = "expected [shortest, longest] averaging time, e.g. [1 s, 1000 s]";
  else if (!(range[0] > 0 && range[1] > range[0]))
    r.problem = "expected 0 < shortest < longest";
  else if (!(std::log10(range[1]) - std::log10(range[0]) <= kFlickerMaxDecades))
    r.problem = "spans more than " + std::to_string(int(kFlickerMaxDecades)) +
                " decades (two Gauss-Markov components a decade are drawn at every interval)";
  else
    r.gms = biasInstabilityGms(B, range[0], range[1]);
  return r;
}

}  // namespace

FlickerGms biasInstabilityGmsOf(const EffectSpec& spec) {
  const ReadComponents r = readComponents(spec);
  if (!r.problem.empty()) throw InputError(r.key + ": " + r.problem);
  return r.gms;
}

std::unique_ptr<Effect> buildEffect_bias_instability(const EffectSpec& spec, const EffectSite&,
                                                     SpecProblems& problems) {
  const ReadComponents r = readComponents(spec);
  if (!r.problem.empty()) {
    problems.add(r.key, r.problem);
    return nullptr;
  }
  return std::make_unique<BiasInstability>(r.gms);
}

}  // namespace sinsim::errormodels
