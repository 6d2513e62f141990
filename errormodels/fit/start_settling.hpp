// A settling at the start of a static record (a warm-up: A exp(-t / tau) + level), tested against
// the fitted noise model. No noise term is a settling: left in the record, the composite fit's
// slow terms (random walk, a slow GM, flicker, drift) absorb it. So the fit says where the record
// starts with one, and how much of it to skip.
//
// Method: the record's block means (blockSize: about 4096 blocks), and for each time constant tau
// on a grid of 8 per octave the block-averaged shape exp(-t / tau) (t from the first sample). The
// grid runs from eight blocks (faster, the shape is the first few block means, which the model's
// least misfit at the block scale can imitate) to a tenth of the record (slower, the shape is a
// bend of the whole record, not a start that settles). Its amplitude by generalised least squares
// under the model's own covariance of the block means (blockGlsProducts, the exact state-space law
// of every noise term), the level and a straight trend profiled out (a ramp, a thermal trend or a
// walk's wander through the record is no settling; with the trend in, such records of the
// diagnosis's generators stopped raising the warning): z = A / sd(A), divided by the square root
// of the whitened residuals' mean square where that exceeds 1 (a model that understates the
// record's noise). The largest |z| over the grid is judged with a Bonferroni bound over the octaves
// searched (neighbouring time constants give strongly correlated shapes: the bound is
// conservative).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "errormodels/fit/latent_model.hpp"

namespace sinsim::errormodels::fit {

struct StartSettling {
  double amplitude = 0.0;  ///< [U] A at the first sample
  double tau = 0.0;        ///< [s] the time constant of the largest |z|
  double z = 0.0;          ///< A / its GLS standard deviation
  double pValue = 1.0;     ///< two-sided, times the octaves searched (at most 1)
  double octaves = 0.0;    ///< of the tau grid
  /// [s] where the settling has fallen to the model's Allan deviation at tau (at least tau): the
  /// record from there on holds no more of it than its noise does at that scale.
  double settledAfter = 0.0;
  std::size_t blocks = 0;  ///< block means tested
  /// The whitened residuals' mean square after the level and the settling (1 when the model is
  /// the record's); z is divided by its square root where it exceeds 1.
  double residualScale = 1.0;
};

/// A settling is reported below this p (the look-elsewhere bound above). 1e-4, not 1e-3: fits
/// whose terms cannot hold the record (ar+slow on the diagnosis generators' walks and AR bases)
/// warned on 8 of 540 null channels at 1e-3, on 4 at 1e-4; the 200 settlings of 1.5x in issue
/// 11's round trips had |z| 4.5-44 (bench/fit_settling).
inline constexpr double kStartSettlingP = 1e-4;

/// The test on x (the record's samples, mean removed or not) under `model`, sampled at dt [s].
/// An AR term is taken as the white noise of its long-run variance (dt E / A(1)^2 per density
/// squared), which is what means of blocks much longer than its correlation time see. None when
/// the record has fewer than 64 blocks, the grid is shorter than an octave, or the AR's slowest
/// pole has a correlation time of a quarter block or more.
std::optional<StartSettling> testStartSettling(const std::vector<double>& x, double dt,
                                               const LatentModel& model);

}  // namespace sinsim::errormodels::fit
