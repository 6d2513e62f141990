#include "errormodels/identify.hpp"

#include "errormodels/model_io.hpp"
#include "errormodels/channels.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "common/error.hpp"
#include "common/constants.hpp"
#include "errormodels/fit/ar_fit.hpp"
#include "errormodels/gm_process.hpp"
#include "errormodels/stats/special.hpp"
#include "errormodels/stats/spectrum.hpp"

namespace sinsim::errormodels {

namespace {


std::string fmt(double v, int digits = 6) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

/// A value of a channel in the unit users read it in (deg/s, mg), for comments.
std::string friendly(double si, fit::SensorSignal s) {
  if (s == fit::SensorSignal::Gyro) return fmt(si * kDegPerRad) + " deg/s";
  return fmt(si / kStandardGravity * 1e3) + " mg";
}

fit::SensorSignal signalOf(Sensor s) {
  return s == Sensor::gyro ? fit::SensorSignal::Gyro : fit::SensorSignal::Accel;
}

/// Points of an Allan curve usable by the term fit: finite, positive dev and EDF, and
/// m <= N / 10. Beyond N / 10 a point has fewer than ~10 EDF and the modelled correlation between
/// points (the quadrature behind fit::allanEstimateCorrelation) is no longer reliable: with them
/// the correlated fit of white + random walk records (100 Hz, 2 h) lost K in 7 of 12 records.
struct CurvePoints {
  std::vector<double> tau, dev, edf;
};
CurvePoints usablePoints(const AllanCurve& c) {
  CurvePoints p;
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (!(c.dev[i] > 0.0 && std::isfinite(c.dev[i]))) continue;
    if (i >= c.edf.size() || !(c.edf[i] > 0.0 && std::isfinite(c.edf[i]))) continue;
    if (10 * c.m[i] > c.samples) continue;
    p.tau.push_back(c.tau[i]);
    p.dev.push_back(c.dev[i]);
    p.edf.push_back(c.edf[i]);
  }
  return p;
}

/// One fit of exactly the `enabled` terms (no elimination). correlated = false: independent
/// points (0.02 ms instead of ~40 ms; used for range and term selection).
fit::AllanFit fitTerms(const CurvePoints& p, double dt, std::size_t n,
                       std::array<bool, fit::kAllanTermCount> enabled, double tauMin,
                       bool correlated = true) {
  fit::AllanFitOptions o;
  o.enabled = enabled;
  o.tauMin = tauMin;
  o.eliminateUndetected = false;
  if (!correlated) return fit::fitAllanTerms(p.tau, p.dev, p.edf, o);
  o.sampleInterval = dt;
  o.recordLength = n;
  try {
    return fit::fitAllanTerms(p.tau, p.dev, p.edf, o);
  } catch (const NumericalError&) {
    // The modelled point covariance can be numerically singular: fall back to independent
    // points. AllanFit::correlated is then false, which the model file states.
    o.sampleInterval = 0.0;
    o.recordLength = 0;
    return fit::fitAllanTerms(p.tau, p.dev, p.edf, o);
  }
}

/// Term selection (which of Q, N, B, K, R the data support): every subset of the `allowed` terms
/// is fitted with independent points and scored by BIC, chi^2 + k ln(points) (Schwarz 1978);
/// a subset counts only when each of its terms is detected (theta > 2 sigma). Exhaustive (at
/// most 31 subsets of 0.02 ms each) because backward elimination from all five terms, whose
/// long-tau columns (B, K, R) are nearly collinear, dropped a clear random walk in 4 of 12 white +
/// random-walk records.
fit::AllanFit selectTerms(const CurvePoints& p, double dt, std::size_t n,
                          std::array<bool, fit::kAllanTermCount> allowed, double tauMin) {
  std::optional<fit::AllanFit> best;
  double bestScore = 0.0;
  for (unsigned mask = 1; mask < (1u << fit::kAllanTermCount); ++mask) {
    std::array<bool, fit::kAllanTermCount> en{};
    std::size_t k = 0;
    bool ok = true;
    for (std::size_t j = 0; j < fit::kAllanTermCount; ++j) {
      en[j] = (mask >> j) & 1u;
      if (en[j] && !allowed[j]) ok = false;
      k += en[j];
    }
    if (!ok) continue;
    fit::AllanFit f;
    try {
      f = fitTerms(p, dt, n, en, tauMin, false);
    } catch (const InputError&) {
      continue;  // fewer points than terms
    }
    if (f.dof < 1) continue;
    bool all = true;
    for (std::size_t j = 0; j < fit::kAllanTermCount; ++j)
      if (en[j] && !f.terms[j].detected) all = false;
    if (!all) continue;
    const double score = f.chi2 + static_cast<double>(k) * std::log(static_cast<double>(f.pointsUsed));
    if (!best || score < bestScore) {
      best = f;
      bestScore = score;
    }
  }
  if (!best) throw InputError("Allan-term fit: no term is supported by the points at tau >= " +
                              fmt(tauMin, 4) + " s");
  return *best;
}

std::size_t pointsAtOrAbove(const CurvePoints& p, double tauMin) {
  return static_cast<std::size_t>(std::count_if(p.tau.begin(), p.tau.end(),
                                                [&](double t) { return t >= tauMin * (1 - 1e-12); }));
}

/// The fit range: the first Allan point at or above tauStart from which the term model is
/// consistent with the points, chi^2 <= its 0.999 quantile for the fit's dof (real sensors show
/// features at short tau no term model carries: an internal filter's hump, a vibration line).
/// The start moves up one point at a time while at least minPoints remain; when no start passes,
/// the one with the smallest chi^2 / dof is kept. `consistent` says which case it was. The scan
/// uses independent-point fits (cheap); the chosen range is then refitted with the correlated
/// GLS, whose values and uncertainties are the ones reported.
struct RangedFit {
  fit::AllanFit fit;
  double tauMin = 0.0;
  bool consistent = false;
};
RangedFit fitTermsFrom(const CurvePoints& p, double dt, std::size_t n,
                       std::array<bool, fit::kAllanTermCount> enabled, double tauStart,
                       std::size_t minPoints) {
  std::optional<RangedFit> best;
  double bestRatio = 0.0;
  for (std::size_t i = 0; i < p.tau.size(); ++i) {
    if (p.tau[i] < tauStart * (1 - 1e-12)) continue;
    if (p.tau.size() - i < minPoints) break;
    RangedFit r{selectTerms(p, dt, n, enabled, p.tau[i]), p.tau[i], false};
    const double dof = static_cast<double>(std::max<std::size_t>(r.fit.dof, 1));
    r.consistent = r.fit.chi2 <= chiSquareQuantile(0.999, dof);
    if (r.consistent) {
      best = r;
      break;
    }
    const double ratio = r.fit.chi2 / dof;
    if (!best || ratio < bestRatio) {
      best = r;
      bestRatio = ratio;
    }
  }
  if (!best)
    throw InputError("Allan-term fit: fewer than " + std::to_string(minPoints) +
                     " Allan points at tau >= " + fmt(tauStart, 4) + " s");
  // Final values and uncertainties: correlated GLS of the selected terms, reporting the other
  // allowed terms with their upper bounds (elimination on: a term the GLS no longer supports is
  // dropped).
  std::array<bool, fit::kAllanTermCount> chosen{};
  for (std::size_t j = 0; j < fit::kAllanTermCount; ++j) chosen[j] = best->fit.terms[j].enabled;
  fit::AllanFit gls = fitTerms(p, dt, n, chosen, best->tauMin, true);
  best->fit = gls;
  return *best;
}

std::string describeRange(const RangedFit& r) {
  return "tau >= " + fmt(r.tauMin, 4) + " s (" + std::to_string(r.fit.pointsUsed) + " points, chi2 " +
         fmt(r.fit.chi2, 4) + " / " + std::to_string(r.fit.dof) + " dof" +
         (r.consistent ? "" : ", NO start consistent at 99.9 %: least-bad start kept") +
         (r.fit.correlated ? ")" : ", independent points)");
}

/// Prediction gain r0 / E_p of an AR fit (>= 1; 1 for white noise).
double predictionGain(const fit::ArFit& f) {
  return f.drivingVariancePath.empty() || !(f.drivingVariance > 0.0)
             ? 1.0
             : f.drivingVariancePath.front() / f.drivingVariance;
}

std::string describeAllan(const fit::AllanFit& f) {
  std::string s;
  for (std::size_t j = 0; j < fit::kAllanTermCount; ++j) {
    const auto& t = f.terms[j];
    if (!t.enabled) continue;
    if (!s.empty()) s += ", ";
    s += fit::toString(t.kind) + (t.detected ? " detected" : " not detected");
  }
  return s;
}

}  // namespace

