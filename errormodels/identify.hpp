// The identify pipeline as one library call: a static record goes in, per-axis statistics and
// fits come out, and a model file the simulator reads directly (ImuErrorModel::load).
//
//   record -> [skip warm-up] -> per channel: mean removed -> overlapping ADEV (raw, octave tau,
//   Greenhall EDF) -> [db5 denoise] -> ACF (correlation time) -> fit by kind -> model YAML
//
// Kinds (IdentifyOptions::kind):
//   Ar     Burg AR(p) on the raw, demeaned record; order forced or by criterion (MDL default).
//   Gm     white + first-order Gauss-Markov (+ random walk when selected): the composite
//          latent-process fit (fit/latent_fit.hpp) over the sets {gm, white + gm, gm + rw,
//          white + gm + rw}. The ACF GM fit (Bartlett covariance) is kept beside it for
//          comparison (AxisIdentification::gaussMarkov), not written.
//   Latent the composite latent-process fit over all 48 term sets (white, quantization, 0-2 GM,
//          flicker, random walk, drift), chosen by BIC; docs/fitting.md.
//   ArSlow Burg AR(p) for the short tau plus slow terms (GM, random walk, flicker) selected and
//          fitted beside it on the Allan variance, the AR's driving variance refitted jointly
//          (fit/ar_slow_fit.hpp); written as an `ar` effect plus the slow terms' effects.
//   Allan  IEEE 952 five-term fit (Q, N, B, K, R) of the Allan variance, correlated-point GLS;
//          only detected terms are written.
//   Auto   what the data ask for (the rule is stated in identify_auto.cpp, above chooseAuto, and
//          in docs/identify.md): the Latent fit, unless the record has short correlation its
//          terms do not carry (an AR predicts the next sample >= 2 % better, or the terms fail
//          the Allan curve where the past predicts); then ArSlow, the AR with the slow terms.
//
// Bias. A static record's mean is the turn-on bias plus the projection of Earth rate (gyro) or
// gravity (accelerometer); one record holds ONE draw of the turn-on bias, not its spread. The
// mean is removed before every fit, reported per axis (AxisIdentification::mean) and written as a
// comment, never as an effect: a `bias` effect with that value would also carry gravity / Earth
// rate, and a `bias sigma` cannot be estimated from one record.
//
// Denoising (the paper's step 2: db5 before looking at the ACF). Denoising removes most of the
// white noise, so an AR fitted on denoised data has a driving variance far below the sensor's
// (the simulated output would be too quiet). The AR that is WRITTEN is therefore fitted on the raw
// record (it must reproduce what a navigation filter sees); with denoise = Db5 the ACF / T_c are
// those of the denoised signal (the paper's figures) and a second AR fitted on the denoised
// signal is reported beside it (AxisIdentification::arDenoised) and as a comment.
// IdentifyOptions::arOnDenoised = true writes the paper's variant instead (and says so).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "errormodels/fit/allan_fit.hpp"
#include "errormodels/fit/ar_slow_fit.hpp"
#include "errormodels/fit/composite_fit.hpp"
#include "errormodels/fit/gauss_markov_fit.hpp"
#include "errormodels/fit/model_writer.hpp"
#include "errormodels/fit/order_selection.hpp"
#include "errormodels/fit/start_settling.hpp"
#include "errormodels/stats/allan.hpp"
#include "errormodels/stats/record.hpp"
#include "errormodels/stats/wavelet.hpp"

namespace sinsim::errormodels {

enum class IdentifyKind { Ar, Gm, Allan, Auto, Latent, ArSlow };
std::string toString(IdentifyKind kind);  ///< "ar", "gm", "allan", "auto", "latent", "ar+slow"
IdentifyKind identifyKindByName(const std::string& name);   ///< InputError listing the known ones
/// IdentifyOptions::fitLines from `--lines` fit | warn; InputError otherwise.
bool fitLinesByName(const std::string& name);
/// "mdl" | "bic" | "aic" | "fpe" | "paper" -> criterion; InputError otherwise.
fit::OrderCriterion orderCriterionByName(const std::string& name);

enum class DenoiseChoice { None, Db5 };

struct IdentifyOptions {
  /// Channels to fit: "gx", "gy", "gz", "ax", "ay", "az". Empty: every one the record has.
  std::vector<std::string> axes;
  IdentifyKind kind = IdentifyKind::Auto;
  /// Forced AR order (>= 1); unset: chosen by `criterion` over 0..maxOrder.
  std::optional<std::size_t> order;
  fit::OrderCriterion criterion = fit::OrderCriterion::MDL;
  std::size_t maxOrder = 20;
  /// [s] navigation step of the paper's order rule (always reported; selects only with
  /// criterion PaperRule).
  double navigationStep = 0.01;
  DenoiseChoice denoise = DenoiseChoice::None;
  /// db5 settings when denoise = Db5 (wavelet name, boundary, level, threshold rule, mode).
  DenoiseOptions denoiseOptions;
  /// Write the AR fitted on the denoised signal (the paper's literal pipeline) instead of the
  /// one fitted on the raw record. Needs denoise = Db5 and kind = Ar.
  bool arOnDenoised = false;
  /// [s] discard this much from the start of the record (e.g. a warm-up transient).
  double skipStart = 0.0;
  /// After the fit, where a channel's record starts with a settling (fit/start_settling.hpp),
  /// fit again from where the slowest of them has settled (`fit --skip auto`), unless that is
  /// more than half the record; said in Identification::warnings either way.
  bool skipAuto = false;
  /// Two-sided confidence level of the Allan bounds.
  double confidence = 0.683;
  /// Largest ACF lag [s] for T_c and the GM fit; 0: min(duration / 10, 100 s).
  double maxLag = 0.0;
  /// Auto: the AR (with slow terms) is written when the terms' one-step prediction variance is
  /// >= this x the AR's E_p, or the terms fail the Allan curve and r0 / E_p >= this
  /// (identify_auto.cpp).
  double autoMinPredictionGain = 1.02;
  /// Worker threads over the channels (0: every core); the result does not depend on it.
  unsigned threads = 0;
  /// Narrow lines (a vibration, a test stand's oscillation) fitted as sinusoids, taken out of the
  /// record before its noise terms are fitted and written beside them (identify_lines.hpp); false:
  /// left in the record (its terms absorb them), with a warning.
  bool fitLines = true;
};

/// Results for one channel. Units: SI of the channel (rad/s for gyro, m/s^2 for accelerometer).
struct AxisIdentification {
  std::string channel;                                     ///< "gx"
  fit::SensorSignal sensor = fit::SensorSignal::Gyro;
  std::string axis;                                        ///< "x", "y" or "z"
  std::size_t samples = 0;
  double mean = 0.0;    ///< [U] removed before fitting (turn-on bias + Earth rate / gravity)
  double stddev = 0.0;  ///< [U] of the raw record around the mean
  AllanCurve allan;     ///< overlapping ADEV of the raw record, octave tau, with bounds
  /// [s] 1/e correlation time of the (denoised if asked) ACF; unset when never reached.
  std::optional<double> correlationTime;
  std::optional<DenoiseResult> denoise;  ///< signal cleared (only level, sigma, thresholds kept)

