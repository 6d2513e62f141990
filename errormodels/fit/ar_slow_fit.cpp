#include "errormodels/fit/ar_slow_fit.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/error.hpp"
#include "errormodels/fit/composite_fit.hpp"
#include "errormodels/stats/spectrum.hpp"

namespace sinsim::errormodels::fit {

std::vector<LatentTermSet> arSlowCandidateSets(bool gm, bool randomWalk, bool flicker) {
  std::vector<LatentTermSet> out;
  for (int g = 0; g <= int(gm); ++g)
    for (int k = 0; k <= int(randomWalk); ++k)
      for (int b = 0; b <= int(flicker); ++b) {
        LatentTermSet s;
        s.white = false;
        s.ar = true;
        s.gm = g;
        s.randomWalk = k == 1;
        s.flicker = b == 1;
        out.push_back(s);
      }
  return out;
}

namespace {

/// x minus its level from the steady-state RTS local-level smoother (composite_fit.hpp) with
/// var(w) / var(v) = q / r.
std::vector<double> minusLevel(const std::vector<double>& x, double q, double r) {
  const std::vector<double> level = localLevelSmoother(x, q, r);
  std::vector<double> u(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) u[i] = x[i] - level[i];
  return u;
}

/// Whether the model has a slow term (GM, random walk or flicker) beside its AR.
bool hasSlowTerm(const LatentModel& m) { return !m.gm.empty() || m.randomWalk > 0.0 || m.flicker > 0.0; }

/// x with the model's GM, walk and flicker filtered out so that what is left has, under the model,
/// the spectrum of the rest alone (the AR and any white or quantization): every cosine of x's even
/// extension (stats/spectrum.hpp zeroPhaseFiltered) scaled by sqrt(S_rest / (S_rest + S_slow)),
/// the two parts' PSDs (latent_model.hpp LatentSpectrum). Where a slow term is weak the record is
/// left as it is; where it dominates, its power is taken out, which Burg would otherwise carry as
/// the AR's low-frequency level. (The Wiener estimate's residual, gain S_rest / (S_rest + S_slow),
/// takes out more: its spectrum is S_rest^2 / (S_rest + S_slow), below the AR's wherever the slow
/// terms act, and Burg's AR on it is too low there.) The mean (w = 0) is taken out.
std::vector<double> slowTermsFilteredOut(const std::vector<double>& x, const LatentModel& model, double dt) {
  LatentModel slow, rest = model;
  slow.gm = model.gm, slow.randomWalk = model.randomWalk, slow.flicker = model.flicker;
  rest.gm.clear(), rest.randomWalk = 0.0, rest.flicker = 0.0, rest.drift = 0.0;
  const LatentSpectrum sSlow(slow, dt), sRest(rest, dt);
  return zeroPhaseFiltered(x, [&](double w) {
    if (w == 0.0) return 0.0;
    const double a = sSlow(w), b = sRest(w);
    return a + b > 0.0 ? std::sqrt(b / (a + b)) : 1.0;
  });
}

/// The tau [s] of the last interior local minimum of the record's ADEV c, where a rise at long tau
/// begins: one that lasts, the longest tau above the minimum (0: none, no rise at long tau). The
/// global minimum can be m = 1: a positively correlated AR's ADEV first rises to its hump. A hump
/// that falls again is the AR's (or a GM's) own, not a walk's rise: the minimum before it no level.
double levelMinimumTau(const LatentAllanPoints& c) {
  std::size_t iMin = 0;
  for (std::size_t i = 1; i + 1 < c.dev.size(); ++i)
    if (c.dev[i] < c.dev[i - 1] && c.dev[i] < c.dev[i + 1]) iMin = i;
  return iMin == 0 || !(c.dev.back() > c.dev[iMin]) ? 0.0 : c.tau[iMin];
}

}  // namespace

ArSlowFit fitArPlusSlow(const std::vector<double>& x, const ArSlowFitOptions& options) {
  const double dt = options.sampleInterval;
  if (!(std::isfinite(dt) && dt > 0.0)) throw InputError("AR + slow terms fit: sample interval must be > 0");
  if (!(std::isfinite(options.slowGmMinTc) && options.slowGmMinTc > 0.0))
    throw InputError("AR + slow terms fit: slowGmMinTc must be > 0");
  const LatentAllanPoints c = latentAllanPoints(x, dt);

  OrderSelectionOptions os = options.order;
  os.sampleInterval = dt;
  LatentFitOptions lo;
  lo.sampleInterval = dt;
  lo.candidates = arSlowCandidateSets(options.gm, options.randomWalk, options.flicker);
  lo.scanStart = options.scanStart;
  lo.penaltyPerTerm = options.penaltyPerTerm;
  lo.penaltyPerParameter = options.penaltyPerParameter;
  auto burg = [&](const std::vector<double>& series, ArSlowFit& out) {
    out.ar = selectArOrder(series, os);
    try {
      out.arCorrelationTime = arCorrelationTime(out.ar.fit.a, dt);
    } catch (const InputError& e) {
      throw InputError(std::string("AR + slow terms fit: the Burg AR has a pole at ~1 (") + e.text() +
                       "): a slow process rides inside the AR; try --kind latent");
    }
  };
  auto joint = [&](ArSlowFit& out) {
    lo.arPolynomial = out.ar.fit.a;
    lo.arVarianceMax = out.ar.fit.drivingVariance;
    lo.minGmTauSamples = std::max(options.slowGmMinTc * out.arCorrelationTime / dt, 0.5);
    out.joint = fitLatentModel(c.m, c.avar, x.size(), lo);
  };
  auto jointWith = [&](const std::vector<double>& series, ArSlowFit& out) {
    burg(series, out);
    joint(out);
  };

  // The first Burg fit sees the record minus a level smoothed at that minimum (gain dt / tau_min),
  // so that a strong random walk does not pull an AR pole to 1 (the walk would then ride as a slow
  // AR mode, hidden from the slow terms) -- for a rise that lasts (levelMinimumTau) and where the
  // smoother stays much slower than the AR it leaves (tau_min >= slowGmMinTc T_c, the rule of the
  // rounds below). An oscillating AR's ADEV has a minimum of its own a few samples in, white noise
  // beside a slow AR pole one before the AR's hump: smoothed there, Burg saw the record high-passed
  // and wrote an AR(20) 2.3x the record at one sample (challenge null records, docs/fitting.md).
  // Only Burg decides which series; the joint fit runs once, on the one kept.
  ArSlowFit out;
  const double tauMin = levelMinimumTau(c);
  bool smoothed = false;
  if (tauMin > 0.0) {
    const double g = dt / tauMin;
    burg(minusLevel(x, g * g, 1.0), out);
    smoothed = tauMin >= options.slowGmMinTc * out.arCorrelationTime;
  }
  if (!smoothed) {
    try {
      ArSlowFit raw;
      burg(x, raw);
      out = std::move(raw);
    } catch (const InputError&) {
      if (tauMin == 0.0) throw;  // a pole at ~1 in the record itself, and no level to take out
    }
  }
  joint(out);
  // Then, while a random walk is selected: Burg on the record minus the walk's level smoothed
  // with the fitted model (q = K^2 dt, r = the AR's long-tau white variance per sample
  // E / A(1)^2), the joint fit again; at most 3 rounds, until the chosen set repeats. Only the
  // walk: it is what pulls a Burg pole to 1. A GM (tau >= 10 T_c, stationary) is left to the
  // joint fit; removing its level with this random-walk smoother took AR power with it (40 seeds,
  // docs/fitting.md: gm1.tau covered 35/40 with that step, 40/40 without).
  for (int round = 0; round < 3; ++round) {
    const double q = out.joint.model.randomWalk * out.joint.model.randomWalk * dt;
    if (!(q > 0.0)) break;
    const double r = arLongRunVariance(out.joint.model.arPolynomial, out.joint.model.arVariance);
    // The smoother must stay much slower than the AR (else it eats the AR's correlation): its
    // time constant dt / g >= slowGmMinTc T_c, g ~ sqrt(q / r).
    if (!(dt / std::sqrt(q / r) >= options.slowGmMinTc * out.arCorrelationTime)) break;
    ArSlowFit next;
    jointWith(minusLevel(x, q, r), next);
    const bool same = next.joint.terms == out.joint.terms;
    out = std::move(next);
    if (same) break;
  }
  // Then, where the joint fit leaves the model off the record below a scanned start
  // (offBelowStart, the fit's warning) with a slow term selected, once: Burg on the record with the
  // fitted model's slow terms filtered out (slowTermsFilteredOut), the joint fit again. A GM or a
  // flicker raises the AR's low-frequency level E / A(1)^2, which a joint fit from a later start
  // can lower only with E, and so the AR's whole spectrum (ADIS16405 run 2 ax: the model 0.61x the
  // record's ADEV at one sample). Kept only with the same terms and no further from the record at
  // its worst point, fitted or below the start (worstAdevLogRatio): the filter takes the slow
  // terms' power out of what Burg sees, so a term it removed would be needed again by construction
  // (as rounds, with the Wiener residual: AR(2) + walk records read as AR + GM + walk, the right
  // set 92 -> 27 of 100). Only there: on every record the AR(2) + GM / walk study's 2-sigma
  // coverage of the GM tau and the AR sigma fell (100 -> 98, 91 -> 85 of the right sets).
  if (hasSlowTerm(out.joint.model) && offBelowStart(out.joint)) {
    ArSlowFit next;
    jointWith(slowTermsFilteredOut(x, out.joint.model, dt), next);
    if (next.joint.terms == out.joint.terms && worstAdevLogRatio(next.joint) <= worstAdevLogRatio(out.joint))
      out = std::move(next);
  }
  if (out.joint.terms == arSlowCandidateSets(false, false, false).front()) {
    // AR alone (no slow term): the paper's AR, Burg on the record itself.
    ArSlowFit raw;
    jointWith(x, raw);
    if (raw.joint.terms == out.joint.terms) out = std::move(raw);
  }
  out.arOnlyAvar = arAllanVariance(out.ar.fit.a, out.ar.fit.drivingVariance, out.joint.m);
  return out;
}

}  // namespace sinsim::errormodels::fit
