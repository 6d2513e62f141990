// The boundary between the simulator and the sensor error plug-ins.
//
// ImuErrorModel is the parsed, immutable description of an IMU's errors (a model file or an
// inline `errors:` block of a scenario). It is shared by every run of a Monte Carlo batch.
// ImuCorruptor is one realisation of it: stateful, seeded, turning ideal increments into measured
// ones interval by interval. Ideal and corrupted signals stay apart: the simulator keeps the ideal
// sample and hands a copy to the corruptor.
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <memory>
#include <string>
#include <vector>

#include "common/config.hpp"
#include "common/types.hpp"
#include "errormodels/model_spec.hpp"

namespace sinsim::errormodels {

/// Identifies one realisation: every random stream is keyed by (seed, run, sensor, axis, effect),
/// so run k of a batch can be regenerated alone and results do not depend on thread count.
struct StreamKey {
  std::uint64_t seed = 0;
  std::uint64_t run = 0;
};

/// One realisation of an IMU error model.
class ImuCorruptor {
 public:
  virtual ~ImuCorruptor() = default;
  /// Replaces the ideal increments of `sample` (interval (t - dt, t]) by measured ones.
  /// temperature [K] is the sensor temperature over the interval (NaN when the scenario has no
  /// temperature profile; a model that needs it was refused at instantiation).
  virtual void corrupt(ImuSample& sample, double temperature) = 0;
  /// corrupt() for n consecutive samples, in order (temperature[i] for samples[i]); the same
  /// numbers, with one call per effect for the block instead of one per effect and sample.
  virtual void corruptBlock(ImuSample* samples, const double* temperature, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) corrupt(samples[i], temperature[i]);
  }
};

class ImuErrorModel {
 public:
  /// A perfect IMU.
  static ImuErrorModel none();
  /// Builds the effects of a spec (enabled ones only). `source` names the model in reports and
  /// messages. Throws ConfigError when an effect refuses its parameters (e.g. an unstable AR
  /// polynomial), naming file, line and key when the spec was read from a file.
  static ImuErrorModel fromSpec(const ErrorModelSpec& spec, const std::string& source);
  /// Reads a model file; throws ConfigError listing every problem with file, line, key path.
  static ImuErrorModel load(const std::string& path);
  /// Reads a model from a node of an already opened file (a scenario's inline `errors:` block);
  /// problems are recorded in that file's diagnostics.
  static ImuErrorModel parse(const ConfigNode& node);
  /// Parses model text as if read from the named file (tests, generated models).
  static ImuErrorModel fromString(const std::string& text, const std::string& name);

  bool empty() const;
  /// Does any effect need a temperature profile?
  bool needsTemperature() const;
  /// Does any effect add an error that depends on the ideal signal (Effect::readsSignal)?
  bool readsSignal() const;
  /// Names of the effects, "gyro.x.white" style, in model order (for listings and budgets).
  std::vector<std::string> effectNames() const;
  /// Where the model came from (file name or "inline"), for reports.
  const std::string& source() const { return source_; }
  /// The fitted record's length [s] (ErrorModelSpec::recordDuration); unset when not given.
  std::optional<double> recordDuration() const { return recordDuration_; }
  /// The same model keeping only the effects whose name passes `keep` (error budgets: switch
  /// effects off one at a time). Random streams are unchanged: the kept effects draw exactly the
  /// numbers they draw in the full model.
  ImuErrorModel filtered(const std::function<bool(const std::string&)>& keep) const;

  /// A realisation for an IMU at imuRate [Hz]. Throws InputError when the model cannot run at
  /// that rate (e.g. a stochastic process defined at a rate slower than the IMU).
  std::unique_ptr<ImuCorruptor> instantiate(double imuRate, const StreamKey& key) const;

  struct Impl;

 private:
  std::shared_ptr<const Impl> impl_;
  std::string source_ = "none";
  std::optional<double> recordDuration_;
};

}  // namespace sinsim::errormodels
