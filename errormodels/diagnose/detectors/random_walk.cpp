// Random walk: the Allan variance K^2 tau / 3 (IEEE Std 952-1997 Annex C), its size from the
// Allan fit.
#include "errormodels/diagnose/detector.hpp"

#include <cmath>

namespace sinsim::errormodels::diagnose::detail {

std::vector<Candidate> detect_random_walk(const DetectorContext& ctx) {
  const Units& u = ctx.units;
  Candidate c;
  c.effect = "random_walk";
  c.g = ctx.shape([](double t) { return t / 3.0; });  // K^2 tau / 3
  c.evidence = "Allan deviation rising with slope +1/2 at long tau (K^2 tau/3)";
  const Dimension walk = ctx.signal / Dimension::time().sqrt();
  c.describe = [u, walk](double theta, Finding& f) {
    f.size = "K = " + quantity(std::sqrt(theta), u.walk);
    f.spec = EffectSpec::make("random_walk", {ParamSpec::quantity("K", stated(std::sqrt(theta), u.walk), walk)});
    f.params["K"] = std::sqrt(theta);
  };
  return {c};
}

}  // namespace sinsim::errormodels::diagnose::detail
