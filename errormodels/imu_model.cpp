#include "errormodels/imu_model.hpp"

#include <algorithm>
#include <sstream>

#include "errormodels/effect.hpp"

namespace sinsim::errormodels {

struct ImuErrorModel::Impl {
  struct Entry {
    EffectSite site;
    std::shared_ptr<const Effect> effect;
  };
  std::vector<Entry> entries;
};

namespace {

const char* const kSensorNames[2] = {"gyro", "accel"};
const char* const kAxisNames[3] = {"x", "y", "z"};
// List identities, part of every stream id (EffectSite::stream): never renumber.
constexpr unsigned kListAll = 0, kListAxis = 1, kListTriad = 2;

void parseList(const ConfigNode& list, Sensor sensor, unsigned listId, int axis,
               std::vector<ImuErrorModel::Impl::Entry>& out) {
  if (!list.exists()) return;
  const auto items = list.items();
  for (std::size_t i = 0; i < items.size(); ++i) {
    const ConfigNode& item = items[i];
    if (!item.isMap()) {
      item.error("expected an effect, e.g. {type: white, density: 0.2 deg/sqrt(h)}");
      continue;
    }
    std::string type = item.string("type");
    if (type.empty()) continue;
    const EffectType* et = findEffectType(type);
    if (!et) {
      item["type"].error("unknown effect type \"" + type + "\" (known: " + knownEffectTypes() + ")");
      continue;
    }
    const bool triadList = listId == kListTriad;
    if (et->scope == Scope::triad && !triadList) {
      item["type"].error(type + " acts on the whole triad: put it under " +
                         kSensorNames[int(sensor)] + ".triad");
      continue;
    }
    if (et->scope == Scope::axis && triadList) {
      item["type"].error(type + " acts on one axis: put it under " + kSensorNames[int(sensor)] +
                         ".x, .y, .z or .all");
      continue;
    }
    EffectSite site;
    site.sensor = sensor;
    site.listId = listId;
    site.index = int(i);
    site.axis = triadList ? -1 : (listId == kListAll ? 0 : axis);
    site.name = item.path() + "." + type;
    bool enabled = item.boolean("enabled", true);
    std::shared_ptr<const Effect> effect = et->parse(item, site);
    if (!effect || !enabled) continue;
    if (listId == kListAll) {
      for (int a = 0; a < 3; ++a) {
        EffectSite s = site;
        s.axis = a;
        s.name = item.path() + "." + type + "(" + kAxisNames[a] + ")";
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

  void corrupt(nav::ImuSample& sample, double temperature) override {
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
    for (auto& e : gyro) e->apply(sample.dtheta_b, iv);
    for (auto& e : accel) e->apply(sample.dv_b, iv);
  }
};

}  // namespace

ImuErrorModel ImuErrorModel::none() { return ImuErrorModel(); }

ImuErrorModel ImuErrorModel::load(const std::string& path) {
  ConfigFile file = ConfigFile::load(
      path, "an empty error model; write `gyro: {}` if you mean a perfect IMU");
  ImuErrorModel m = parse(file.root());
  file.throwIfErrors();
  m.source_ = path;
  return m;
}

ImuErrorModel ImuErrorModel::fromString(const std::string& text, const std::string& name) {
  ConfigFile file = ConfigFile::fromString(text, name);
  ImuErrorModel m = parse(file.root());
  file.throwIfErrors();
  m.source_ = name;
  return m;
}

ImuErrorModel ImuErrorModel::parse(const ConfigNode& node) {
  auto impl = std::make_shared<Impl>();
  ImuErrorModel m;
  m.source_ = "inline";
  if (!node.exists()) {
    m.impl_ = impl;
    return m;
  }
  if (!node.isMap()) {
    node.error("expected an error model: a map with keys gyro and/or accel");
    m.impl_ = impl;
    return m;
  }
  node.allowKeys({"description", "gyro", "accel"});
  for (int s = 0; s < 2; ++s) {
    ConfigNode sn = node[kSensorNames[s]];
    if (!sn.exists()) continue;
    if (!sn.isMap()) {
      sn.error("expected a map with keys triad, all, x, y, z (each a list of effects)");
      continue;
    }
    sn.allowKeys({"triad", "all", "x", "y", "z"});
    Sensor sensor = Sensor(s);
    parseList(sn["triad"], sensor, kListTriad, -1, impl->entries);
    parseList(sn["all"], sensor, kListAll, 0, impl->entries);
    for (int a = 0; a < 3; ++a) parseList(sn[kAxisNames[a]], sensor, kListAxis, a, impl->entries);
  }
  m.impl_ = impl;
  return m;
}

bool ImuErrorModel::empty() const { return !impl_ || impl_->entries.empty(); }

bool ImuErrorModel::needsTemperature() const {
  if (!impl_) return false;
  for (const auto& e : impl_->entries)
    if (e.effect->needsTemperature()) return true;
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
    auto state = e->effect->instantiate(ctx);
    (e->site.sensor == Sensor::gyro ? c->gyro : c->accel).push_back(std::move(state));
    c->needsTemperature = c->needsTemperature || e->effect->needsTemperature();
  }
  return c;
}

}  // namespace sinsim::errormodels
