// The filter's sensor-error states from an error-model spec (the `filter: {model: ...}` of a
// scenario; docs/aided.md, "The filter's model"). The one place that turns effects into filter
// state blocks (sensor_states.hpp), per sensor axis, from the axis's own list and `all`:
//   white          → no state: its density N adds N² to the axis's white-noise density
//                    (`sigma` at `rate`: N = sigma/sqrt(rate), the density of the held sequence)
//   bias           → 1 constant state, prior mean `value`, prior sigma `sigma`
//   random_walk    → 1 random-walk state with K, starting at 0 (exact without a rate; with a
//                    `rate` the held discrete walk is modelled by the continuous walk of the same K)
//   gauss_markov   → 1 state σ, τ (with a `rate`: the held discrete GM, φ = exp(−h/τ), exactly,
//                    as an AR(1) at that rate)
//   bias_instability → its Gauss-Markov components (errormodels/flicker_gms.hpp, two per decade
//                    over tau_range widened 1.5 decades each side: those the simulation draws), a
//                    state each; a component faster than the filter step enters as white noise of
//                    its low-frequency density (N² += 2 σ² τ)
//   ar             → p companion states at the model's own rate
//   quantization   → no state (quantizationRule reads it as the effect does): carried, the
//                    integrated output is within one step of the input's, no noise; each sample
//                    rounded alone, white noise of variance step²/12 at the IMU rate
//                    (N² += step² / (12 rate))
//   scale_factor   → (triad, `value` or `diagonal`, optional `sigma`) 1 constant state per axis
//                    with a mean or a sigma, prior mean the diagonal entry, prior sigma `sigma`;
//                    after the axis's other states (several scale_factor effects add)
//   bias_jumps     → 1 state with its second moments (errormodels::biasJumpsEquivalentOf): steps
//                    a random walk of K² = rate size², a telegraph a GM of size/2, 1/(2 rate)
//   outliers       → no state: white noise of their variance, N² += rate amplitude² / imu_rate²
//   scale_factor `matrix` off-diagonal entries, misalignment, g_sensitivity, ramp, warmup,
//   sinusoid, temperature → no state: known, compensated (known_errors.hpp; a temperature
//   without the scenario's is refused by the scenario reader)
// Disabled effects (`enabled: no`) are skipped. An effect none of these covers (a newly
// registered one) is refused, naming the model file, line and key.
#pragma once

#include <vector>

#include "common/error.hpp"
#include "errormodels/model_spec.hpp"
#include "sim/aided/error_state_filter.hpp"

namespace sinsim::sim::aided {

/// The filter's sensor model of `spec` for a filter step of `step` [s] (the GNSS interval) and
/// IMU samples at `imuRate` [Hz] (a per-sample rounding's white noise). Problems (effects the filter cannot represent) are appended to `problems` with the effect's
/// file, line and key path; the returned model then holds the effects that could be converted.
FilterSensorModel filterModelFromSpec(const errormodels::ErrorModelSpec& spec, double step,
                                      double imuRate, std::vector<Diagnostic>& problems);

/// The same, throwing ConfigError with every problem when there is any.
FilterSensorModel filterModelFromSpec(const errormodels::ErrorModelSpec& spec, double step,
                                      double imuRate);

/// Exact equality of two state blocks (every matrix entry, rate and name).
bool operator==(const StateBlock& a, const StateBlock& b);
bool operator==(const SensorAxisModel& a, const SensorAxisModel& b);
bool operator==(const FilterSensorModel& a, const FilterSensorModel& b);

}  // namespace sinsim::sim::aided
