// The `auto` kind of the identify pipeline (identify_auto.hpp).
#include "errormodels/identify_auto.hpp"

#include <algorithm>
#include <string>

#include "common/error.hpp"
#include "common/number_text.hpp"
#include "errormodels/fit/ar_fit.hpp"
#include "errormodels/fit/latent_fit.hpp"

namespace sinsim::errormodels::detail {
namespace {

/// Prediction gain r0 / E_p of an AR fit (>= 1; 1 for white noise).
double predictionGain(const fit::ArFit& f) {
  return f.drivingVariancePath.empty() || !(f.drivingVariance > 0.0)
             ? 1.0
             : f.drivingVariancePath.front() / f.drivingVariance;
}

}  // namespace

/// Auto (the rule, stated once here and in docs/identify.md, "The auto rule"):
///  1. Fit all five Allan terms to the raw curve (GLS) — the white-noise-family description.
///  2. Screen for short correlation: Burg AR by the order criterion on the record; if step 1
///     detected a random walk, on the record minus its smoothed random-walk level (the composite
///     AR + RW fit; an AR alone would put a pole near 1 and distort its short-lag coefficients).
///  3. Short correlation present <=> selected order >= 1 AND prediction gain r0 / E_p >=
///     autoMinPredictionGain (default 1.02: the past predicts >= 2 % of the variance). White,
///     quantization-dominated and white + RW records give MDL order 0 or a gain ~1.
///  4. Present: write the AR (from step 2); N and Q are the AR's business (its long-tau level is
///     white), so the long-tau terms B, K, R are refitted on tau >= 60 T_c (T_c of the AR model;
///     there the AR's Allan variance is within ~3 % of its white asymptote, IEEE 952 C GM form)
///     with N free and Q off, and only detected B, K, R are written.
///     Absent: write the composite latent fit (fit/latent_fit.hpp: white, quantization, GM, random
///     walk, flicker chosen by the penalised GLS criterion) over the whole tau range, so that no
///     term that dominates a tau range of the record is dropped.
void chooseAuto(AxisIdentification& out, const std::vector<double>& x, const CurvePoints& pts,
                double dt, const fit::OrderSelectionOptions& os, const IdentifyOptions& opt,
                const std::optional<fit::OrderSelection>& arDen) {
  const std::size_t n = x.size();
  const RangedFit whole = fitTermsFrom(pts, dt, n, {true, true, true, true, true}, 0.0, 7);
  out.allanFit = whole.fit;
  out.decision.push_back("Allan terms on " + describeRange(whole) + ": " + describeAllan(*out.allanFit));
  const bool rw = out.allanFit->term(fit::AllanTermKind::RandomWalk).detected;

  fit::OrderSelection screen;
  if (rw) {
    fit::ArRandomWalkFitOptions co;
    co.sampleInterval = dt;
    co.order = os;
    // K where the AR part already looks white: 60 x the measured 1/e correlation time (the same
    // margin as step 4; the composite's own default looks for the first ADEV maximum, which on
    // real data can be a long-tau bump).
    co.tauMin = 60.0 * std::max(out.correlationTime.value_or(dt), dt);
    try {
      out.composite = fit::fitArPlusRandomWalk(x, pts.tau, pts.dev, pts.edf, co);
    } catch (const Error& e) {
      out.decision.push_back(std::string("composite AR + random walk failed (") + e.what() +
                             "): AR screened on the record itself");
    }
  }
  if (out.composite && !out.composite->randomWalkDetected) {
    out.decision.push_back("composite fit did not confirm the random walk (tau >= " +
                           significant(out.composite->allan.tau.empty() ? 0.0 : out.composite->allan.tau.front(), 4) +
                           " s): AR screened on the record itself");
    out.composite.reset();
  }
  if (out.composite) {
    screen = out.composite->ar;
    out.decision.push_back("random walk detected: AR screened on the record minus its RTS-smoothed "
                           "random-walk level (T_s " + significant(out.composite->smootherTimeConstant, 4) +
                           " s)");
  } else {
    screen = *out.ar;
  }
  const fit::OrderSelection& use = opt.arOnDenoised && arDen ? *arDen : screen;
  const double gain = predictionGain(screen.fit);
  const bool shortCorr = screen.selectedOrder >= 1 && gain >= opt.autoMinPredictionGain;
  out.decision.push_back("AR screen: order " + std::to_string(screen.selectedOrder) + " by " +
                         fit::toString(screen.selectedBy) + ", prediction gain " + significant(gain, 5) +
                         (shortCorr ? " >= " : " < ") + significant(opt.autoMinPredictionGain, 3) + " -> " +
                         (shortCorr ? "short correlation: AR" : "no short correlation: Allan terms"));
  if (!shortCorr) {
    // The composite latent fit over the whole tau range (no start scan): every term that
    // dominates some tau range of the record stays in the model (issue 11: the Allan-term
    // description alone could keep a flicker floor and drop the white noise above it).
    fit::LatentFitOptions lo;
    lo.sampleInterval = dt;
    out.latent = fit::fitLatentModel(x, lo);
    out.kind = IdentifyKind::Latent;
    out.written.latent = out.latent;
    out.decision.push_back("no short correlation: composite latent fit over the whole tau range: " +
                           out.latent->terms.name() + " (chi2 " + significant(out.latent->chi2, 3) +
                           " / " + std::to_string(out.latent->dof) + " dof, p " +
                           significant(out.latent->pValue, 2) + ")");
    return;
  }
  out.kind = IdentifyKind::Ar;
  out.written.ar = use.fit;
  out.written.arOrders = use;
  out.written.arRate = 1.0 / dt;
  double tc = dt;
  try {
    tc = fit::arCorrelationTime(use.fit.a, dt);
  } catch (const InputError&) {
  }
  const double tauMin = 60.0 * tc;
  const std::size_t avail = pointsAtOrAbove(pts, tauMin);
  if (avail < 6) {
    out.decision.push_back("only " + std::to_string(avail) + " Allan points at tau >= " +
                           significant(tauMin, 3) + " s (60 T_c): no long-tau terms beside the AR");
    return;
  }
  const RangedFit longTau = fitTermsFrom(pts, dt, n, {false, true, true, true, true}, tauMin, 6);
  out.allanLongTau = longTau.fit;
  out.written.allan = out.allanLongTau;
  out.written.allanWrite = {false, false, true, true, true};
  out.decision.push_back("long-tau terms (start >= 60 T_c = " + significant(tauMin, 3) + " s) on " +
                         describeRange(longTau) + ": " + describeAllan(*out.allanLongTau) +
                         "; B, K, R written when detected");
}

}  // namespace sinsim::errormodels::detail
