// Bias instability: a flat Allan floor (0.664 B) over the record's tau range, sized by the Allan
// fit. Its signature and autocovariance are those of the effect as the plug-in builds it
// (effects/bias_instability.cpp: GM components, 2 per decade over tau_range widened 1.5 decades,
// each of variance B^2 ln10 / (2 pi)). The floor is 0.664 B within -2.5 %/+1 % over tau_range.
#include "errormodels/diagnose/detector.hpp"
#include "errormodels/flicker_gms.hpp"
#include "errormodels/gm_process.hpp"

#include <algorithm>
#include <cmath>

namespace sinsim::errormodels::diagnose::detail {

namespace {

/// The GM components of the plug-in per unit B^2 (flicker_gms.hpp).
struct Components {
  std::vector<double> taus;  // [s]
  double s2 = 0;             // variance of each per unit B^2
};

/// AVAR per unit B^2 at tau [s]: the sum of its components' GM closed forms.
double avar(const Components& m, double t) {
  double v = 0;
  for (double tc : m.taus) v += gaussMarkovAllanVariance(m.s2, tc, t);
  return v;
}

/// Autocovariance per unit B^2 of the samples (interval averages over dt) at lags 0..maxLag.
std::vector<double> acov(const Components& m, double dt, std::size_t maxLag) {
  std::vector<double> r(maxLag + 1, 0.0);
  for (double tc : m.taus) addGaussMarkovIntervalAcov(m.s2, tc, dt, r);
  return r;
}

}  // namespace

std::vector<Candidate> detect_bias_instability(const DetectorContext& ctx) {
  const Units& u = ctx.units;
  const double dt = ctx.dt;
  const double lo = std::max(10 * dt, ctx.T / 1000), hi = ctx.T / 2;
  Components m;
  m.taus = flickerGmTaus(lo * std::pow(10.0, -1.5), hi * std::pow(10.0, 1.5));
  m.s2 = flickerGmVariance();
  Candidate c;
  c.effect = "bias_instability";
  c.acov = [m, dt](std::size_t maxLag) { return acov(m, dt, maxLag); };
  c.g = ctx.shape([&](double t) { return avar(m, t); });
  c.evidence = "a flat Allan floor the model falls below (0.664 B)";
  const Dimension signalDim = ctx.signal;
  c.describe = [u, lo, hi, signalDim](double theta, Finding& f) {
    const double B = std::sqrt(theta);
    f.size = "B = " + quantity(B, u.level) + " (floor " + quantity(0.664 * B, u.level) + ")";
    f.spec = EffectSpec::make(
        "bias_instability",
        {ParamSpec::quantity("B", stated(B, u.level), signalDim),
         ParamSpec::quantities("tau_range", {stated(lo, "s", 4), stated(hi, "s", 4)}, Dimension::time())});
    f.params["B"] = B;
  };
  return {c};
}

}  // namespace sinsim::errormodels::diagnose::detail
