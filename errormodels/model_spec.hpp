// ErrorModelSpec: an IMU error model as a value — what a model file says, in SI, with no YAML.
//
// It is the one type that travels between the identify path (fit → ErrorModelSpec), the diagnosis
// (reads and edits a spec) and the simulator (ImuErrorModel::fromSpec). Text enters once through
// the reader (model_reader.hpp: YAML → spec, every problem with file, line and key path) and
// leaves once through the writer (model_writer.hpp: spec → YAML with units chosen per quantity).
//
// Layout (the model-file layout, docs/model-format.md):
//   description, header comment lines (provenance)
//   gyro / accel: lists triad, all, x, y, z; each an ordered list of EffectSpec
// An EffectSpec is its registry type name (`type:` in the file, effects/effects.def), its
// parameters in file order with their values in SI, `enabled`, an optional note, and the comment
// lines the writer puts above it. Changes are functions on values (withEffect, withoutEffects,
// scaleParameter): they return a new spec and never touch text.
//
// Equality (operator==) compares everything that is written to or read from a file: values,
// dimensions, order, enabled, notes, comments and the 1-sigma uncertainties. It ignores where a
// value was read from (SourceLocation), so a spec read from two differently laid out files that
// say the same thing compares equal.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "common/units.hpp"

namespace sinsim::errormodels {

enum class Sensor { gyro = 0, accel = 1 };
/// The five effect lists of a sensor, in the order the reader and the writer visit them. `all`
/// holds effects applied to each of x, y, z independently (own random streams per axis); `triad`
/// holds 3×3 effects (scale factor, misalignment, g-sensitivity).
enum class EffectList { triad = 0, all = 1, x = 2, y = 3, z = 4 };

/// "gyro" / "accel".
const char* sensorName(Sensor s);
/// "triad", "all", "x", "y", "z".
const char* listName(EffectList l);
/// The list of axis 0, 1, 2 (x, y, z).
EffectList axisList(int axis);

/// Where a value was read from (for messages); line 0 when it did not come from a file.
struct SourceLocation {
  std::string file;  ///< as the user named it; empty when built in code
  int line = 0;      ///< 1-based
  std::string key;   ///< YAML key path, e.g. "gyro.x[0].a"
  std::string text;  ///< a scalar's text as written ("-3 s"), for messages; empty otherwise
};

/// What kind of value a parameter holds (the effect's schema says which kinds a key accepts).
enum class ParamKind {
  quantity,  ///< one value with a dimension ("0.2 deg/sqrt(h)"); a plain number has Dimension::none()
  list,      ///< a list of values, each with its own dimension ("[1 s, 1000 s]", AR "a: [..]")
  matrix,    ///< 3×3, row-major, each entry with its dimension (a plain 0 has Dimension::none())
  text,      ///< a string
  flag,      ///< a boolean (yes/no, true/false, on/off)
};

/// One `key: value` of an effect. Values are SI ([rad], [s], [m/s^2], ... and their products).
struct ParamSpec {
  std::string key;
  ParamKind kind = ParamKind::quantity;
  std::vector<double> values;     ///< SI: 1 (quantity), n (list), 9 row-major (matrix), 0 (text, flag)
  std::vector<Dimension> dims;    ///< one per value: the dimension it was given in
  std::string text;               ///< kind text
  bool flag = false;              ///< kind flag
  /// 1-sigma uncertainty of each value (same size as values) when known, e.g. from a fit; empty
  /// otherwise. Kept in memory for the diagnosis; the writer does not write it (a fit writes its
  /// uncertainties as comment lines of its own wording).
  std::vector<double> sigma;
  SourceLocation where;           ///< not compared by operator==

  /// The single SI value of a quantity (throws InputError when this is not a one-value parameter).
  double si() const;

  /// A quantity: one SI value of dimension dim.
  static ParamSpec quantity(std::string key, double si, Dimension dim);
  /// A plain number (dimensionless quantity).
  static ParamSpec number(std::string key, double v);
  /// A list of plain numbers (AR coefficients).
  static ParamSpec numbers(std::string key, std::vector<double> v);
  /// A list of SI values, all of dimension dim (tau_range).
  static ParamSpec quantities(std::string key, std::vector<double> si, Dimension dim);
  /// A list of SI values with one dimension each (temperature coefficients).
  static ParamSpec quantities(std::string key, std::vector<double> si, std::vector<Dimension> dims);
  /// A 3×3 matrix, row-major, every entry of dimension dim.
  static ParamSpec matrix(std::string key, std::vector<double> rowMajor9, Dimension dim);
  static ParamSpec textValue(std::string key, std::string text);
  static ParamSpec flagValue(std::string key, bool flag);

  bool operator==(const ParamSpec& o) const;
  bool operator!=(const ParamSpec& o) const { return !(*this == o); }
};

/// One effect of a model, as the file states it.
struct EffectSpec {
  std::string type;                   ///< registry name: "white", "ar", ... (effects/effects.def)
  std::vector<ParamSpec> parameters;  ///< in file order, without `type`, `enabled` and `note`
  bool enabled = true;                ///< `enabled: no` / `false` / `off` all mean false
  std::string note;                   ///< optional free text (`note:` in the file); empty if none
  std::vector<std::string> comments;  ///< comment lines written just above the effect, without "# "
  SourceLocation where;               ///< of the effect's map; not compared by operator==

