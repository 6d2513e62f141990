// The model's ramps, warm-ups and temperature polynomials taken out of the record and the model
// (model_drift.hpp).
#include "errormodels/diagnose/model_drift.hpp"

#include <cmath>
#include <utility>

#include "errormodels/diagnose/channels.hpp"
#include "errormodels/diagnose/series_stats.hpp"
#include "errormodels/stats/lattice.hpp"

namespace sinsim::errormodels::diagnose::detail {
namespace {

bool isDrift(const EffectSpec& e, bool withTemperature) {
  return e.enabled && (e.type == "ramp" || e.type == "warmup" || (withTemperature && e.type == "temperature"));
}

double scalar(const EffectSpec& e, const char* name) {
  const ParamSpec* p = e.find(name);
  return p && p->values.size() == 1 ? p->values[0] : NAN;
}

void addDrift(const EffectSpec& e, ChannelDrift& d) {
  if (e.type == "ramp") {
    if (const double R = scalar(e, "slope"); std::isfinite(R)) d.slope += R;
  } else if (e.type == "warmup") {
    d.warmups.push_back({scalar(e, "amplitude"), scalar(e, "tau")});
  } else {
    d.temperature = true;
  }
}

// The enabled drift effects of channel c's sensor on its axis: the `all` list's, then its own.
std::vector<EffectSpec> driftEffects(const ErrorModelSpec& model, int c, bool withTemperature) {
  const SensorSpec& s = model.sensor(c < 3 ? Sensor::gyro : Sensor::accel);
  std::vector<EffectSpec> out;
  for (const auto* list : {&s.all, &s.list(axisList(c % 3))})
    for (const auto& e : *list)
      if (isDrift(e, withTemperature)) out.push_back(e);
  return out;
}

std::array<ChannelDrift, 6> modelDrifts(const ErrorModelSpec& model, bool withTemperature) {
  std::array<ChannelDrift, 6> drift{};
  for (int c = 0; c < 6; ++c)
    for (const auto& e : driftEffects(model, c, withTemperature)) addDrift(e, drift[std::size_t(c)]);
  return drift;
}

}  // namespace

std::optional<DriftFree> withoutModelDrift(const Record& record, const ErrorModelSpec& model) {
  const bool withTemperature = !record.temperature.empty();
  auto drift = modelDrifts(model, withTemperature);
  std::array<bool, 6> kept{};
  bool any = false;
  for (int c = 0; c < 6; ++c) {
    const auto& y = channelData(record, c);
    auto& d = drift[std::size_t(c)];
    if (!y.empty() && d.any() && latticeVisible(y, latticeStep(y))) {
      kept[std::size_t(c)] = true;
      d = ChannelDrift{};
    }
    any = any || (d.any() && !y.empty());
  }
  if (!any) return std::nullopt;
  // The drift alone, realised as the model's realisations hold it (no random effect: none drawn).
  ErrorModelSpec alone;
  alone.source = model.source;
  for (int c = 0; c < 6; ++c)
    if (drift[std::size_t(c)].any())
      alone.sensor(c < 3 ? Sensor::gyro : Sensor::accel).list(axisList(c % 3)) =
          driftEffects(model, c, withTemperature);
  const Record series = simulateRecord(alone, record.rate_hz, record.rows, 0, 0, std::vector<double>(6, 0.0),
                                       record.temperature);
  DriftFree out{record, model, drift};
  for (int c = 0; c < 6; ++c) {
    if (!drift[std::size_t(c)].any()) continue;
    auto& y = c < 3 ? out.record.gyro[std::size_t(c)] : out.record.accel[std::size_t(c - 3)];
    const auto& s = channelData(series, c);
    for (std::size_t k = 0; k < y.size(); ++k) y[k] -= s[k];
  }
  for (Sensor sensor : {Sensor::gyro, Sensor::accel})
    for (EffectList l : {EffectList::all, EffectList::x, EffectList::y, EffectList::z})
      for (auto& e : out.model.sensor(sensor).list(l))
        if (isDrift(e, withTemperature)) e.enabled = false;
  for (int c = 0; c < 6; ++c)  // a kept drift back on its own axis, after its other effects
    if (kept[std::size_t(c)])
      for (EffectSpec& e : driftEffects(model, c, withTemperature))
        out.model.sensor(c < 3 ? Sensor::gyro : Sensor::accel).list(axisList(c % 3)).push_back(std::move(e));
  return out;
}

void stateModelDrift(Diagnosis& d, const std::array<ChannelDrift, 6>& drift) {
  for (auto& a : d.axes) {
    const int c = channelIndex(a.channel);
    const ChannelDrift& m = drift[std::size_t(c)];
    if (!m.any()) continue;
    a.modelDrift = m.slope;
    a.modelWarmups = m.warmups;
    a.modelTemperature = m.temperature;
    const Units& u = unitsFor(c);
    for (auto& f : a.findings) {
      if (f.effect == "ramp" && m.slope != 0.0 && f.params.count("slope"))
        f.evidence += "; beside the model's own ramp " + quantity(m.slope, u.slope) + " (taken out of the record "
                      "and the model before the comparison): the record's drift is " +
                      quantity(m.slope + f.params.at("slope"), u.slope);
      if ((f.effect == "warmup" && !m.warmups.empty()) || (f.effect == "temperature" && m.temperature))
        f.evidence += "; beyond the model's own " + f.effect + " (taken out of the record and the model before "
                      "the comparison): `--add " + f.effect + "` writes it beside the model's, the two add";
    }
  }
}

}  // namespace sinsim::errormodels::diagnose::detail
