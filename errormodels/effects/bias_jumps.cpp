// `bias_jumps`: a bias that holds its level and jumps at random instants (a Poisson process of
// mean rate `rate`): a bias step, a mode hop, a knock on the mount.
//   rate: 0.001 Hz       mean number of jumps per second
//   size: 0.01 deg/s     steps: standard deviation of each jump (zero-mean normal);
//                        telegraph: the distance between the two levels
//   telegraph: no        (optional) yes: two levels +-size/2, each jump to the other (random
//                        telegraph; it starts on either level with probability 1/2)
// Steps start at zero and add up: a compound Poisson process, whose second-order statistics are a
// random walk's with K^2 = rate size^2 (Allan variance K^2 tau / 3). A telegraph has the
// autocovariance (size/2)^2 exp(-2 rate |t|) of a Gauss-Markov process of tau = 1 / (2 rate).
// In each IMU interval a jump occurs with probability p = 1 - exp(-rate dt), dt = 1 / the nominal
// IMU rate as for `outliers` (at most one: dt << 1 / rate is the intended use), at a uniform
// instant inside it, so the interval's integral holds the old level before it and the new one
// after. Three normals per interval from
// the effect's stream: z1 < Phi^-1(p) decides the event (P = p exactly), Phi(z2) its instant, z3
// its size (steps) — drawn whether or not a jump occurs, so each interval uses the same draws.
#include "errormodels/effect.hpp"
#include "errormodels/stats/special.hpp"

namespace sinsim::errormodels {
namespace {

class BiasJumpsState final : public AxisErrorState {
 public:
  BiasJumpsState(int axis, double zEvent, double size, bool telegraph, NormalStream s)
      : AxisErrorState(axis), zEvent_(zEvent), size_(size), telegraph_(telegraph), s_(s) {
    if (telegraph_) level_ = (s_.next() < 0 ? -0.5 : 0.5) * size_;
  }
  double integral(const Interval& iv) override {
    const double z1 = s_.next(), z2 = s_.next(), z3 = s_.next();
    if (!(z1 < zEvent_)) return level_ * iv.dt;
    const double before = level_, at = normalCdf(z2);  // the jump's instant, fraction of dt
    level_ = telegraph_ ? -level_ : level_ + size_ * z3;
    return (before * at + level_ * (1.0 - at)) * iv.dt;
  }

 private:
  double zEvent_, size_;
  bool telegraph_;
  NormalStream s_;
  double level_ = 0.0;  // [signal]
};

class BiasJumps final : public Effect {
 public:
  BiasJumps(double rate, double size, bool telegraph) : rate_(rate), size_(size), telegraph_(telegraph) {}
  std::unique_ptr<EffectState> instantiate(const InstanceContext& ctx) const override {
    const double p = -std::expm1(-rate_ / ctx.imuRate);
    return std::make_unique<BiasJumpsState>(ctx.site->axis, normalQuantile(p), size_, telegraph_, ctx.stream());
  }

 private:
  double rate_, size_;  // [Hz], [signal]
  bool telegraph_;
};

}  // namespace

const std::vector<ParamSchema>& paramsOf_bias_jumps() {
  static const std::vector<ParamSchema> p = {
      param("rate", ParamKind::quantity, fixed(Dimension::frequency())).positive().printed(6)
          .doc("mean number of jumps per second"),
      param("size", ParamKind::quantity, signal()).positive()
          .doc("standard deviation of a jump; with telegraph, the distance between the two levels"),
      param("telegraph", ParamKind::flag, fixed(Dimension::none())).optional("no")
          .doc("two levels +-size/2, each jump to the other (random telegraph)")};
  return p;
}

std::unique_ptr<Effect> buildEffect_bias_jumps(const EffectSpec& spec, const EffectSite&, SpecProblems&) {
  const ParamSpec* telegraph = spec.find("telegraph");
  return std::make_unique<BiasJumps>(valueOr(spec, "rate", NAN), valueOr(spec, "size", NAN),
                                     telegraph && telegraph->flag);
}

JumpsEquivalent biasJumpsEquivalentOf(const EffectSpec& spec, double imuRate) {
  const double rate = valueOr(spec, "rate", NAN), size = valueOr(spec, "size", NAN);
  const ParamSpec* telegraph = spec.find("telegraph");
  const double p = -std::expm1(-rate / imuRate);
  JumpsEquivalent e;
  e.telegraph = telegraph && telegraph->flag;
  if (!e.telegraph) {
    e.K = std::sqrt(imuRate * p) * size;
    return e;
  }
  e.sigma = 0.5 * size;
  // The level's correlation over n intervals is (1 − 2p)^n; at p ≥ 1/2 it alternates, and the
  // continuous form is the one left.
  e.tau = p < 0.5 ? -1.0 / (imuRate * std::log1p(-2.0 * p)) : 0.5 / rate;
  return e;
}

}  // namespace sinsim::errormodels
