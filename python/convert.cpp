#include "python/convert.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "common/config.hpp"
#include "common/error.hpp"
#include "common/limits.hpp"
#include "common/units.hpp"
#include "errormodels/model_io.hpp"
#include "errormodels/stats/record_time.hpp"

namespace sinsim::python {

namespace fs = std::filesystem;

namespace {

/// Nesting a dict or list may have: yaml-cpp's parser refuses a file nested deeper than 2000, and
/// a Python tree must stop where a file would (a dict holding itself recursed until the stack
/// overflowed: a segfault).
constexpr int kMaxDepth = 1000;

YAML::Node tree(const py::handle& v, const std::string& path, int depth);

}  // namespace

YAML::Node yamlTree(const py::handle& v, const std::string& source, const std::string& path) {
  try {
    return tree(v, path, 0);
  } catch (const InputError& e) {
    throw InputError(source + ": " + e.text());
  }
}

namespace {

/// A Python str as UTF-8; one holding a lone surrogate (bytes decoded with surrogateescape) has
/// none: an InputError naming where it stood (the cast's RuntimeError "Unable to cast Python
/// instance to C++ type" named nothing).
std::string utf8(const py::handle& v, const std::string& where) {
  try {
    return v.cast<std::string>();
  } catch (const py::cast_error&) {
    PyErr_Clear();
    throw InputError((where.empty() ? std::string("value") : where) + ": " +
                     py::repr(v).cast<std::string>().substr(0, 200) +
                     " is not UTF-8 text (it holds a lone surrogate)");
  }
}

/// A path (str or os.PathLike) as the bytes the file system names it by: os.fsencode gives a
/// name that is no UTF-8 (decoded with surrogateescape, as os.listdir returns it) its bytes back.
std::string pathBytes(const py::handle& v) {
  return py::module_::import("os").attr("fsencode")(v).cast<std::string>();
}

YAML::Node tree(const py::handle& v, const std::string& path, int depth) {
  if (depth > kMaxDepth)
    throw InputError((path.empty() ? std::string("value") : path.substr(0, 200) + " ...") + ": nested deeper than " +
                     std::to_string(kMaxDepth) + " levels (a dict or list that holds itself?)");
  if (v.is_none()) return YAML::Node(YAML::NodeType::Null);
  if (py::isinstance<py::bool_>(v)) return YAML::Node(v.cast<bool>() ? "true" : "false");
  if (py::isinstance<py::str>(v)) return YAML::Node(utf8(v, path));
  if (py::isinstance<py::int_>(v)) return YAML::Node(py::str(v).cast<std::string>());
  if (py::isinstance<py::float_>(v)) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v.cast<double>());
    return YAML::Node(std::string(buf));
  }
  // NumPy scalars (np.int64, np.float32, 0-d arrays) as the Python scalar they hold.
  if (py::hasattr(v, "dtype") && py::hasattr(v, "item") &&
      !(py::isinstance<py::array>(v) && py::reinterpret_borrow<py::array>(v).ndim() > 0))
    return tree(v.attr("item")(), path, depth + 1);
  if (py::isinstance<py::dict>(v)) {
    YAML::Node n(YAML::NodeType::Map);
    for (const auto& kv : py::reinterpret_borrow<py::dict>(v)) {
      if (!py::isinstance<py::str>(kv.first))
        throw InputError(joinKey(path, py::repr(kv.first).cast<std::string>()) +
                         ": a key must be a string");
      const std::string key = utf8(kv.first, joinKey(path, "<key>"));
      n[key] = tree(kv.second, joinKey(path, key), depth + 1);
    }
    return n;
  }
  if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v) || py::isinstance<py::array>(v)) {
    YAML::Node n(YAML::NodeType::Sequence);
    std::size_t i = 0;
    for (const auto& item : v) n.push_back(tree(item, path + "[" + std::to_string(i++) + "]", depth + 1));
    return n;
  }
  throw InputError((path.empty() ? std::string("value") : path) + ": cannot use a Python " +
                   py::str(v.get_type().attr("__name__")).cast<std::string>() +
                   " (expected str, number, bool, None, dict or list)");
}

}  // namespace

sim::Scenario toScenario(const py::handle& v) {
  if (py::isinstance<sim::Scenario>(v)) return v.cast<sim::Scenario>();
  if (py::isinstance<py::dict>(v)) {
    ConfigFile file = ConfigFile::fromNode(yamlTree(v, "<scenario dict>"), "<scenario dict>");
    return sim::parseScenario(file, ".");
  }
  if (py::isinstance<py::str>(v) || py::hasattr(v, "__fspath__"))
    return sim::loadScenario(pathBytes(v));
  throw InputError("a scenario is a file path, a dict or a sinsim.Scenario");
}

