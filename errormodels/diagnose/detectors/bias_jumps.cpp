// Bias jumps: the level steps the record shows (DetectorContext::steps: the window-mean jump test,
// else the level-shift test, at 1e-3 for the whole record) taken out as a signal. Its trial is
// the record without them against the record with them; each jump costs two parameters (its
// instant and its size), so a staircase cut out of a smooth drift pays for every stair. Steps that
// go back and forth (revertingSteps) are stated as a two-level telegraph, others as steps of
// random size.
#include "errormodels/diagnose/detector.hpp"
#include "errormodels/diagnose/significance.hpp"

#include <cmath>

namespace sinsim::errormodels::diagnose::detail {

std::vector<Candidate> detect_bias_jumps(const DetectorContext& ctx) {
  if (ctx.steps.size() != ctx.N) return {};
  const auto jumps = jumpsOf(ctx.steps, 1.0 / ctx.dt);
  if (jumps.empty()) return {};
  const Units& u = ctx.units;
  Candidate c;
  c.effect = "bias_jumps";
  c.slowShape = true;
  c.freeSize = false;
  c.parameters = 2 * jumps.size();
  double mean = 0;
  for (double v : ctx.steps) mean += v / double(ctx.N);
  c.signal = ctx.steps;
  for (double& v : c.signal) v -= mean;
  c.g = allanVariance(c.signal, ctx.setup);
  const bool telegraph = revertingSteps(jumps);
  double ss = 0, sa = 0;
  for (const auto& j : jumps) ss += j.size * j.size, sa += std::fabs(j.size);
  const double n = double(jumps.size());
  const double rate = n / ctx.T;
  // A telegraph's size is the distance between its levels (the mean jump); steps of random size
  // are stated by their root mean square.
  const double size = telegraph ? sa / n : std::sqrt(ss / n);
  c.evidence = std::to_string(jumps.size()) + " level step" + (jumps.size() > 1 ? "s" : "") + " (";
  for (std::size_t i = 0; i < jumps.size() && i < 4; ++i)
    c.evidence += (i ? ", " : "") + std::string("t = ") + num(jumps[i].time, 5) + " s " +
                  (jumps[i].size > 0 ? "+" : "") + quantity(jumps[i].size, u.level);
  c.evidence += std::string(jumps.size() > 4 ? ", ..." : "") + ")" +
                (telegraph ? ", going back and forth between two levels" : "");
  const Dimension signalDim = ctx.signal;
  c.describe = [rate, size, telegraph, u, signalDim](double, Finding& f) {
    f.size = num(rate, 4) + " Hz of " + (telegraph ? "" : "+-") + quantity(size, u.level) +
             (telegraph ? " (telegraph)" : "");
    std::vector<ParamSpec> p = {ParamSpec::quantity("rate", stated(rate, "Hz"), Dimension::frequency()),
                                ParamSpec::quantity("size", stated(size, u.level), signalDim)};
    if (telegraph) p.push_back(ParamSpec::flagValue("telegraph", true));
    f.spec = EffectSpec::make("bias_jumps", std::move(p));
    f.params["rate"] = rate;
    f.params["size"] = size;
  };
  return {c};
}

}  // namespace sinsim::errormodels::diagnose::detail
