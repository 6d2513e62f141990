#include "errormodels/imu_model.hpp"

#include <algorithm>
#include <sstream>

#include "errormodels/effect.hpp"
#include "errormodels/model_io.hpp"

namespace sinsim::errormodels {

struct ImuErrorModel::Impl {
  struct Entry {
    EffectSite site;
    std::shared_ptr<const Effect> effect;
  };
  std::vector<Entry> entries;
};

namespace {

const char* const kAxisNames[3] = {"x", "y", "z"};
// List identities, part of every stream id (EffectSite::stream): never renumber.
constexpr unsigned kListAll = 0, kListAxis = 1, kListTriad = 2;

unsigned listId(EffectList l) {
  return l == EffectList::triad ? kListTriad : l == EffectList::all ? kListAll : kListAxis;
}

// Builds the enabled effects of one list; problems are turned into diagnostics located by the
// spec's source locations (file, line, key path) when it was read from a file.
void buildList(const ErrorModelSpec& spec, const std::string& source, Sensor sensor, EffectList list,
               std::vector<ImuErrorModel::Impl::Entry>& out, std::vector<Diagnostic>& problems) {
  const auto& effects = spec.sensor(sensor).list(list);
  const std::string listPath = std::string(sensorName(sensor)) + "." + listName(list);
  for (std::size_t i = 0; i < effects.size(); ++i) {
    const EffectSpec& e = effects[i];
    const std::string path = listPath + "[" + std::to_string(i) + "]";
    EffectSite site;
    site.sensor = sensor;
    site.listId = listId(list);
    site.index = int(i);
    site.axis = list == EffectList::triad ? -1 : list == EffectList::all ? 0 : int(list) - 2;
    site.name = path + "." + e.type;
    site.line = e.where.line;
    SpecProblems found;
    const EffectType* et = findEffectType(e.type);
    if (et && (et->scope == Scope::triad) != (list == EffectList::triad))
      found.add("type", e.type + (et->scope == Scope::triad ? " acts on the whole triad: put it under "
                                                            : " acts on one axis: put it under ") +
                            sensorName(sensor) +
                            (et->scope == Scope::triad ? ".triad" : ".x, .y, .z or .all"));
    std::shared_ptr<const Effect> effect;
    if (found.empty()) effect = buildEffect(e, site, found);
    for (const auto& [key, message] : found.items) {
      const ParamSpec* p = e.find(key.substr(0, key.find('[')));
      // A value set in code after its effect was read (Model.with_param) is in no line of the file:
      // the file's line of the effect quoted a value it does not hold.
      const bool setInCode = p && p->where.line == 0 && e.where.line > 0;
      const SourceLocation& at = p && p->where.line > 0 ? p->where : e.where;
      problems.push_back({setInCode ? e.where.file + " (edited)" : e.where.file.empty() ? source : e.where.file,
                          setInCode ? 0 : at.line, key.empty() ? path : path + "." + key, message});
    }
    if (!effect || !e.enabled) continue;
    if (list == EffectList::all) {
      for (int a = 0; a < 3; ++a) {
        EffectSite s = site;
        s.axis = a;
        s.name = path + "." + e.type + "(" + kAxisNames[a] + ")";
        out.push_back({s, effect});
      }
    } else {
      out.push_back({site, effect});
    }
  }
}

class Corruptor final : public ImuCorruptor {
 public:
  std::vector<std::unique_ptr<EffectState>> gyro, accel;
  bool needsTemperature = false;

  void corrupt(ImuSample& sample, double temperature) override {
    const Interval iv = intervalOf(sample, temperature);
    for (auto& e : gyro) e->apply(sample.dtheta_b, iv);
    for (auto& e : accel) e->apply(sample.dv_b, iv);
  }

  // Effect by effect over the block: each effect sees its intervals in time order and each
  // sample its effects in list order, as corrupt() does sample by sample.
  void corruptBlock(ImuSample* samples, const double* temperature, std::size_t n) override {
    intervals_.resize(n);
    gyroU_.resize(n);
    accelU_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      intervals_[i] = intervalOf(samples[i], temperature[i]);
      gyroU_[i] = samples[i].dtheta_b;
      accelU_[i] = samples[i].dv_b;
    }
    for (auto& e : gyro) e->applyBlock(gyroU_.data(), intervals_.data(), n);
    for (auto& e : accel) e->applyBlock(accelU_.data(), intervals_.data(), n);
    for (std::size_t i = 0; i < n; ++i) {
      samples[i].dtheta_b = gyroU_[i];
      samples[i].dv_b = accelU_[i];
    }
  }

