// How large a start error the error-state filter, linear in its errors, still handles: one home
// for the angle the mc verdict names and for the start priors `run` warns about.
#pragma once

#include "common/constants.hpp"

namespace sinsim::sim {

/// The attitude error [rad] beyond which the filter's small-angle linearisation is named in the
/// mc verdict (5 deg: the second-order terms reach ~4 % of the first).
inline constexpr double kSmallAngle = 5.0 * kRadPerDeg;

namespace aided {
/// The largest attitude 1-sigma [rad] the filter starts from without a warning: beyond it more
/// than 5 % of the runs start beyond kSmallAngle (two-sided, 1.96 sigma). A blind probe's city car
/// with a 5-deg heading prior and an exact model: the run-averaged NEES above its band for ~220 s,
/// long after the yaw sigma fell to 0.1 deg; at rest a 10-deg prior's yaw sigma fell to 4.6 deg
/// while the error stayed ~10 deg (bench/blind_probe/aided61). A 0.5-deg prior: consistent.
inline constexpr double kMaxStartAttitudeSigma = kSmallAngle / 1.959963984540054;
/// The largest horizontal position 1-sigma [m] the filter starts from without a warning. Measured,
/// not derived: the blind probe's city car (100 runs, exact model) kept its NEES in its band at
/// 10 km (mean 9.8 against 9), not from 20 km (15.4; 100 km: 3.7e3 while aided, never recovering).
inline constexpr double kMaxStartPositionSigma = 10e3;
}  // namespace aided

}  // namespace sinsim::sim
