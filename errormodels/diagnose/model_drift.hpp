// The model's known drift: a `ramp` (R t), a `warmup` (A exp(-t/tau)) and, on a record with a
// temperature column, a `temperature` polynomial in the model are deterministic, with no scatter.
// The diagnosis takes them out of the record and out of the model before comparing them, so that
// what is compared is the rest, and a drift the record shows beyond the model's own (a slope off
// by dR, a warm-up of another size, another temperature coefficient; or of the other sign: the
// Allan variance cannot tell R from -R) is found as a `ramp`, `warmup` or `temperature` of what
// is beyond, which `--add` writes beside the model's own (the two add).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "errormodels/diagnose/diagnose.hpp"
#include "errormodels/model_spec.hpp"
#include "errormodels/stats/record.hpp"

namespace sinsim::errormodels::diagnose::detail {

/// One channel's deterministic drift in the model (its enabled effects of the `all` list and the
/// axis' own): the summed slope of its ramps [SI/s], its warm-ups, whether it has a temperature
/// polynomial (counted only when `withTemperature`: the record has a temperature column).
struct ChannelDrift {
  double slope = 0.0;
  std::vector<ModelWarmup> warmups;
  bool temperature = false;
  bool any() const { return slope != 0.0 || !warmups.empty() || temperature; }
};

/// A record and a model with the model's deterministic drift taken out: channel c of the record
/// less that drift as the model's realisations hold it (the model's ramps, warm-ups and
/// temperature polynomials alone, realised by simulateRecord on the record's samples and
/// temperatures; the offset is the record's level, which the comparison does not see), those
/// effects disabled in the model; the record keeps its name. A channel whose values lie on a
/// lattice the diagnosis sees (latticeVisible) keeps them in both (drift[c] empty; the model's
/// drift effects of that axis put back on it after its other effects): less a drift, its values
/// would leave the lattice and their rounding would read as white noise. None when no channel's
/// drift is taken out.
struct DriftFree {
  Record record;
  ErrorModelSpec model;
  std::array<ChannelDrift, 6> drift{};
};
std::optional<DriftFree> withoutModelDrift(const Record& record, const ErrorModelSpec& model);

/// States on each axis of `d` the drift taken out (AxisDiagnosis::modelDrift, ::modelWarmups,
/// ::modelTemperature) and, in a `ramp` finding's evidence, the record's whole drift (the model's
/// and the finding's slopes summed); in a `warmup` or `temperature` finding's, that it is beyond
/// the model's own.
void stateModelDrift(Diagnosis& d, const std::array<ChannelDrift, 6>& drift);

}  // namespace sinsim::errormodels::diagnose::detail
