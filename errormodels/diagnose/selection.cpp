// Selection of the candidates by trial (selection.hpp).
#include "errormodels/diagnose/selection.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <string>

#include "errormodels/diagnose/level_shift.hpp"
#include "errormodels/diagnose/low_frequency.hpp"
#include "errormodels/diagnose/series_stats.hpp"
#include "errormodels/diagnose/series_tools.hpp"
#include "errormodels/diagnose/significance.hpp"
#include "errormodels/fit/ar_fit.hpp"
#include "errormodels/stats/special.hpp"

namespace sinsim::errormodels::diagnose::detail {

namespace {

/// Each candidate's last trial fit (with the accepted ones), its drop of the criterion and score.
struct Trials {
  std::vector<double> score, drop;
  std::vector<AllanSolution> sol;
  std::vector<char> refit;  // the trial fitted better with the AR base re-estimated
  std::vector<char> standIn;  // a stationary noise sized by a change of the noise level (standsInForChange)
  void resize(std::size_t n) {
    score.assign(n, 0.0), drop.assign(n, 0.0), sol.assign(n, AllanSolution{}), refit.assign(n, 0);
    standIn.assign(n, 0);
  }
};

/// The candidate's own test (lattice, PSD line, one-sign increments, first step, largest
/// residual, the trend given the model) as a chi-square(1) term of the criterion: z^2 of its
/// Gaussian-equivalent z.
double ownEvidence(const Candidate& c, const ModelNow& now) {
  double z = c.zSpecial;
  if (c.zConditional) z = std::max(z, c.zConditional(now));
  return z * z;
}

/// Variance of a record's least-squares trend [SI^2/s^2] that a noise of AVAR g on the tau grid
/// [s] makes over a record of T [s]: 8 g(T/2) / T^2, the variance of the half-record means'
/// difference over (T/2)^2, with g carried from the last two grid points (N/8 at most) to T/2
/// along their log-log slope (clamped to [-1, 2], white to ramp-like). It is the trend variance
/// of white noise times 4/3 and of a random walk times 10/9 (least squares: 12 s^2/(N T^2) and
/// 6 K^2/(5 T)): on the high side, so an accepted noise never makes a trend look significant.
double trendVarianceOf(const std::vector<double>& g, const std::vector<double>& tau, double T) {
  return 8.0 * allanTermAt(g, tau, 0.5 * T) / (T * T);
}

/// The variance of a record's least-squares trend per unit theta under a noise with an
/// autocovariance (Candidate::acov) over n samples at dt [s], exact (trendVarianceFromAcov);
/// computed once per candidate. Used where that autocovariance dies out within the Allan grid
/// (Candidate::acovSpan, the lags computed).
double trendVariance(const Candidate& c, std::size_t n, double dt) {
  if (c.trendVarCache < 0)
    c.trendVarCache = n > 1 ? trendVarianceFromAcov(c.acov(std::min(n, c.acovSpan) - 1), n, dt) : 0.0;
  return c.trendVarCache;
}

/// The trend scatter of the current model: the realisations' variance (w.trendVar, w.trendDof
/// of them) at the fitted level plus each accepted noise's in closed form (trendVarianceOf; for the
/// line itself exact where its autocovariance dies out within the grid: TrendScatter::exactLine), with
/// the dof of that sum (satterthwaiteDof). After a large noise is accepted most of the variance is
/// known exactly: judging a trend beside it with the realisations' 16 dof would turn a t of 10
/// into a z of 5.7. Also the accepted noises' AVAR (another shape's variance under them:
/// regressorTestGivenModel).
TrendScatter currentTrendVar(const ChannelWork& w, const std::vector<const Candidate*>& set, const AllanSolution& sol) {
  const double T = double(w.y->size()) / w.rate;
  const std::vector<double> zero(w.d.adev.x.size(), 0.0);
  TrendScatter s{sol.s * w.trendVar, w.trendDof, 0.0, zero, 0.0, 0.0, zero, w.prob.mu, {}};
  for (double& v : s.baseAvar) v *= sol.s;
  auto addAvar = [](std::vector<double>& to, const std::vector<double>& g, double theta) {
    for (std::size_t k = 0; k < to.size() && k < g.size(); ++k) to[k] += theta * g[k];
  };
  for (std::size_t j = 0; j < set.size(); ++j) {
    const double theta = set[j]->freeSize ? sol.theta[j] : 1.0;
    const double v = theta * trendVarianceOf(set[j]->g, w.d.adev.x, T);
    s.known += v;
    addAvar(s.knownAvar, set[j]->g, theta);
    if (set[j]->acov && set[j]->acovSpan > 0) {
      s.exactLine += theta * trendVariance(*set[j], w.y->size(), 1.0 / w.rate);
      continue;
    }
    s.restKnown += v;
    addAvar(s.restAvar, set[j]->g, theta);
  }
  return s;
}

/// The variance of the record's coefficient on each slow direction (low_frequency.hpp) under the
/// model `set` at `sol` [SI^2]: the realisations' (w.lowFreqVar) at the fitted level plus each
/// noise's (lowFrequencyVarianceOf, on the high side like trendVarianceOf). A candidate with a
/// signal adds none: its signal is taken out of the coefficients instead.
std::vector<double> lowFreqVarOf(const ChannelWork& w, const std::vector<const Candidate*>& set,
                                 const AllanSolution& sol) {
  const double T = double(w.y->size()) / w.rate;
  std::vector<double> v(w.lowFreqVar.size());
  for (std::size_t d = 0; d < v.size(); ++d) {
    v[d] = sol.s * w.lowFreqVar[d];
    for (std::size_t j = 0; j < set.size(); ++j)
      if (set[j]->signal.empty())
        v[d] += (set[j]->freeSize ? sol.theta[j] : 1.0) *
                lowFrequencyVarianceOf(set[j]->g, w.d.adev.x, T, 1.0 / w.rate, w.lowFreq.k[d]);
  }
  return v;
}

/// What the record's longest scales say for a trial: the decrease of -2 ln L of the slow
/// coefficients c (the record's, or without its steps) from the current model to the trial's,
/// the candidate's signal (if any) taken out of c. A signal is credited only with a decrease: a
/// fitted shape a little off (a warm-up's time constant bent by a thermal drift) leaves its own
/// misfit in the slow coefficients, which its Allan terms already judge.
double lowFreqGain(const ChannelWork& w, const std::vector<double>& c, const std::vector<double>& v0,
                   const Candidate& cand, const std::vector<const Candidate*>& trial, const AllanSolution& sol) {
  if (c.empty()) return 0.0;
  auto c1 = c;
  if (!cand.signal.empty()) {
    const auto cs = lowFrequencyCoefficients(cand.signal, w.lowFreq);
    for (std::size_t d = 0; d < c1.size() && d < cs.size(); ++d) c1[d] -= cs[d];
  }
  const double gain = lowFrequencyNll(c, v0, w.trendDof) - lowFrequencyNll(c1, lowFreqVarOf(w, trial, sol), w.trendDof);
  return cand.signal.empty() ? gain : std::max(0.0, gain);
}

/// Closed-form AVAR on the tau grid of the AR base re-estimated (Burg, its order) on the record
/// without w.removed and without `signal` (may be empty).
std::vector<double> refittedBaseAvar(const ChannelWork& w, const std::vector<double>& signal) {
  std::vector<double> x = *w.y;
  for (std::size_t k = 0; k < x.size(); ++k)
    x[k] -= (w.removed.empty() ? 0.0 : w.removed[k]) + (signal.empty() ? 0.0 : signal[k]);
  const auto ar = fit::burg(x, w.arOrder);
  return fit::arAllanVariance(ar.a, ar.drivingVariance, w.factors);
}

/// The problem of a trial: for an AR base and a candidate with a signal, the model's AVAR scaled
/// by what re-estimating the base on the record without the signal does to it (the base's free
/// parameters refitted: a base fitted to a record with a ramp is bent by it, and only the refit
/// shows how much of the misfit the ramp explains); otherwise the current problem. The trial
/// keeps the better of the two fits: a base given as the truth (not fitted to this record) is
/// not bent, and re-estimating it on the record without spikes would shrink it by their share.
AllanProblem trialProblem(const ChannelWork& w, const Candidate& c, std::vector<double>* trialAvar) {
  if (w.arOrder == 0 || c.signal.empty()) return w.prob;
  AllanProblem p = w.prob;
  const auto av = refittedBaseAvar(w, c.signal);
  for (std::size_t k = 0; k < p.mu.size(); ++k)
    if (w.baseAvar[k] > 0 && av[k] > 0) p.mu[k] *= av[k] / w.baseAvar[k];
  if (trialAvar) *trialAvar = av;
  return p;
}

/// The accepted candidates the Allan model holds: those without a signal (an accepted signal is
/// taken out of the record instead, remeasure()).
std::vector<const Candidate*> allanSet(const ChannelWork& w) {
  std::vector<const Candidate*> set;
  for (auto i : w.accepted)
    if (w.cands[i].signal.empty()) set.push_back(&w.cands[i]);
  return set;
}

constexpr double kJumpP = 1e-3;  // the jump test's level for the whole record (Bonferroni inside)

/// The level steps of the series x as a piecewise-constant series (empty: none): those of the
/// window-mean jump test (levelSteps), else the level shifts of the residual test (levelShift)
/// beyond the limit that keeps its scan of every sample at kJumpP (Bonferroni, 2 N Phi(-z) =
/// kJumpP), the largest first, each taken out before the next scan (at most maxPasses) -- a bias
/// step 1.5x the base's Allan deviation, or a telegraph's few switches, change few window means
/// by much but shift the level of the whole rest of the record. `modelAvar`: the current model's,
/// which with the record's own Allan variance sets the shift test's long-tau variance where the
/// record's AR is too short to (a slow Gauss-Markov the model has, a weak random walk it lacks:
/// neither is a step, and both wander over the long sums). On an
/// undithered lattice a one-level change is rounding (w.lattice).
std::vector<double> stepSeries(const ChannelWork& w, const std::vector<double>& x,
                               const std::vector<double>& modelAvar, int maxPasses = 8) {
  auto steps = levelSteps(x, w.factors, zFromTwoSidedP(kJumpP), w.lattice, maxPasses);
  if (!steps.empty()) return steps;
  const double zLimit = normalTwoSidedCritical(kJumpP / double(x.size()));
  std::vector<double> r = x;
  for (int pass = 0; pass < maxPasses; ++pass) {
    const auto s = levelShift(r, kLevelShiftOrder, zLimit, w.factors, modelAvar);
    if (!s || !(std::fabs(s->size) > 1.5 * w.lattice)) break;
    if (steps.empty()) steps.assign(x.size(), 0.0);
    for (std::size_t k = s->at; k < x.size(); ++k) steps[k] += s->size, r[k] -= s->size;
  }
  return steps;
}

/// The level steps of `steps` that the model's own noise does not make: at some factor m of the
/// grid that fits between the neighbouring steps, the means of the m samples after and before the
/// step differ by more than the model allows -- their difference's variance is twice the model's
/// Allan variance at m -- beyond the limit that keeps kJumpP over the ~N/m places a scan could pick
/// and the factors tried. The scans that find steps measure their scale on the record's short-tau
/// residuals; a walk the model holds wanders over the long sums by as much as a step (a white +
/// random-walk base against its exact model: an unexplained step on 13 of 240 clean channels, each
/// within 3.6 sigma of the model at every m), so what is left unexplained is judged by the model.
std::vector<LevelStep> beyondModelNoise(const std::vector<LevelStep>& steps, const std::vector<double>& x,
                                        double rate, const std::vector<std::size_t>& factors,
                                        const std::vector<double>& modelAvar) {
  const std::size_t N = x.size();
  std::vector<double> P(N + 1, 0.0);
  for (std::size_t k = 0; k < N; ++k) P[k + 1] = P[k] + x[k];
  auto mean = [&P](std::size_t a, std::size_t b) { return (P[b] - P[a]) / double(b - a); };
  std::vector<LevelStep> kept;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const auto at = std::size_t(std::llround(steps[i].time * rate));
    const std::size_t lo = i ? std::size_t(std::llround(steps[i - 1].time * rate)) : 0;
    const std::size_t hi = i + 1 < steps.size() ? std::size_t(std::llround(steps[i + 1].time * rate)) : N;
    bool beyond = false;
    for (std::size_t j = 0; j < factors.size() && j < modelAvar.size() && !beyond; ++j) {
      const std::size_t m = factors[j];
      if (!(at >= lo + m && at + m <= hi) || !(modelAvar[j] > 0)) continue;
      const double z = std::fabs(mean(at, at + m) - mean(at - m, at)) / std::sqrt(2.0 * modelAvar[j]);
      beyond = z > normalTwoSidedCritical(kJumpP / (double(N) / double(m) * double(factors.size())));
    }
    if (beyond) kept.push_back(steps[i]);
  }
  return kept;
}

/// ln AVAR of a series of this channel on its tau grid (the Allan problem's L).
std::vector<double> lnAvarOf(const ChannelWork& w, const std::vector<double>& x) {
  Setup s;
  s.rate = w.rate;
  s.n = x.size();
  s.factors = w.factors;
  auto av = allanVariance(x, s);
  for (auto& v : av) v = std::log(std::max(v, 1e-300));
  return av;
}

/// The series x without the stretches whose noise level departs (NoiseLevelChange::stretches),
/// the pieces joined; empty when there is no change, or when what is left is under half of x or
/// too short for the tau grid's longest factor. Every Allan shape can take part of a burst's
/// excess: a burst's contribution at long tau is a white's, beside a model sized to the quiet
/// level, and a ramp or a warm-up fitted to the long tau absorbs it. A drift the record holds is
/// in its quiet stretches as well (Candidate::slowShape).
std::vector<double> quietRecord(const ChannelWork& w, const std::vector<double>& x) {
  const auto& ch = w.d.noiseLevelChange;
  if (!ch || ch->stretches.empty() || w.factors.empty()) return {};
  std::vector<double> q;
  q.reserve(x.size());
  std::size_t from = 0;
  for (const auto& [a, b] : ch->stretches) {
    const auto lo = std::min(x.size(), std::size_t(std::max(0.0, std::floor(a * w.rate))));
    const auto hi = std::min(x.size(), std::size_t(std::max(0.0, std::ceil(b * w.rate))) + 1);
    if (lo > from) q.insert(q.end(), x.begin() + std::ptrdiff_t(from), x.begin() + std::ptrdiff_t(lo));
    from = std::max(from, hi);
  }
  if (from < x.size()) q.insert(q.end(), x.begin() + std::ptrdiff_t(from), x.end());
  if (2 * q.size() < x.size() || 2 * w.factors.back() + 1 > q.size()) return {};
  return q;
}

/// Sum of squared deviations from the mean of a piecewise-constant step series.
double spread(const std::vector<double>& s) {
  double m = 0, ss = 0;
  for (double v : s) m += v / double(s.size());
  for (double v : s) ss += (v - m) * (v - m);
  return ss;
}

/// The level steps of the series x (the record without the accepted signals) under the current
/// model: w.steps (stepSeries).
void findSteps(ChannelWork& w, const std::vector<double>& x) {
  w.steps = stepSeries(w, x, modelAvarOf(w.prob, allanSet(w), w.sol));
}

/// w.jumpFreeL, w.explainsJumps and w.ownJumpFreeL for the steps w.steps of the series x (the
/// record without the accepted signals). A level jump (a bias step, a telegraph switch, a
/// disturbance of the test stand) is what the bias_jumps candidate takes out, and every other
/// candidate's Allan shape can absorb part of its excess: a single step has exactly a random
/// walk's Allan variance, a telegraph's switches make a ramp's slope. So on a record with jumps a
/// candidate is credited only with what it explains on the record with the jumps taken out as well
/// (trialRound) -- unless its own signal takes them out (bias_jumps' does, whole). A signal that
/// takes most of them out (what its removal leaves of the steps' variance is less than half: a
/// settling the step test cut into pieces, beside the sensor's own blips) is credited on the record
/// without the steps that remain once it is taken out: the steps found on the record are then
/// mostly its own shape. (Every other candidate is judged on one record
/// without the same steps: on a record of its own, left with more excess, any Allan term could
/// gain more.)
void markJumps(ChannelWork& w, const std::vector<double>& x) {
  w.jumpFreeL.clear();
  w.lowFreqCoef = lowFrequencyCoefficients(x, w.lowFreq);
  w.jumpFreeCoef.clear();
  w.explainsJumps.assign(w.cands.size(), 0);
  w.ownJumpFreeL.assign(w.cands.size(), {});
  const auto quiet = quietRecord(w, x);
  w.quietL = quiet.empty() ? std::vector<double>{} : lnAvarOf(w, quiet);
  const auto modelAvar = modelAvarOf(w.prob, allanSet(w), w.sol);
  const auto& steps = w.steps;
  if (steps.empty()) return;
  std::vector<double> r(x.size());
  for (std::size_t k = 0; k < x.size(); ++k) r[k] = x[k] - steps[k];
  w.jumpFreeCoef = lowFrequencyCoefficients(r, w.lowFreq);
  w.jumpFreeL = lnAvarOf(w, r);
  const bool reverting = revertingSteps(jumpsOf(steps, w.rate));
  for (std::size_t i = 0; i < w.cands.size(); ++i) {
    const auto& sig = w.cands[i].signal;
    if (w.cands[i].switching && reverting) {
      w.explainsJumps[i] = 1;
      continue;
    }
    if (sig.size() != x.size()) continue;
    for (std::size_t k = 0; k < x.size(); ++k) r[k] = x[k] - sig[k];
    const auto left = stepSeries(w, r, modelAvar);
    w.explainsJumps[i] = left.empty();
    if (left.empty() || !(spread(left) < 0.5 * spread(steps))) continue;
    for (std::size_t k = 0; k < x.size(); ++k) r[k] = x[k] - left[k];
    w.ownJumpFreeL[i] = lnAvarOf(w, r);
  }
}

/// The measurement's ln AVAR recomputed on the record without the accepted signals (w.removed):
/// what is left for the next effect to explain. A deterministic effect enters the trials as its
/// Allan term beside the noise (their cross term neglected); once accepted it is subtracted, so
/// that a second, smaller effect is judged against the record without the first — not against
/// the first's Allan term, whose own estimation scatter (a sinusoid's or a spike train's at the
/// long tau) would hide it.
/// The candidates not accepted are proposed again on the same series (w.propose).
void remeasure(ChannelWork& w, Trials& t) {
  std::vector<double> x = *w.y;
  for (std::size_t k = 0; k < x.size(); ++k) x[k] -= w.removed[k];
  w.prob.L = lnAvarOf(w, x);
  findSteps(w, x);
  if (!w.propose) return markJumps(w, x);
  std::vector<Candidate> cands;
  for (auto i : w.accepted) cands.push_back(std::move(w.cands[i]));
  for (std::size_t j = 0; j < cands.size(); ++j) w.accepted[j] = j;
  std::vector<Line> lines;
  for (const auto& c : cands)
    if (c.line.frequency > 0) lines.push_back(c.line);
  for (auto& c : w.propose(x, w.taken, lines, w.steps)) cands.push_back(std::move(c));
  w.cands = std::move(cands);
  t.resize(w.cands.size());
  markJumps(w, x);
}

/// ModelNow::trendVarWith: the current set refitted to the series of AVAR `avar`, alone and with
/// each Gaussian candidate (no signal) whose effect is not taken, the best by the penalised
/// criterion; its trend scatter.
TrendScatter trendVarWithNoise(const ChannelWork& w, const std::vector<const Candidate*>& set,
                               const std::set<std::string>& taken, double penalty, const std::vector<double>& avar) {
  AllanProblem p = w.prob;
  for (std::size_t k = 0; k < p.L.size() && k < avar.size(); ++k) p.L[k] = std::log(std::max(avar[k], 1e-300));
  auto sol = solveAllan(p, set, w.sol.theta);
  double bestCrit = sol.chi2;
  TrendScatter bestVar = currentTrendVar(w, set, sol);
  auto start = w.sol.theta;
  start.push_back(-1.0);
  for (const auto& c : w.cands) {
    if (!c.signal.empty() || taken.count(c.effect)) continue;
    auto trial = set;
    trial.push_back(&c);
    const auto s = solveAllan(p, trial, start);
    const double crit = s.chi2 + penalty * double(c.parameters);
    if (crit < bestCrit) {
      bestCrit = crit, bestVar = currentTrendVar(w, trial, s);
      const double theta = c.freeSize ? s.theta.back() : 1.0;
      bestVar.fittedAvar = c.g;
      for (double& v : bestVar.fittedAvar) v *= theta;
    }
  }
  return bestVar;
}

/// Whether candidate i may still be tried: not accepted, and its effect accepted fewer times than
/// it may be (Candidate::maxAccepted).
bool stillOpen(const ChannelWork& w, std::size_t i) {
  std::size_t same = 0;
  for (auto a : w.accepted) {
    if (a == i) return false;
    same += w.cands[a].effect == w.cands[i].effect;
  }
  return same < w.cands[i].maxAccepted;
}

/// Tolerance of the quiet stretches' level, in sd of the realisations' ln medians.
constexpr double kQuietSd = 3.0;

/// Whether stationary noise candidate c, at its trial fit `sol` as the last of `trial`, stands in
/// for a change of the channel's noise level (AxisDiagnosis::noiseLevelChange): a noise fitted to
/// the whole record averages a burst into every stretch (alone, or with the level s raised beside
/// it), and the trial model's Allan variance at the shortest tau then exceeds what the record's
/// quiet stretches show. In units of the model's AVAR mu there: the trial raises the model from
/// the current fit's (`now` [SI^2]) by d, and the quiet stretches show Q = quiet^2
/// (noise_level.hpp). It stands in when d > 2 (Q - now) + tolerance, i.e. when the quiet stretches hold less than half
/// of the rise -- unless they are themselves above the model at its stated level (1 and the
/// findings taken, r) by more than that level is taken to be known (Q > r e^kLevelLnSd, a factor
/// 1.5): a noise the model lacks in every stretch, beside the change (against a fit of another
/// run the quiet stretches of real windows were 2-17 % above; a white the model lacks by 1.5-3x
/// in Allan deviation is 2.25-9x). Signals (a line, a ramp) are not judged so, nor a noise with
/// a test of its own (a rounding whose lattice the values show: on the alt generator's channel
/// of a hidden quantization with outliers the flip rate on a lattice ~2x the noise read as a
/// change of level, and the rounding was withheld).
bool standsInForChange(const ChannelWork& w, const std::vector<const Candidate*>& trial, const AllanSolution& sol,
                       double now) {
  const auto& ch = w.d.noiseLevelChange;
  const Candidate& c = *trial.back();
  if (!ch || !c.signal.empty() || c.zSpecial > 0 || c.g.empty() || w.prob.mu.empty() || sol.theta.empty() ||
      !(w.prob.mu[0] > 0))
    return false;
  const double mu = w.prob.mu[0];
  const double total = modelAvarOf(w.prob, trial, sol)[0] / mu;
  now /= mu;
  const double r = 1.0 + total - sol.s - sol.theta.back() * c.g[0] / mu;
  const double q2 = ch->quiet * ch->quiet;
  if (q2 > r * std::exp(kLevelLnSd)) return false;
  return total - now > 2.0 * (q2 - now) + 4.0 * kQuietSd * ch->quietLnSd * q2;
}

/// Whether candidate i may be named: still open, and at its last trial no stand-in for a change
/// of the noise level (standsInForChange); such a one is shown among the candidates.
bool nameable(const ChannelWork& w, const Trials& t, std::size_t i) {
  return stillOpen(w, i) && !t.standIn[i];
}

/// Trial of every candidate still open (stillOpen: its effect not accepted yet, or one more line):
/// added to the current set, the level and every free size refitted; drop = chi2 before - chi2
/// after + own evidence - penalty x parameters. On a record with jumps, the smaller of that drop and the same on the record without
/// its jumps (markJumps), unless the candidate's signal takes the jumps out. Returns the best, or
/// -1 when none is left.
std::ptrdiff_t trialRound(const ChannelWork& w, double penalty, Trials& t, const std::string& only = "") {
  std::set<std::string> taken;
  for (auto i : w.accepted) taken.insert(w.cands[i].effect);
  const auto set = allanSet(w);
  std::ptrdiff_t best = -1;
  const auto currentAvar = modelAvarOf(w.prob, set, w.sol);
  const TrendScatter trendNow = currentTrendVar(w, set, w.sol);
  ModelNow now{currentAvar, trendNow.var(), satterthwaiteDof(trendNow.realised, trendNow.realisedDof, trendNow.known),
               nullptr};
  now.trendVarWith = [&](const std::vector<double>& avar) { return trendVarWithNoise(w, set, taken, penalty, avar); };
  AllanProblem jumpFree = w.prob;
  double chi2JumpFree = 0;
  AllanSolution jumpFreeSol;
  if (!w.jumpFreeL.empty()) {
    jumpFree.L = w.jumpFreeL;
    jumpFreeSol = solveAllan(jumpFree, set, w.sol.theta);
    chi2JumpFree = jumpFreeSol.chi2;
  }
  AllanProblem quiet = w.prob;
  double chi2Quiet = 0;
  if (!w.quietL.empty()) {
    quiet.L = w.quietL;
    chi2Quiet = solveAllan(quiet, set, w.sol.theta).chi2;
  }
  const auto v0 = lowFreqVarOf(w, set, w.sol);
  for (std::size_t i = 0; i < w.cands.size(); ++i) {
    if (!stillOpen(w, i) || !(only.empty() || w.cands[i].effect == only)) continue;
    auto trial = set;
    trial.push_back(&w.cands[i]);
    auto start = w.sol.theta;
    start.push_back(-1.0);
    t.sol[i] = solveAllan(w.prob, trial, start);
    t.refit[i] = 0;
    AllanProblem refitProblem;
    if (w.arOrder > 0 && !w.cands[i].signal.empty()) {
      refitProblem = trialProblem(w, w.cands[i], nullptr);
      auto refitted = solveAllan(refitProblem, trial, start);
      if (refitted.chi2 < t.sol[i].chi2) t.sol[i] = std::move(refitted), t.refit[i] = 1;
    }
    const double own = ownEvidence(w.cands[i], now) - penalty * double(w.cands[i].parameters);
    t.drop[i] = w.sol.chi2 - t.sol[i].chi2 + own + lowFreqGain(w, w.lowFreqCoef, v0, w.cands[i], trial, t.sol[i]);
    if (!w.jumpFreeL.empty() && !w.explainsJumps[i]) {
      AllanProblem p = t.refit[i] ? refitProblem : jumpFree;
      const auto& ownL = w.ownJumpFreeL[i];
      double before = chi2JumpFree;
      if (!ownL.empty()) {  // the record without the steps its signal leaves (markJumps)
        AllanProblem b = jumpFree;
        b.L = ownL;
        before = solveAllan(b, set, w.sol.theta).chi2;
      }
      p.L = ownL.empty() ? w.jumpFreeL : ownL;
      const auto jf = solveAllan(p, trial, start);
      // A signal's coefficients are not taken out of the record without steps: the steps may
      // already hold part of it (a warm-up's start); there it is credited by the Allan terms alone.
      const double gain = w.cands[i].signal.empty()
                              ? lowFreqGain(w, w.jumpFreeCoef, lowFreqVarOf(w, set, jumpFreeSol), w.cands[i], trial, jf)
                              : 0.0;
      t.drop[i] = std::min(t.drop[i], before - jf.chi2 + own + gain);
    }
    if (!w.quietL.empty() && w.cands[i].slowShape) {  // a drift: seen where the noise is quiet too
      AllanProblem p = t.refit[i] ? refitProblem : quiet;
      p.L = w.quietL;
      t.drop[i] = std::min(t.drop[i], chi2Quiet - solveAllan(p, trial, start).chi2 + own);
    }
    t.score[i] = std::min(kMaxScore, std::sqrt(std::max(0.0, t.drop[i])));
    t.standIn[i] = standsInForChange(w, trial, t.sol[i], currentAvar.empty() ? 0.0 : currentAvar[0]);
    if (nameable(w, t, i) && (best < 0 || t.drop[i] > t.drop[std::size_t(best)])) best = std::ptrdiff_t(i);
  }
  return best;
}

/// Accepts candidate `best` of the last trial round: added to the set at its trial's fit; a signal
/// is taken out of the record (and an AR base refitted without it) and the candidates proposed
/// again on what is left (remeasure). Returns its finding.
Finding accept(ChannelWork& w, Trials& t, std::size_t best) {
  Finding f;
  f.effect = w.cands[best].effect;
  f.score = t.score[best];
  f.drop = t.drop[best];
  f.reported = true;
  const Candidate& c = w.cands[best];
  w.accepted.push_back(best);
  w.sol = t.sol[best];
  if (c.roundedRealisations && w.rounded.W.size() > 0) {
    // The rounded model's Allan estimates scatter as its rounded realisations' do (more where
    // few samples leave their cell): later trials are weighed with that scatter.
    w.prob.W = w.rounded.W;
    w.prob.bias = w.rounded.bias;
    w.sol = solveAllan(w.prob, allanSet(w), w.sol.theta);
  }
  // c refers into w.cands, which remeasure() replaces: not used after it.
  if (!c.signal.empty()) {  // taken out of the record (and the AR base refitted without it)
    if (w.arOrder > 0) {
      std::vector<double> av;
      const auto refitted = trialProblem(w, c, &av);
      if (t.refit[best]) w.prob = refitted;
      w.baseAvar = av;  // later refits scale the model by their change from this one
    }
    w.removed.resize(c.signal.size(), 0.0);
    for (std::size_t k = 0; k < c.signal.size(); ++k) w.removed[k] += c.signal[k];
    w.taken.insert(w.taken.end(), c.basis.begin(), c.basis.end());
    remeasure(w, t);
    auto start = w.sol.theta;
    start.pop_back();
    w.sol = solveAllan(w.prob, allanSet(w), start);
  }
  return f;
}

/// Whether the temperature candidate `temp`, which passed `threshold` in the last full trial round,
/// only imitates a noise or a ramp of that round that passed it too: that candidate x still passes
/// `next` with the temperature taken, while the temperature does not pass `next` with x taken. A
/// temperature column that no drift follows (a chamber's cycle, the room's wander) correlates by
/// chance with a walk's or a flicker's realised wander, and its fitted polynomial takes part of
/// that wander out of the record: alone it passes, beside the noise it imitates it does not. A
/// column that rises or falls through the record (a chamber's ramp between holds) imitates a
/// ramp the same way, but only in part: its polynomial in the temperature leaves the ramp's
/// straight line in time to a ramp. Where neither passes beside the other the temperature keeps
/// its place ("regress on it first"), and so it does against a warm-up, a thermal settling's own
/// shape (with warm-ups too a warm-up took a ramp and a thermal drift together). Each candidate
/// is tried by its best variant, the largest drop first.
bool temperatureImitates(const ChannelWork& w, double penalty, const Trials& t, std::size_t temp, double threshold,
                         double next) {
  std::vector<std::size_t> others;  // the best variant of each other effect that passes
  for (std::size_t i = 0; i < w.cands.size(); ++i) {
    const bool noise = w.cands[i].signal.empty(), ramp = w.cands[i].effect == "ramp";
    if (!nameable(w, t, i) || !(noise || ramp) || t.drop[i] < threshold * threshold) continue;
    auto same = std::find_if(others.begin(), others.end(), [&](std::size_t j) { return w.cands[j].effect == w.cands[i].effect; });
    if (same == others.end()) others.push_back(i);
    else if (t.drop[i] > t.drop[*same]) *same = i;
  }
  std::sort(others.begin(), others.end(), [&](std::size_t a, std::size_t b) { return t.drop[a] > t.drop[b]; });
  std::optional<ChannelWork> withT;
  Trials tt;
  for (std::size_t x : others) {
    ChannelWork withX = w;
    Trials tx = t;
    accept(withX, tx, x);
    const std::ptrdiff_t tempBesideX = trialRound(withX, penalty, tx, "temperature");
    if (tempBesideX >= 0 && tx.drop[std::size_t(tempBesideX)] >= next * next) continue;
    if (!withT) withT = w, tt = t, accept(*withT, tt, temp);
    const std::ptrdiff_t xBesideT = trialRound(*withT, penalty, tt, w.cands[x].effect);
    if (xBesideT >= 0 && tt.drop[std::size_t(xBesideT)] >= next * next) return true;
  }
  return false;
}

/// Whether a candidate has a shape a thermal drift can take in time, and so may only imitate the
/// temperature: the smooth ones (a warm-up, a ramp, the slow noises). A level step, a line,
/// spikes, a lattice or white noise are no drift's shape: where one of them explains more than the
/// temperature it is taken first, and the temperature is tried on what it leaves (a bias step
/// under a warming chamber: the temperature's polynomial took part of the step, a walk the rest).
bool thermalShape(const Candidate& c) {
  static const char* const kNot[] = {"bias_jumps", "sinusoid", "outliers", "quantization", "white"};
  return std::none_of(std::begin(kNot), std::end(kNot), [&](const char* e) { return c.effect == e; });
}

/// The open candidate of the largest drop in the last trial round whose effect is (`is`) or is not
/// `effect`; -1 when there is none.
std::ptrdiff_t bestOpen(const ChannelWork& w, const Trials& t, const std::string& effect, bool is) {
  std::ptrdiff_t x = -1;
  for (std::size_t i = 0; i < w.cands.size(); ++i)
    if (nameable(w, t, i) && (w.cands[i].effect == effect) == is && (x < 0 || t.drop[i] > t.drop[std::size_t(x)]))
      x = std::ptrdiff_t(i);
  return x;
}

/// One finding per effect still open (its best variant; a further line of a sinusoid), by score.
std::vector<Finding> otherFindings(const ChannelWork& w, const Trials& t) {
  std::vector<Finding> rest;
  for (std::size_t i = 0; i < w.cands.size(); ++i) {
    if (!stillOpen(w, i)) continue;
    Finding f;
    f.effect = w.cands[i].effect;
    f.evidence = w.cands[i].evidence;
    f.score = t.score[i];
    f.drop = t.drop[i];
    w.cands[i].describe(t.sol[i].theta.empty() ? 0.0 : t.sol[i].theta.back(), f);
    auto it = std::find_if(rest.begin(), rest.end(), [&](const Finding& g) { return g.effect == f.effect; });
    if (it == rest.end()) rest.push_back(f);
    else if (f.drop > it->drop) *it = f;
  }
  std::stable_sort(rest.begin(), rest.end(), [](const Finding& a, const Finding& b) { return a.drop > b.drop; });
  return rest;
}

/// The longest run of tau points (>= 2) whose residual under the final fit lies beyond the 99 %
/// two-sided limit of its own estimation scatter on one side, when the remaining chi2 exceeds its
/// 0.999 quantile: what no candidate explained.
std::optional<FailRange> unexplainedRange(const ChannelWork& w, const std::vector<const Candidate*>& set) {
  const std::size_t K = w.prob.L.size();
  if (K < 3 || !(w.sol.chi2 > chiSquareQuantile(0.999, double(K)))) return std::nullopt;
  const Eigen::VectorXd var = w.prob.W.inverse().diagonal();
  const auto M = modelAvarOf(w.prob, set, w.sol);
  std::vector<double> r(K);
  std::vector<int> side(K, 0);
  for (std::size_t k = 0; k < K; ++k) {
    r[k] = w.prob.L[k] - w.prob.bias[k] - std::log(std::max(M[k], 1e-300));
    const double z = r[k] / std::sqrt(std::max(var[Eigen::Index(k)], 1e-300));
    side[k] = z > 2.576 ? 1 : (z < -2.576 ? -1 : 0);
  }
  std::optional<FailRange> best;
  for (std::size_t a = 0; a < K;) {
    std::size_t b = a;
    while (b < K && side[b] != 0 && side[b] == side[a]) ++b;
    if (b - a >= 2 && (!best || b - a > best->points)) {
      FailRange f;
      f.statistic = "adev";
      f.from = w.d.adev.x[a], f.to = w.d.adev.x[b - 1];
      f.direction = side[a];
      f.points = b - a;
      for (std::size_t k = a; k < b; ++k) {
        const double ratio = std::exp(0.5 * r[k]);  // of the deviations
        if (std::fabs(std::log(ratio)) > std::fabs(std::log(f.worstRatio))) f.worstRatio = ratio;
      }
      best = f;
    }
    a = b > a ? b : a + 1;
  }
  return best;
}


/// The accepted signals sized as one joint fit: a signal fitted beside earlier ones has its
/// joint size (Candidate::stated), and each earlier one with regressors is fitted again on the
/// record without the others as stated (one backfitting pass), so that the sizes reported and
/// added hold the shape they share once -- not a ramp's likeness to a thermal drift in both.
void restateSignals(ChannelWork& w) {
  std::vector<std::size_t> sig;
  bool joint = false;
  for (auto i : w.accepted)
    if (!w.cands[i].signal.empty()) sig.push_back(i), joint = joint || !w.cands[i].stated.empty();
  if (!joint || !w.propose) return;
  for (std::size_t a = 0; a + 1 < sig.size(); ++a) {
    Candidate& c = w.cands[sig[a]];
    if (c.basis.empty()) continue;
    std::vector<double> x = *w.y;
    for (auto i : sig) {
      if (i == sig[a]) continue;
      const auto& s = w.cands[i].statedSignal();
      for (std::size_t k = 0; k < x.size() && k < s.size(); ++k) x[k] -= s[k];
    }
    for (auto& n : w.propose(x, {}, {}, {}))
      if (n.effect == c.effect && n.parameters == c.parameters) {
        // The evidence is the record's alone (a ramp's "least-squares trend"); a size that the
        // joint fit changed says so, or a ramp read "R = 168 deg/h^2 ... least-squares trend
        // 5391 deg/h^2" with no word why (bench/blind_probe/long60).
        Finding alone, joint;
        c.describe(0.0, alone);
        n.describe(0.0, joint);
        if (alone.size != joint.size)
          c.evidence += "; sized jointly with the other signals found (alone: " + alone.size + ")";
        c.describe = std::move(n.describe);
        c.stated = std::move(n.signal);
        break;
      }
  }
}

/// Backward step of the selection: the accepted noise (a candidate without a signal) whose removal
/// from the final set raises the criterion least -- its Allan chi-square rise with the set
/// refitted and that of the slow coefficients (lowFreqGain), plus its own evidence, less its
/// penalty -- is dropped when that rise is negative (the term no longer pays for its parameters),
/// and so on until every noise left does. A term taken early can be made redundant by the effects
/// taken after it (a Gauss-Markov hump fitted to a warm-up's Allan variance before the warm-up
/// itself was tried): kept, it is a finding of size zero, and the wrong name first. Only a term
/// that explains nothing beside the others is dropped: of two that share an excess, the one the
/// forward step took first is kept (dropping the one of the smaller rise instead, down to the
/// entry threshold, lost true partners on the challenge benchmark). A dropped term is listed with
/// the others not reported, its drop the (negative) rise. Signals are not dropped: they are taken
/// out of the record, and each was tried on the record without the ones before it.
void dropRedundant(ChannelWork& w, double penalty, Trials& t, std::vector<Finding>& findings) {
  for (;;) {
    const auto set = allanSet(w);
    std::ptrdiff_t worst = -1;  // position in w.accepted
    double worstLoss = 0.0;
    AllanSolution worstSol;
    for (std::size_t j = 0, a = 0; j < w.accepted.size(); ++j) {
      const Candidate& c = w.cands[w.accepted[j]];
      if (!c.signal.empty()) continue;
      std::vector<const Candidate*> reduced;
      std::vector<double> start;
      for (std::size_t b = 0; b < set.size(); ++b)
        if (b != a) reduced.push_back(set[b]), start.push_back(w.sol.theta[b]);
      ++a;
      auto sol = solveAllan(w.prob, reduced, start);
      // the trial's drop of c added to the set without it (trialRound), with c in the set as it is
      const double loss = sol.chi2 - w.sol.chi2 + lowFreqGain(w, w.lowFreqCoef, lowFreqVarOf(w, reduced, sol), c, set, w.sol) +
                          c.zSpecial * c.zSpecial - penalty * double(c.parameters);
      if (loss < worstLoss) worstLoss = loss, worst = std::ptrdiff_t(j), worstSol = std::move(sol);
    }
    if (worst < 0) return;
    const std::size_t i = w.accepted[std::size_t(worst)];
    t.drop[i] = worstLoss, t.score[i] = 0.0;
    w.accepted.erase(w.accepted.begin() + worst);
    findings.erase(findings.begin() + worst);
    w.sol = std::move(worstSol);
  }
}

}  // namespace