  IdentifyKind kind = IdentifyKind::Auto;  ///< what was written (never Auto)
  std::vector<std::string> decision;       ///< why (Auto), one line per step

  std::optional<fit::OrderSelection> ar;           ///< AR on the raw record (criteria table)
  std::optional<fit::OrderSelection> arDenoised;   ///< AR on the denoised signal (denoise = Db5)
  std::optional<fit::ArRandomWalkFit> composite;   ///< AR + random walk (Auto)
  std::optional<fit::GaussMarkovFit> gaussMarkov;
  std::optional<fit::LatentFit> latent;            ///< composite latent fit (Gm, Latent, ArSlow)
  std::optional<fit::ArSlowFit> arSlow;            ///< AR + slow terms (ArSlow)
  std::optional<fit::AllanFit> allanFit;           ///< five-term fit of the whole curve
  /// Allan terms fitted beside an AR on the long-tau part (Auto); the AR carries N and Q.
  std::optional<fit::AllanFit> allanLongTau;
  /// The start-settling test against the written composite model (fit/start_settling.hpp; `gm`,
  /// `latent`, `ar+slow`, `auto`); unset where it was not run (`ar` and `allan`, whose models
  /// hold no slow part to test against; an AR slow at the block scale; fewer than 64 blocks).
  std::optional<fit::StartSettling> settling;

  fit::AxisFitResult written;  ///< exactly what goes into the model file for this axis

  /// Allan deviation [U] of the written model at tau (each a multiple of 1 / record rate, > 0):
  /// AR (exact, arAllanVariance) + GM (closed form, IEEE 952 C) + written Allan terms (their
  /// asymptotes). The prediction a diagnosis compares with a measured curve.
  std::vector<double> modelAdev(const std::vector<double>& tau) const;

  double rate_hz = 0.0;  ///< [Hz] of the record
};

struct Identification {
  std::string source;         ///< data file as given
  double rate_hz = 0.0;       ///< [Hz]
  std::size_t samples = 0;    ///< samples used (after skipStart)
  std::size_t skipped = 0;    ///< samples dropped at the start
  /// [s] of the file the reader's --skip dropped before (Record::skipped_s); the model's notes
  /// state both (the CLI's `fit --skip` cuts in the reader, the Python module's skip= in the fit).
  double fileSkipped_s = 0.0;
  double duration() const { return rate_hz > 0 ? samples / rate_hz : 0.0; }  ///< [s] used
  IdentifyOptions options;
  std::vector<AxisIdentification> axes;
  /// Sanity findings (also in the model's comments): GM tau outside [2 dt, duration / 3], a
  /// parameter less certain than its value, an accelerometer mean that looks like g units read
  /// as m/s^2.
  std::vector<std::string> warnings;

  const AxisIdentification& axis(const std::string& channel) const;  ///< InputError if absent
  std::string method() const;  ///< one line: kind, denoise, criterion/order
  fit::ModelProvenance provenance() const;
  /// The written model as a value: what the diagnosis and the simulator take
  /// (ImuErrorModel::fromSpec), with the fit's provenance and uncertainties.
  ErrorModelSpec modelSpec() const;
  /// Its text (the one model writer, errormodels/model_io.hpp).
  std::string modelYaml() const;
  /// Writes modelYaml() via a temporary file renamed into place (never half-written).
  void writeModel(const std::string& path) const;
};

/// Runs the pipeline. Throws InputError for: an unknown or absent channel, a record too short
/// for the fits (after skipStart), inconsistent options (arOnDenoised without denoise, order 0,
/// maxOrder too large, skipStart beyond the record), and whatever the fits refuse.
Identification identify(const Record& record, const IdentifyOptions& options = {});

}  // namespace sinsim::errormodels
