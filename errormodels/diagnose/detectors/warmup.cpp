// Warm-up: e(t) = A exp(-t/tau_w) + c fitted to block means (tau_w on a log grid, then golden
// section), and its own test: the first window-mean step against the later ones.
#include "errormodels/diagnose/detector.hpp"
#include "errormodels/diagnose/significance.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace sinsim::errormodels::diagnose::detail {

namespace {

struct Settling {
  double A = 0;       // amplitude at t = 0 [SI]
  double tau = 0;     // time constant [s]
  double tauMax = 0;  // the top of the range searched [s]
  double octaves = 1; // of the time constants searched
};

/// With `trend`, a straight line t is fitted beside it as a nuisance: a drift that runs through
/// the record (a ramp, a thermal trend) otherwise pulls the time constant to the record's length,
/// where exp(-t / tau_w) imitates the line, and the settling itself is missed. The amplitude is
/// then the joint fit's (the line's share of the settling's shape left out).
Settling fitSettling(const DetectorContext& ctx, bool trend) {
  const auto& bt = ctx.blocks.t;
  const std::size_t nb = ctx.blocks.m.size();
  Eigen::VectorXd yb = Eigen::Map<const Eigen::VectorXd>(ctx.blocks.m.data(), Eigen::Index(nb));
  const std::size_t extra = trend ? 1 : 0;
  // Beside the signals already taken out, their regressors are fitted with it (joint amplitude).
  auto rss = [&](double tw, Eigen::VectorXd& beta) {
    Eigen::MatrixXd X(static_cast<Eigen::Index>(nb), Eigen::Index(2 + extra + ctx.takenBlocks.size()));
    for (std::size_t j = 0; j < nb; ++j) {
      X(Eigen::Index(j), 0) = 1, X(Eigen::Index(j), 1) = std::exp(-bt[j] / tw);
      if (trend) X(Eigen::Index(j), 2) = bt[j] / ctx.T;
      for (std::size_t i = 0; i < ctx.takenBlocks.size(); ++i)
        X(Eigen::Index(j), Eigen::Index(2 + extra + i)) = ctx.takenBlocks[i][j];
    }
    return leastSquares(X, yb, beta);
  };
  // Beside a line only time constants up to T/8 are told from it: a slower settling and a line
  // make one curvature, which the plain fit covers.
  const double lo = std::log(3.0 * double(ctx.blocks.size) * ctx.dt), hi = std::log(ctx.T / (trend ? 8 : 2));
  double bestL = lo, best = INFINITY;
  Eigen::VectorXd beta;
  for (int i = 0; i <= 40; ++i) {
    const double l = lo + (hi - lo) * i / 40.0;
    const double v = rss(std::exp(l), beta);
    if (v < best) best = v, bestL = l;
  }
  double a = std::max(lo, bestL - (hi - lo) / 40), b = std::min(hi, bestL + (hi - lo) / 40);
  const double gr = (std::sqrt(5.0) - 1) / 2;
  for (int i = 0; i < 40; ++i) {
    const double c1 = b - gr * (b - a), c2 = a + gr * (b - a);
    if (rss(std::exp(c1), beta) < rss(std::exp(c2), beta)) b = c2;
    else a = c1;
  }
  Settling s;
  s.tau = std::exp(0.5 * (a + b));
  s.tauMax = std::exp(hi);
  s.octaves = std::max(1.0, (hi - lo) / std::log(2.0));
  rss(s.tau, beta);
  s.A = beta[1];
  return s;
}

/// Start test: the first increment of window means D_0 = ybar_1 - ybar_0 against the spread of
/// the later increments D_j (j >= 1): t = |D_0| / rms(D_j), n - 1 dof. Stationary noise and a ramp
/// make D_0 like the others; a settling transient makes it stand out. Windows >= 1 s with >= 16
/// increments, Bonferroni. Returns z and the best t.
double startTest(const DetectorContext& ctx, double& tStart) {
  double zStart = 0;
  tStart = 0;
  std::size_t tested = 0;
  for (auto m : ctx.setup.factors) {
    if (double(m) * ctx.dt < 1.0) continue;
    const auto wm = windowMeans(ctx.y, m);
    if (wm.size() < 17) continue;
    const std::size_t n = wm.size() - 2;
    double ss = 0, md = 0;
    for (std::size_t j = 1; j <= n; ++j) md += wm[j + 1] - wm[j];
    md /= double(n);
    for (std::size_t j = 1; j <= n; ++j) ss += (wm[j + 1] - wm[j] - md) * (wm[j + 1] - wm[j] - md);
    ++tested;
    const double rms = std::sqrt(ss / double(n - 1));
    if (!(rms > 0)) continue;
    const double t = std::fabs(wm[1] - wm[0] - md) / rms;
    const double z = zFromStudentT(t, double(n - 1));
    if (z > zStart) zStart = z, tStart = t;
  }
  return tested ? zFromTwoSidedP(double(tested) * std::erfc(zStart / std::sqrt(2.0))) : 0.0;
}

/// The candidate of one settling fit; none when its shape is taken out already.
std::optional<Candidate> settlingCandidate(const DetectorContext& ctx, const Settling& s, bool besideTrend) {
  const std::size_t nb = ctx.blocks.m.size();
  const Units& u = ctx.units;
  const double A = s.A, tw = s.tau;
  std::vector<double> shapeX(ctx.N);
  for (std::size_t k = 0; k < ctx.N; ++k) shapeX[k] = std::exp(-(double(k) + 0.5) * ctx.dt / tw);
  if (ctx.spanned(shapeX)) return std::nullopt;
  std::vector<double> w(ctx.N);
  for (std::size_t k = 0; k < ctx.N; ++k) w[k] = A * shapeX[k];
  Candidate c;
  c.effect = "warmup";
  c.slowShape = true;
  c.freeSize = false;
  c.parameters = 2;  // amplitude and time constant
  // Beside a trend the amplitude is already the joint fit's, so a drift found later is fitted on
  // the record without the settling as it stands, not apart from its shape (no basis): apart
  // from it, the later line's share of the shape would be taken out twice.
  if (!besideTrend) c.basis = {shapeX};
  if (!ctx.taken.empty()) {  // the part apart from the signals taken out is what is left to remove
    c.stated = w;
    w = ctx.apart(shapeX);
    for (double& v : w) v *= A;
  }
  c.g = allanVariance(w, ctx.setup);
  c.signal = w;
  double tStart = 0;
  c.zSpecial = startTest(ctx, tStart);
  // The settling given the model: the record's coefficient on exp(-t / tau_w) against the scatter
  // the current model predicts for it (regressorTestGivenModel), Bonferroni over the octaves of
  // tau_w searched (neighbouring time constants give strongly correlated shapes: an upper bound).
  // The start test above compares the first window step with the later ones' own scatter, not
  // with what the model (and the effects it has accepted) predicts.
  c.zConditional = regressorTestGivenModel(ctx, shapeX, s.octaves);
  c.evidence = "exponential settling at the start: " + quantity(A, u.level) + " decaying with tau " +
               num(tw, 4) + " s (least squares on " + std::to_string(nb) + " block means" +
               (besideTrend ? ", a straight trend fitted beside it" : "") + "); first window-mean step t = " +
               num(tStart, 3);
  // At the top of the range searched the time constant is a bound, not an estimate: a settling
  // slower than the record is a curvature that a drift in time shapes alike (a blind probe's
  // ramps on real ADIS16405 windows came out as warm-ups of tau = T/2, 4 of 8 named first).
  if (s.tau >= 0.95 * s.tauMax)
    c.evidence += "; tau sits at the top of the range searched (" + num(s.tauMax, 4) +
                  " s): a bound, not an estimate; a settling this slow is a drift through the record, "
                  "as a ramp (see its score) shapes it too";
  const Dimension signalDim = ctx.signal;
  c.describe = [A, tw, u, signalDim](double, Finding& f) {
    f.size = "A = " + quantity(A, u.level) + ", tau = " + num(tw, 4) + " s";
    f.spec = EffectSpec::make("warmup", {ParamSpec::quantity("amplitude", stated(A, u.level), signalDim),
                                         ParamSpec::quantity("tau", stated(tw, "s"), Dimension::time())});
    f.params["amplitude"] = A;
    f.params["tau"] = tw;
  };
  return c;
}

}  // namespace

/// Two variants in the first round: the settling fitted alone, and fitted beside a straight trend
/// (kept when its time constant differs by more than 5 %). A drift through the record pulls the
/// plain fit's time constant, and on a large settling even a 30 % error leaves a residual
/// transient whose trial loses to a Gauss-Markov hump. The trial chooses between them.
std::vector<Candidate> detect_warmup(const DetectorContext& ctx) {
  if (ctx.blocks.m.size() < 20) return {};
  std::vector<Candidate> out;
  const Settling plain = fitSettling(ctx, false);
  if (auto c = settlingCandidate(ctx, plain, false)) out.push_back(std::move(*c));
  if (!ctx.taken.empty()) return out;  // a drift taken out already is fitted beside the settling
  const Settling besideTrend = fitSettling(ctx, true);
  // At the top of its range the settling beside the line is no settling of its own (it would be
  // slower still): no variant.
  if (std::fabs(std::log(besideTrend.tau / plain.tau)) > 0.05 && besideTrend.tau < 0.9 * ctx.T / 8)
    if (auto c = settlingCandidate(ctx, besideTrend, true)) out.push_back(std::move(*c));
  return out;
}

}  // namespace sinsim::errormodels::diagnose::detail