std::string toString(IdentifyKind kind) {
  switch (kind) {
    case IdentifyKind::Ar: return "ar";
    case IdentifyKind::Gm: return "gm";
    case IdentifyKind::Allan: return "allan";
    case IdentifyKind::Auto: return "auto";
    case IdentifyKind::Latent: return "latent";
  }
  return "?";
}

IdentifyKind identifyKindByName(const std::string& name) {
  if (name == "ar") return IdentifyKind::Ar;
  if (name == "gm") return IdentifyKind::Gm;
  if (name == "allan") return IdentifyKind::Allan;
  if (name == "auto") return IdentifyKind::Auto;
  if (name == "latent") return IdentifyKind::Latent;
  throw InputError("unknown model kind \"" + name + "\" (known: ar, gm, allan, auto, latent)");
}

fit::OrderCriterion orderCriterionByName(const std::string& name) {
  if (name == "mdl" || name == "bic") return fit::OrderCriterion::MDL;
  if (name == "aic") return fit::OrderCriterion::AIC;
  if (name == "fpe") return fit::OrderCriterion::FPE;
  if (name == "paper") return fit::OrderCriterion::PaperRule;
  throw InputError("unknown order criterion \"" + name + "\" (known: mdl, bic, aic, fpe, paper)");
}

std::vector<double> AxisIdentification::modelAdev(const std::vector<double>& tau) const {
  std::vector<double> avar(tau.size(), 0.0);
  for (double t : tau)
    if (!(std::isfinite(t) && t > 0.0))
      throw InputError("model Allan deviation: tau must be positive");
  if (written.ar) {
    const double rate = written.arRate;
    std::vector<std::size_t> m(tau.size());
    for (std::size_t i = 0; i < tau.size(); ++i) {
      const double mi = tau[i] * rate;
      m[i] = static_cast<std::size_t>(std::llround(mi));
      if (m[i] < 1 || std::fabs(mi - m[i]) > 1e-6 * mi)
        throw InputError("model Allan deviation: tau " + fmt(tau[i]) +
                         " s is not a multiple of the AR sample interval");
    }
    const auto v = fit::arAllanVariance(written.ar->a, written.ar->drivingVariance, m);
    for (std::size_t i = 0; i < tau.size(); ++i) avar[i] += v[i];
  }
  if (written.gaussMarkov) {
    const auto& g = *written.gaussMarkov;
    for (std::size_t i = 0; i < tau.size(); ++i)
      avar[i] += gaussMarkovAllanVariance(g.sigma * g.sigma, g.tau, tau[i]);
  }
  if (written.latent) {
    const double dtl = written.latent->sampleInterval;
    std::vector<std::size_t> m(tau.size());
    for (std::size_t i = 0; i < tau.size(); ++i) {
      m[i] = static_cast<std::size_t>(std::llround(tau[i] / dtl));
      if (m[i] < 1 || std::fabs(m[i] * dtl - tau[i]) > 1e-6 * tau[i])
        throw InputError("model Allan deviation: tau " + fmt(tau[i]) +
                         " s is not a multiple of the latent model's sample interval");
    }
    const auto v = fit::latentAllanVariance(written.latent->model, dtl, m);
    for (std::size_t i = 0; i < tau.size(); ++i) avar[i] += v[i];
  }
  if (written.allan) {
    std::array<double, fit::kAllanTermCount> theta{};
    for (std::size_t j = 0; j < fit::kAllanTermCount; ++j) {
      const auto& t = written.allan->terms[j];
      if (written.allanWrite[j] && t.enabled && t.detected) theta[j] = t.theta;
    }
    const auto a = fit::allanModelAdev(theta, tau);
    for (std::size_t i = 0; i < tau.size(); ++i) avar[i] += a[i] * a[i];
  }
  for (double& v : avar) v = std::sqrt(v);
  return avar;
}

