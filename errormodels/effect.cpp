#include "errormodels/effect.hpp"

#include <algorithm>
#include <sstream>

namespace sinsim::errormodels {

const std::vector<EffectType>& effectTypes() {
  static const std::vector<EffectType> types = {
#define SINSIM_EFFECT(name, scope, summary) {#name, Scope::scope, summary, &parseEffect_##name},
#include "errormodels/effects/effects.def"
#undef SINSIM_EFFECT
  };
  return types;
}

const EffectType* findEffectType(const std::string& name) {
  for (const auto& t : effectTypes())
    if (name == t.name) return &t;
  return nullptr;
}

std::string knownEffectTypes() {
  std::string s;
  for (const auto& t : effectTypes()) s += (s.empty() ? "" : ", ") + std::string(t.name);
  return s;
}

double positiveQuantity(const ConfigNode& node, const std::string& key, Dimension dim) {
  ConfigNode c = node.require(key);
  if (!c.exists()) return NAN;
  auto v = c.asQuantity(dim);
  if (!v) return NAN;
  if (!(std::isfinite(*v) && *v > 0)) {
    c.error("must be positive, got \"" + c.asString().value_or("") + "\"");
    return NAN;
  }
  return *v;
}

double optionalPositive(const ConfigNode& node, const std::string& key, Dimension dim) {
  return node.has(key) ? positiveQuantity(node, key, dim) : NAN;
}

std::vector<double> numberList(const ConfigNode& node, const std::string& key) {
  std::vector<double> out;
  ConfigNode c = node.require(key);
  if (!c.exists()) return out;
  for (const auto& item : c.items()) out.push_back(item.asNumber().value_or(NAN));
  return out;
}

namespace {
std::optional<double> entry(const ConfigNode& n, Dimension dim, bool alsoAngle) {
  auto s = n.asString();
  if (!s) return std::nullopt;
  try {
    Quantity q = parseQuantity(*s);
    if (q.dim == dim || (alsoAngle && q.dim == Dimension::angle())) return q.si;
    // A plain 0 needs no unit.
    if (q.dim == Dimension::none() && q.si == 0.0) return 0.0;
    std::string want = exampleUnit(dim) + (alsoAngle ? " or an angle (deg, mrad)" : "");
    n.error("expected a value in " + want + ", got \"" + *s + "\"");
  } catch (const InputError& e) {
    n.error(e.what());
  }
  return std::nullopt;
}
}  // namespace

bool readMatrix3(const ConfigNode& node, Dimension dim, Mat3& out, bool alsoAngle) {
  std::string form = exactlyOne(node, {"matrix", "diagonal", "value"});
  if (form.empty()) return false;
  ConfigNode c = node[form];
  bool ok = true;
  out.setZero();
  if (form == "value") {
    auto v = entry(c, dim, alsoAngle);
    if (!v) return false;
    out = *v * Mat3::Identity();
    return true;
  }
  auto rows = c.items();
  if (!c.isSequence()) return false;
  if (rows.size() != 3) {
    c.error("expected 3 " + std::string(form == "matrix" ? "rows" : "values") + ", got " +
            std::to_string(rows.size()));
    return false;
  }
  for (int i = 0; i < 3; ++i) {
    if (form == "diagonal") {
      auto v = entry(rows[i], dim, alsoAngle);
      ok = ok && v.has_value();
      if (v) out(i, i) = *v;
      continue;
    }
    auto cols = rows[i].items();
    if (cols.size() != 3) {
      rows[i].error("expected a row of 3 values");
      ok = false;
      continue;
    }
    for (int j = 0; j < 3; ++j) {
      auto v = entry(cols[j], dim, alsoAngle);
      ok = ok && v.has_value();
      if (v) out(i, j) = *v;
    }
  }
  return ok;
}

std::string exactlyOne(const ConfigNode& node, const std::vector<std::string>& keys) {
  std::vector<std::string> present;
  for (const auto& k : keys)
    if (node.has(k)) present.push_back(k);
  if (present.size() == 1) return present[0];
  std::string list;
  for (const auto& k : keys) list += (list.empty() ? "" : ", ") + k;
  node.error(present.empty() ? "missing parameter: give one of " + list
                             : "give only one of " + list);
  return "";
}

void requireRateAtLeastImu(double processRate, const InstanceContext& ctx) {
  // 1e-9 relative: rates read from text ("1 kHz" vs 1000 Hz) agree to rounding only.
  if (processRate < ctx.imuRate * (1.0 - 1e-9)) {
    std::ostringstream s;
    s << ctx.site->name << ": the process is defined at " << processRate
      << " Hz, slower than the IMU rate " << ctx.imuRate
      << " Hz; a discrete model cannot be generated between its own samples (refit it at the IMU "
         "rate or faster, or run the IMU at " << processRate << " Hz or slower)";
    throw InputError(s.str());
  }
}

}  // namespace sinsim::errormodels
