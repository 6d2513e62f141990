#include "errormodels/effect.hpp"

#include <algorithm>
#include <sstream>

namespace sinsim::errormodels {

const std::vector<EffectType>& effectTypes() {
  static const std::vector<EffectType> types = {
#define SINSIM_EFFECT(name, scope, nature, summary) \
  {#name, Scope::scope, Nature::nature, summary, &paramsOf_##name, &buildEffect_##name},
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

std::unique_ptr<Effect> buildEffect(const EffectSpec& spec, const EffectSite& site,
                                    SpecProblems& problems) {
  const EffectType* et = findEffectType(spec.type);
  if (!et) {
    problems.add("type", "unknown effect type \"" + spec.type + "\" (known: " +
                             knownEffectTypes() + ")");
    return nullptr;
  }
  if (!checkParameters(spec, et->params(), site.sensor, problems)) return nullptr;
  return et->build(spec, site, problems);
}

double valueOr(const EffectSpec& spec, const std::string& key, double fallback) {
  const ParamSpec* p = spec.find(key);
  return p && p->values.size() == 1 ? p->values[0] : fallback;
}

std::vector<double> valuesOf(const EffectSpec& spec, const std::string& key) {
  const ParamSpec* p = spec.find(key);
  return p ? p->values : std::vector<double>{};
}

Mat3 matrix3Of(const EffectSpec& spec) {
  Mat3 M = Mat3::Zero();
  if (const ParamSpec* p = spec.find("value")) M = p->values[0] * Mat3::Identity();
  if (const ParamSpec* p = spec.find("diagonal"))
    for (int i = 0; i < 3; ++i) M(i, i) = p->values[std::size_t(i)];
  if (const ParamSpec* p = spec.find("matrix"))
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) M(i, j) = p->values[std::size_t(3 * i + j)];
  return M;
}

std::vector<ParamSchema> matrixParams(DimRule entry, bool alsoAngle) {
  std::vector<ParamSchema> p = {
      param("matrix", ParamKind::matrix, entry).oneOf(1).zeroWithoutUnit()
          .doc("the full 3x3 matrix, row by row"),
      param("diagonal", ParamKind::list, entry).oneOf(1).items(3).zeroWithoutUnit()
          .doc("a diagonal matrix: [xx, yy, zz]"),
      param("value", ParamKind::quantity, entry).oneOf(1).zeroWithoutUnit()
          .doc("the same value on the diagonal (value * I)")};
  if (alsoAngle)
    for (auto& q : p) q.orDim(fixed(Dimension::angle()));
  return p;
}

void requireRateAtLeastImu(double processRate, const InstanceContext& ctx) {
  // 1e-6 relative: a model fitted at a record's rate read from its time stamps (jittered, or
  // Unix time in ns: 100.0000013 Hz) is at that rate, and was refused as "100 Hz, slower than
  // the IMU rate 100 Hz"; a discrete process run 1e-6 off its rate is off by far less than its
  // parameters' own uncertainty.
  if (processRate < ctx.imuRate * (1.0 - 1e-6)) {
    std::ostringstream s;
    s.precision(12);
    s << ctx.site->name << ": the process is defined at " << processRate
      << " Hz, slower than the IMU rate " << ctx.imuRate
      << " Hz; a discrete model cannot be generated between its own samples (refit it at the IMU "
         "rate or faster, or run the IMU at " << processRate << " Hz or slower)";
    throw InputError(s.str());
  }
}

}  // namespace sinsim::errormodels
