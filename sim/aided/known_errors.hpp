// The filter model's known errors: effects that draw nothing a filter could estimate —
// misalignment, a scale_factor matrix's off-diagonal part, g-sensitivity (triad), ramp, warmup,
// sinusoid and temperature (axis; at the scenario's sensor temperature, which an INS reads from
// its IMU). An INS's calibration removes them; the aided navigation does the same: it
// subtracts what they add to each measured sample, computed by the effects' own code (error
// models of these effects alone, applied to the measured sample; the misalignment inverted to
// O(K³), the g-sensitivity taken of the compensated specific force). They carry no filter state.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "common/types.hpp"
#include "errormodels/imu_model.hpp"
#include "errormodels/model_spec.hpp"

namespace sinsim::sim::aided {

/// True for the effect types the filter compensates as known: the registry's `fixed` ones
/// (errormodels::Nature; today misalignment, g_sensitivity, ramp, warmup, sinusoid,
/// temperature); a scale_factor's off-diagonal part is known too (knownPart).
bool isKnownEffect(const std::string& type);

/// The known part of a filter model: its enabled known effects in their lists, and each
/// scale_factor matrix's off-diagonal entries as a misalignment (its diagonal stays a filter
/// state). `linear` true: the effects that act on the signal (misalignment, scale off-diagonals),
/// false: the ones added to it (g_sensitivity, ramp, warmup, sinusoid, temperature). Empty when
/// there is none.
errormodels::ErrorModelSpec knownPart(const errormodels::ErrorModelSpec& spec, bool linear);

/// The known effects as the model file places them: "gyro.all[2].warmup", "gyro.triad[1].
/// scale_factor off-diagonal" (sensor, list, index in the list, type).
std::vector<std::string> knownLabels(const errormodels::ErrorModelSpec& spec);

/// One run's compensation of the known errors, in the reverse of the order a sensor adds them
/// (the signal is scaled and misaligned first, then errors are added: errormodels/effect.hpp):
/// withoutAdded first, the filter's bias estimate, then withoutLinear.
class KnownErrors {
 public:
  /// added, linear: ImuErrorModel::fromSpec of knownPart(spec, false / true); imuRate [Hz].
  KnownErrors(const errormodels::ImuErrorModel& added, const errormodels::ImuErrorModel& linear,
              double imuRate);
  /// The sample less what the known added effects (ramp, warm-up, sinusoid; a temperature
  /// polynomial at the sensor's `temperature` [K]; g-sensitivity times the specific force's
  /// increment `dv` [m/s], best the compensated one) add over its interval; unchanged when there
  /// are none.
  ImuSample withoutAdded(const ImuSample& s, const Vec3& dv, double temperature);
  /// Does a known error depend on the specific force (a g-sensitivity)?
  bool sensesForce() const { return sensesForce_; }
  /// (I + K)⁻¹ s to O(K³ s), I + K the known misalignments' product; unchanged when there is none.
  ImuSample withoutLinear(const ImuSample& s);

 private:
  static ImuSample less(const ImuSample& s, errormodels::ImuCorruptor& c, double temperature);
  std::unique_ptr<errormodels::ImuCorruptor> added_, linear_;  // nullptr: none
  bool sensesForce_ = false;
};

}  // namespace sinsim::sim::aided
