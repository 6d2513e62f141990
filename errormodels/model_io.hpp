// The one reader and the one writer of the error-model file format (docs/model-format.md).
//
//   reader: YAML → ErrorModelSpec. Units are converted to SI here and nowhere else; each effect's
//           parameters are checked against the schema its plug-in declares (effect_schema.hpp),
//           then against the effect's own rules (e.g. a stable AR polynomial). Every problem is
//           recorded with file, line and key path, and all of them are reported at once.
//   writer: ErrorModelSpec → YAML, one line per effect in flow style, each value in the unit its
//           quantity is usually quoted in (deg/h, deg/sqrt(h), mg, ug, m/s/sqrt(h), ...), comment
//           lines kept. read(write(spec)) == spec up to the printed digits (9 significant digits
//           for quantities), and read(write(read(text))) == read(text) exactly.
#pragma once

#include <string>

#include "common/config.hpp"
#include "errormodels/model_spec.hpp"

namespace sinsim::errormodels {

/// Reads a model from a node of an already opened file (a model file's root, or a scenario's
/// inline `errors:` block). Problems are recorded in that file's diagnostics (the caller calls
/// throwIfErrors); the returned spec holds the effects that could be read. Comment lines of the
/// file are attached to the spec (header) and to the effects they stand above.
ErrorModelSpec readErrorModel(const ConfigNode& node);
/// Reads a model file; throws ConfigError listing every problem with file, line and key path.
ErrorModelSpec loadErrorModel(const std::string& path);
/// Reads model text as if from the named file (tests, generated models); throws like loadErrorModel.
ErrorModelSpec errorModelFromString(const std::string& text, const std::string& name);

/// The model-file text of a spec. Throws InputError when a parameter cannot be written (an
/// unknown effect type, a value of a dimension its schema does not accept).
std::string errorModelYaml(const ErrorModelSpec& spec);
/// One effect in the writer's inline (flow) syntax, exactly as errorModelYaml writes it on its
/// line, e.g. {type: ramp, slope: 12.5 deg/h^2}, in the units of `sensor` (reports show an effect
/// as the model file will hold it). Throws like errorModelYaml.
std::string effectYaml(const EffectSpec& effect, Sensor sensor);
/// The spec as a file written from it reads back: every value rounded to the digits the writer
/// prints, in the unit it prints it in (what a diagnosis or a simulation of the written file
/// sees). Locations, notes and comments are kept. Throws like errorModelYaml.
ErrorModelSpec asWritten(ErrorModelSpec spec);
/// Writes errorModelYaml(spec) to `path` atomically (common/atomic_file.hpp: a failure never
/// leaves a half-written model). Throws InputError when the folder is missing, Error on I/O failure.
void writeErrorModel(const std::string& path, const ErrorModelSpec& spec);

}  // namespace sinsim::errormodels