  /// The parameter with that key, or nullptr.
  const ParamSpec* find(const std::string& key) const;
  ParamSpec* find(const std::string& key);
  bool has(const std::string& key) const { return find(key) != nullptr; }

  /// An effect of the given type with the given parameters (enabled, no note, no comments).
  static EffectSpec make(std::string type, std::vector<ParamSpec> parameters);

  bool operator==(const EffectSpec& o) const;
  bool operator!=(const EffectSpec& o) const { return !(*this == o); }
};

/// The effects of one sensor triad.
struct SensorSpec {
  std::vector<EffectSpec> triad, all, x, y, z;
  /// Comment lines written after the last effect of a list (a fit's notes on terms it did not
  /// write, e.g. "ramp: not supported by the data, upper bound ..."), indexed by EffectList.
  std::vector<std::string> trailing[5];
  /// A list that has no effects but is to be written anyway (as `x: []`), indexed by EffectList.
  /// Set by the reader for a list present in the file; a fit sets it for every axis it fitted.
  bool keepEmpty[5] = {false, false, false, false, false};

  std::vector<EffectSpec>& list(EffectList l);
  const std::vector<EffectSpec>& list(EffectList l) const;
  bool empty() const;  ///< no effect in any list

  bool operator==(const SensorSpec& o) const;
  bool operator!=(const SensorSpec& o) const { return !(*this == o); }
};

/// An IMU error model.
struct ErrorModelSpec {
  std::string description;                  ///< `description:`; empty when absent
  /// `record_duration:` [s]: how long the record a fitted model came from was (`sinsim fit` writes
  /// it); unset when absent. What a model says about times beyond it is extrapolated.
  std::optional<double> recordDuration;
  std::vector<std::string> headerComments;  ///< comment lines at the top (provenance), without "# "
  SensorSpec gyro, accel;
  std::string source;  ///< file name it was read from ("inline", "" when built in code); not compared

  SensorSpec& sensor(Sensor s) { return s == Sensor::gyro ? gyro : accel; }
  const SensorSpec& sensor(Sensor s) const { return s == Sensor::gyro ? gyro : accel; }
  bool empty() const { return gyro.empty() && accel.empty(); }

  bool operator==(const ErrorModelSpec& o) const;
  bool operator!=(const ErrorModelSpec& o) const { return !(*this == o); }
};

// ---- functions on specs (each returns a new value; the argument is unchanged) -----------------

/// spec with `effect` appended to list `list` of `sensor`.
ErrorModelSpec withEffect(ErrorModelSpec spec, Sensor sensor, EffectList list, EffectSpec effect);

/// spec with every effect of `type` removed from the lists that act on `axis` (0, 1, 2) of
/// `sensor`: the axis's own list, and `all` (an `all` effect is removed from all three axes, so the
/// other two axes lose it too: callers that want to keep it there add it back per axis with
/// withEffect). Triad effects are not touched (use withoutEffects on EffectList::triad).
ErrorModelSpec withoutEffects(ErrorModelSpec spec, Sensor sensor, int axis, const std::string& type);
/// spec with every effect of `type` removed from one list.
ErrorModelSpec withoutEffects(ErrorModelSpec spec, Sensor sensor, EffectList list,
                              const std::string& type);

/// spec with `effect` in place of the effects of the same type acting on `axis` of `sensor`
/// (withoutEffects(type) then withEffect(axisList(axis))). Keeps the removed effect's comments when
/// `effect` has none.
ErrorModelSpec withReplacedEffect(ErrorModelSpec spec, Sensor sensor, int axis, EffectSpec effect);

/// The types of the ENABLED effects acting on `axis` (0, 1, 2) of `sensor`, from the axis's own
/// list and from `all`, in list order (`all` first), each type once. Disabled effects
/// (`enabled: no`) are not counted: the simulator does not run them either.
std::vector<std::string> effectTypesOn(const ErrorModelSpec& spec, Sensor sensor, int axis);
/// The same for the triad list of `sensor`.
std::vector<std::string> triadEffectTypes(const ErrorModelSpec& spec, Sensor sensor);

/// Where an effect sits: sensor, list and index in that list.
struct EffectRef {
  Sensor sensor = Sensor::gyro;
  EffectList list = EffectList::x;
  int index = 0;
};
/// The first ENABLED effect of `type` acting on `axis` of `sensor` (its own list first, then
/// `all`), or nullopt.
std::optional<EffectRef> findEffect(const ErrorModelSpec& spec, Sensor sensor, int axis,
                                    const std::string& type);
/// The effect a reference points at (throws InputError when the reference is out of range).
const EffectSpec& effectAt(const ErrorModelSpec& spec, const EffectRef& ref);

/// spec with every value of parameter `key` of the effect at `ref` multiplied by `factor` (and
/// its uncertainties by |factor|). Throws InputError when the effect has no such numeric
/// parameter.
ErrorModelSpec scaleParameter(ErrorModelSpec spec, const EffectRef& ref, const std::string& key,
                              double factor);
/// spec with parameter `key` of the effect at `ref` replaced by (or, if absent, appended as) `p`.
ErrorModelSpec withParameter(ErrorModelSpec spec, const EffectRef& ref, ParamSpec p);

}  // namespace sinsim::errormodels
