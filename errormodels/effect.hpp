// The plug-in interface of the sensor error effects and their registry, keyed by the YAML `type:`.
//
// An effect is built once from its EffectSpec (SI parameters, model_spec.hpp) into an immutable
// Effect (shared by every run of a batch) and turned into a stateful EffectState per run. Every state works on one sensor triad's increment vector u for one
// IMU interval (t0, t1]: u is dtheta_b [rad] for the gyro, dv_b [m/s] for the accelerometer.
//
// Adding an effect: write errormodels/effects/<name>.cpp defining
//     const std::vector<ParamSchema>& paramsOf_<name>();   // its parameters (effect_schema.hpp)
//     std::unique_ptr<Effect> buildEffect_<name>(const EffectSpec& spec, const EffectSite& site,
//                                                SpecProblems& problems);
// and add one line SINSIM_EFFECT(<name>, axis|triad, drawn|fixed|rounding, "summary") to
// errormodels/effects/effects.def (Scope, Nature below).
// buildEffect_ is called only with parameters that passed checkParameters (present, of the right
// kind, dimension and bound); it checks the rules that tie them together (a stable AR polynomial,
// a zero diagonal), records what is wrong in `problems` and returns nullptr, or builds the effect.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "common/error.hpp"
#include "common/units.hpp"
#include "errormodels/effect_schema.hpp"
#include "errormodels/flicker_gms.hpp"
#include "errormodels/imu_model.hpp"
#include "errormodels/random.hpp"
#include "common/types.hpp"

namespace sinsim::errormodels {

/// Scope of an effect: one axis of a triad, or the whole triad (3×3 effects).
enum class Scope { axis, triad };
/// What a run of an effect is: `drawn` — each run draws its realisation (a process, or a turn-on
/// value from a sigma); `fixed` — the same error in every run, a function of time, temperature and
/// the ideal signal (a calibration can remove it: the GNSS/INS filter compensates these as known);
/// `rounding` — the output's rounding.
enum class Nature { drawn, fixed, rounding };
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
  int line = 0;          ///< the effect's line in its model file (0: not from a file), for messages

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
  /// apply() for n consecutive intervals, in order: u[i] for iv[i].
  virtual void applyBlock(Vec3* u, const Interval* iv, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) apply(u[i], iv[i]);
  }
};

/// A realisation of an additive error e(t) on one axis: adds ∫_{t0}^{t1} e dt to u[axis].
class AxisErrorState : public EffectState {
 public:
  explicit AxisErrorState(int axis) : axis_(axis) {}
  void apply(Vec3& u, const Interval& iv) override { u[axis_] += integral(iv); }
  /// ∫ e dt over the interval [signal·s].
  virtual double integral(const Interval& iv) = 0;

 protected:
  int axis() const { return axis_; }

 private:
  int axis_;
};

/// The same for a class D whose integral() is final: apply() calls D::integral directly, so that
/// an IMU interval costs one virtual call per effect instead of two and the integral is inlined
/// (the processes every Monte Carlo run draws at each IMU epoch derive from this).
template <class D>
class DirectAxisErrorState : public AxisErrorState {
 public:
  using AxisErrorState::AxisErrorState;
  void apply(Vec3& u, const Interval& iv) final {
    u[axis()] += static_cast<D*>(this)->D::integral(iv);
  }
  void applyBlock(Vec3* u, const Interval* iv, std::size_t n) final {
    static_cast<D*>(this)->D::addIntegrals(u, iv, n, axis());
  }
  /// u[i][a] += integral(iv[i]) in order; a class D may hide it with a faster one of its own
  /// (the same draws in the same order, the same operations).
  void addIntegrals(Vec3* u, const Interval* iv, std::size_t n, int a) {
    D* d = static_cast<D*>(this);
    for (std::size_t i = 0; i < n; ++i) u[i][a] += d->D::integral(iv[i]);
  }
};

/// For a faster addIntegrals: calls chunk(iv + i, m, I) for consecutive chunks of at most kMax
/// intervals (I: their m integrals to fill, in order) and adds I to u[.][a].
template <std::size_t kMax, class Chunk>
void addIntegralsInChunks(Vec3* u, const Interval* iv, std::size_t n, int a, Chunk&& chunk) {
  double I[kMax];
  for (std::size_t i = 0; i < n; i += kMax) {
    const std::size_t m = std::min(kMax, n - i);
    chunk(iv + i, m, I);
    for (std::size_t k = 0; k < m; ++k) u[i + k][a] += I[k];
  }
}

struct InstanceContext {
  double imuRate = 0.0;  ///< nominal IMU output rate [Hz]
  StreamKey key;
  const EffectSite* site = nullptr;
  NormalStream stream(unsigned sub = 0) const {
    return NormalStream(key.seed, key.run, site->stream(sub));
  }
};

