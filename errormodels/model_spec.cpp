#include "errormodels/model_spec.hpp"

#include <algorithm>
#include <cmath>

#include "common/error.hpp"

namespace sinsim::errormodels {

const char* sensorName(Sensor s) { return s == Sensor::gyro ? "gyro" : "accel"; }

const char* listName(EffectList l) {
  static const char* const names[5] = {"triad", "all", "x", "y", "z"};
  return names[int(l)];
}

EffectList axisList(int axis) {
  if (axis < 0 || axis > 2) throw InputError("axis must be 0, 1 or 2, got " + std::to_string(axis));
  return EffectList(int(EffectList::x) + axis);
}

// ---- ParamSpec --------------------------------------------------------------------------------

double ParamSpec::si() const {
  if (values.size() != 1 || kind != ParamKind::quantity)
    throw InputError("parameter " + key + " is not a single value");
  return values[0];
}

ParamSpec ParamSpec::quantity(std::string key, double si, Dimension dim) {
  ParamSpec p;
  p.key = std::move(key);
  p.kind = ParamKind::quantity;
  p.values = {si};
  p.dims = {dim};
  return p;
}

ParamSpec ParamSpec::number(std::string key, double v) {
  return quantity(std::move(key), v, Dimension::none());
}

ParamSpec ParamSpec::numbers(std::string key, std::vector<double> v) {
  return quantities(std::move(key), std::move(v), Dimension::none());
}

ParamSpec ParamSpec::quantities(std::string key, std::vector<double> si, Dimension dim) {
  std::vector<Dimension> dims(si.size(), dim);
  return quantities(std::move(key), std::move(si), std::move(dims));
}

ParamSpec ParamSpec::quantities(std::string key, std::vector<double> si,
                                std::vector<Dimension> dims) {
  if (si.size() != dims.size())
    throw InputError("parameter " + key + ": one dimension per value is needed");
  ParamSpec p;
  p.key = std::move(key);
  p.kind = ParamKind::list;
  p.values = std::move(si);
  p.dims = std::move(dims);
  return p;
}

ParamSpec ParamSpec::matrix(std::string key, std::vector<double> rowMajor9, Dimension dim) {
  if (rowMajor9.size() != 9) throw InputError("parameter " + key + ": a 3x3 matrix has 9 entries");
  ParamSpec p;
  p.key = std::move(key);
  p.kind = ParamKind::matrix;
  p.values = std::move(rowMajor9);
  p.dims.assign(9, dim);
  return p;
}

ParamSpec ParamSpec::textValue(std::string key, std::string text) {
  ParamSpec p;
  p.key = std::move(key);
  p.kind = ParamKind::text;
  p.text = std::move(text);
  return p;
}

ParamSpec ParamSpec::flagValue(std::string key, bool flag) {
  ParamSpec p;
  p.key = std::move(key);
  p.kind = ParamKind::flag;
  p.flag = flag;
  return p;
}

namespace {
// Bitwise equality of values, NaN equal to NaN (a value compares equal to its own copy).
bool sameValues(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!(a[i] == b[i] || (std::isnan(a[i]) && std::isnan(b[i])))) return false;
  return true;
}
}  // namespace

bool ParamSpec::operator==(const ParamSpec& o) const {
  return key == o.key && kind == o.kind && sameValues(values, o.values) && dims == o.dims &&
         text == o.text && flag == o.flag && sameValues(sigma, o.sigma);
}

// ---- EffectSpec / SensorSpec / ErrorModelSpec -------------------------------------------------

const ParamSpec* EffectSpec::find(const std::string& key) const {
  for (const auto& p : parameters)
    if (p.key == key) return &p;
  return nullptr;
}

ParamSpec* EffectSpec::find(const std::string& key) {
  for (auto& p : parameters)
    if (p.key == key) return &p;
  return nullptr;
}

EffectSpec EffectSpec::make(std::string type, std::vector<ParamSpec> parameters) {
  EffectSpec e;
  e.type = std::move(type);
  e.parameters = std::move(parameters);
  return e;
}

bool EffectSpec::operator==(const EffectSpec& o) const {
  return type == o.type && parameters == o.parameters && enabled == o.enabled && note == o.note &&
         comments == o.comments;
}

std::vector<EffectSpec>& SensorSpec::list(EffectList l) {
  switch (l) {
    case EffectList::triad: return triad;
    case EffectList::all: return all;
    case EffectList::x: return x;
    case EffectList::y: return y;
    case EffectList::z: return z;
  }
  throw InputError("unknown effect list");
}

const std::vector<EffectSpec>& SensorSpec::list(EffectList l) const {
  return const_cast<SensorSpec*>(this)->list(l);
}

bool SensorSpec::empty() const {
  return triad.empty() && all.empty() && x.empty() && y.empty() && z.empty();
}

bool SensorSpec::operator==(const SensorSpec& o) const {
  // keepEmpty matters only for a list without effects (a list with effects is written anyway).
  for (int l = 0; l < 5; ++l) {
    const bool empty = list(EffectList(l)).empty();
    if (trailing[l] != o.trailing[l] || (empty && keepEmpty[l] != o.keepEmpty[l])) return false;
  }
  return triad == o.triad && all == o.all && x == o.x && y == o.y && z == o.z;
}

