// Ramp: sign and size from the least-squares trend, Allan signature R^2 tau^2 / 2 (exact for a
// ramp), and its own test: window-mean increments of one sign.
#include "errormodels/diagnose/detector.hpp"
#include "errormodels/diagnose/significance.hpp"

#include <cmath>

namespace sinsim::errormodels::diagnose::detail {

namespace {

/// Constant-slope test: the increments D_j = ybar_{j+1} - ybar_j of window means of m samples
/// have mean R m dt for a ramp and 0 for any noise with stationary increments (random walk,
/// flicker, white): t = mean(D) / (sd(D) / sqrt(n)), n - 1 dof (conservative for white noise,
/// whose D_j are negatively correlated); windows with 8..4096 increments, Bonferroni.
/// Returns z (look-elsewhere corrected) and the best t.
double oneSignTest(const DetectorContext& ctx, double& tBest) {
  double zRamp = 0;
  tBest = 0;
  std::size_t tested = 0;
  for (auto m : ctx.setup.factors) {
    const auto wm = windowMeans(ctx.y, m);
    if (wm.size() < 9 || wm.size() > 4097) continue;
    const std::size_t n = wm.size() - 1;
    double md = 0, sd = 0;
    for (std::size_t j = 0; j < n; ++j) md += wm[j + 1] - wm[j];
    md /= double(n);
    for (std::size_t j = 0; j < n; ++j) sd += (wm[j + 1] - wm[j] - md) * (wm[j + 1] - wm[j] - md);
    sd = std::sqrt(sd / double(n - 1));
    ++tested;
    if (!(sd > 0)) continue;
    const double t = std::fabs(md) / (sd / std::sqrt(double(n)));
    const double z = zFromStudentT(t, double(n - 1));
    if (z > zRamp) zRamp = z, tBest = t;
  }
  return tested ? zFromTwoSidedP(double(tested) * std::erfc(zRamp / std::sqrt(2.0))) : 0.0;
}

}  // namespace

std::vector<Candidate> detect_ramp(const DetectorContext& ctx) {
  const Units& u = ctx.units;
  std::vector<double> line(ctx.N);
  for (std::size_t k = 0; k < ctx.N; ++k) line[k] = (double(k) + 0.5) * ctx.dt;
  if (ctx.spanned(line)) return {};
  Candidate c;
  c.effect = "ramp";
  c.slowShape = true;
  c.basis = {line};
  double slope = 0;
  if (ctx.taken.empty()) {
    slope = trendSlope(ctx.y, ctx.dt);
    c.signal.resize(ctx.N);
    for (std::size_t k = 0; k < ctx.N; ++k) c.signal[k] = slope * (line[k] - 0.5 * ctx.T);
    c.g = ctx.shape([](double t) { return t * t / 2.0; });
  } else {
    // Beside the signals taken out: the slope of the joint fit, the line apart from them
    // (DetectorContext::apart) as the signal left to remove and as the Allan shape.
    const auto x = ctx.apart(line);
    double xy = 0, xx = 0;
    for (std::size_t k = 0; k < ctx.N; ++k) xy += x[k] * ctx.y[k], xx += x[k] * x[k];
    slope = xx > 0 ? xy / xx : 0.0;
    c.signal.resize(ctx.N);
    c.stated.resize(ctx.N);
    for (std::size_t k = 0; k < ctx.N; ++k) c.signal[k] = slope * x[k], c.stated[k] = slope * (line[k] - 0.5 * ctx.T);
    c.g = allanVariance(x, ctx.setup);
  }
  double tBest = 0;
  c.zSpecial = oneSignTest(ctx, tBest);
  // Conditional test: the record's trend against the scatter of a least-squares trend under the
  // current model (its realisations' trends and the accepted noises') with the Gaussian noise that
  // best fits the record without its trend (ModelNow::trendVarWith): a realised random walk has a
  // trend of variance 6 K^2 / (5 T), and a walk the model lacks must not pass for a ramp. The
  // one-sign test above sees a ramp only against the increments' own scatter (white noise's
  // increments are negatively correlated, so it is weak there: a 1.5x ramp on a white base gives
  // t ~ 1); this one weighs the trend by what the model predicts. It is the regressor test of
  // the warm-up and the temperature with the line as the shape (the same variance rule for all
  // three: a settling of long time constant is nearly a line, and a tie between them must not be
  // decided by which variance bound each uses).
  c.zConditional = trendTestGivenModel(ctx, line);
  c.evidence = "Allan deviation rising with slope +1 at long tau; least-squares trend " +
               quantity(slope, u.slope) + "; window-mean increments of one sign (t = " + num(tBest, 3) + ")";
  // The size written is the least-squares slope: the realised trend of this record, which the
  // long-tau Allan points (deterministic, no scatter) must meet; the Allan fit's R scored it.
  const Dimension rampDim = ctx.signal / Dimension::time();
  c.describe = [u, slope, rampDim](double, Finding& f) {
    const double R = slope;
    f.size = "R = " + quantity(R, u.slope);
    f.spec = EffectSpec::make("ramp", {ParamSpec::quantity("slope", stated(R, u.slope), rampDim)});
    f.params["slope"] = R;
  };
  return {c};
}

}  // namespace sinsim::errormodels::diagnose::detail
