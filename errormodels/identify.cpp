#include "errormodels/identify.hpp"


#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "common/constants.hpp"
#include "common/error.hpp"
#include "common/limits.hpp"
#include "common/number_text.hpp"
#include "common/parallel.hpp"
#include "common/progress.hpp"
#include "errormodels/channels.hpp"
#include "errormodels/fit/ar_fit.hpp"
#include "errormodels/gm_process.hpp"
#include "errormodels/identify_auto.hpp"
#include "errormodels/identify_lines.hpp"
#include "errormodels/identify_terms.hpp"
#include "errormodels/model_io.hpp"
#include "errormodels/stats/lattice.hpp"
#include "errormodels/stats/special.hpp"
#include "errormodels/stats/line_fit.hpp"
#include "errormodels/stats/spectrum.hpp"
#include "errormodels/stats/trend.hpp"

namespace sinsim::errormodels {

namespace {

using detail::CurvePoints;
using detail::RangedFit;

/// A value of a channel in the unit users read it in (deg/s, mg), for comments.
std::string friendly(double si, fit::SensorSignal s, int digits = 6) {
  if (s == fit::SensorSignal::Gyro) return significant(si * kDegPerRad, digits) + " deg/s";
  return significant(si / kStandardGravity * 1e3, digits) + " mg";
}

/// What fit says of a line it found: taken out and written as a sinusoid, or (not fitted) that the
/// terms absorb it.
/// The amplitude is the coherent sinusoid's, fitted on the whole record, as `diagnose` sizes it.
/// Where the Welch bin holds much more (a line broadened: a vibration whose frequency wanders),
/// that is said too: the bin's power is what the noise terms absorb when the line is left in.
std::string lineMessage(const detail::RecordLine& l, fit::SensorSignal s, bool fitted) {
  const double a = l.fitted.amplitude, band = l.welchAmplitude;
  const std::string broad = band > 1.25 * a ? ", and its band " + friendly(band, s, 3) +
                                                  " (a broadened line, as a vibration whose frequency wanders)"
                                            : "";
  const std::string found = "a narrow line at " + significant(l.fitted.frequency, 6) + " Hz, amplitude " +
                            friendly(a, s, 3) + broad + " (" + significant(l.welch.ratio, 3) +
                            " times the noise density around it): ";
  if (fitted)
    return found + "written as a sinusoid and taken out of the record before its noise terms were fitted "
                   "(`--lines warn` leaves it in)";
  return found + "no fitted term is a line, so the terms absorb it; `sinsim diagnose` names it (sinusoid) "
                 "and its `--add sinusoid` adds it to the model";
}

/// What fit says of a settling at the record's start (fit/start_settling.hpp): its size, its test,
/// and the --skip (from the file's start, `skipped` [s] already skipped) after which it is settled,
/// rounded up to two digits; `used` [s] the record's length after the skip.
std::string settlingMessage(const fit::StartSettling& st, fit::SensorSignal s, double skipped, double used) {
  const double skip = skipped + st.settledAfter;
  const double step = std::pow(10.0, std::floor(std::log10(skip)) - 1.0);
  const double rounded = std::ceil(skip / step - 1e-9) * step;
  std::string t = "the record starts with a settling: " + friendly(st.amplitude, s, 3) + " decaying with tau " +
                  significant(st.tau, 3) + " s (its amplitude by generalised least squares against the fitted noise "
                  "terms: z " + significant(st.z, 3) + ", p " + significant(st.pValue, 2) + " over " +
                  significant(st.octaves, 3) + " octaves of tau). No noise term is a settling: the fitted terms take "
                  "what they can of it. Fit the settled part with --skip " +
                  (rounded >= 10.0 ? std::to_string(std::llround(rounded)) : significant(rounded, 2)) +
                  " (s), or let `sinsim diagnose` name it (warmup)";
  if (st.settledAfter > 0.5 * used)
    t += "; it settles over more than half of the record: record longer, or start recording later";
  return t;
}

/// The AR part of an AR + slow fit, for the model comments: order and how it was chosen, the
/// coefficients with their 1-sigma, Burg's driving sigma beside the jointly refitted one.
std::string describeArSlow(const fit::ArSlowFit& f, fit::SensorSignal s) {
  const fit::ArFit& a = f.ar.fit;
  std::string t = "AR(" + std::to_string(a.order) + ") by Burg, order by " + fit::toString(f.ar.selectedBy) +
                  " (AIC " + std::to_string(f.ar.aicOrder) + ", MDL " + std::to_string(f.ar.mdlOrder) +
                  "), T_c " + significant(f.arCorrelationTime * 1e3, 4) + " ms; a =";
  for (std::size_t i = 1; i < a.a.size(); ++i)
    t += " " + significant(a.a[i], 6) + " +- " + significant(a.stdError[i - 1], 2);
  t += "; driving sigma: Burg " + friendly(std::sqrt(a.drivingVariance), s) + ", refitted jointly " +
       friendly(std::sqrt(f.joint.model.arVariance), s);
  return t;
}

/// `--kind ar` writes the AR alone, which forgets within its correlation time: where the record's
/// Allan deviation stays above the model's 99 % band up to its last tau (the model below the
/// record's 99 % chi-square bound at the point's EDF, chiSquareBounds), the warning says from which
/// tau and by how much. (A blind probe's AR(1) fits of white + GM + walk records predicted 0.1-0.46x
/// the drift of the truth, with no word from `fit`.) Empty when the last two points are inside.
std::string arLongTauWarning(const AxisIdentification& ax) {
  const AllanCurve& c = ax.allan;
  if (!ax.written.ar || c.size() < 2 || c.edf.size() != c.size()) return {};
  const std::vector<double> model = ax.modelAdev(c.tau);
  auto below = [&](std::size_t i) {
    if (!(c.edf[i] > 0.0)) return false;
    double lo = 0, hi = 0;
    chiSquareBounds(c.dev[i], c.edf[i], 0.99, lo, hi);
    return model[i] < lo;
  };
  std::size_t from = c.size();
  while (from > 0 && below(from - 1)) --from;
  if (from + 2 > c.size()) return {};
  const std::size_t last = c.size() - 1;
  return "the AR model's ADEV is below the record's 99 % band from tau " + significant(c.tau[from], 3) +
         " s up (" + significant(model[last] / c.dev[last], 2) + "x the record's at " + significant(c.tau[last], 3) +
         " s): an AR forgets within its correlation time, and the record's slow part (a GM, a walk, a "
         "flicker) is in no term of this model, so the drift it predicts is too small; --kind ar+slow fits "
         "slow terms beside the AR, --kind auto chooses";
}

fit::SensorSignal signalOf(Sensor s) {
  return s == Sensor::gyro ? fit::SensorSignal::Gyro : fit::SensorSignal::Accel;
}

}  // namespace

std::string toString(IdentifyKind kind) {
  switch (kind) {
    case IdentifyKind::Ar: return "ar";
    case IdentifyKind::Gm: return "gm";
    case IdentifyKind::Allan: return "allan";
    case IdentifyKind::Auto: return "auto";
    case IdentifyKind::Latent: return "latent";
    case IdentifyKind::ArSlow: return "ar+slow";
  }
  return "?";
}

bool fitLinesByName(const std::string& name) {
  if (name == "fit") return true;
  if (name == "warn") return false;
  throw InputError("--lines: expected fit or warn, got \"" + limits::echo(name) + "\"");
}

IdentifyKind identifyKindByName(const std::string& name) {
  if (name == "ar") return IdentifyKind::Ar;
  if (name == "gm") return IdentifyKind::Gm;
  if (name == "allan") return IdentifyKind::Allan;
  if (name == "auto") return IdentifyKind::Auto;
  if (name == "latent") return IdentifyKind::Latent;
  if (name == "ar+slow") return IdentifyKind::ArSlow;
  throw InputError("--kind: unknown model kind \"" + name + "\" (known: ar, gm, allan, auto, latent, ar+slow)");
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
        throw InputError("model Allan deviation: tau " + significant(tau[i]) +
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
        throw InputError("model Allan deviation: tau " + significant(tau[i]) +
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
  for (const FittedLine& l : written.lines)
    for (std::size_t i = 0; i < tau.size(); ++i) avar[i] += sinusoidAllanVariance(l.amplitude, l.frequency, tau[i]);
  if (written.roundedRateLsb > 0.0 && written.latent) {
    // each sample rounded onto the lattice of a busy input: white, q^2 / 12 per sample
    const double q = written.roundedRateLsb, dtl = written.latent->sampleInterval;
    for (std::size_t i = 0; i < tau.size(); ++i) avar[i] += q * q / 12.0 * dtl / tau[i];
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
  if (o.kind == IdentifyKind::Ar || o.kind == IdentifyKind::Auto || o.kind == IdentifyKind::ArSlow) {
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
  if (o.kind == IdentifyKind::ArSlow)
    m += ", slow terms (GM, random walk, flicker) beside the AR by the composite GLS fit, the AR's "
         "driving variance refitted (docs/fitting.md)";
  return m;
}

fit::ModelProvenance Identification::provenance() const {
  fit::ModelProvenance p;
  p.description = "fitted by sinsim fit from " + source;
  p.dataFile = source;
  p.rate = rate_hz;
  p.duration = duration();
  p.method = method();
  const std::size_t firstSkipped = skipped + static_cast<std::size_t>(std::llround(fileSkipped_s * rate_hz));
  p.notes.push_back("samples used: " + std::to_string(samples) +
                    (firstSkipped ? " (first " + std::to_string(firstSkipped) + " samples = " +
                                        significant(fileSkipped_s + double(skipped) / rate_hz) + " s skipped)"
                                  : ""));
  p.notes.push_back(
      "bias: each channel's mean (turn-on bias + Earth rate / gravity, not separable in one static "
      "record) is removed before fitting and only reported below; add a `bias` effect by hand if "
      "wanted.");
  if (options.denoise == DenoiseChoice::Db5 && !options.arOnDenoised)
    p.notes.push_back(options.kind == IdentifyKind::Ar
                          ? "denoising: the written AR is fitted on the RAW record (denoised data lack "
                            "most of the white noise); the denoised fit is shown for comparison."
                          : "denoising: only the ACF and its correlation time are the denoised "
                            "record's; every fit is on the RAW record (denoised data lack most of the "
                            "white noise).");
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

/// The quantization Q [SI s] the written model holds (0: none).
double writtenQuantization(const fit::AxisFitResult& w) {
  if (w.latent) return w.latent->model.quantization;
  if (w.allan) {
    const auto& t = w.allan->term(fit::AllanTermKind::Quantization);
    if (w.allanWrite[std::size_t(fit::AllanTermKind::Quantization)] && t.enabled && t.detected) return t.value;
  }
  return 0.0;
}

/// Whether a fitted quantization Q [SI s] is written dithered: the record shows no value lattice
/// its rounding could leave -- none, or one finer than half its LSB as a rate (a CSV's printing
/// precision) -- so the Allan slope -1 is the remainder of a busy input (IEEE 952's Q, GMWM's QN).
bool quantizationIsDithered(double Q, double lattice, double dt) {
  return !(lattice >= 0.5 * std::sqrt(12.0) * Q / dt);
}

/// The record's value lattice as the increment LSB of a fitted quantization Q [SI s]: step * dt
/// where that is within 1.5x of the fit's LSB sqrt(12) Q (values on a lattice are rounded at its
/// step: the lattice is the exact LSB, the Allan slope -1 only its estimate); 0 otherwise.
double latticeLsb(double Q, double lattice, double dt) {
  const double lsb = lattice * dt, fitted = std::sqrt(12.0) * Q;
  return lsb > 0.0 && std::fabs(std::log(lsb / fitted)) < std::log(1.5) ? lsb : 0.0;
}

/// A value lattice of step q [SI] the diagnosis sees (latticeVisible, either rounding) that no
/// written term rounds onto: a composite fit's model gets it as the record's rate LSB, each sample
/// rounded, so that `diagnose` of the same record finds no quantization the model lacks. To the
/// Allan fit that rounding is white noise of variance q^2 / 12 per sample, which the white term
/// (else the AR's driving noise) took in: that share moves out of it. Where neither keeps half of
/// itself, the lattice is as coarse as the noise, its rounding no white noise: not written. x is the
/// record as fitted, sd its standard deviation [SI].
void writeVisibleLattice(fit::AxisFitResult& w, const std::vector<double>& x, double sd, double q, double dt) {
  if (!w.latent || writtenQuantization(w) > 0.0 || !latticeVisible(x, q, true)) return;
  fit::LatentModel& m = w.latent->model;
  const double v = q * q / 12.0;  // [U^2] per sample
  const std::string lattice = "values on a lattice of " + friendly(q, w.sensor) + " (q^2 / 12 " +
                              significant(v / (sd * sd) * 100.0, 3) + " % of the record's variance)";
  std::string moved;
  if (m.white > 0.0 && v * dt <= 0.5 * m.white * m.white) {
    const double before = m.white;
    m.white = std::sqrt(m.white * m.white - v * dt);
    moved = "the white density x" + significant(m.white / before, 4);
    // Its stated 1-sigma moves with it: the same relative width about the value written.
    for (fit::LatentParameter& p : w.latent->parameters)
      if (p.name == "white") {
        const double k = m.white / before;
        p.value *= k, p.stdError *= k, p.logCenter += std::log(k);
      }
  } else if (m.arVariance > 0.0 && v <= 0.5 * m.arVariance) {
    const double before = std::sqrt(m.arVariance);
    if (const auto less = fit::arLessWhite(m.arPolynomial, m.arVariance, v)) {
      // Out of the AR's spectrum, a flat q^2 / 12, not out of its driving noise: that would lower
      // the whole spectrum, most where the AR's gain is high (alt null record 9 gy, seed 4: an
      // oscillating AR(3) under an LSB of 1.2 sd, the model 0.85-0.94x the record's ADEV from
      // 0.25 s up and the diagnosis of the same record naming a GM; so: within 4 %).
      m.arPolynomial = less->a;
      m.arVariance = less->drivingVariance;
      moved = "the AR's spectrum (its autocovariance less q^2 / 12 at lag 0, Levinson-Durbin at its order: driving "
              "sigma x" + significant(std::sqrt(m.arVariance) / before, 4) + ", the coefficients no longer Burg's)";
    } else {
      m.arVariance -= v;
      moved = "the AR's driving sigma x" + significant(std::sqrt(m.arVariance) / before, 4);
    }
  } else {
    // As coarse as the noise: rounding is no white noise there (it may hide variance), and no
    // term holds its share. Not written, as before; the diagnosis sizes it on the record.
    w.notes.push_back(lattice + ", as coarse as the noise (more than half of its white or AR term): no " +
                      "quantization written; `sinsim diagnose` sizes it against the record");
    return;
  }
  w.notes.push_back(lattice + ": a quantization of that LSB written (each sample rounded), its share moved out of " +
                    moved);
  w.roundedRateLsb = q;
}

/// One identification of the record as `opt` says (skipAuto aside).
/// [s] Records shorter than this are warned: they show tau up to a third of their length, and
/// the slow terms a navigation drift depends on (Gauss-Markov, random walk, bias instability) are
/// minutes to hours; static records for a model are 20 min to several hours.
constexpr double kShortRecord = 60.0;

std::string shortRecordWarning(const Record& record) {
  const double T = record.duration();
  if (!(T < kShortRecord)) return "";
  return "the record is " + limits::fmt(T, 3) + " s long (" + std::to_string(record.size()) +
         " samples): the fit sees tau up to " + limits::fmt(T / 3.0, 3) +
         " s only, so no Gauss-Markov, random walk or bias instability slower than that can be told, and "
         "the model written describes the short-tau noise alone (static records for a model are 20 min "
         "to several hours)";
}

Identification identifyOnce(const Record& record, const IdentifyOptions& opt) {
  if (!(record.rate_hz > 0.0 && std::isfinite(record.rate_hz)))
    throw InputError(record.source + ": the record has no valid sample rate");
  if (!(std::isfinite(opt.skipStart) && opt.skipStart >= 0.0))
    throw InputError("skip: expected a non-negative time, got " + significant(opt.skipStart));
  const auto maxAr = static_cast<std::size_t>(limits::kMaxArOrder);
  if (opt.order && !(*opt.order >= 1 && *opt.order <= maxAr))
    throw InputError("order: expected 1 to " + std::to_string(maxAr) + " (or auto; docs/limits.md)");
  if (!(opt.maxOrder >= 1 && opt.maxOrder <= maxAr))
    throw InputError("max order: expected 1 to " + std::to_string(maxAr) + " (docs/limits.md)");
  if (opt.arOnDenoised && opt.denoise != DenoiseChoice::Db5)
    throw InputError("fitting the AR on denoised data needs denoising (db5)");
  if (opt.arOnDenoised && opt.kind != IdentifyKind::Ar)
    throw InputError("writing the AR fitted on denoised data (the paper's literal pipeline) is a --kind ar "
                     "option, got --kind " + toString(opt.kind));
  if (!(opt.navigationStep > 0.0 && std::isfinite(opt.navigationStep)))
    throw InputError("navigation step: expected a positive time");
  if (!(opt.confidence > 0.0 && opt.confidence < 1.0))
    throw InputError("confidence: expected a level in (0, 1)");

  std::vector<int> chans;  // indices into kRecordChannels
  if (opt.axes.empty()) {
    for (int c = 0; c < int(kRecordChannels.size()); ++c)
      if (!channelData(record, c).empty()) chans.push_back(c);
    if (chans.empty())
      throw InputError(record.source + ": no gx/gy/gz/ax/ay/az column to fit; " + sensorColumnsHint(record));
  } else {
    for (const auto& name : opt.axes) {
      const std::optional<int> c = findChannel(name);
      if (!c) throw InputError("--axes: axis \"" + name + "\": expected one of " + kChannelList);
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
    throw InputError(record.source + ": skip " + significant(opt.skipStart) + " s is beyond the record (" +
                     significant(record.duration()) + " s)");
  const std::size_t skip = static_cast<std::size_t>(std::llround(opt.skipStart * record.rate_hz));
  if (skip >= record.size())
    throw InputError(record.source + ": skip " + significant(opt.skipStart) + " s is beyond the record (" +
                     significant(record.duration()) + " s)");
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
  out.fileSkipped_s = record.skipped_s;
  out.options = opt;

  // Channels are independent: on worker threads, each result in its channel's
  // slot, so the identification is the same for any thread count.
  std::vector<AxisIdentification> axes(chans.size());
  std::vector<std::vector<std::string>> warnings(chans.size());
  std::atomic<std::size_t> done{0};
  parallelFor<int>(chans.size(), opt.threads, [&](std::size_t slot, int &) {
    const int ci = chans[slot];
    withContext(record.source + ": channel " + kRecordChannels[ci].name, [&] {
      const Channel &c = kRecordChannels[ci];
      progress::checkpoint(std::string("channel ") + c.name, done,
                           chans.size());
      const fit::SensorSignal sensor = signalOf(c.sensor);
      const std::vector<double> &src = channelData(record, ci);
      std::vector<double> x(src.begin() + static_cast<std::ptrdiff_t>(skip),
                            src.end());
      if (isConstantChannel(x))
        throw InputError(record.source + ": channel " + c.name + " is constant: nothing to fit; leave it out: --axes " +
                         otherChannels(record, ci, ","));
      AxisIdentification ax;
      ax.channel = c.name;
      ax.sensor = sensor;
      ax.axis = std::string(1, "xyz"[c.axis]);
      ax.samples = n;
      ax.rate_hz = record.rate_hz;
      double mean = 0.0;
      for (double v : x)
        mean += v;
      mean /= static_cast<double>(n);
      double var = 0.0;
      for (double &v : x) {
        v -= mean;
        var += v * v;
      }
      ax.mean = mean;
      ax.stddev = std::sqrt(var / static_cast<double>(n));
      // The value lattice (0: none) and, for a quantization term, the lattice its rounding is on.
      const double lattice = latticeStep(x);
      const fit::RoundingLattice rounding{lattice * dt, 0.0, mean * dt};

      AllanOptions ao;
      ao.grid = TauGrid::Octave;
      ao.confidence = opt.confidence;
      ax.allan =
          allanDeviation(x, record.rate_hz, AllanVariant::Overlapping, ao);
      // The record's lines: taken out before the noise terms are fitted (its Allan curve above
      // keeps them: the model's, lines included, is compared with it), or only warned of.
      const auto lines = opt.fitLines ? detail::takeOutLines(x, record.rate_hz)
                                      : detail::recordLines(x, record.rate_hz);
      for (const auto& l : lines) {
        warnings[slot].push_back(std::string(c.name) + ": " + lineMessage(l, sensor, opt.fitLines));
        if (opt.fitLines) ax.written.lines.push_back(l.fitted);
      }
      const CurvePoints pts = detail::usablePoints(
          opt.fitLines && !lines.empty() ? allanDeviation(x, record.rate_hz, AllanVariant::Overlapping, ao)
                                         : ax.allan);

      std::vector<double> den;
      if (opt.denoise == DenoiseChoice::Db5) {
        DenoiseResult d = waveletDenoise(x, opt.denoiseOptions);
        den = std::move(d.signal);
        d.signal.clear();
        ax.denoise = std::move(d);
      }
      const std::vector<double> &forAcf = den.empty() ? x : den;
      const double duration = n * dt;
      const double maxLagS =
          opt.maxLag > 0.0 ? opt.maxLag : std::min(duration / 10.0, 100.0);
      const std::size_t maxLag = std::clamp<std::size_t>(
          static_cast<std::size_t>(
              std::llround(std::min(maxLagS, duration) * record.rate_hz)),
          4, n - 1);
      const Autocorrelation acf =
          autocorrelation(forAcf, record.rate_hz, maxLag, AcfScaling::Biased);
      try {
        ax.correlationTime = fit::correlationTime(acf.r, dt);
      } catch (const InputError &) {
        // the ACF never falls to 1/e within maxLag (drift-dominated record):
        // left unset
      }

      fit::OrderSelectionOptions os;
      os.maxOrder = opt.maxOrder;
      os.criterion = opt.criterion;
      os.forcedOrder = opt.order;
      os.sampleInterval = dt;
      os.navigationStep = opt.navigationStep;
      if (ax.correlationTime)
        os.correlationTime = *ax.correlationTime;

      if (opt.kind == IdentifyKind::Ar || opt.kind == IdentifyKind::Auto) {
        // A (nearly) deterministic record -- a noiseless ramp -- has no stable AR; auto then
        // writes the latent terms (identify_auto.cpp), as --kind gm and latent fit it.
        try {
          ax.ar = fit::selectArOrder(x, os);
        } catch (const InputError& e) {
          if (opt.kind == IdentifyKind::Ar) throw;
          ax.written.notes.push_back(std::string("auto: no AR (") + e.text() + ")");
        }
        // The denoised AR is the paper's variant beside the written one: --kind ar only (auto
        // writes the AR with slow terms, not a bare AR to compare it with).
        if (!den.empty() && opt.kind == IdentifyKind::Ar)
          ax.arDenoised = fit::selectArOrder(den, os);
        const auto& sel = opt.arOnDenoised ? ax.arDenoised : ax.ar;  // the AR written
        if (sel && sel->paperCapped)
          warnings[slot].push_back(
              std::string(c.name) + ": the paper's rule asks for AR order " + std::to_string(*sel->paperOrder) +
              " (T_c " + significant(*sel->correlationTime, 4) + " s): capped at --max-order " +
              std::to_string(opt.maxOrder) + "; a correlation that slow is a slow term, not an AR's "
              "(--kind ar+slow or auto)");
      }

      ax.written.sensor = sensor;
      ax.written.axis = ax.axis;
      ax.written.trendSlope = trendSlope(x, dt);
      ax.written.notes.push_back(
          "mean removed (not written): " + friendly(mean, sensor) + " = " +
          significant(mean, 8) + " (SI); sd " + friendly(ax.stddev, sensor));
      if (ax.correlationTime)
        ax.written.notes.push_back(
            std::string("1/e correlation time of the ") +
            (den.empty() ? "raw" : "denoised") +
            " ACF: " + significant(*ax.correlationTime * 1e3, 4) + " ms");
      else
        ax.written.notes.push_back(
            std::string("the ") + (den.empty() ? "raw" : "denoised") +
            " ACF stays above 1/e up to its largest lag (" + significant(maxLag * dt, 4) +
            " s): the paper's rule takes T_c from each fitted series' AR (its MDL order)");
      if (ax.denoise)
        ax.written.notes.push_back(
            "db5 denoise: level " + std::to_string(ax.denoise->level) +
            ", noise sigma " + friendly(ax.denoise->sigma, sensor) +
            ", finest threshold " +
            friendly(ax.denoise->thresholds.empty() ? 0.0
                                                    : ax.denoise->thresholds[0],
                     sensor));

      switch (opt.kind) {
      case IdentifyKind::Ar: {
        const fit::OrderSelection &use =
            opt.arOnDenoised ? *ax.arDenoised : *ax.ar;
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
          // Only a comparison: a white-dominated record's ACF past lag 0 is
          // estimation noise and may not decay at all; that must not fail the
          // composite fit, which is what is written.
          try {
            ax.gaussMarkov = fit::fitGaussMarkov(acf.r, dt, go);
            ax.written.notes.push_back(
                "for comparison, GM from the ACF (not written): sigma " +
                friendly(ax.gaussMarkov->sigma, sensor) + ", tau " +
                significant(ax.gaussMarkov->tau, 4) + " s");
          } catch (const InputError &e) {
            ax.written.notes.push_back(
                std::string("for comparison, no GM from the ACF: ") + e.text());
          }
        }
        fit::LatentFitOptions lo;
        lo.sampleInterval = dt;
        lo.scanStart = true;
        lo.lattice = rounding;
        if (opt.kind == IdentifyKind::Gm)
          lo.minGmTauSamples = 2.0;
        if (opt.kind == IdentifyKind::Gm) {
          lo.candidates = {{false, false, 1, false, false, false},
                           {false, true, 1, false, false, false},
                           {false, false, 1, false, true, false},
                           {false, true, 1, false, true, false}};
          // On a value lattice, the quantization beside them (carried increments: rounded
          // correlated, their Allan variance falls as 1/tau^2); without it the model lacked the
          // rounding noise at short tau (0.3x the record's ADEV at one sample) or wrote it as
          // white rounding of each sample.
          if (lattice > 0.0) {
            lo.candidates.push_back({true, true, 1, false, false, false});
            lo.candidates.push_back({true, true, 1, false, true, false});
          }
        }
        ax.latent = fit::fitLatentModel(x, lo);
        ax.kind = opt.kind;
        ax.written.latent = ax.latent;
        for (const auto &w : ax.latent->warnings)
          warnings[slot].push_back(std::string(c.name) + ": " + w);
        break;
      }
      case IdentifyKind::ArSlow: {
        fit::ArSlowFitOptions so;
        so.sampleInterval = dt;
        so.order = os;
        so.scanStart = true;
        ax.arSlow = fit::fitArPlusSlow(x, so);
        ax.latent = ax.arSlow->joint;
        ax.kind = IdentifyKind::ArSlow;
        ax.written.latent = ax.latent;
        ax.written.notes.push_back(describeArSlow(*ax.arSlow, sensor));
        for (const auto &w : ax.latent->warnings)
          warnings[slot].push_back(std::string(c.name) + ": " + w);
        break;
      }
      case IdentifyKind::Allan: {
        const RangedFit r = detail::fitTermsFrom(
            pts, dt, n, {true, true, true, true, true}, 0.0, 7);
        ax.allanFit = r.fit;
        ax.written.notes.push_back("Allan-term fit range: " +
                                   detail::describeRange(r));
        ax.kind = IdentifyKind::Allan;
        ax.written.allan = ax.allanFit;
        break;
      }
      case IdentifyKind::Auto:
        detail::chooseAuto(ax, x, pts, dt, rounding, os, opt);
        for (const auto &d : ax.decision)
          ax.written.notes.push_back("auto: " + d);
        if (ax.arSlow)
          ax.written.notes.push_back(describeArSlow(*ax.arSlow, sensor));
        if (ax.latent)
          for (const auto &w : ax.latent->warnings)
            warnings[slot].push_back(std::string(c.name) + ": " + w);
        break;
      }

      if (ax.kind == IdentifyKind::Ar)
        if (std::string w = arLongTauWarning(ax); !w.empty()) warnings[slot].push_back(std::string(c.name) + ": " + w);
      if (ax.arDenoised && ax.ar && ax.written.ar) {
        const auto &other = opt.arOnDenoised ? *ax.ar : *ax.arDenoised;
        std::string s = std::string("for comparison, AR(") +
                        std::to_string(other.fit.order) + ") on the " +
                        (opt.arOnDenoised ? "raw" : "denoised") +
                        " record: a = [";
        for (std::size_t i = 1; i < other.fit.a.size(); ++i)
          s += (i > 1 ? ", " : "") + significant(other.fit.a[i], 6);
        s += "], driving sigma " +
             friendly(std::sqrt(other.fit.drivingVariance), sensor) +
             " (written: " +
             friendly(std::sqrt(ax.written.ar->drivingVariance), sensor) + ")";
        ax.written.notes.push_back(s);
      }
      // The settling test needs a model of the record's slow part: the composite fits have one
      // (an AR alone does not: against it, every record's slow wander would be a settling).
      if (ax.latent) {
        ax.settling = fit::testStartSettling(x, dt, ax.latent->model);
        if (ax.settling && ax.settling->pValue < fit::kStartSettlingP)
          warnings[slot].push_back(std::string(c.name) + ": " +
                                   settlingMessage(*ax.settling, sensor, record.skipped_s + double(skip) * dt,
                                                   double(n) * dt));
      }
      writeVisibleLattice(ax.written, x, ax.stddev, lattice, dt);
      const double Q = writtenQuantization(ax.written);
      ax.written.ditheredQuantization = Q > 0.0 && quantizationIsDithered(Q, lattice, dt);
      if (ax.written.latent && Q > 0.0 && !ax.written.ditheredQuantization)
        ax.written.latticeLsb = latticeLsb(Q, lattice, dt);
      axes[slot] = std::move(ax);
      ++done;
    });
  });
  for (std::size_t k = 0; k < chans.size(); ++k) {
    out.axes.push_back(std::move(axes[k]));
    out.warnings.insert(out.warnings.end(), warnings[k].begin(),
                        warnings[k].end());
  }
  for (std::string& w : recordWarnings(record)) out.warnings.push_back(std::move(w));
  if (std::string w = shortRecordWarning(record); !w.empty()) out.warnings.push_back(std::move(w));
  return out;
}

}  // namespace

Identification identify(const Record& record, const IdentifyOptions& opt) {
  Identification first = identifyOnce(record, opt);
  if (!opt.skipAuto) return first;
  // The slowest settling decides: one skip serves every channel of the record.
  double settle = 0.0;
  std::string which;
  for (const AxisIdentification& ax : first.axes)
    if (ax.settling && ax.settling->pValue < fit::kStartSettlingP) {
      settle = std::max(settle, ax.settling->settledAfter);
      which += (which.empty() ? "" : ", ") + ax.channel;
    }
  if (settle == 0.0) {
    first.warnings.push_back("--skip auto: no channel starts with a settling; nothing more skipped");
    return first;
  }
  const double used = first.duration();
  if (settle > 0.5 * used) {
    first.warnings.push_back("--skip auto: not applied: the settling of " + which + " lasts " + significant(settle, 3) +
                             " s, more than half of the " + significant(used, 4) + " s used");
    return first;
  }
  IdentifyOptions again = opt;
  again.skipStart = opt.skipStart + settle;
  again.skipAuto = false;
  Identification second = identifyOnce(record, again);
  second.warnings.insert(second.warnings.begin(),
                         "--skip auto: fitted from " + significant(record.skipped_s + again.skipStart, 4) +
                             " s of the file on (" + significant(settle, 3) + " s more skipped for the settling of " +
                             which + "), where the first fit said:");
  std::ptrdiff_t at = 1;
  for (const std::string& w : first.warnings)
    if (w.find("starts with a settling") != std::string::npos)
      second.warnings.insert(second.warnings.begin() + at++, "  " + w);
  return second;
}

}  // namespace sinsim::errormodels