Model toModel(const py::handle& v) {
  if (py::isinstance<Model>(v)) return v.cast<Model>();
  if (py::isinstance<py::dict>(v)) {
    ConfigFile file = ConfigFile::fromNode(yamlTree(v, "<model dict>"), "<model dict>");
    errormodels::ErrorModelSpec spec = errormodels::readErrorModel(file.root());
    file.throwIfErrors();
    spec.source = "<model dict>";
    return {spec, "dict"};
  }
  if (py::isinstance<py::str>(v) || py::hasattr(v, "__fspath__")) {
    const std::string path = pathBytes(v);
    if (path == "none") return {errormodels::ErrorModelSpec{}, "none"};
    return {errormodels::loadErrorModel(path), labelOf(fs::path(path).stem().string())};
  }
  throw InputError("a model is a sinsim.Model, a file path, \"none\" or a dict");
}

namespace {

std::vector<double> column(const py::dict& d, const char* key) {
  if (!d.contains(key)) return {};
  // A masked array's mask and a complex array's imaginary part were dropped by the cast (NumPy
  // only warned): refused, as a file's empty field or text is.
  const py::object value = d[key];
  if (py::hasattr(value, "mask") && py::module_::import("numpy").attr("ma").attr("is_masked")(value).cast<bool>())
    throw InputError(std::string("record dict: \"") + key +
                     "\": a masked array with masked values (fill or drop them first)");
  if (py::isinstance<py::array>(value) &&
      py::reinterpret_borrow<py::array>(value).dtype().kind() == 'c')
    throw InputError(std::string("record dict: \"") + key + "\": complex values (a record holds real numbers)");
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(d[key]);
  if (!a || a.ndim() != 1) throw InputError(std::string("record dict: \"") + key +
                                            "\": expected a 1-D array of numbers");
  return std::vector<double>(a.data(), a.data() + a.size());
}

}  // namespace

errormodels::Record toRecord(const py::handle& v, const errormodels::RecordOptions& options) {
  if (py::isinstance<py::str>(v) || py::hasattr(v, "__fspath__"))
    return errormodels::loadRecord(pathBytes(v), options);
  if (!py::isinstance<py::dict>(v))
    throw InputError("a record is a file path or a dict of arrays (gx..az, rate or t)");
  const py::dict d = py::reinterpret_borrow<py::dict>(v);
  static const char* known[] = {"source", "rate", "t", "gx", "gy", "gz", "ax", "ay", "az", "temp"};
  for (const auto& kv : d) {
    const std::string k = py::str(kv.first).cast<std::string>();
    bool ok = false;
    for (const char* n : known) ok = ok || k == n;
    if (!ok)
      throw InputError("record dict: unknown key \"" + k +
                       "\" (known: source, rate, t, gx, gy, gz, ax, ay, az, temp)");
  }
  errormodels::Record r;
  // The source as given (a dict from load_record names its file, perhaps by bytes that are no UTF-8).
  r.source = d.contains("source") ? pathBytes(py::str(d["source"])) : "<record dict>";
  r.t = column(d, "t");
  const char* g[] = {"gx", "gy", "gz"};
  const char* a[] = {"ax", "ay", "az"};
  for (int i = 0; i < 3; ++i) {
    r.gyro[i] = column(d, g[i]);
    r.accel[i] = column(d, a[i]);
  }
  r.temperature = column(d, "temp");
  // The arrays are SI unless gyro_unit / accel_unit say otherwise (they were ignored, and an
  // unknown unit passed in silence): converted here, with the file reader's dimension check.
  auto convert = [&](const std::optional<std::string>& unit, Dimension dim, const char* what,
                     std::array<std::vector<double>, 3>& columns) {
    if (!unit) return;
    Quantity q;
    try {
      q = parseUnit(*unit);
    } catch (const InputError& e) {
      throw InputError(std::string(what) + ": " + e.text());
    }
    if (q.dim != dim)
      throw InputError(std::string(what) + ": \"" + *unit + "\" has dimension " + q.dim.siUnit() +
                       ", expected " + dim.siUnit() + " (e.g. " + exampleUnit(dim) + ")");
    for (auto& c : columns)
      for (double& x : c) x *= q.si;
  };
  convert(options.gyro_unit, Dimension::angularRate(), "gyro_unit", r.gyro);
  r.gyroUnitStated = options.gyro_unit.has_value();
  convert(options.accel_unit, Dimension::acceleration(), "accel_unit", r.accel);
  std::size_t n = 0;
  auto agree = [&](const std::vector<double>& c, const std::string& name) {
    if (c.empty()) return;
    if (n == 0) n = c.size();
    if (c.size() != n)
      throw InputError("record dict: \"" + name + "\" has " + std::to_string(c.size()) +
                       " samples, another column " + std::to_string(n));
    for (double x : c) {
      if (!std::isfinite(x)) throw InputError("record dict: \"" + name + "\" holds NaN or inf");
      // As the file reader: beyond this (SI) the statistics' sums of squares overflow (a 1e300
      // sample gave sd = inf).
      if (name != "t" && name != "temp" && !(std::abs(x) <= limits::kMaxQuantity))
        throw InputError("record dict: \"" + name + "\" holds " + limits::fmt(x) + " (SI), beyond any sensor (|x| <= " +
                         limits::fmt(limits::kMaxQuantity) + "; docs/limits.md)");
    }
  };
  agree(r.t, "t");
  for (int i = 0; i < 3; ++i) agree(r.gyro[i], g[i]), agree(r.accel[i], a[i]);
  agree(r.temperature, "temp");
  if (n == 0) throw InputError("record dict: no samples (give gx..az arrays)");
  r.rows = n;
  errormodels::RecordOptions o = options;
  if (d.contains("rate")) o.rate_hz = quantityArg(d["rate"], Dimension::frequency(), "record dict: \"rate\"");
  if (o.rate_hz && !(std::isfinite(*o.rate_hz) && *o.rate_hz > 0))
    throw InputError("record dict: \"rate\" must be a sample rate [Hz] > 0");
  if (!r.t.empty()) {
    // The file reader's time checks: increasing, uniform (or rounded), the rate agreeing with them.
    errormodels::detail::checkTime(r, 1, o);
  } else if (o.rate_hz) {
    r.rate_hz = *o.rate_hz;
  } else {
    throw InputError("record dict: give \"rate\": the sample rate [Hz] (> 0)");
  }
  errormodels::detail::checkRate(r.rate_hz, r.source, r.t.empty() ? "the given sample rate" : "the time stamps' rate", "");
  return r;
}

