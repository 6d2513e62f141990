// The plug-in interface of the sensor error effects and their registry, keyed by the YAML `type:`.
//
// An effect is parsed once into an immutable Effect (shared by every run of a batch) and turned into
// a stateful EffectState per run. Every state works on one sensor triad's increment vector u for one
// IMU interval (t0, t1]: u is dtheta_b [rad] for the gyro, dv_b [m/s] for the accelerometer.
//
// Adding an effect: write errormodels/effects/<name>.cpp defining
//     std::unique_ptr<Effect> parseEffect_<name>(const ConfigNode& node, const EffectSite& site);
// and add one line SINSIM_EFFECT(<name>, axis|triad, "summary") to errormodels/effects/effects.def.
#pragma once

#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "common/config.hpp"
#include "common/error.hpp"
#include "common/units.hpp"
#include "errormodels/imu_model.hpp"
#include "errormodels/random.hpp"
#include "common/types.hpp"

namespace sinsim::errormodels {

enum class Sensor { gyro = 0, accel = 1 };
/// Scope of an effect: one axis of a triad, or the whole triad (3×3 effects).
enum class Scope { axis, triad };
/// Order of application inside one interval: linear (scale factor, misalignment, in file order) on
/// the ideal vector, then additive errors (processes, biases, g-sensitivity), then the output stage
/// (quantization).
enum class Stage { linear = 0, additive = 1, output = 2 };

/// Where an effect sits in a model; also names its random streams.
struct EffectSite {
  Sensor sensor = Sensor::gyro;
  int axis = 0;          ///< 0, 1, 2; -1 for a triad effect
  unsigned listId = 0;   ///< which list it came from (see streamBase)
  int index = 0;         ///< position in that list
  std::string name;      ///< "gyro.x[1].ar" style, for listings and messages

  /// The dimension of the sensor's signal: angular rate (gyro) or acceleration (accel).
  Dimension signal() const {
    return sensor == Sensor::gyro ? Dimension::angularRate() : Dimension::acceleration();
  }
  /// A unit for messages ("deg/s" or "m/s^2").
  std::string signalUnit() const { return sensor == Sensor::gyro ? "deg/s" : "m/s^2"; }
  /// Stream id of sub-stream `sub` of this effect (random.hpp).
  std::uint64_t stream(unsigned sub = 0) const {
    unsigned axisField = axis < 0 ? 3u : unsigned(axis);
    return streamId(unsigned(sensor), axisField, (listId << 12) | unsigned(index), sub);
  }
};

/// What one interval gives an effect: the interval, the temperature and the ideal signals.
struct Interval {
  double t0 = 0.0;  ///< start [s]
  double t1 = 0.0;  ///< end [s]
  double dt = 0.0;  ///< t1 - t0 [s]
  double temperature = NAN;         ///< sensor temperature [K] (NaN when none is given)
  Vec3 dtheta_ideal_b = Vec3::Zero();  ///< ideal angle increment [rad]
  Vec3 dv_ideal_b = Vec3::Zero();      ///< ideal velocity increment [m/s]
};

/// One realisation of an effect.
class EffectState {
 public:
  virtual ~EffectState() = default;
  /// Changes the triad's increment vector u [rad or m/s] for the interval.
  virtual void apply(Vec3& u, const Interval& iv) = 0;
};

/// A realisation of an additive error e(t) on one axis: adds ∫_{t0}^{t1} e dt to u[axis].
class AxisErrorState : public EffectState {
 public:
  explicit AxisErrorState(int axis) : axis_(axis) {}
  void apply(Vec3& u, const Interval& iv) final { u[axis_] += integral(iv); }
  /// ∫ e dt over the interval [signal·s].
  virtual double integral(const Interval& iv) = 0;

 private:
  int axis_;
};

struct InstanceContext {
  double imuRate = 0.0;  ///< nominal IMU output rate [Hz]
  StreamKey key;
  const EffectSite* site = nullptr;
  NormalStream stream(unsigned sub = 0) const {
    return NormalStream(key.seed, key.run, site->stream(sub));
  }
};

/// A parsed effect (immutable).
class Effect {
 public:
  virtual ~Effect() = default;
  virtual Stage stage() const { return Stage::additive; }
  virtual bool needsTemperature() const { return false; }
  /// A realisation; throws InputError when the effect cannot run at ctx.imuRate.
  virtual std::unique_ptr<EffectState> instantiate(const InstanceContext& ctx) const = 0;
};

using EffectParser = std::unique_ptr<Effect> (*)(const ConfigNode& node, const EffectSite& site);

struct EffectType {
  const char* name;
  Scope scope;
  const char* summary;
  EffectParser parse;
};

/// Every registered effect type, in registration order (effects/effects.def).
const std::vector<EffectType>& effectTypes();
/// nullptr when unknown.
const EffectType* findEffectType(const std::string& name);
/// "ar, bias, ..." for messages.
std::string knownEffectTypes();

// ---- helpers for effect parsers (record diagnostics on the node, return NaN/empty on failure) --

/// A required strictly positive quantity of the given dimension.
double positiveQuantity(const ConfigNode& node, const std::string& key, Dimension dim);
/// An optional strictly positive quantity; NaN when absent.
double optionalPositive(const ConfigNode& node, const std::string& key, Dimension dim);
/// A list of numbers (plain, dimensionless).
std::vector<double> numberList(const ConfigNode& node, const std::string& key);
/// A 3×3 matrix given as `matrix: [[..],[..],[..]]`, `diagonal: [a, b, c]` or `value: a` (a·I);
/// entries of dimension dim (or, when alsoAngle, an angle, read as a small angle in rad).
/// Exactly one form must be present. Returns false (and records why) on failure.
bool readMatrix3(const ConfigNode& node, Dimension dim, Mat3& out, bool alsoAngle = false);
/// Records "give exactly one of a, b" unless exactly one is present; returns the present one.
std::string exactlyOne(const ConfigNode& node, const std::vector<std::string>& keys);
/// Refuses a process rate [Hz] slower than the IMU (throws InputError naming the effect).
void requireRateAtLeastImu(double processRate, const InstanceContext& ctx);

// Registration: one parse function per effect file.
#define SINSIM_EFFECT(name, scope, summary) \
  std::unique_ptr<Effect> parseEffect_##name(const ConfigNode& node, const EffectSite& site);
#include "errormodels/effects/effects.def"
#undef SINSIM_EFFECT

}  // namespace sinsim::errormodels
