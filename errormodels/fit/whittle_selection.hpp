// Term-set selection of the composite latent fit by a Whittle likelihood (Whittle 1953) of the
// record's tapered periodogram. The octave Allan variance sees a random walk only through its last 2-3
// points (11-25 EDF each; docs/fitting-log.md, "detectability"); the periodogram keeps every Fourier
// frequency down to 1 / (N dt), where the walk lives.
//
// Method:
//  1. Tapered periodogram of the rate record (stats/spectrum.hpp taperedPeriodogram: split-cosine
//     10 %, the h-weighted least-squares line removed): a drift is profiled out (decided by the
//     Allan score afterwards), and the taper keeps the random walk's 1/w^2 power from leaking far.
//  2. Model: E I_j = sum of each term's column, linear in the variances (Q^2, N^2, sigma_j^2, B^2,
//     K^2). Above the lowest kExactOrdinates Fourier frequencies a column is the term's discrete
//     PSD (latent_model.hpp latentPsd, the one home of every term's spectrum) averaged over the
//     bin. At those lowest frequencies, where the line removal and the taper change E I_j by tens
//     of per cent, the columns of white noise, quantization and the random walk are exact:
//     E|U_j|^2 / sum h^2 with U_j = sum_k a_jk x_k the linear map of the record to the tapered,
//     detrended DFT (white: sum |a_jk|^2 / dt; quantization (e_k - e_{k-1}) / dt: sum
//     |a_jk - a_j,k+1|^2 / dt^2; walk x_k = sum_{i<=k} w_i: dt sum_i |sum_{k>=i} a_jk|^2). GM and
//     flicker columns there are their PSD times white's exact-to-PSD ratio (exact for a spectrum
//     flat over a few bins, the GMs of a fitted range).
//  3. Bins: the lowest 16 Fourier frequencies alone, then bins 10 % wide. In a bin of n_b
//     ordinates of mean I_b and model mean f_b, -2 log L = 2 sum_b c_b (ln f_b + I_b / f_b),
//     c_b = n_b / the taper's variance inflation (the effective number of independent ordinates):
//     Whittle's sum when f is flat over a bin, the Gamma likelihood of the bin mean.
//  4. Per set: variances by Fisher scoring (weighted NNLS with weights c_b / f_b^2, iterated, a
//     step halved when -2 log L rises; variances >= 0), GM taus by golden section on log T from
//     the Allan fit's taus. Score = -2 log L + latentPenalty (the same per-term costs: a term
//     enters when it lowers -2 log L by more than 5.41 (7.82 for a GM), the 1 % point of the
//     boundary mixture of its likelihood-ratio statistic, Self & Liang 1987).
//  5. Drift: the removed line's slope against its variance under the chosen set's Whittle model
//     (whittleSlopeVariance); the slope is the drift estimate, exactly normal under the model.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "errormodels/fit/latent_fit.hpp"

namespace sinsim::errormodels::fit {

/// The binned tapered periodogram of the record with the fixed columns of its model.
struct WhittleBins {
  double dt = 0.0;                        ///< [s]
  std::vector<double> count;              ///< c_b: effective independent ordinates
  std::vector<double> level;              ///< I_b: mean periodogram [U^2 per rad/sample]
  std::vector<double> wHigh;              ///< [rad/sample] highest frequency in the bin
  std::vector<std::vector<double>> nodes; ///< [rad/sample] frequencies a PSD is averaged over
  std::vector<std::vector<double>> nodeSin; ///< sin(w / 2) at each node (fit::LatentSpectrum's s)
  std::vector<double> lowFactor;          ///< E I / PSD of white noise in the bin (1 above the exact ordinates)
  /// E I_b at unit variance of quantization, white, flicker, random walk (Q^2, N^2, B^2, K^2 = 1).
  std::vector<double> quantization, white, flicker, randomWalk;
  double slope = 0.0;    ///< [U/s] the removed line's slope (the drift estimate)
  /// The slope's weights g (slope = sum g_k x_k / dt) and sum g^2, sum (g_k - g_{k+1})^2,
  /// sum_i (sum_{k>=i} g_k)^2, (1/M) sum |G(w_k)|^2 / |w_k| (whittleSlopeVariance); shared by the
  /// channels of one record length.
  std::shared_ptr<const std::vector<double>> slopeWeights;
  double slopeWhite = 0, slopeQuantization = 0, slopeWalk = 0, slopeFlicker = 0;
  /// The quantization's lattice (LatentModel::lattice) its column and the fitted models use.
  RoundingLattice lattice;
};
/// Fourier frequencies j = 1..kExactOrdinates get exact white, quantization and walk columns.
inline constexpr std::size_t kExactOrdinates = 16;

/// Throws InputError for fewer than 64 samples or non-finite samples. dt [s]. With an active
/// lattice the quantization column is its rounding's PSD (at the exact low ordinates: theirs
/// scaled by the lattice PSD over the classical one).
WhittleBins whittleBins(const std::vector<double>& x, double dt, const RoundingLattice& lattice = {});

/// Whittle fit of one term set (no drift, no AR). start: the Allan fit of that set (its taus and
/// variances start the search). Bins above wMax [rad/sample] are left out (the start of the Allan
/// range: features at short tau no term carries). minT, maxT [s]: the GM tau range.
struct WhittleSetFit {
  LatentModel model;
  double m2LogLik = 0.0;  ///< -2 log L (up to a constant common to all sets)
  bool valid = false;     ///< every variance > 0
};
/// Variance [U^2/s^2] of WhittleBins::slope when the record is `model` (its drift ignored): the
/// slope is sum g_k x_k (spectrum.hpp), so white N^2/dt sum g^2, quantization Q^2/dt^2 sum
/// (g_k - g_{k+1})^2, walk K^2 dt sum_i (sum_{k>=i} g_k)^2, GM sigma^2 sum_k,l g_k g_l phi^|k-l|
/// (two recursive passes), flicker (1/M) sum S(w_k) |G(w_k)|^2 (M = 4 n), all divided by dt^2.
/// Drift enters the Whittle choice when slope^2 / this > the chi^2_1 1 % point 6.63 (the sign of a
/// ramp is free: no boundary).
double whittleSlopeVariance(const WhittleBins& bins, const LatentModel& model);

/// The model's expected bin levels E I_b [U^2 per rad/sample] (its drift ignored; no AR).
std::vector<double> whittleExpectedLevels(const WhittleBins& bins, const LatentModel& model);

/// -2 log L (as WhittleSetFit::m2LogLik) of the bins at expected levels f.
double whittleM2LogLik(const WhittleBins& bins, const std::vector<double>& f);

WhittleSetFit whittleFitSet(const WhittleBins& bins, double wMax, const LatentTermSet& set,
                            const LatentModel& start, double minT, double maxT);

}  // namespace sinsim::errormodels::fit
