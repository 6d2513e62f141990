// `white`: white noise on the sensor output.
//   density: 0.2 deg/sqrt(h)    noise density N (= ARW/VRW; signal·sqrt(time), e.g. deg/s/sqrt(Hz))
//   or sigma: 0.6 deg/s, rate: 1 kHz     per-sample standard deviation at a stated sample rate
//   rate (optional with density): generate at that rate instead of as a continuous process
//
// Without a rate the noise is continuous white noise with autocovariance N²·δ(τ) (so that the Allan
// variance is N²/τ, IEEE Std 952-1997 Annex C, angle/velocity random walk); its exact integral over
// an interval of length dt is N·sqrt(dt)·w, w ~ N(0,1). The rate output dtheta/dt then has standard
// deviation N/sqrt(dt): it grows with the output rate, as it must. With a rate f the process is a
// discrete sequence of standard deviation sigma = N·sqrt(f) held over each 1/f and integrated into
// the IMU intervals; both forms have the same low-frequency density N = sigma/sqrt(f).
#include "errormodels/held_process.hpp"
#include "errormodels/interval_cache.hpp"

namespace sinsim::errormodels {
namespace {

class ContinuousWhite final : public DirectAxisErrorState<ContinuousWhite> {
 public:
  ContinuousWhite(int axis, double density, NormalStream s)
      : DirectAxisErrorState(axis), n_(density), s_(s) {}
  double integral(const Interval& iv) override {
    return scale_.get(iv.dt, [this](double dt) { return n_ * std::sqrt(dt); }) * s_.next();
  }
  // integral() over chunks of intervals: the same draws and operations, the draws taken at once.
  void addIntegrals(Vec3* u, const Interval* iv, std::size_t n, int a) {
    addIntegralsInChunks<128>(u, iv, n, a, [this](const Interval* c, std::size_t m, double* I) {
      s_.fill(I, m);
      for (std::size_t i = 0; i < m; ++i)
        I[i] = scale_.get(c[i].dt, [this](double h) { return n_ * std::sqrt(h); }) * I[i];
    });
  }

 private:
  double n_;  // [signal·sqrt(s)]
  NormalStream s_;
  IntervalCache<double> scale_;  // N sqrt(dt) [signal·s]
};

class DiscreteWhite final : public HeldProcessState {
 public:
  DiscreteWhite(int axis, double rate, double sigma, NormalStream s)
      : HeldProcessState(axis, rate), sigma_(sigma), s_(s) {}

 protected:
  double next() override { return sigma_ * s_.next(); }

 private:
  double sigma_;  // [signal]
  NormalStream s_;
};

class White final : public Effect {
 public:
  White(double density, double rate) : density_(density), rate_(rate) {}
  std::unique_ptr<EffectState> instantiate(const InstanceContext& ctx) const override {
    if (std::isnan(rate_)) return std::make_unique<ContinuousWhite>(ctx.site->axis, density_, ctx.stream());
    requireRateAtLeastImu(rate_, ctx);
    return std::make_unique<DiscreteWhite>(ctx.site->axis, rate_, density_ * std::sqrt(rate_),
                                           ctx.stream());
  }

 private:
  double density_;  // N [signal·sqrt(s)]
  double rate_;     // [Hz] or NaN for continuous
};

}  // namespace

const std::vector<ParamSchema>& paramsOf_white() {
  static const std::vector<ParamSchema> p = {
      param("density", ParamKind::quantity, signal(Dimension::time().sqrt())).oneOf(1).positive()
          .doc("noise density N = ARW / VRW (deg/sqrt(h), m/s/sqrt(h))"),
      param("sigma", ParamKind::quantity, signal()).oneOf(1).positive()
          .doc("or the per-sample standard deviation at `rate`"),
      param("rate", ParamKind::quantity, fixed(Dimension::frequency())).optional().positive()
          .doc("sample rate (required with sigma; with density: generate at this rate)")};
  return p;
}

std::unique_ptr<Effect> buildEffect_white(const EffectSpec& spec, const EffectSite&,
                                          SpecProblems& problems) {
  if (spec.has("sigma") && !spec.has("rate")) {
    problems.add("", "missing key rate: a per-sample sigma needs the sample rate it holds at");
    return nullptr;
  }
  return std::make_unique<White>(whiteDensityOf(spec), valueOr(spec, "rate", NAN));
}

double whiteDensityOf(const EffectSpec& spec) {
  if (spec.has("sigma")) return valueOr(spec, "sigma", NAN) / std::sqrt(valueOr(spec, "rate", NAN));
  return valueOr(spec, "density", NAN);
}

}  // namespace sinsim::errormodels
