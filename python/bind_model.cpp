// sinsim.Model: an error model (ErrorModelSpec) as a Python value. Reading and writing go through
// the one model reader and writer (errormodels/model_io.hpp); edits are the spec's functions on
// values (withParameter, scaleParameter, withEffect, withoutEffects), each returning a new Model.
#include <pybind11/stl.h>

#include <cmath>

#include "common/error.hpp"
#include "common/limits.hpp"
#include "errormodels/imu_model.hpp"
#include "errormodels/model_io.hpp"
#include "python/bindings.hpp"
#include "python/convert.hpp"

namespace sinsim::python {
namespace {

namespace em = errormodels;

em::Sensor sensorByName(const std::string& s) {
  for (em::Sensor v : {em::Sensor::gyro, em::Sensor::accel})
    if (s == em::sensorName(v)) return v;
  throw InputError("sensor \"" + s + "\": expected gyro or accel");
}

em::EffectList listByName(const std::string& s) {
  for (em::EffectList l : {em::EffectList::triad, em::EffectList::all, em::EffectList::x,
                           em::EffectList::y, em::EffectList::z})
    if (s == em::listName(l)) return l;
  throw InputError("list \"" + s + "\": expected triad, all, x, y or z");
}

em::EffectRef ref(const Model& m, const std::string& sensor, const std::string& list, int index) {
  em::EffectRef r{sensorByName(sensor), listByName(list), index};
  em::effectAt(m.spec, r);  // InputError when out of range
  return r;
}

// One parameter as Python: a float (quantity, SI), a list of floats (list, 3x3 row-major
// matrix), a str (text) or a bool (flag).
py::object paramValue(const em::ParamSpec& p) {
  switch (p.kind) {
    case em::ParamKind::quantity: return py::float_(p.values.at(0));
    case em::ParamKind::list:
    case em::ParamKind::matrix: return py::cast(p.values);
    case em::ParamKind::text: return py::str(p.text);
    case em::ParamKind::flag: return py::bool_(p.flag);
  }
  return py::none();
}

py::list effectList(const Model& m) {
  py::list out;
  for (em::Sensor s : {em::Sensor::gyro, em::Sensor::accel})
    for (em::EffectList l : {em::EffectList::triad, em::EffectList::all, em::EffectList::x,
                             em::EffectList::y, em::EffectList::z}) {
      const auto& effects = m.spec.sensor(s).list(l);
      for (std::size_t i = 0; i < effects.size(); ++i) {
        py::dict params;
        for (const auto& p : effects[i].parameters) params[p.key.c_str()] = paramValue(p);
        py::dict e;
        e["sensor"] = em::sensorName(s);
        e["list"] = em::listName(l);
        e["index"] = i;
        e["type"] = effects[i].type;
        e["enabled"] = effects[i].enabled;
        e["params"] = params;
        if (!effects[i].note.empty()) e["note"] = effects[i].note;
        out.append(e);
      }
    }
  return out;
}

// The edited spec must still build (an effect's own rules, e.g. a stable AR polynomial), and hold
// only values a model file may (limits::kMaxQuantity, as the reader): a density of 1e200 ran to
// NaN, and its file was refused when read back.
Model checked(Model m) {
  for (em::Sensor s : {em::Sensor::gyro, em::Sensor::accel})
    for (em::EffectList l : {em::EffectList::triad, em::EffectList::all, em::EffectList::x,
                             em::EffectList::y, em::EffectList::z}) {
      const auto& effects = m.spec.sensor(s).list(l);
      for (std::size_t i = 0; i < effects.size(); ++i)
        for (const auto& p : effects[i].parameters)
          for (double v : p.values)
            if (!(std::abs(v) <= limits::kMaxQuantity))
              throw InputError(std::string(em::sensorName(s)) + "." + em::listName(l) + "[" + std::to_string(i) +
                               "]." + p.key + ": " + limits::fmt(v) + " (SI) is beyond any physical value (|x| <= " +
                               limits::fmt(limits::kMaxQuantity) + "; docs/limits.md)");
    }
  em::ImuErrorModel::fromSpec(m.spec, m.label);
  return m;
}

// A Model made by editing another: its source says so. An edited file's model was reported as the
// file itself (run's summary line and summary.json: "model scenarios/grade-tactical.yaml").
Model edited(const Model& from, em::ErrorModelSpec spec) {
  const std::string mark = " (edited)";
  if (!spec.source.empty() &&
      (spec.source.size() < mark.size() || spec.source.compare(spec.source.size() - mark.size(), mark.size(), mark) != 0))
    spec.source += mark;
  return {std::move(spec), from.label};
}

// `value`: a number (SI) or a string with a unit for a quantity, a list for a list or matrix,
// str for text, bool for a flag. The new value keeps the old one's dimensions.
Model withParam(const Model& m, const std::string& sensor, const std::string& list, int index,
                const std::string& key, const py::object& value) {
  const em::EffectRef r = ref(m, sensor, list, index);
  const em::ParamSpec* old = em::effectAt(m.spec, r).find(key);
  if (!old) throw InputError(std::string(sensor) + "." + list + "[" + std::to_string(index) +
                             "]: the effect has no parameter \"" + key + "\"");
  em::ParamSpec p = *old;
  p.sigma.clear();  // no longer the fitted value
  const std::string what = sensor + "." + list + "[" + std::to_string(index) + "]." + key;
  switch (p.kind) {
    case em::ParamKind::quantity: p.values = {quantityArg(value, p.dims.at(0), what)}; break;
    case em::ParamKind::list:
    case em::ParamKind::matrix: {
      std::vector<double> v;
      for (const auto& item : value) v.push_back(quantityArg(item, p.dims.at(0), what));
      if (p.kind == em::ParamKind::matrix && v.size() != 9)
        throw InputError(what + ": expected 9 values (3x3, row-major)");
      if (v.size() != p.dims.size()) p.dims.assign(v.size(), p.dims.at(0));
      p.values = v;
      break;
    }
    case em::ParamKind::text: p.text = value.cast<std::string>(); break;
    case em::ParamKind::flag: p.flag = value.cast<bool>(); break;
  }
  return checked(edited(m, em::withParameter(m.spec, r, p)));
}

// The effect is read by the one model reader, as the line `sensor: {list: [effect]}` of a file.
Model withEffect(const Model& m, const std::string& sensor, const std::string& list,
                 const py::dict& effect) {
  const em::Sensor s = sensorByName(sensor);
  const em::EffectList l = listByName(list);
  YAML::Node root(YAML::NodeType::Map);
  root[sensor][list].push_back(yamlTree(effect, "<effect dict>", sensor + "." + list + "[0]"));
  ConfigFile file = ConfigFile::fromNode(root, "<effect dict>");
  const em::ErrorModelSpec one = em::readErrorModel(file.root());
  file.throwIfErrors();
  return checked(edited(m, em::withEffect(m.spec, s, l, one.sensor(s).list(l).at(0))));
}

std::string repr(const Model& m) {
  return "<sinsim.Model " + m.label + ": " +
         std::to_string(em::ImuErrorModel::fromSpec(m.spec, m.label).effectNames().size()) +
         " effects>";
}

}  // namespace

em::ImuErrorModel imuModel(const Model& m) {
  return em::ImuErrorModel::fromSpec(m.spec, m.spec.source.empty() ? m.label : m.spec.source);
}

void bindModel(py::module_& mod) {
  py::class_<Model>(mod, "Model",
                    "An IMU error model (the model-file format, docs/model-format.md) as a value.\n"
                    "Model(path | dict | 'none'); edits return a new Model.")
      .def(py::init([](const py::object& src) { return checked(toModel(src)); }), py::arg("source"))
      .def_readwrite("label", &Model::label, "name of the model in mc() results")
      .def_property_readonly("description", [](const Model& m) { return m.spec.description; })
      .def_property_readonly(
          "record_duration", [](const Model& m) { return m.spec.recordDuration; },
          "length [s] of the record the model was fitted on (record_duration:), None when not given")
      .def_property_readonly("source", [](const Model& m) { return m.spec.source; })
      .def_property_readonly("header_comments", [](const Model& m) { return m.spec.headerComments; })
      .def("effects", &effectList,
           "every effect: dicts {sensor, list, index, type, enabled, params (SI)}")
      .def("effect_names",
           [](const Model& m) { return imuModel(m).effectNames(); },
           "the enabled effects as the simulator names them (gyro.x[0].white, ...)")
      .def("get",
           [](const Model& m, const std::string& sensor, const std::string& list, int index,
              const std::string& key) {
             const em::ParamSpec* p = em::effectAt(m.spec, ref(m, sensor, list, index)).find(key);
             if (!p) throw InputError("the effect has no parameter \"" + key + "\"");
             return paramValue(*p);
           },
           py::arg("sensor"), py::arg("list"), py::arg("index"), py::arg("key"),
           "a parameter's value in SI")
      .def("with_param", &withParam, py::arg("sensor"), py::arg("list"), py::arg("index"),
           py::arg("key"), py::arg("value"),
           "a copy with one parameter set (number: SI; str: with a unit, e.g. '0.2 deg/sqrt(h)')")
      .def("scaled",
           [](const Model& m, const std::string& sensor, const std::string& list, int index,
              const std::string& key, double factor) {
             return checked(edited(m, em::scaleParameter(m.spec, ref(m, sensor, list, index), key, factor)));
           },
           py::arg("sensor"), py::arg("list"), py::arg("index"), py::arg("key"), py::arg("factor"),
           "a copy with one parameter multiplied by factor")
      .def("with_effect", &withEffect, py::arg("sensor"), py::arg("list"), py::arg("effect"),
           "a copy with an effect appended, given as in a model file: {'type': 'white', ...}")
      .def("without",
           [](const Model& m, const std::string& sensor, const std::string& list,
              const std::string& type) {
             return edited(m, em::withoutEffects(m.spec, sensorByName(sensor), listByName(list), type));
           },
           py::arg("sensor"), py::arg("list"), py::arg("type"),
           "a copy without the effects of that type in one list")
      .def("yaml", [](const Model& m) { return strOf(em::errorModelYaml(m.spec)); },
           "the model-file text (the one model writer)")
      .def("write", [](const Model& m, const py::object& path) { em::writeErrorModel(pathArg(path), m.spec); },
           py::arg("path"), "writes the model file (temporary + rename)")
      .def("__eq__", [](const Model& a, const Model& b) { return a.spec == b.spec; })
      .def("__repr__", &repr);
  mod.def("load_model", [](const py::object& src) { return checked(toModel(src)); },
          py::arg("source"), "Model(source): a model file path, a dict or 'none'");
}

}  // namespace sinsim::python
