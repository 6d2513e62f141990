// The one writer of the error-model format: ErrorModelSpec → YAML (model_io.hpp).
//
// Units per quantity, gyro / accelerometer (the units data sheets quote; the factor comes from the
// same unit parser that reads them back):
//   level (signal)           deg/s            mg
//   density (signal·√time)   deg/sqrt(h)      m/s/sqrt(h)
//   walk (signal/√time)      deg/h/sqrt(h)    m/s^2/sqrt(h)
//   increment (signal·time)  deg              m/s
//   slope (signal/time)      deg/h^2          m/s^3
//   per temperature^k        deg/s/degC^k     mg/degC^k
// and s, Hz, deg, degC (absolute, for a lone temperature), plain numbers, deg/s/g.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "common/atomic_file.hpp"
#include "common/constants.hpp"
#include "errormodels/effect.hpp"
#include "common/number_text.hpp"
#include "errormodels/model_io.hpp"

namespace sinsim::errormodels {

std::string displayUnit(Dimension d, Sensor sensor) {
  const bool gyro = sensor == Sensor::gyro;
  const Dimension sig = gyro ? Dimension::angularRate() : Dimension::acceleration();
  const Dimension t = Dimension::time(), T = Dimension::temperature();
  if (d == Dimension::none()) return "";
  if (d == sig) return gyro ? "deg/s" : "mg";
  if (d == sig * t.sqrt()) return gyro ? "deg/sqrt(h)" : "m/s/sqrt(h)";
  if (d == sig / t.sqrt()) return gyro ? "deg/h/sqrt(h)" : "m/s^2/sqrt(h)";
  if (d == sig * t) return gyro ? "deg" : "m/s";
  if (d == sig / t) return gyro ? "deg/h^2" : "m/s^3";
  for (int k = 1; k <= 8; ++k)
    if (d == sig / T.pow(k))
      return std::string(gyro ? "deg/s/degC" : "mg/degC") + (k > 1 ? "^" + std::to_string(k) : "");
  if (d == t) return "s";
  if (d == Dimension::frequency()) return "Hz";
  if (d == Dimension::angle()) return "deg";
  if (d == T) return "degC";
  if (d == Dimension::angularRate() / Dimension::acceleration()) return "deg/s/g";
  // The other sensor's signal units (a value of a fixed dimension, e.g. in a hand-built spec).
  if (gyro) return displayUnit(d, Sensor::accel);
  throw InputError("model writer: no unit to write a value of dimension " + d.siUnit());
}

namespace {

std::string number(double v, int digits) {
  return significant(v, digits);
}

// A lone temperature is absolute: degC with its offset (parseQuantity adds 273.15 back).
double shownIn(double si, const std::string& unit) {
  return unit == "degC" ? si - kZeroCelsius : si / parseUnit(unit).si;
}

std::string value(double si, Dimension d, Sensor sensor, int digits) {
  const std::string unit = displayUnit(d, sensor);
  if (unit.empty()) return number(si, digits);
  return number(shownIn(si, unit), digits) + " " + unit;
}

// si as the reader reads back value(si, d, sensor, digits).
double readBack(double si, Dimension d, Sensor sensor, int digits) {
  const std::string unit = displayUnit(d, sensor);
  const double printed = std::strtod(number(unit.empty() ? si : shownIn(si, unit), digits).c_str(), nullptr);
  if (unit.empty()) return printed;
  return unit == "degC" ? printed + kZeroCelsius : printed * parseUnit(unit).si;
}

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out + "\"";
}

std::string paramText(const ParamSpec& p, int digits, Sensor sensor) {
  switch (p.kind) {
    case ParamKind::text: return quoted(p.text);
    case ParamKind::flag: return p.flag ? "true" : "false";
    case ParamKind::quantity: return value(p.values.at(0), p.dims.at(0), sensor, digits);
    case ParamKind::list: {
      std::string s = "[";
      for (std::size_t i = 0; i < p.values.size(); ++i)
        s += (i ? ", " : "") + value(p.values[i], p.dims.at(i), sensor, digits);
      return s + "]";
    }
    case ParamKind::matrix: {
      std::string s = "[";
      for (std::size_t r = 0; r < 3; ++r) {
        s += r ? ", [" : "[";
        for (std::size_t c = 0; c < 3; ++c)
          s += (c ? ", " : "") + value(p.values.at(3 * r + c), p.dims.at(3 * r + c), sensor, digits);
        s += "]";
      }
      return s + "]";
    }
  }
  return "";
}

const EffectType& typeOf(const EffectSpec& e) {
  const EffectType* et = findEffectType(e.type);
  if (!et) throw InputError("model writer: unknown effect type \"" + e.type + "\"");
  return *et;
}

// The significant digits the writer prints parameter `key` of an effect with (its schema's).
int digitsOf(const EffectType& et, const std::string& key) {
  for (const auto& sc : et.params())
    if (sc.key == key) return sc.digits;
  return 9;
}

std::string effectLine(const EffectSpec& e, Sensor sensor) {
  const EffectType& et = typeOf(e);
  std::string s = "{type: " + e.type;
  if (!e.enabled) s += ", enabled: false";
  for (const auto& p : e.parameters) s += ", " + p.key + ": " + paramText(p, digitsOf(et, p.key), sensor);
  if (!e.note.empty()) s += ", note: " + quoted(e.note);
  return s + "}";
}

void comment(std::ostringstream& out, const char* indent, const std::string& line) {
  out << indent << (line.empty() ? "#" : "# " + line) << "\n";
}

}  // namespace