bool ErrorModelSpec::operator==(const ErrorModelSpec& o) const {
  return description == o.description && recordDuration == o.recordDuration &&
         headerComments == o.headerComments && gyro == o.gyro && accel == o.accel;
}

// ---- functions on specs -----------------------------------------------------------------------

ErrorModelSpec withEffect(ErrorModelSpec spec, Sensor sensor, EffectList list, EffectSpec effect) {
  spec.sensor(sensor).list(list).push_back(std::move(effect));
  return spec;
}

ErrorModelSpec withoutEffects(ErrorModelSpec spec, Sensor sensor, EffectList list,
                              const std::string& type) {
  auto& l = spec.sensor(sensor).list(list);
  l.erase(std::remove_if(l.begin(), l.end(), [&](const EffectSpec& e) { return e.type == type; }),
          l.end());
  return spec;
}

ErrorModelSpec withoutEffects(ErrorModelSpec spec, Sensor sensor, int axis,
                              const std::string& type) {
  spec = withoutEffects(std::move(spec), sensor, axisList(axis), type);
  return withoutEffects(std::move(spec), sensor, EffectList::all, type);
}

ErrorModelSpec withReplacedEffect(ErrorModelSpec spec, Sensor sensor, int axis, EffectSpec effect) {
  if (effect.comments.empty()) {
    for (EffectList l : {axisList(axis), EffectList::all})
      for (const auto& e : spec.sensor(sensor).list(l))
        if (e.type == effect.type && effect.comments.empty()) effect.comments = e.comments;
  }
  spec = withoutEffects(std::move(spec), sensor, axis, effect.type);
  return withEffect(std::move(spec), sensor, axisList(axis), std::move(effect));
}

namespace {
void addTypes(const std::vector<EffectSpec>& list, std::vector<std::string>& out) {
  for (const auto& e : list)
    if (e.enabled && std::find(out.begin(), out.end(), e.type) == out.end()) out.push_back(e.type);
}
}  // namespace

std::vector<std::string> effectTypesOn(const ErrorModelSpec& spec, Sensor sensor, int axis) {
  std::vector<std::string> out;
  addTypes(spec.sensor(sensor).all, out);
  addTypes(spec.sensor(sensor).list(axisList(axis)), out);
  return out;
}

std::vector<std::string> triadEffectTypes(const ErrorModelSpec& spec, Sensor sensor) {
  std::vector<std::string> out;
  addTypes(spec.sensor(sensor).triad, out);
  return out;
}

std::optional<EffectRef> findEffect(const ErrorModelSpec& spec, Sensor sensor, int axis,
                                    const std::string& type) {
  for (EffectList l : {axisList(axis), EffectList::all}) {
    const auto& list = spec.sensor(sensor).list(l);
    for (std::size_t i = 0; i < list.size(); ++i)
      if (list[i].enabled && list[i].type == type) return EffectRef{sensor, l, int(i)};
  }
  return std::nullopt;
}

namespace {
EffectSpec& effectAtMutable(ErrorModelSpec& spec, const EffectRef& ref) {
  auto& list = spec.sensor(ref.sensor).list(ref.list);
  if (ref.index < 0 || std::size_t(ref.index) >= list.size())
    throw InputError(std::string("no effect ") + sensorName(ref.sensor) + "." +
                     listName(ref.list) + "[" + std::to_string(ref.index) + "]");
  return list[std::size_t(ref.index)];
}
}  // namespace

const EffectSpec& effectAt(const ErrorModelSpec& spec, const EffectRef& ref) {
  return effectAtMutable(const_cast<ErrorModelSpec&>(spec), ref);
}

ErrorModelSpec scaleParameter(ErrorModelSpec spec, const EffectRef& ref, const std::string& key,
                              double factor) {
  EffectSpec& e = effectAtMutable(spec, ref);
  ParamSpec* p = e.find(key);
  if (!p || p->values.empty())
    throw InputError("effect " + e.type + " has no numeric parameter " + key);
  for (double& v : p->values) v *= factor;
  for (double& s : p->sigma) s *= std::abs(factor);
  p->where.text.clear();  // the text as written no longer states this value (messages quote it)
  p->where.line = 0;      // nor is it on that line of the file
  return spec;
}

ErrorModelSpec withParameter(ErrorModelSpec spec, const EffectRef& ref, ParamSpec p) {
  EffectSpec& e = effectAtMutable(spec, ref);
  // A new value: neither the file's text nor its line state it (a refusal quoted the old value,
  // "must be positive, got \"0.05 deg/sqrt(h)\"", at the old line).
  p.where.text.clear();
  p.where.line = 0;
  if (ParamSpec* old = e.find(p.key))
    *old = std::move(p);
  else
    e.parameters.push_back(std::move(p));
  return spec;
}

}  // namespace sinsim::errormodels
