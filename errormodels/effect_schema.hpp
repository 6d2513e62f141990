// The parameters an effect accepts, declared by each effect plug-in next to its implementation
// (errormodels/effects/<type>.cpp). The one reader converts YAML by it, the one writer chooses units
// and digits by it, ImuErrorModel::fromSpec checks a spec built in code by it, and
// docs/model-format.md lists it (a test checks that the document names every parameter).
//
//   const std::vector<ParamSchema>& paramsOf_white() {
//     static const std::vector<ParamSchema> p = {
//         param("density", ParamKind::quantity, signal(Dimension::time().sqrt())).oneOf(1).positive()
//             .doc("noise density N (ARW / VRW)"),
//         param("sigma", ParamKind::quantity, signal()).oneOf(1).positive().doc("..."),
//         param("rate", ParamKind::quantity, fixed(Dimension::frequency())).optional().positive()};
//     return p;
//   }
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "common/units.hpp"
#include "errormodels/model_spec.hpp"

namespace sinsim::errormodels {

/// The dimension of a parameter value: the sensor's signal dimension (angular rate for the gyro,
/// acceleration for the accelerometer) to the power signalPower, times `times`; for a list with
/// perItemTemperature, item k (0-based) is further divided by temperature^(k+1) (polynomial
/// coefficients in T - T0).
struct DimRule {
  int signalPower = 0;
  Dimension times;
  bool perItemTemperature = false;
  Dimension of(Sensor sensor, int item = 0) const;
};
/// signal · times (e.g. signal(Dimension::time().sqrt()) is a noise density).
DimRule signal(Dimension times = Dimension::none());
/// A dimension that does not depend on the sensor (time, frequency, plain number).
DimRule fixed(Dimension d);

/// Whether a parameter must be given.
enum class Need {
  required,  ///< always
  optional,  ///< may be absent
  oneOf,     ///< exactly one of the parameters with the same group number
};
/// The range a value must lie in (NaN is refused by every bound but any).
enum class Bound { any, positive, nonNegative };

/// One parameter of an effect.
struct ParamSchema {
  std::string key;
  ParamKind kind = ParamKind::quantity;
  DimRule dim;                ///< the dimension its values must have
  DimRule alt;                ///< a second accepted dimension when hasAlt
  bool hasAlt = false;
  bool plainZero = false;     ///< a plain 0 is accepted whatever the dimension (matrix entries)
  Need need = Need::required;
  int group = 0;              ///< for Need::oneOf
  Bound bound = Bound::any;
  int count = 0;              ///< list: exact number of values (0: one or more)
  int maxCount = 0;           ///< list: at most this many values (0: no limit)
  int digits = 9;             ///< significant digits the writer prints
  std::string fallback;       ///< the value when absent, as the docs state it ("" for none)
  std::string help;           ///< one line for docs/model-format.md
  /// What a value of the wrong dimension is told it should be, with {0} and {1} standing for
  /// example units of dim and alt ("" for the plain "expected a value in {0}").
  std::string expecting;

  ParamSchema& optional(std::string fallbackText = "") {
    need = Need::optional;
    fallback = std::move(fallbackText);
    return *this;
  }
  ParamSchema& oneOf(int g) { need = Need::oneOf; group = g; return *this; }
  ParamSchema& positive() { bound = Bound::positive; return *this; }
  ParamSchema& nonNegative() { bound = Bound::nonNegative; return *this; }
  ParamSchema& orDim(DimRule d) { alt = d; hasAlt = true; return *this; }
  ParamSchema& zeroWithoutUnit() { plainZero = true; return *this; }
  ParamSchema& items(int n) { count = n; return *this; }
  ParamSchema& atMost(int n) { maxCount = n; return *this; }
  ParamSchema& printed(int significantDigits) { digits = significantDigits; return *this; }
  ParamSchema& doc(std::string text) { help = std::move(text); return *this; }
  ParamSchema& expect(std::string words) { expecting = std::move(words); return *this; }

  /// Does value item `item` of dimension d fit this parameter on `sensor`?
  bool accepts(Dimension d, Sensor sensor, int item = 0) const;
};

/// A required parameter; chain .optional(), .oneOf(g), .positive(), ... to refine it.
ParamSchema param(std::string key, ParamKind kind, DimRule dim);

/// Problems an effect finds in a spec, each at a parameter key ("" for the effect as a whole, or
/// "key[i]" for one item). The reader turns them into file/line/key diagnostics.
struct SpecProblems {
  std::vector<std::pair<std::string, std::string>> items;  ///< (key, message)
  void add(std::string key, std::string message) {
    items.emplace_back(std::move(key), std::move(message));
  }
  bool empty() const { return items.empty(); }
};

/// Checks a spec's parameters against a schema: unknown keys, presence (required, one of a group),
/// kinds, list lengths, dimensions and bounds. Records each problem and returns whether there was
/// none. The reader has already refused what it could not convert; this is the check a spec built
/// in code goes through too.
bool checkParameters(const EffectSpec& spec, const std::vector<ParamSchema>& schema, Sensor sensor,
                     SpecProblems& problems);

}  // namespace sinsim::errormodels