std::string errorModelYaml(const ErrorModelSpec& spec) {
  std::ostringstream out;
  for (const auto& c : spec.headerComments) comment(out, "", c);
  if (!spec.description.empty()) out << "description: " << quoted(spec.description) << "\n";
  if (spec.recordDuration) out << "record_duration: " << number(*spec.recordDuration, 10) << " s\n";
  for (Sensor sensor : {Sensor::gyro, Sensor::accel}) {
    const SensorSpec& ss = spec.sensor(sensor);
    std::ostringstream body;
    for (EffectList l : {EffectList::triad, EffectList::all, EffectList::x, EffectList::y,
                         EffectList::z}) {
      const auto& effects = ss.list(l);
      const auto& trailing = ss.trailing[int(l)];
      if (effects.empty() && trailing.empty() && !ss.keepEmpty[int(l)]) continue;
      body << "  " << listName(l) << ":\n";
      for (const auto& e : effects) {
        for (const auto& c : e.comments) comment(body, "    ", c);
        body << "    - " << effectLine(e, sensor) << "\n";
      }
      for (const auto& c : trailing) comment(body, "    ", c);
      if (effects.empty()) body << "    []\n";  // an axis without effects stays valid YAML
    }
    if (!body.str().empty()) out << sensorName(sensor) << ":\n" << body.str();
  }
  return out.str();
}

std::string effectYaml(const EffectSpec& effect, Sensor sensor) { return effectLine(effect, sensor); }

ErrorModelSpec asWritten(ErrorModelSpec spec) {
  for (Sensor sensor : {Sensor::gyro, Sensor::accel})
    for (EffectList l : {EffectList::triad, EffectList::all, EffectList::x, EffectList::y, EffectList::z})
      for (auto& e : spec.sensor(sensor).list(l)) {
        const EffectType& et = typeOf(e);
        for (auto& p : e.parameters)
          for (std::size_t i = 0; i < p.values.size(); ++i)
            p.values[i] = readBack(p.values[i], p.dims.at(i), sensor, digitsOf(et, p.key));
      }
  return spec;
}

void writeErrorModel(const std::string& path, const ErrorModelSpec& spec) {
  writeFileAtomic(path, errorModelYaml(spec));
}

}  // namespace sinsim::errormodels
