// The model's known drift: a `ramp` in the model is a deterministic line, R t, with no scatter.
// The diagnosis takes it out of the record and out of the model before comparing them, so that
// what is compared is the rest, and a drift the record shows beyond the model's own (a slope off
// by dR, or of the other sign: the Allan variance cannot tell R from -R) is found as a `ramp` of
// slope dR, which `--add` writes beside the model's own (the slopes add).
#pragma once

#include <array>
#include <optional>

#include "errormodels/diagnose/diagnose.hpp"
#include "errormodels/model_spec.hpp"
#include "errormodels/stats/record.hpp"

namespace sinsim::errormodels::diagnose::detail {

/// The summed slope of the enabled ramps on each channel gx..az [SI/s] (the `all` list's and the
/// axis' own).
std::array<double, 6> modelDrifts(const ErrorModelSpec& model);

/// A record and a model with the model's ramps taken out: channel c of the record less
/// drift[c] (k + 1) dt (the ramp as the model's realisations hold it, t from 0 at the first
/// sample's end; the offset is the record's level, which the comparison does not see), the
/// model's ramps disabled; the record keeps its name. A channel whose values lie on a lattice the
/// diagnosis sees (latticeVisible) keeps its ramp in both (drift[c] = 0; the model's ramps of that
/// axis summed into one after its other effects). None when no channel's ramp is taken out.
struct DriftFree {
  Record record;
  ErrorModelSpec model;
  std::array<double, 6> drift{};
};
std::optional<DriftFree> withoutModelDrift(const Record& record, const ErrorModelSpec& model);

/// States on each axis of `d` the drift taken out (AxisDiagnosis::modelDrift) and, in a `ramp`
/// finding's evidence, the record's whole drift (the model's and the finding's slopes summed).
void stateModelDrift(Diagnosis& d, const std::array<double, 6>& drift);

}  // namespace sinsim::errormodels::diagnose::detail