const AxisIdentification& Identification::axis(const std::string& channel) const {
  for (const auto& a : axes)
    if (a.channel == channel) return a;
  throw InputError("identification of " + source + " has no channel \"" + channel + "\"");
}

std::string Identification::method() const {
  const IdentifyOptions& o = options;
  std::string m = "kind " + toString(o.kind);
  m += o.denoise == DenoiseChoice::Db5 ? ", db5 denoise (" +
                                             std::string(o.denoiseOptions.rule == ThresholdRule::Sure
                                                             ? "SURE"
                                                             : "universal") +
                                             (o.denoiseOptions.mode == ThresholdMode::Soft ? ", soft" : ", hard") +
                                             ") before the ACF"
                                       : ", no denoising";
  if (o.kind == IdentifyKind::Ar || o.kind == IdentifyKind::Auto) {
    m += ", Burg AR on the " + std::string(o.arOnDenoised ? "DENOISED" : "raw") + " record, order ";
    m += o.order ? std::to_string(*o.order) + " (forced)"
                 : "by " + fit::toString(o.criterion) + " over 0.." + std::to_string(o.maxOrder);
  }
  m += ", overlapping ADEV (octave tau, Greenhall EDF)";
  if (o.kind == IdentifyKind::Allan || o.kind == IdentifyKind::Auto)
    m += ", IEEE 952 Allan-term GLS fit";
  if (o.kind == IdentifyKind::Gm || o.kind == IdentifyKind::Latent)
    m += ", composite latent-process GLS fit (" +
         std::string(o.kind == IdentifyKind::Gm ? "white + GM (+ random walk)" : "all term sets") +
         ", BIC; docs/fitting.md)";
  return m;
}

