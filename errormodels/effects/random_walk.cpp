// `random_walk`: rate random walk (gyro) / acceleration random walk (accel) of the sensor output,
// b' = K w(t): the output's bias wanders as Brownian motion.
//   K: 0.5 deg/h/sqrt(h)     coefficient (IEEE Std 952-1997 Annex C: AVAR = K² tau / 3)
//   rate: 1 kHz              (optional) generate as a discrete walk at that rate, held (ZOH)
//
// Without a rate the walk is continuous and both its value and its integral over an interval are
// drawn exactly (integrated Brownian motion): with w1, w2 ~ N(0,1) independent,
//   b1 = b0 + K sqrt(dt) w1,      ∫ b dt = b0 dt + K dt^(3/2) (w1/2 + w2/(2 sqrt 3))
// (Var = K² dt³/3, Cov with the step = K² dt²/2). The step is scaled by sqrt(dt), never dt.
// The walk starts at 0 (add a `bias` with sigma for a random starting value).
#include "errormodels/held_process.hpp"
#include "errormodels/interval_cache.hpp"

namespace sinsim::errormodels {
namespace {

class ContinuousWalk final : public DirectAxisErrorState<ContinuousWalk> {
 public:
  ContinuousWalk(int axis, double K, NormalStream s) : DirectAxisErrorState(axis), k_(K), s_(s) {}
  double integral(const Interval& iv) override {
    const double w1 = s_.next(), w2 = s_.next();
    const Factors& f = factors_.get(iv.dt, [this](double dt) { return factors(dt); });
    const double I = b_ * iv.dt + f.kDtSqrtDt * (0.5 * w1 + w2 / (2.0 * std::sqrt(3.0)));
    b_ += f.kSqrtDt * w1;
    return I;
  }
  // integral() over chunks of intervals: the same draws and operations, the draws taken at once.
  void addIntegrals(Vec3* u, const Interval* iv, std::size_t n, int a) {
    constexpr std::size_t kChunk = 64;
    addIntegralsInChunks<kChunk>(u, iv, n, a, [this](const Interval* c, std::size_t m, double* I) {
      double w[2 * kChunk];
      s_.fill(w, 2 * m);
      double b = b_;
      for (std::size_t i = 0; i < m; ++i) {
        const double dt = c[i].dt;
        const Factors& f = factors_.get(dt, [this](double h) { return factors(h); });
        const double w1 = w[2 * i], w2 = w[2 * i + 1];
        I[i] = b * dt + f.kDtSqrtDt * (0.5 * w1 + w2 / (2.0 * std::sqrt(3.0)));
        b += f.kSqrtDt * w1;
      }
      b_ = b;
    });
  }

 private:
  struct Factors {
    double kDtSqrtDt = 0.0, kSqrtDt = 0.0;  // K dt^1.5 [signal·s], K dt^0.5 [signal]
  };
  Factors factors(double dt) const {
    const double sdt = std::sqrt(dt);
    return Factors{k_ * dt * sdt, k_ * sdt};
  }
  double k_;  // [signal/sqrt(s)]
  NormalStream s_;
  double b_ = 0.0;
  IntervalCache<Factors> factors_;
};

class DiscreteWalk final : public HeldProcessState {
 public:
  DiscreteWalk(int axis, double rate, double K, NormalStream s)
      : HeldProcessState(axis, rate), step_(K / std::sqrt(rate)), s_(s) {}

 protected:
  double next() override { return b_ += step_ * s_.next(); }

 private:
  double step_;  // K sqrt(h) [signal]
  NormalStream s_;
  double b_ = 0.0;
};

class RandomWalk final : public Effect {
 public:
  RandomWalk(double K, double rate) : k_(K), rate_(rate) {}
  std::unique_ptr<EffectState> instantiate(const InstanceContext& ctx) const override {
    if (std::isnan(rate_)) return std::make_unique<ContinuousWalk>(ctx.site->axis, k_, ctx.stream());
    requireRateAtLeastImu(rate_, ctx);
    return std::make_unique<DiscreteWalk>(ctx.site->axis, rate_, k_, ctx.stream());
  }

 private:
  double k_, rate_;
};

}  // namespace

const std::vector<ParamSchema>& paramsOf_random_walk() {
  static const std::vector<ParamSchema> p = {
      param("K", ParamKind::quantity, signal(Dimension::frequency().sqrt())).positive()
          .doc("rate / acceleration random-walk coefficient K (deg/h/sqrt(h), m/s^2/sqrt(h))"),
      param("rate", ParamKind::quantity, fixed(Dimension::frequency())).optional().positive()
          .doc("generate as a discrete process at this rate (default: exact continuous process)")};
  return p;
}

std::unique_ptr<Effect> buildEffect_random_walk(const EffectSpec& spec, const EffectSite&,
                                                SpecProblems&) {
  return std::make_unique<RandomWalk>(valueOr(spec, "K", NAN), valueOr(spec, "rate", NAN));
}

}  // namespace sinsim::errormodels
