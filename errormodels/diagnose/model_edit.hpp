// What the diagnosis reads from the model (ErrorModelSpec) beyond its effect types, and the
// change improve() makes to it: functions on specs, never on text.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "errormodels/diagnose/candidate.hpp"
#include "errormodels/model_spec.hpp"

namespace sinsim::errormodels::diagnose::detail {

/// The `ar` effect of channel c (0..5 = gx..az) as [1, a1..ap] when exactly one enabled `ar` acts
/// on the channel (its axis list or `all`) and it runs at the record's rate [Hz] (to 1e-6
/// relative); nullopt otherwise.
std::optional<std::vector<double>> baseAr(const ErrorModelSpec& model, int channel, double rate);

/// baseAr when that `ar` is the channel's whole base (no other enabled effect acts on it): the
/// AR then stands for all of the record's noise, as the seed paper's fit makes it, and may be
/// refitted on the record with added effects taken out. Beside other terms (white noise, a
/// lattice, slow terms) a Burg refit on the record would take their noise into the AR as well,
/// and the model would count it twice.
std::optional<std::vector<double>> soleBaseAr(const ErrorModelSpec& model, int channel, double rate);

/// The enabled `sinusoid` effects acting on channel c (0..5 = gx..az; its axis list or `all`):
/// frequency [Hz] and amplitude [SI], Line::model set. A line the record shows at one of them is
/// the model's own (detectors/sinusoid.cpp treats them as lines taken), not a line the model
/// lacks, unless the record's is more than twice as large.
std::vector<Line> modelLines(const ErrorModelSpec& model, int channel);

/// What improve() changes, per channel (0..5 = gx..az).
struct ModelEdits {
  std::array<std::vector<EffectSpec>, 6> add;                  ///< appended to the axis list
  std::array<double, 6> varianceScale{1, 1, 1, 1, 1, 1};      ///< of the base noise
  /// When non-empty: the channel's `ar` gets coefficients a1..ap and driving sigma (the last
  /// element, SI) in place of its own (output_sigma dropped).
  std::array<std::vector<double>, 6> arReplace;
};

/// model with the edits. On a sensor whose axes are scaled or refitted, the noise effects of
/// `all` (ar, white, gauss_markov, random_walk, bias_instability) move to the three axis lists
/// (ahead of each axis's own effects, in their order) so that each axis gets its own level; the
/// noise keys (sigma, output_sigma, density, K, B, floor) are multiplied by sqrt(variance
/// factor); the added effects come last. List order decides the random streams
/// (imu_model.cpp), so the order is part of the result. The result is a new model: its source
/// locations are cleared (messages about it must not point into the original's file). Throws
/// InputError for a variance factor that is not positive.
ErrorModelSpec editedModel(ErrorModelSpec model, const ModelEdits& edits);

/// si rounded to `digits` significant digits in `unit` (a unit of common/units.hpp): a size as
/// the diagnosis states it, and as the improved model then holds it.
double stated(double si, const char* unit, int digits = 6);

}  // namespace sinsim::errormodels::diagnose::detail