fit::ModelProvenance Identification::provenance() const {
  fit::ModelProvenance p;
  p.description = "fitted by sinsim fit from " + source;
  p.dataFile = source;
  p.rate = rate_hz;
  p.duration = duration();
  p.method = method();
  p.notes.push_back("samples used: " + std::to_string(samples) +
                    (skipped ? " (first " + std::to_string(skipped) + " samples = " +
                                   fmt(skipped / rate_hz) + " s skipped)"
                             : ""));
  p.notes.push_back(
      "bias: each channel's mean (turn-on bias + Earth rate / gravity, not separable in one static "
      "record) is removed before fitting and only reported below; add a `bias` effect by hand if "
      "wanted.");
  if (options.denoise == DenoiseChoice::Db5 && !options.arOnDenoised)
    p.notes.push_back("denoising: the written AR is fitted on the RAW record (denoised data lack "
                      "most of the white noise); the denoised fit is shown for comparison.");
  if (options.arOnDenoised)
    p.notes.push_back("denoising: the written AR is fitted on the DENOISED record (the paper's "
                      "pipeline): its driving noise underestimates the sensor's white noise.");
  p.notes.push_back("uncertainties are 1 sigma; units: values in the file, SI in comments marked (SI)");
  for (const auto& w : warnings) p.notes.push_back("WARNING: " + w);
  return p;
}

ErrorModelSpec Identification::modelSpec() const {
  std::vector<fit::AxisFitResult> entries;
  for (const auto& a : axes) entries.push_back(a.written);
  return fit::modelSpec(entries, provenance());
}

std::string Identification::modelYaml() const { return errorModelYaml(modelSpec()); }

void Identification::writeModel(const std::string& path) const {
  writeErrorModel(path, modelSpec());
}