double criterionPenalty(std::size_t points) { return std::log(double(std::max<std::size_t>(points, 2))); }

void selectFindings(ChannelWork& w, double first, double next) {
  AxisDiagnosis& d = w.d;
  const double penalty = criterionPenalty(w.prob.L.size());
  const std::vector<double> measured = w.prob.L;
  w.sol = solveAllan(w.prob, {});
  if (w.arOrder > 0) w.baseAvar = refittedBaseAvar(w, {});
  findSteps(w, *w.y);
  if (w.propose) w.cands = w.propose(*w.y, {}, {}, w.steps);
  markJumps(w, *w.y);
  Trials t;
  t.resize(w.cands.size());
  // With a temperature column the temperature is taken first in every round (issue 12: "regress
  // on it first"): a thermal drift has the shape of the record's temperature in time, which a
  // warm-up, a ramp or a random walk can imitate; when the temperature passes the threshold it is
  // taken before them, and they are tried on what it leaves -- unless it only imitates a noise
  // that passes too (temperatureImitates: a column no drift follows); the round then takes the
  // best other candidate. A candidate of no thermal shape (thermalShape) that explains more is
  // taken before it. A round after an accepted signal tries it again on the record without
  // that signal (spikes hide a thermal drift).
  for (;;) {
    const double threshold = w.accepted.empty() ? first : next;
    std::ptrdiff_t best = trialRound(w, penalty, t);
    const std::ptrdiff_t temp = bestOpen(w, t, "temperature", true);
    const bool tempPasses = temp >= 0 && t.drop[std::size_t(temp)] >= threshold * threshold;
    const bool shapeAhead = tempPasses && best >= 0 && !thermalShape(w.cands[std::size_t(best)]) &&
                            t.drop[std::size_t(best)] > t.drop[std::size_t(temp)];
    if (tempPasses && !shapeAhead)
      best = temperatureImitates(w, penalty, t, std::size_t(temp), threshold, next)
                 ? bestOpen(w, t, "temperature", false)
                 : temp;
    if (best < 0 || t.drop[std::size_t(best)] < threshold * threshold) break;
    d.findings.push_back(accept(w, t, std::size_t(best)));
  }
  dropRedundant(w, penalty, t, d.findings);
  restateSignals(w);
  // Sizes of the reported ones from the final joint fit (an accepted signal has its own size).
  // Steps that go back and forth are the realisation of an accepted switching process: no longer
  // unexplained, they are its evidence.
  const auto set = allanSet(w);
  // those the record without the accepted signals shows (none unexplained where the model makes
  // bias jumps itself)
  auto steps = w.modelJumps ? std::vector<LevelStep>{} : jumpsOf(w.steps, w.rate);
  const bool reverting = revertingSteps(steps);
  if (!reverting && !steps.empty()) {  // the switching of a process found stays its evidence
    std::vector<double> x = *w.y;
    for (std::size_t k = 0; k < x.size() && k < w.removed.size(); ++k) x[k] -= w.removed[k];
    steps = beyondModelNoise(steps, x, w.rate, w.factors, modelAvarOf(w.prob, set, w.sol));
  }
  bool switched = false;
  for (std::size_t j = 0, a = 0; j < w.accepted.size(); ++j) {
    const auto& cand = w.cands[w.accepted[j]];
    Finding& f = d.findings[j];
    f.evidence = cand.evidence;
    if (cand.switching && reverting) {
      switched = true;
      f.evidence += "; the level switches back and forth (" + std::to_string(steps.size()) + " steps)";
    }
    cand.describe(cand.signal.empty() ? w.sol.theta[a++] : 1.0, f);
  }
  d.noiseScale = w.sol.s;
  d.chi2Selected = w.sol.chi2;
  d.unexplained = unexplainedRange(w, set);
  (switched ? d.switchingSteps : d.unexplainedSteps) = std::move(steps);
  if (d.noiseLevelChange) {  // the noises the last round would have named but for the change
    auto& av = d.noiseLevelChange->averaged;
    const double threshold = w.accepted.empty() ? first : next;
    for (std::size_t i = 0; i < w.cands.size(); ++i)
      if (stillOpen(w, i) && t.standIn[i] && t.drop[i] >= threshold * threshold &&
          std::find(av.begin(), av.end(), w.cands[i].effect) == av.end())
        av.push_back(w.cands[i].effect);
  }
  for (auto& f : otherFindings(w, t)) d.findings.push_back(f);
  w.prob.L = measured;  // improve() sizes the wanted effects against the record as measured
}

}  // namespace sinsim::errormodels::diagnose::detail
