// Gauss-Markov: a first-order GM (AR(1) at the record's rate) with correlation time on a grid of
// factor sqrt(2) from 8 samples to tau_max / 4, one candidate per grid time; the trial selection keeps the
// time whose Allan shape lowers the criterion most and the fit sizes its variance. The Allan
// variance is the composite fit's closed form of the discrete GM (fit/latent_model.hpp), written
// with `rate:` = the record's rate so that the simulator draws exactly that AR(1).
#include "errormodels/diagnose/detector.hpp"
#include "errormodels/fit/latent_model.hpp"
#include "errormodels/gm_process.hpp"

#include <cmath>

namespace sinsim::errormodels::diagnose::detail {

namespace {

Candidate gmCandidate(const DetectorContext& ctx, double Tc) {
  const Units& u = ctx.units;
  const double dt = ctx.dt, rate = ctx.record.rate_hz;
  Candidate c;
  c.effect = "gauss_markov";
  c.parameters = 2;  // sigma and its correlation time
  c.switching = true;  // a telegraph's autocorrelation is exp(-2 lambda |t|): a GM's
  c.g = ctx.shape([&](double t) {
    const auto m = std::size_t(std::llround(t / dt));
    return fit::gmDiscreteAllanVariance(1.0, Tc, dt, m < 1 ? 1 : m);
  });
  // A GM's autocovariance falls as exp(-lag dt / Tc): below 1e-17 of lag 0 beyond 40 Tc.
  if (Tc <= ctx.tau.back() / 8) c.acovSpan = std::size_t(std::ceil(40.0 * Tc / dt)) + 1;
  c.acov = [Tc, dt](std::size_t maxLag) {
    std::vector<double> r(maxLag + 1, 0.0);
    addGaussMarkovIntervalAcov(1.0, Tc, dt, r);
    return r;
  };
  c.evidence = "an Allan hump (rising as tau, falling as 1/tau, peak at 1.89 T) with T = " + num(Tc, 3) + " s";
  const Dimension signalDim = ctx.signal;
  c.describe = [u, Tc, rate, signalDim](double theta, Finding& f) {
    const double sigma = std::sqrt(theta);
    f.size = "sigma = " + quantity(sigma, u.level) + ", tau = " + num(Tc, 4) + " s";
    f.spec = EffectSpec::make("gauss_markov",
                              {ParamSpec::quantity("sigma", stated(sigma, u.level), signalDim),
                               ParamSpec::quantity("tau", stated(Tc, "s"), Dimension::time()),
                               ParamSpec::quantity("rate", stated(rate, "Hz", 9), Dimension::frequency())});
    f.params["sigma"] = sigma;
    f.params["tau"] = Tc;
  };
  return c;
}

}  // namespace

std::vector<Candidate> detect_gauss_markov(const DetectorContext& ctx) {
  // From 8 samples: a faster GM only reshapes the first two or three Allan octaves, where a base
  // fitted to the record (an AR whose level alone is refitted here) is itself bent by whatever
  // else the record holds (a ramp, spikes, a lattice); there it was a false finding on 3 of 9
  // diagnosis tests. To a navigation filter at this rate it is white noise anyway.
  // Up to tau_max / 4: the hump (peak at 1.89 T) must turn over an octave before the longest
  // Allan tau; a slower GM is a random walk to these statistics and is named so.
  std::vector<Candidate> out;
  if (ctx.tau.empty()) return out;
  for (double Tc = 8 * ctx.dt; Tc <= ctx.tau.back() / 4; Tc *= std::sqrt(2.0)) out.push_back(gmCandidate(ctx, Tc));
  return out;
}

}  // namespace sinsim::errormodels::diagnose::detail
