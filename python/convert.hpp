// Conversions at the Python edge: dicts into the readers' trees, NumPy arrays to and from the
// library's vectors, and the typed values the module hands around (Scenario, ErrorModelSpec,
// Record) from "a path or a dict or an object".
#pragma once

#include <cstdint>
#include <limits>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "common/units.hpp"
#include "errormodels/model_spec.hpp"
#include "errormodels/stats/record.hpp"
#include "sim/scenario.hpp"

namespace sinsim::python {

namespace py = pybind11;

/// The Python-side model object: an ErrorModelSpec and the label it carries into mc().
struct Model {
  errormodels::ErrorModelSpec spec;
  std::string label;  // file stem, "fit", "dict" or set by the user
};

/// A dict / list / scalar as a YAML tree for the one reader of a format (ConfigFile::fromNode):
/// str as written ("0.2 deg/sqrt(h)"), bool as true/false, numbers with 17 significant digits,
/// None as null, lists, tuples and 1-D arrays as sequences. Messages name `source` ("<model
/// dict>") and the key's path below it (`path` at the top).
YAML::Node yamlTree(const py::handle& value, const std::string& source, const std::string& path = "");

/// A scenario from a file path, a dict (the file's layout) or a Scenario object.
sim::Scenario toScenario(const py::handle& value);

/// A model from a Model object, a file path, or a dict (the model file's layout).
Model toModel(const py::handle& value);

/// A record from a file path (with the loader's options) or a dict of arrays
/// {"rate": Hz (required), "t": s, "gx".."gz": rad/s, "ax".."az": m/s^2, "temp": K} (SI, as loaded).
errormodels::Record toRecord(const py::handle& value, const errormodels::RecordOptions& options);

/// The record as that dict of arrays (SI) plus "rate" and "source".
py::dict recordDict(const errormodels::Record& record);

/// A copy of v as a 1-D float64 array.
py::array_t<double> array(const std::vector<double>& v);

}  // namespace sinsim::python

namespace sinsim::python {

/// A quantity argument: a number is SI already, a string carries its unit ("10 min", "45 deg").
/// InputError naming `what` when the string's dimension is not `dim`.
double quantityArg(const py::handle& value, Dimension dim, const std::string& what);

/// A count or seed argument: a Python int from 0 to `max`. InputError naming `what` for a negative
/// one, one beyond `max` or a bool (pybind11 refused -1 for an unsigned parameter as "incompatible
/// function arguments", naming neither the argument nor the value).
std::uint64_t countArg(const py::int_& value, const std::string& what,
                       std::uint64_t max = std::numeric_limits<std::uint64_t>::max());

/// A path argument (str, bytes or os.PathLike) as the bytes the file system names it by
/// (os.fsencode: a name that is no UTF-8, as os.listdir returns it, gets its bytes back; a cast to
/// std::string raised TypeError for it). None gives "" (no output), as the CLI's absent option.
std::string pathArg(const py::handle& value);

/// Text the library holds as bytes (a path, a label or warning that names a file) as a Python
/// str: UTF-8 with surrogateescape, as os.fsdecode gives file names (a byte that is no UTF-8
/// becomes a lone surrogate, and pathArg gives it back). A std::string returned as is was decoded
/// as strict UTF-8 and raised UnicodeDecodeError after the work was done.
py::str strOf(const std::string& text);

/// A file stem as UTF-8 text for a label (a byte that is no UTF-8 written as \xff).
std::string labelOf(const std::string& stem);

/// A list of such texts (strOf each).
py::list strs(const std::vector<std::string>& texts);

}  // namespace sinsim::python
