// `gauss_markov`: first-order Gauss-Markov process, stationary standard deviation sigma,
// correlation time tau (autocorrelation sigma² exp(-|t|/tau)).
//   sigma: 0.01 deg/s
//   tau: 25 ms
//   rate: 1 kHz      (optional) a discrete model at that rate, e.g. fitted to data sampled there
//
// Discrete (with rate f, h = 1/f): x[k+1] = φ x[k] + sigma sqrt(1-φ²) w[k], φ = exp(-h/tau) — the
// exact discretisation (variance sigma² at every rate; ACF sigma² φ^|k| = sigma² exp(-|k| h/tau)),
// each sample held over h and integrated into the IMU intervals.
// Continuous (no rate): the process and its integral over each IMU interval are drawn exactly
// (gm_process.hpp), as an IMU integrating a continuous GM error would see it.
#include "errormodels/gm_process.hpp"
#include "errormodels/held_process.hpp"

namespace sinsim::errormodels {
namespace {

class ContinuousGm final : public DirectAxisErrorState<ContinuousGm> {
 public:
  ContinuousGm(int axis, double sigma, double tau, NormalStream s)
      : DirectAxisErrorState(axis), gm_(sigma, tau, s) {}
  double integral(const Interval& iv) override { return gm_.integral(iv.dt); }
  void addIntegrals(Vec3* u, const Interval* iv, std::size_t n, int a) {
    constexpr std::size_t kChunk = ExactGaussMarkov::kMaxChunk;
    addIntegralsInChunks<kChunk>(u, iv, n, a, [this](const Interval* c, std::size_t m, double* I) {
      gm_.integrals(m, [c](std::size_t i) { return c[i].dt; }, I);
    });
  }

 private:
  ExactGaussMarkov gm_;
};

class DiscreteGm final : public HeldProcessState {
 public:
  DiscreteGm(int axis, double rate, double sigma, double tau, NormalStream s)
      : HeldProcessState(axis, rate), s_(s) {
    phi_ = std::exp(-1.0 / (rate * tau));
    q_ = sigma * std::sqrt(-std::expm1(-2.0 / (rate * tau)));  // sigma sqrt(1-φ²)
    x_ = sigma * s_.next();                                     // stationary start
    first_ = true;
  }

 protected:
  double next() override {
    if (first_) {
      first_ = false;
      return x_;
    }
    return x_ = phi_ * x_ + q_ * s_.next();
  }
  void generate(double* out, int n) override {
    int i = 0;
    if (first_ && n > 0) {
      first_ = false;
      out[i++] = x_;
    }
    double x = x_;
    for (; i < n; ++i) out[i] = x = phi_ * x + q_ * s_.next();
    x_ = x;
  }

 private:
  NormalStream s_;
  double phi_, q_, x_;
  bool first_;
};

class GaussMarkov final : public Effect {
 public:
  GaussMarkov(double sigma, double tau, double rate) : sigma_(sigma), tau_(tau), rate_(rate) {}
  std::unique_ptr<EffectState> instantiate(const InstanceContext& ctx) const override {
    if (std::isnan(rate_))
      return std::make_unique<ContinuousGm>(ctx.site->axis, sigma_, tau_, ctx.stream());
    requireRateAtLeastImu(rate_, ctx);
    return std::make_unique<DiscreteGm>(ctx.site->axis, rate_, sigma_, tau_, ctx.stream());
  }

 private:
  double sigma_, tau_, rate_;
};

}  // namespace

const std::vector<ParamSchema>& paramsOf_gauss_markov() {
  static const std::vector<ParamSchema> p = {
      param("sigma", ParamKind::quantity, signal()).positive().doc("stationary standard deviation"),
      param("tau", ParamKind::quantity, fixed(Dimension::time())).positive().printed(7)
          .doc("correlation time"),
      param("rate", ParamKind::quantity, fixed(Dimension::frequency())).optional().positive()
          .doc("generate as a discrete process at this rate (default: exact continuous process)")};
  return p;
}

std::unique_ptr<Effect> buildEffect_gauss_markov(const EffectSpec& spec, const EffectSite&,
                                                 SpecProblems&) {
  return std::make_unique<GaussMarkov>(valueOr(spec, "sigma", NAN), valueOr(spec, "tau", NAN),
                                       valueOr(spec, "rate", NAN));
}

}  // namespace sinsim::errormodels
