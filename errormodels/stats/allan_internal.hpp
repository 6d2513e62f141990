// Pieces shared by the files of the Allan-family code (estimators in allan.cpp, noise
// identification in allan_noise_id.cpp); not part of the public interface (allan.hpp).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "errormodels/stats/allan.hpp"

namespace sinsim::errormodels::detail {

/// Phase in units of tau0 of the rate y with its mean removed: x_0 = 0, x_{i+1} = x_i + y_i - ybar
/// (N + 1 points, accumulated in long double).
std::vector<double> phaseOf(const std::vector<double>& y);

/// Lag-1 noise identification at averaging factor m on the phase x (see identifyNoise).
std::optional<NoiseId> identifyFromPhase(const std::vector<double>& x, std::size_t m, int d_max,
                                         int alpha_min);

}  // namespace sinsim::errormodels::detail
