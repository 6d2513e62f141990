// White noise: the Allan variance N^2 / tau of continuous white noise averaged over each interval
// (IEEE Std 952-1997 Annex C), its density N from the Allan fit. A candidate when the model's own
// short-tau level is wrong in shape, not only in scale (the level s is refitted in every trial,
// so a white term is chosen only when it explains what scaling the base cannot).
#include "errormodels/diagnose/detector.hpp"

#include <cmath>
#include <string>

namespace sinsim::errormodels::diagnose::detail {

std::vector<Candidate> detect_white(const DetectorContext& ctx) {
  const Units& u = ctx.units;
  const double dt = ctx.dt;
  Candidate c;
  c.effect = "white";
  c.parameters = 1;
  c.g = ctx.shape([](double t) { return 1.0 / t; });  // N^2 / tau
  // Interval averages of continuous white noise: variance N^2 / dt at lag 0, uncorrelated.
  c.acovSpan = 1;
  c.acov = [dt](std::size_t maxLag) {
    std::vector<double> r(maxLag + 1, 0.0);
    r[0] = 1.0 / dt;
    return r;
  };
  c.evidence = "Allan deviation falling with slope -1/2 (N^2/tau) where the model is too low";
  const std::string unit = std::string(u.level) + "/sqrt(Hz)";
  const Dimension density = ctx.signal * Dimension::time().sqrt();
  c.describe = [unit, density](double theta, Finding& f) {
    const double N = std::sqrt(theta);
    f.size = "N = " + quantity(N, unit.c_str());
    f.spec = EffectSpec::make("white", {ParamSpec::quantity("density", stated(N, unit.c_str()), density)});
    f.params["density"] = N;
  };
  return {c};
}

}  // namespace sinsim::errormodels::diagnose::detail