namespace {

/// Auto (the rule, stated once here and in the README):
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
///     Absent: write the detected terms of step 1.
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
                           fmt(out.composite->allan.tau.empty() ? 0.0 : out.composite->allan.tau.front(), 4) +
                           " s): AR screened on the record itself");
    out.composite.reset();
  }
  if (out.composite) {
    screen = out.composite->ar;
    out.decision.push_back("random walk detected: AR screened on the record minus its RTS-smoothed "
                           "random-walk level (T_s " + fmt(out.composite->smootherTimeConstant, 4) +
                           " s)");
  } else {
    screen = *out.ar;
  }
  const fit::OrderSelection& use = opt.arOnDenoised && arDen ? *arDen : screen;
  const double gain = predictionGain(screen.fit);
  const bool shortCorr = screen.selectedOrder >= 1 && gain >= opt.autoMinPredictionGain;
  out.decision.push_back("AR screen: order " + std::to_string(screen.selectedOrder) + " by " +
                         fit::toString(screen.selectedBy) + ", prediction gain " + fmt(gain, 5) +
                         (shortCorr ? " >= " : " < ") + fmt(opt.autoMinPredictionGain, 3) + " -> " +
                         (shortCorr ? "short correlation: AR" : "no short correlation: Allan terms"));
  if (!shortCorr) {
    out.kind = IdentifyKind::Allan;
    out.written.allan = out.allanFit;
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
                           fmt(tauMin, 3) + " s (60 T_c): no long-tau terms beside the AR");
    return;
  }
  const RangedFit longTau = fitTermsFrom(pts, dt, n, {false, true, true, true, true}, tauMin, 6);
  out.allanLongTau = longTau.fit;
  out.written.allan = out.allanLongTau;
  out.written.allanWrite = {false, false, true, true, true};
  out.decision.push_back("long-tau terms (start >= 60 T_c = " + fmt(tauMin, 3) + " s) on " +
                         describeRange(longTau) + ": " + describeAllan(*out.allanLongTau) +
                         "; B, K, R written when detected");
}

/// A static accelerometer reads |f| = g = 9.8 m/s^2. Means whose norm is 0.5..1.5 "m/s^2" (or a
/// single axis mean of that size when only one is fitted) are g units read as m/s^2.
void warnAccelUnit(Identification& id) {
  double s2 = 0.0;
  int count = 0;
  for (const auto& a : id.axes)
    if (a.sensor == fit::SensorSignal::Accel) s2 += a.mean * a.mean, ++count;
  const double norm = std::sqrt(s2);
  if (count > 0 && norm > 0.5 && norm < 1.5)
    id.warnings.push_back("accelerometer mean |f| = " + fmt(norm, 4) +
                          " m/s^2 in a static record (gravity is 9.8 m/s^2): did you forget --accel-unit g?");
}

}  // namespace

