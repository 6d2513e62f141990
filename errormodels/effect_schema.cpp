#include "errormodels/effect_schema.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace sinsim::errormodels {

Dimension DimRule::of(Sensor sensor, int item) const {
  const Dimension sig =
      sensor == Sensor::gyro ? Dimension::angularRate() : Dimension::acceleration();
  Dimension d = sig.pow(signalPower) * times;
  if (perItemTemperature) d = d / Dimension::temperature().pow(item + 1);
  return d;
}

DimRule signal(Dimension times) { return DimRule{1, times, false}; }
DimRule fixed(Dimension d) { return DimRule{0, d, false}; }

ParamSchema param(std::string key, ParamKind kind, DimRule dim) {
  ParamSchema p;
  p.key = std::move(key);
  p.kind = kind;
  p.dim = dim;
  return p;
}

bool ParamSchema::accepts(Dimension d, Sensor sensor, int item) const {
  return d == dim.of(sensor, item) || (hasAlt && d == alt.of(sensor, item)) ||
         (plainZero && d == Dimension::none());
}

namespace {

const char* kindName(ParamKind k) {
  switch (k) {
    case ParamKind::quantity: return "a value";
    case ParamKind::list: return "a list";
    case ParamKind::matrix: return "a 3x3 matrix";
    case ParamKind::text: return "a text";
    case ParamKind::flag: return "true or false";
  }
  return "?";
}

// The value as the user wrote it when read from a file, else in SI.
std::string shown(const ParamSpec& p, std::size_t i) {
  if (!p.where.text.empty()) return p.where.text;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", p.values[i]);
  const std::string unit = p.dims[i].siUnit();
  return std::string(buf) + (unit == "1" ? "" : " " + unit);
}

void checkValues(const ParamSpec& p, const ParamSchema& s, Sensor sensor, SpecProblems& problems) {
  if (p.kind != s.kind) {
    problems.add(p.key, std::string("expected ") + kindName(s.kind));
    return;
  }
  if (p.kind == ParamKind::text || p.kind == ParamKind::flag) return;
  const std::size_t n = p.values.size();
  if (p.dims.size() != n) {
    problems.add(p.key, "one dimension per value is needed");
    return;
  }
  if (p.kind == ParamKind::quantity && n != 1) {
    problems.add(p.key, "expected one value, got " + std::to_string(n));
    return;
  }
  if (p.kind == ParamKind::matrix && n != 9) {
    problems.add(p.key, "expected 3 rows of 3 values");
    return;
  }
  if (p.kind == ParamKind::list) {
    if (s.count > 0 && int(n) != s.count) {
      problems.add(p.key, "expected " + std::to_string(s.count) + " values, got " +
                              std::to_string(n));
      return;
    }
    if (n == 0) {
      problems.add(p.key, "expected at least one value");
      return;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    const std::string key = p.kind == ParamKind::quantity ? p.key : p.key + "[" + std::to_string(i) + "]";
    const int item = p.kind == ParamKind::list ? int(i) : 0;
    if (!s.accepts(p.dims[i], sensor, item) && !(s.plainZero && p.values[i] == 0.0)) {
      problems.add(key, "expected a value in " + exampleUnit(s.dim.of(sensor, item)) + ", got " +
                            p.dims[i].siUnit());
      continue;
    }
    const double v = p.values[i];
    if (s.bound == Bound::any && std::isnan(v)) problems.add(key, "expected a number");
    if (s.bound == Bound::positive && !(std::isfinite(v) && v > 0))
      problems.add(key, p.dims[i] == Dimension::temperature()
                            ? "must be above absolute zero (0 K = -273.15 degC), got \"" + shown(p, i) + "\""
                            : "must be positive, got \"" + shown(p, i) + "\"");
    if (s.bound == Bound::nonNegative && !(v >= 0)) problems.add(key, "must be zero or positive");
  }
}

}  // namespace

bool checkParameters(const EffectSpec& spec, const std::vector<ParamSchema>& schema, Sensor sensor,
                     SpecProblems& problems) {
  const std::size_t before = problems.items.size();
  std::vector<std::string> known;
  for (const auto& s : schema) known.push_back(s.key);
  for (std::size_t i = 0; i < spec.parameters.size(); ++i) {
    const ParamSpec& p = spec.parameters[i];
    const ParamSchema* s = nullptr;
    for (const auto& c : schema)
      if (c.key == p.key) s = &c;
    bool twice = false;
    for (std::size_t j = 0; j < i; ++j) twice = twice || spec.parameters[j].key == p.key;
    if (twice) problems.add(p.key, "given twice");
    else if (!s) {
      std::string list;
      for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
      problems.add(p.key, "unknown parameter of " + spec.type + " (known: " + list + ")");
    } else {
      checkValues(p, *s, sensor, problems);
    }
  }
  // Presence: required ones, and exactly one of each group.
  for (const auto& s : schema)
    if (s.need == Need::required && !spec.has(s.key)) problems.add(s.key, "missing key");
  std::vector<int> groups;
  for (const auto& s : schema)
    if (s.need == Need::oneOf && std::find(groups.begin(), groups.end(), s.group) == groups.end())
      groups.push_back(s.group);
  for (int g : groups) {
    std::string list;
    int present = 0;
    for (const auto& s : schema) {
      if (s.need != Need::oneOf || s.group != g) continue;
      list += (list.empty() ? "" : ", ") + s.key;
      present += spec.has(s.key) ? 1 : 0;
    }
    if (present == 0) problems.add("", "missing parameter: give one of " + list);
    if (present > 1) problems.add("", "give only one of " + list);
  }
  return problems.items.size() == before;
}

}  // namespace sinsim::errormodels