 private:
  Interval intervalOf(const ImuSample& sample, double temperature) const {
    if (needsTemperature && !std::isfinite(temperature))
      throw InputError("the IMU error model has a temperature effect but no sensor temperature "
                       "was given (add a temperature profile)");
    Interval iv;
    iv.t1 = sample.t;
    iv.dt = sample.dt;
    iv.t0 = sample.t - sample.dt;
    iv.temperature = temperature;
    iv.dtheta_ideal_b = sample.dtheta_b;
    iv.dv_ideal_b = sample.dv_b;
    return iv;
  }

  std::vector<Interval> intervals_;  // corruptBlock's work space
  std::vector<Vec3> gyroU_, accelU_;
};

}  // namespace

ImuErrorModel ImuErrorModel::none() { return ImuErrorModel(); }

ImuErrorModel ImuErrorModel::fromSpec(const ErrorModelSpec& spec, const std::string& source) {
  auto impl = std::make_shared<Impl>();
  std::vector<Diagnostic> problems;
  for (Sensor sensor : {Sensor::gyro, Sensor::accel})
    for (EffectList l : {EffectList::triad, EffectList::all, EffectList::x, EffectList::y,
                         EffectList::z})
      buildList(spec, source, sensor, l, impl->entries, problems);
  if (!problems.empty()) throw ConfigError(problems);
  ImuErrorModel m;
  m.impl_ = impl;
  m.source_ = source;
  m.recordDuration_ = spec.recordDuration;
  return m;
}

ImuErrorModel ImuErrorModel::load(const std::string& path) {
  return fromSpec(loadErrorModel(path), path);
}

ImuErrorModel ImuErrorModel::fromString(const std::string& text, const std::string& name) {
  return fromSpec(errorModelFromString(text, name), name);
}

ImuErrorModel ImuErrorModel::parse(const ConfigNode& node) {
  // The reader records every problem in the node's file (the caller throws); a model is built
  // only from a spec that was read without one.
  ErrorModelSpec spec = readErrorModel(node);
  try {
    return fromSpec(spec, "inline");
  } catch (const ConfigError&) {
    ImuErrorModel m;
    m.source_ = "inline";
    m.impl_ = std::make_shared<Impl>();
    return m;  // the same problems are already in the file's diagnostics
  }
}

bool ImuErrorModel::empty() const { return !impl_ || impl_->entries.empty(); }

bool ImuErrorModel::needsTemperature() const {
  if (!impl_) return false;
  for (const auto& e : impl_->entries)
    if (e.effect->needsTemperature()) return true;
  return false;
}

bool ImuErrorModel::readsSignal() const {
  if (!impl_) return false;
  for (const auto& e : impl_->entries)
    if (e.effect->readsSignal()) return true;
  return false;
}

std::vector<std::string> ImuErrorModel::effectNames() const {
  std::vector<std::string> names;
  if (impl_)
    for (const auto& e : impl_->entries) names.push_back(e.site.name);
  return names;
}

ImuErrorModel ImuErrorModel::filtered(const std::function<bool(const std::string&)>& keep) const {
  ImuErrorModel m = *this;
  if (!impl_) return m;
  auto impl = std::make_shared<Impl>();
  for (const auto& e : impl_->entries)
    if (keep(e.site.name)) impl->entries.push_back(e);
  m.impl_ = impl;
  return m;
}

std::unique_ptr<ImuCorruptor> ImuErrorModel::instantiate(double imuRate,
                                                         const StreamKey& key) const {
  if (!(std::isfinite(imuRate) && imuRate > 0))
    throw InputError("IMU rate must be positive, got " + std::to_string(imuRate) + " Hz");
  auto c = std::make_unique<Corruptor>();
  if (!impl_) return c;
  // Stable sort by stage: linear effects (in file order) before additive before output.
  std::vector<const Impl::Entry*> order;
  for (const auto& e : impl_->entries) order.push_back(&e);
  std::stable_sort(order.begin(), order.end(), [](const Impl::Entry* a, const Impl::Entry* b) {
    return int(a->effect->stage()) < int(b->effect->stage());
  });
  for (const Impl::Entry* e : order) {
    InstanceContext ctx;
    ctx.imuRate = imuRate;
    ctx.key = key;
    ctx.site = &e->site;
    // "gyro.x[0].ar: the process is defined at 5 Hz, slower than the IMU rate" names the model
    // file and the effect's line too (it is found only here, once the IMU rate is known).
    const std::string where =
        e->site.line > 0 ? source() + ":" + std::to_string(e->site.line) : source();
    auto state = source().empty() ? e->effect->instantiate(ctx)
                                  : withContext(where, [&] { return e->effect->instantiate(ctx); });
    (e->site.sensor == Sensor::gyro ? c->gyro : c->accel).push_back(std::move(state));
    c->needsTemperature = c->needsTemperature || e->effect->needsTemperature();
  }
  return c;
}

}  // namespace sinsim::errormodels