/// A built effect (immutable).
class Effect {
 public:
  virtual ~Effect() = default;
  virtual Stage stage() const { return Stage::additive; }
  virtual bool needsTemperature() const { return false; }
  /// Does the error it adds depend on the ideal signal (a g-sensitivity: the specific force)? The
  /// linear stage's effects act on the signal by definition and answer false.
  virtual bool readsSignal() const { return false; }
  /// A realisation; throws InputError when the effect cannot run at ctx.imuRate.
  virtual std::unique_ptr<EffectState> instantiate(const InstanceContext& ctx) const = 0;
};

using EffectParams = const std::vector<ParamSchema>& (*)();
using EffectBuilder = std::unique_ptr<Effect> (*)(const EffectSpec& spec, const EffectSite& site,
                                                  SpecProblems& problems);

struct EffectType {
  const char* name;
  Scope scope;
  Nature nature;
  const char* summary;
  EffectParams params;
  EffectBuilder build;
};

/// Every registered effect type, in registration order (effects/effects.def).
const std::vector<EffectType>& effectTypes();
/// nullptr when unknown.
const EffectType* findEffectType(const std::string& name);
/// "ar, bias, ..." for messages.
std::string knownEffectTypes();

/// Checks `spec` against its type's schema and builds it; nullptr (problems recorded) when the
/// type is unknown or a parameter is refused.
std::unique_ptr<Effect> buildEffect(const EffectSpec& spec, const EffectSite& site,
                                    SpecProblems& problems);

// ---- helpers for effect builders --------------------------------------------------------------

/// The SI value of quantity `key`, or `fallback` when the spec does not have it.
double valueOr(const EffectSpec& spec, const std::string& key, double fallback);
/// The values of list `key` (empty when absent).
std::vector<double> valuesOf(const EffectSpec& spec, const std::string& key);
/// The 3×3 matrix of a triad effect given as `matrix` (row-major), `diagonal` (3 values) or
/// `value` (a·I); zero when none is present.
Mat3 matrix3Of(const EffectSpec& spec);
/// The three parameters of a triad effect's matrix, entries of dimension `entry` (alsoAngle: a
/// small angle is accepted too); exactly one of them must be given.
std::vector<ParamSchema> matrixParams(DimRule entry, bool alsoAngle);
/// White noise density N [signal·sqrt(s)] of a `white` effect: `density`, or `sigma`/sqrt(`rate`)
/// (effects/white.cpp); NaN when neither form is complete.
double whiteDensityOf(const EffectSpec& spec);
/// Driving-noise standard deviation sigma_e [signal] of an `ar` effect: `sigma`, or
/// `output_sigma`/sqrt(G) with G the variance gain of its `a` (effects/ar.cpp).
double arDrivingSigmaOf(const EffectSpec& spec);
/// The Gauss-Markov components of a `bias_instability` (B or floor, tau_range; flicker_gms.hpp):
/// the ones its realisations draw. Throws InputError naming the key when tau_range is not valid.
FlickerGms biasInstabilityGmsOf(const EffectSpec& spec);
/// The second-order equivalent of a `bias_jumps` at the IMU rate `imuRate` [Hz]
/// (effects/bias_jumps.cpp), p = 1 − exp(−rate / imuRate) the chance of a jump per interval:
/// steps are a random walk of K² = imuRate p size² (rate size² when rate ≪ imuRate); a telegraph
/// a Gauss-Markov of sigma size/2 and tau = −1 / (imuRate ln(1 − 2p)) (1 / (2 rate) then).
struct JumpsEquivalent {
  bool telegraph = false;
  double K = 0.0;                 // steps [signal/sqrt(s)]
  double sigma = 0.0, tau = 0.0;  // telegraph [signal], [s]
};
JumpsEquivalent biasJumpsEquivalentOf(const EffectSpec& spec, double imuRate);
/// The white-noise density [signal·sqrt(s)] with the second moments of an `outliers` effect at
/// the IMU rate (effects/outliers.cpp): N² = p amplitude² / imuRate, p = rate / imuRate.
double outliersWhiteDensityOf(const EffectSpec& spec, double imuRate);
/// Refuses a process rate [Hz] slower than the IMU (throws InputError naming the effect).
void requireRateAtLeastImu(double processRate, const InstanceContext& ctx);

// Registration: one parameter list and one builder per effect file.
#define SINSIM_EFFECT(name, scope, nature, summary)                                           \
  const std::vector<ParamSchema>& paramsOf_##name();                                          \
  std::unique_ptr<Effect> buildEffect_##name(const EffectSpec& spec, const EffectSite& site, \
                                             SpecProblems& problems);
#include "errormodels/effects/effects.def"
#undef SINSIM_EFFECT

}  // namespace sinsim::errormodels
