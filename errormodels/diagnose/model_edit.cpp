// The AR base of a channel and the edit of improve(), on ErrorModelSpec (model_edit.hpp).
#include "errormodels/diagnose/model_edit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "common/error.hpp"
#include "common/units.hpp"
#include "errormodels/diagnose/channels.hpp"

namespace sinsim::errormodels::diagnose::detail {

namespace {

Sensor sensorOf(int channel) { return isGyro(channel) ? Sensor::gyro : Sensor::accel; }

/// The keys holding a stochastic effect's noise level (scaled by sqrt of the variance factor).
std::vector<std::string> noiseKeys(const std::string& type) {
  if (type == "ar") return {"sigma", "output_sigma"};
  if (type == "white") return {"density", "sigma"};
  if (type == "gauss_markov") return {"sigma"};
  if (type == "random_walk") return {"K"};
  if (type == "bias_instability") return {"B", "floor"};
  return {};
}

bool isNoise(const EffectSpec& e) { return !noiseKeys(e.type).empty(); }

/// Each axis of `sensor` gets the noise effects of `all` at the head of its own list (they leave
/// `all`), so that the axes can be scaled apart.
ErrorModelSpec noiseOfAllToAxes(ErrorModelSpec spec, Sensor sensor) {
  SensorSpec& s = spec.sensor(sensor);
  std::vector<EffectSpec> moved;
  for (const auto& e : s.all)
    if (isNoise(e)) moved.push_back(e);
  s.all.erase(std::remove_if(s.all.begin(), s.all.end(), isNoise), s.all.end());
  for (int a = 0; a < 3; ++a) {
    auto& list = s.list(axisList(a));
    list.insert(list.begin(), moved.begin(), moved.end());
  }
  return spec;
}

/// The `ar` at ref with coefficients a1..ap and driving sigma rep.back() [SI], stated like the
/// sizes of the findings.
ErrorModelSpec withRefittedAr(ErrorModelSpec spec, const EffectRef& ref, int channel,
                              const std::vector<double>& rep) {
  spec = withParameter(std::move(spec), ref, ParamSpec::numbers("a", std::vector<double>(rep.begin(), rep.end() - 1)));
  auto& params = spec.sensor(ref.sensor).list(ref.list).at(std::size_t(ref.index)).parameters;
  params.erase(std::remove_if(params.begin(), params.end(),
                              [](const ParamSpec& p) { return p.key == "output_sigma"; }),
               params.end());
  const Dimension signal = isGyro(channel) ? Dimension::angularRate() : Dimension::acceleration();
  return withParameter(std::move(spec), ref,
                       ParamSpec::quantity("sigma", stated(rep.back(), unitsFor(channel).level), signal));
}

/// Scales the noise and refits the AR of one axis list (channel c), then appends its effects.
ErrorModelSpec editAxis(ErrorModelSpec spec, int c, const ModelEdits& edits) {
  const Sensor sensor = sensorOf(c);
  const EffectList list = axisList(c % 3);
  const double f = std::sqrt(edits.varianceScale[std::size_t(c)]);
  const auto& rep = edits.arReplace[std::size_t(c)];
  const auto n = spec.sensor(sensor).list(list).size();
  for (std::size_t i = 0; i < n; ++i) {
    const EffectRef ref{sensor, list, int(i)};
    const EffectSpec& e = effectAt(spec, ref);
    if (e.type == "ar" && !rep.empty()) {
      spec = withRefittedAr(std::move(spec), ref, c, rep);
    } else if (f != 1.0) {
      for (const auto& key : noiseKeys(e.type))
        if (effectAt(spec, ref).has(key)) spec = scaleParameter(std::move(spec), ref, key, f);
    }
  }
  for (const auto& e : edits.add[std::size_t(c)]) spec = withEffect(std::move(spec), sensor, list, e);
  return spec;
}

}  // namespace

std::optional<std::vector<double>> baseAr(const ErrorModelSpec& model, int channel, double rate) {
  const SensorSpec& s = model.sensor(sensorOf(channel));
  const EffectSpec* found = nullptr;
  int count = 0;
  for (const auto* list : {&s.all, &s.list(axisList(channel % 3))})
    for (const auto& e : *list)
      if (e.type == "ar" && e.enabled) ++count, found = &e;
  if (count != 1) return std::nullopt;
  const ParamSpec* r = found->find("rate");
  const ParamSpec* a = found->find("a");
  if (!r || !a || r->values.size() != 1 || std::fabs(r->values[0] - rate) > 1e-6 * rate)
    return std::nullopt;
  std::vector<double> poly{1.0};
  poly.insert(poly.end(), a->values.begin(), a->values.end());
  return poly;
}

std::optional<std::vector<double>> soleBaseAr(const ErrorModelSpec& model, int channel, double rate) {
  const SensorSpec& s = model.sensor(sensorOf(channel));
  for (const auto* list : {&s.all, &s.list(axisList(channel % 3))})
    for (const auto& e : *list)
      if (e.type != "ar" && e.enabled) return std::nullopt;
  return baseAr(model, channel, rate);
}

std::vector<Line> modelLines(const ErrorModelSpec& model, int channel) {
  const SensorSpec& s = model.sensor(sensorOf(channel));
  std::vector<Line> out;
  for (const auto* list : {&s.all, &s.list(axisList(channel % 3))})
    for (const auto& e : *list) {
      if (e.type != "sinusoid" || !e.enabled) continue;
      const ParamSpec* f = e.find("frequency");
      const ParamSpec* a = e.find("amplitude");
      if (f && a && f->values.size() == 1 && a->values.size() == 1)
        out.push_back({f->values[0], std::fabs(a->values[0]), true});
    }
  return out;
}

ErrorModelSpec editedModel(ErrorModelSpec model, const ModelEdits& edits) {
  for (double s : edits.varianceScale)
    if (!(std::isfinite(s) && s > 0))
      throw InputError("diagnose: a variance factor must be positive, got " + std::to_string(s));
  for (Sensor sensor : {Sensor::gyro, Sensor::accel}) {
    const int c0 = sensor == Sensor::gyro ? 0 : 3;
    bool any = false, differs = false;
    for (int c = c0; c < c0 + 3; ++c) {
      const bool scaled = edits.varianceScale[std::size_t(c)] != 1.0 || !edits.arReplace[std::size_t(c)].empty();
      any = any || scaled || !edits.add[std::size_t(c)].empty();
      differs = differs || scaled;
    }
    if (!any) continue;
    if (differs) model = noiseOfAllToAxes(std::move(model), sensor);
    for (int c = c0; c < c0 + 3; ++c) model = editAxis(std::move(model), c, edits);
  }
  // A new model: no value points into the file the original was read from any more.
  for (Sensor sensor : {Sensor::gyro, Sensor::accel})
    for (EffectList l : {EffectList::triad, EffectList::all, EffectList::x, EffectList::y, EffectList::z})
      for (auto& e : model.sensor(sensor).list(l)) {
        e.where = {};
        for (auto& p : e.parameters) p.where = {};
      }
  return model;
}

double stated(double si, const char* unit, int digits) {
  const double f = parseUnit(unit).si;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, si / f);
  return std::strtod(buf, nullptr) * f;
}

}  // namespace sinsim::errormodels::diagnose::detail