Identification identify(const Record& record, const IdentifyOptions& opt) {
  if (!(record.rate_hz > 0.0 && std::isfinite(record.rate_hz)))
    throw InputError(record.source + ": the record has no valid sample rate");
  if (!(std::isfinite(opt.skipStart) && opt.skipStart >= 0.0))
    throw InputError("skip: expected a non-negative time, got " + fmt(opt.skipStart));
  if (opt.order && *opt.order < 1) throw InputError("order: expected >= 1 (or auto)");
  if (opt.maxOrder < 1) throw InputError("max order: expected >= 1");
  if (opt.arOnDenoised && opt.denoise != DenoiseChoice::Db5)
    throw InputError("fitting the AR on denoised data needs denoising (db5)");
  if (!(opt.navigationStep > 0.0 && std::isfinite(opt.navigationStep)))
    throw InputError("navigation step: expected a positive time");
  if (!(opt.confidence > 0.0 && opt.confidence < 1.0))
    throw InputError("confidence: expected a level in (0, 1)");

  std::vector<int> chans;  // indices into kRecordChannels
  if (opt.axes.empty()) {
    for (int c = 0; c < int(kRecordChannels.size()); ++c)
      if (!channelData(record, c).empty()) chans.push_back(c);
    if (chans.empty()) throw InputError(record.source + ": no gx/gy/gz/ax/ay/az column to fit");
  } else {
    for (const auto& name : opt.axes) {
      const std::optional<int> c = findChannel(name);
      if (!c) throw InputError("axis \"" + name + "\": expected one of " + kChannelList);
      if (channelData(record, *c).empty())
        throw InputError(record.source + ": axis \"" + name + "\" is not in the record");
      if (std::find(chans.begin(), chans.end(), *c) != chans.end())
        throw InputError("axis \"" + name + "\" given twice");
      chans.push_back(*c);
    }
  }

  const double dt = 1.0 / record.rate_hz;
  // Compared in floating point first: llround of a skip of 1e300 s is undefined.
  if (!(opt.skipStart >= 0.0 && opt.skipStart < record.duration()))
    throw InputError(record.source + ": skip " + fmt(opt.skipStart) + " s is beyond the record (" +
                     fmt(record.duration()) + " s)");
  const std::size_t skip = static_cast<std::size_t>(std::llround(opt.skipStart * record.rate_hz));
  if (skip >= record.size())
    throw InputError(record.source + ": skip " + fmt(opt.skipStart) + " s is beyond the record (" +
                     fmt(record.duration()) + " s)");
  const std::size_t n = record.size() - skip;
  // Burg needs order < N - 2; the Allan-term fit needs >= 5 octave points (m <= N/4 -> N >= 64).
  if (n < std::max<std::size_t>(64, opt.maxOrder + 3))
    throw InputError(record.source + ": " + std::to_string(n) +
                     " samples after the skip: too short to fit (at least " +
                     std::to_string(std::max<std::size_t>(64, opt.maxOrder + 3)) + ")");

  Identification out;
  out.source = record.source;
  out.rate_hz = record.rate_hz;
  out.samples = n;
  out.skipped = skip;
  out.options = opt;

  for (const int ci : chans) withContext(record.source + ": channel " + kRecordChannels[ci].name, [&] {
    const Channel& c = kRecordChannels[ci];
    const fit::SensorSignal sensor = signalOf(c.sensor);
    const std::vector<double>& src = channelData(record, ci);
    std::vector<double> x(src.begin() + static_cast<std::ptrdiff_t>(skip), src.end());
    AxisIdentification ax;
    ax.channel = c.name;
    ax.sensor = sensor;
    ax.axis = std::string(1, "xyz"[c.axis]);
    ax.samples = n;
    ax.rate_hz = record.rate_hz;
    double mean = 0.0;
    for (double v : x) mean += v;
    mean /= static_cast<double>(n);
    double var = 0.0;
    for (double& v : x) {
      v -= mean;
      var += v * v;
    }
    ax.mean = mean;
    ax.stddev = std::sqrt(var / static_cast<double>(n));
    if (!(ax.stddev > 0.0))
      throw InputError(record.source + ": channel " + c.name + " is constant: nothing to fit");

    AllanOptions ao;
    ao.grid = TauGrid::Octave;
    ao.confidence = opt.confidence;
    ax.allan = allanDeviation(x, record.rate_hz, AllanVariant::Overlapping, ao);
    const CurvePoints pts = usablePoints(ax.allan);

    std::vector<double> den;
    if (opt.denoise == DenoiseChoice::Db5) {
      DenoiseResult d = waveletDenoise(x, opt.denoiseOptions);
      den = std::move(d.signal);
      d.signal.clear();
      ax.denoise = std::move(d);
    }
    const std::vector<double>& forAcf = den.empty() ? x : den;
    const double duration = n * dt;
    const double maxLagS = opt.maxLag > 0.0 ? opt.maxLag : std::min(duration / 10.0, 100.0);
    const std::size_t maxLag = std::clamp<std::size_t>(
        static_cast<std::size_t>(std::llround(std::min(maxLagS, duration) * record.rate_hz)), 4,
        n - 1);
    const Autocorrelation acf =
        autocorrelation(forAcf, record.rate_hz, maxLag, AcfScaling::Biased);
    try {
      ax.correlationTime = fit::correlationTime(acf.r, dt);
    } catch (const InputError&) {
      // the ACF never falls to 1/e within maxLag (drift-dominated record): left unset
    }

    fit::OrderSelectionOptions os;
    os.maxOrder = opt.maxOrder;
    os.criterion = opt.criterion;
    os.forcedOrder = opt.order;
    os.sampleInterval = dt;
    os.navigationStep = opt.navigationStep;
    if (ax.correlationTime) os.correlationTime = *ax.correlationTime;

    if (opt.kind == IdentifyKind::Ar || opt.kind == IdentifyKind::Auto) {
      ax.ar = fit::selectArOrder(x, os);
      if (!den.empty()) ax.arDenoised = fit::selectArOrder(den, os);
    }

    ax.written.sensor = sensor;
    ax.written.axis = ax.axis;
    ax.written.notes.push_back("mean removed (not written): " + friendly(mean, sensor) + " = " +
                               fmt(mean, 8) + " (SI); sd " + friendly(ax.stddev, sensor));
    if (ax.correlationTime)
      ax.written.notes.push_back(std::string("1/e correlation time of the ") +
                                 (den.empty() ? "raw" : "denoised") + " ACF: " +
                                 fmt(*ax.correlationTime * 1e3, 4) + " ms");
    if (ax.denoise)
      ax.written.notes.push_back("db5 denoise: level " + std::to_string(ax.denoise->level) +
                                 ", noise sigma " + friendly(ax.denoise->sigma, sensor) +
                                 ", finest threshold " +
                                 friendly(ax.denoise->thresholds.empty() ? 0.0 : ax.denoise->thresholds[0],
                                          sensor));

    switch (opt.kind) {
      case IdentifyKind::Ar: {
        const fit::OrderSelection& use = opt.arOnDenoised ? *ax.arDenoised : *ax.ar;
        ax.kind = IdentifyKind::Ar;
        ax.written.ar = use.fit;
        ax.written.arOrders = use;
        ax.written.arRate = record.rate_hz;
        break;
      }
      case IdentifyKind::Gm:
      case IdentifyKind::Latent: {
        fit::GaussMarkovFitOptions go;
        go.recordLength = n;
        if (opt.kind == IdentifyKind::Gm) {
          ax.gaussMarkov = fit::fitGaussMarkov(acf.r, dt, go);
          ax.written.notes.push_back("for comparison, GM from the ACF (not written): sigma " +
                                     friendly(ax.gaussMarkov->sigma, sensor) + ", tau " +
                                     fmt(ax.gaussMarkov->tau, 4) + " s");
        }
        fit::LatentFitOptions lo;
        lo.sampleInterval = dt;
        lo.scanStart = true;
        if (opt.kind == IdentifyKind::Gm) lo.minGmTauSamples = 2.0;
        if (opt.kind == IdentifyKind::Gm)
          lo.candidates = {{false, false, 1, false, false, false}, {false, true, 1, false, false, false},
                           {false, false, 1, false, true, false}, {false, true, 1, false, true, false}};
        ax.latent = fit::fitLatentModel(x, lo);
        ax.kind = opt.kind;
        ax.written.latent = ax.latent;
        for (const auto& w : ax.latent->warnings) out.warnings.push_back(std::string(c.name) + ": " + w);
        break;
      }
      case IdentifyKind::Allan: {
        const RangedFit r = fitTermsFrom(pts, dt, n, {true, true, true, true, true}, 0.0, 7);
        ax.allanFit = r.fit;
        ax.written.notes.push_back("Allan-term fit range: " + describeRange(r));
        ax.kind = IdentifyKind::Allan;
        ax.written.allan = ax.allanFit;
        break;
      }
      case IdentifyKind::Auto:
        chooseAuto(ax, x, pts, dt, os, opt, ax.arDenoised);
        for (const auto& d : ax.decision) ax.written.notes.push_back("auto: " + d);
        break;
    }

    if (ax.arDenoised && ax.ar && ax.written.ar) {
      const auto& other = opt.arOnDenoised ? *ax.ar : *ax.arDenoised;
      std::string s = std::string("for comparison, AR(") + std::to_string(other.fit.order) +
                      ") on the " + (opt.arOnDenoised ? "raw" : "denoised") + " record: a = [";
      for (std::size_t i = 1; i < other.fit.a.size(); ++i)
        s += (i > 1 ? ", " : "") + fmt(other.fit.a[i], 6);
      s += "], driving sigma " + friendly(std::sqrt(other.fit.drivingVariance), sensor) +
           " (written: " + friendly(std::sqrt(ax.written.ar->drivingVariance), sensor) + ")";
      ax.written.notes.push_back(s);
    }
    out.axes.push_back(std::move(ax));
  });
  warnAccelUnit(out);
  return out;
}

}  // namespace sinsim::errormodels
