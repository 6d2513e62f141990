// How a `quantization` effect rounds (effects/quantization.cpp): its LSB read as a rate or an
// increment LSB, and the carry and dither it applies, defaults included. The effect builds itself
// from this; the diagnosis reads it to take a coarse per-sample rounding over (diagnose/montecarlo.cpp).
#pragma once

#include "common/units.hpp"
#include "errormodels/model_spec.hpp"

namespace sinsim::errormodels {

struct QuantizationRule {
  double lsb = 0;         ///< [SI] as given: of the rate output, or of the increment output
  bool isRate = false;    ///< the LSB has the dimension of the channel's signal
  bool carry = false;     ///< the remainder is carried (default: yes for an increment LSB)
  bool dithered = false;  ///< the remainder is a fresh uniform draw each sample
  /// The step on the rate scale [SI] for samples at `rate` [Hz]: lsb, or lsb x rate.
  double rateStep(double rate) const { return isRate ? lsb : lsb * rate; }
  /// Each sample rounded on its own onto a fixed lattice (neither carried nor dithered).
  bool roundsEachSample() const { return !carry && !dithered; }
};

/// The rule of a `quantization` spec (its `lsb` present, one value) on a channel whose signal has
/// dimension `signal` (rad/s or m/s^2).
QuantizationRule quantizationRule(const EffectSpec& spec, const Dimension& signal);

}  // namespace sinsim::errormodels