py::array_t<double> array(const std::vector<double>& v) {
  py::array_t<double> a(static_cast<py::ssize_t>(v.size()));
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

py::dict recordDict(const errormodels::Record& r) {
  py::dict d;
  d["source"] = strOf(r.source);
  d["rate"] = r.rate_hz;
  if (!r.t.empty()) {  // the stamps as written (t_origin_s + t: Unix time back to its digits in a double)
    std::vector<double> t(r.t);
    for (double& x : t) x += r.t_origin_s;
    d["t"] = array(t);
  }
  const char* g[] = {"gx", "gy", "gz"};
  const char* a[] = {"ax", "ay", "az"};
  for (int i = 0; i < 3; ++i) {
    if (r.hasGyro(i)) d[g[i]] = array(r.gyro[i]);
    if (r.hasAccel(i)) d[a[i]] = array(r.accel[i]);
  }
  if (!r.temperature.empty()) d["temp"] = array(r.temperature);
  return d;
}

}  // namespace sinsim::python

namespace sinsim::python {

double quantityArg(const py::handle& v, Dimension dim, const std::string& what) {
  if (py::isinstance<py::str>(v)) {
    try {
      return parseQuantityAs(v.cast<std::string>(), dim);
    } catch (const InputError& e) {
      throw InputError(what + ": " + e.text());
    }
  }
  if (py::isinstance<py::bool_>(v))  // True read as 1 (a rate of 1 Hz)
    throw InputError(what + ": expected a number (SI) or a string with a unit, got a bool");
  try {
    return v.cast<double>();
  } catch (const py::cast_error&) {
    throw InputError(what + ": expected a number (SI) or a string with a unit, e.g. \"" +
                     exampleUnit(dim) + "\"");
  }
}

std::uint64_t countArg(const py::int_& v, const std::string& what, std::uint64_t max) {
  if (py::isinstance<py::bool_>(v)) throw InputError(what + ": expected an integer, got a bool");
  const unsigned long long n = PyLong_AsUnsignedLongLong(v.ptr());
  if (PyErr_Occurred() || n > max) {
    PyErr_Clear();  // OverflowError: negative, or beyond 64 bits
    throw InputError(what + ": expected an integer from 0 to " +
                     (max == std::numeric_limits<std::uint64_t>::max() ? std::string("2^64 - 1") : std::to_string(max)) + ", got " +
                     py::repr(v).cast<std::string>());
  }
  return n;
}

std::string pathArg(const py::handle& v) { return v.is_none() ? std::string() : pathBytes(v); }

py::str strOf(const std::string& text) {
  PyObject* o = PyUnicode_DecodeUTF8(text.data(), py::ssize_t(text.size()), "surrogateescape");
  if (!o) throw py::error_already_set();
  return py::reinterpret_steal<py::str>(o);
}

py::list strs(const std::vector<std::string>& texts) {
  py::list l;
  for (const auto& t : texts) l.append(strOf(t));
  return l;
}

std::string labelOf(const std::string& stem) {
  PyObject* o = PyUnicode_DecodeUTF8(stem.data(), py::ssize_t(stem.size()), "backslashreplace");
  if (!o) throw py::error_already_set();
  return py::reinterpret_steal<py::str>(o).cast<std::string>();
}

}  // namespace sinsim::python
