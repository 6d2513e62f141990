// The model's ramps taken out of the record and the model (model_drift.hpp).
#include "errormodels/diagnose/model_drift.hpp"

#include <utility>

#include "errormodels/diagnose/channels.hpp"
#include "errormodels/diagnose/series_stats.hpp"
#include "errormodels/stats/lattice.hpp"

namespace sinsim::errormodels::diagnose::detail {

std::array<double, 6> modelDrifts(const ErrorModelSpec& model) {
  std::array<double, 6> drift{};
  for (int c = 0; c < 6; ++c) {
    const SensorSpec& s = model.sensor(c < 3 ? Sensor::gyro : Sensor::accel);
    for (const auto* list : {&s.all, &s.list(axisList(c % 3))})
      for (const auto& e : *list)
        if (e.enabled && e.type == "ramp")
          if (const ParamSpec* p = e.find("slope"); p && p->values.size() == 1) drift[std::size_t(c)] += p->values[0];
  }
  return drift;
}

std::optional<DriftFree> withoutModelDrift(const Record& record, const ErrorModelSpec& model) {
  auto drift = modelDrifts(model);
  std::array<double, 6> kept{};
  bool any = false;
  for (int c = 0; c < 6; ++c) {
    // A channel on a lattice the diagnosis sees keeps the model's ramp: less a line its values
    // would leave the lattice, and their rounding would read as white noise.
    const auto& y = channelData(record, c);
    if (!y.empty() && drift[std::size_t(c)] != 0.0 && latticeVisible(y, latticeStep(y), record.rate_hz))
      std::swap(kept[std::size_t(c)], drift[std::size_t(c)]);
    any = any || (drift[std::size_t(c)] != 0.0 && !y.empty());
  }
  if (!any) return std::nullopt;
  DriftFree out{record, model, drift};
  const double dt = 1.0 / record.rate_hz;
  for (int c = 0; c < 6; ++c) {
    auto& y = c < 3 ? out.record.gyro[std::size_t(c)] : out.record.accel[std::size_t(c - 3)];
    for (std::size_t k = 0; k < y.size(); ++k) y[k] -= drift[std::size_t(c)] * double(k + 1) * dt;
  }
  for (Sensor sensor : {Sensor::gyro, Sensor::accel})
    for (EffectList l : {EffectList::all, EffectList::x, EffectList::y, EffectList::z})
      for (auto& e : out.model.sensor(sensor).list(l))
        if (e.type == "ramp") e.enabled = false;
  for (int c = 0; c < 6; ++c)  // a kept ramp back on its own axis, after its other effects
    if (kept[std::size_t(c)] != 0.0) {
      const Dimension signal = c < 3 ? Dimension::angularRate() : Dimension::acceleration();
      out.model.sensor(c < 3 ? Sensor::gyro : Sensor::accel)
          .list(axisList(c % 3))
          .push_back(EffectSpec::make("ramp", {ParamSpec::quantity("slope", kept[std::size_t(c)], signal / Dimension::time())}));
    }
  return out;
}

void stateModelDrift(Diagnosis& d, const std::array<double, 6>& drift) {
  for (auto& a : d.axes) {
    const int c = channelIndex(a.channel);
    const double R = drift[std::size_t(c)];
    if (R == 0.0) continue;
    a.modelDrift = R;
    const char* unit = unitsFor(c).slope;
    for (auto& f : a.findings)
      if (f.effect == "ramp" && f.params.count("slope"))
        f.evidence += "; beside the model's own ramp " + quantity(R, unit) + " (taken out of the record "
                      "and the model before the comparison): the record's drift is " +
                      quantity(R + f.params.at("slope"), unit);
  }
}

}  // namespace sinsim::errormodels::diagnose::detail
