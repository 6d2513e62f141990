// Turns fitted results into an ErrorModelSpec (per sensor and axis, a list of effects with SI values
// and their 1-sigma uncertainties), with the fit's provenance and uncertainties as comment lines.
// The text is written by the one model writer (errormodels/model_io.hpp); the file is read back by
// ImuErrorModel::load like any hand-written model.
//
// What is written, per axis (SI inside, friendly units in the file):
//   ar               a: [a1..ap], sigma = sqrt(E) (driving-noise STANDARD DEVIATION), rate
//   gauss_markov     sigma, tau
//   white            density = N                     (Allan term)
//   random_walk      K                               (Allan term or composite fit)
//   bias_instability B, tau_range = the tau span of the Allan points used
//   quantization     lsb = sqrt(12) Q as an increment LSB (angle / velocity): uniform rounding of
//                    the integrated signal with step q gives AVAR 3 (q^2/12) / tau^2 (IEEE Std
//                    952-1997 Annex C, quantization noise: Q = q / sqrt(12))
//   ramp             slope = R
// Allan terms are written only when detected; the others appear as comments with their upper
// bounds. Gyro values are in rad/s-based SI inside and written in deg-based units; accelerometer
// values in m/s^2-based SI, written in m/s-based units (mg / ug for levels).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "errormodels/fit/allan_fit.hpp"
#include "errormodels/fit/composite_fit.hpp"
#include "errormodels/fit/gauss_markov_fit.hpp"
#include "errormodels/fit/latent_fit.hpp"
#include "errormodels/fit/order_selection.hpp"
#include "errormodels/stats/line_fit.hpp"
#include "errormodels/model_spec.hpp"

namespace sinsim::errormodels::fit {

enum class SensorSignal { Gyro, Accel };

/// The fits to write for one axis of one sensor; any subset.
struct AxisFitResult {
  SensorSignal sensor = SensorSignal::Gyro;
  std::string axis = "x";  ///< "x", "y", "z" (or "all")
  std::optional<ArFit> ar;
  double arRate = 0.0;  ///< [Hz] the rate the AR was fitted at (required with ar)
  std::optional<OrderSelection> arOrders;  ///< criteria table, for the provenance comment
  std::optional<GaussMarkovFit> gaussMarkov;
  std::optional<AllanFit> allan;
  /// Allan terms to consider (Q, N, B, K, R); detected ones among them are written. Turn the
  /// white term off when an AR model already carries the short-term noise.
  std::array<bool, kAllanTermCount> allanWrite{true, true, true, true, true};
  std::optional<ArRandomWalkFit> composite;  ///< writes its AR and (if detected) its K
  /// Composite latent-process fit (latent_fit.hpp): every term of its chosen set, GM terms with
  /// `rate:` = the record's rate (the discrete AR(1) the fit modelled), 1-sigma and fit quality
  /// as comments.
  std::optional<LatentFit> latent;
  std::vector<std::string> notes;            ///< extra comment lines for this axis
  /// Write a fitted quantization term as `dithered: true` (a fresh uniform remainder each sample,
  /// effects/quantization.cpp): the record shows no value lattice that rounding at its LSB would
  /// leave (quantizationIsDithered, identify.cpp), so its Allan slope -1 is quantization noise of a
  /// busy input; carried rounding at that LSB would realise a pulse train instead.
  bool ditheredQuantization = false;
  /// The record's value lattice as an increment LSB [signal s]: its step (stats/lattice.hpp) times
  /// the sample interval, where the composite fit's quantization is within 1.5x of it and not
  /// dithered (latticeLsb, identify.cpp). Written as the lsb, exact, in place of the Allan fit's
  /// (which strong rounding biases low: successive rounding errors are correlated); 0: none.
  double latticeLsb = 0.0;
  /// The record's value lattice [signal] where no fitted term rounds onto it and the diagnosis
  /// would see it (writeVisibleLattice, identify.cpp): written as a quantization of that rate LSB,
  /// each sample rounded; 0: none.
  double roundedRateLsb = 0.0;
  /// Narrow lines taken out of the record before the terms above were fitted, written as
  /// `sinusoid` effects (identify_lines.hpp).
  std::vector<FittedLine> lines;
  /// [signal/s] The least-squares trend of the fitted series (stats/trend.hpp): the sign of a written
  /// ramp (the Allan variance gives a drift's square only, its sign is the record's); 0 reads as +.
  double trendSlope = 0.0;
};

struct ModelProvenance {
  std::string description;  ///< the file's `description:` value
  std::string dataFile;
  double rate = 0.0;         ///< [Hz] of the record
  double duration = 0.0;     ///< [s]
  std::string method;        ///< e.g. "db5 denoise + Burg AR(5), MDL"
  std::vector<std::string> notes;
};

/// The model as a value. Throws InputError when an axis entry is unusable (AR without rate, bad
/// axis, an axis given twice).
ErrorModelSpec modelSpec(const std::vector<AxisFitResult>& axes, const ModelProvenance& provenance);

/// The YAML text (errorModelYaml(modelSpec(...))). Throws InputError when an axis entry is unusable (AR without rate, bad axis).
std::string modelYaml(const std::vector<AxisFitResult>& axes, const ModelProvenance& provenance);

/// Writes the model to `path` via a temporary file renamed into place, so a failure never
/// leaves a half-written model. Throws sinsim::Error on I/O failure.
void writeModelFile(const std::string& path, const std::vector<AxisFitResult>& axes,
                    const ModelProvenance& provenance);

}  // namespace sinsim::errormodels::fit
