// Term-set selection of the composite latent fit by the exact Gaussian likelihood of the record's
// block means (a Kalman filter), with the Whittle likelihood of the periodogram above the blocks'
// band. The Allan variance sees a slow GM, a walk and flicker through 2-3 points of 11-25 EDF, the
// tapered periodogram through a few low ordinates with a taper and leakage; the block means keep
// that information exactly (every term below is a linear state-space process, and its average over
// a block of B samples is exactly representable).
//
// Method:
//  1. Block means y_j of B consecutive samples, B = max(N / 4096, m_1) (m_1 the first Allan point
//     used: features faster than it are not modelled), M = N / B blocks of length L = B dt.
//  2. Per term, one state at the end of each block and its exact block law (blockComponents):
//     y_j = sum_i h_i s_i,j-1 + v_j, s_i,j = f_i s_i,j-1 + u_i,j, with u independent across terms,
//     Var u_i = q_i, Cov(u_i, v) = c_i, Var v = r (the sum over terms):
//       white N^2           no state; r += N^2 / L
//       quantization Q^2    s = the last sample's rounding error e: f 0, h -1/L, q Q^2, c Q^2/L,
//                           r += Q^2/L^2 (the block mean is (e_end - e_end,prev) / L)
//       GM (sigma^2, T)     the discrete AR(1) at dt, phi = exp(-dt/T), g_r = sum_{i<r} phi^i:
//                           f phi^B, h phi g_B / B, q sigma^2 (1 - phi^2B),
//                           eta = sigma^2 (1 - phi^2): r += eta / B^2 sum_r g_r^2,
//                           c = eta / B sum_r phi^(r-1) g_r (sums over r = 1..B)
//       random walk K^2     the bias at the block end: f 1, h 1, q K^2 L, c K^2 L / 2,
//                           r += K^2 L / 3 (Brownian motion averaged over the block)
//       flicker B^2         flickerComponents: GMs two per decade (the bias_instability effect's
//                           construction, sigma^2 = B^2 ln 10 / (2 pi) each) with T from L/4 to
//                           10 N dt; those faster than L/4 are folded into r.
//  3. The level is a fixed effect profiled out exactly by the diffuse (restricted) likelihood: the
//     columns 1 and t_j are filtered with the data (de Jong 1991, the augmented Kalman filter):
//     -2 log L = sum ln F_j + e'F^-1 e - a'A^-1 a + ln A_11, A and a the columns' innovation
//     products (X = [1]: the level alone; every set shares it, so the likelihoods compare). With
//     drift the slope is profiled out too (X = [1, t], the same ln A_11): the two differ by the GLS
//     slope's slope^2 / var. A set without drift keeps the trend's information (a walk's).
//  4. Per set, -2 log L(blocks) + the Whittle -2 log L of the periodogram bins between 2 pi / B
//     (the blocks' first null; the ordinates below are in the block means) and the Allan range's
//     top frequency: minimised over log variances and log T by BFGS from the set's Whittle fit
//     (and again with drift where the slope could pay its cost).
//  5. The sets scored (latent_fit.cpp blockChoice): the drift-free sets within kBlockScoredRange of
//     the best Whittle score; a set's score is min(S, S + drift + 6.63 (chi^2_1 at 1 %: a ramp's
//     sign is free)) + latentPenalty. The lowest wins, except that a set whose slowest GM does not
//     beat its walk-for-that-GM partner by a one-parameter cost is that partner (latent_fit.cpp
//     withoutWalkLikeGms).
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "errormodels/fit/latent_fit.hpp"
#include "errormodels/fit/whittle_selection.hpp"

namespace sinsim::errormodels::fit {

/// Means of consecutive blocks of `perBlock` samples (the tail that fills no block is left out).
struct BlockMeans {
  double dt = 0.0;             ///< [s] the record's sample interval
  std::size_t perBlock = 1;    ///< B
  std::vector<double> y;       ///< [U] block means
};
/// Throws InputError for perBlock = 0, fewer than 8 blocks, non-finite samples or dt <= 0.
BlockMeans blockMeans(const std::vector<double>& x, double dt, std::size_t perBlock);

/// The restricted -2 log L of the block means under `model` (its drift ignored; no AR), up to a
/// constant common to every model, and the GLS slope of a line through them with its variance.
struct BlockLikelihood {
  double m2LogLik = 0.0;       ///< the level profiled out (X = [1])
  /// The level and a drift's slope profiled out: the slope as a parameter, its estimate the GLS
  /// slope (the same X'V^-1 X determinant term as m2LogLik, so the two compare: their difference
  /// is slope^2 / slopeVariance).
  double m2LogLikDrift = 0.0;
  double slope = 0.0;          ///< [U/s]
  double slopeVariance = 0.0;  ///< [U^2/s^2]
};
/// +inf for a model whose block variance is not positive. Throws InputError for an AR term.
BlockLikelihood blockLikelihood(const BlockMeans& b, const LatentModel& model);

/// Generalised least squares on the block means under `model` (its drift and AR not modelled):
/// the whitened cross-products Z' V^-1 Z of the columns Z = [y, 1, t, extra...], V the model's
/// covariance of the block means, t the blocks' centres [s] from the record's middle; symmetric,
/// (3 + extra.size()) square. The GLS fit of y on any of the other columns, and its covariance,
/// follow from its entries. Throws InputError for an AR term, a regressor whose length is not the
/// blocks' count, or a model whose block variance is not positive.
Eigen::MatrixXd blockGlsProducts(const BlockMeans& b, const LatentModel& model,
                                 const std::vector<std::vector<double>>& extra);

/// One state of the block state-space model (step 2), and r, its share of the block's own noise
/// variance; p0 the state's variance before the first block.
struct BlockComponent {
  double f = 0, h = 0, q = 0, c = 0, r = 0, p0 = 0;
};

/// The criterion of step 4 for one model: -2 log L of the block means (the level, and with
/// `drift` the slope, profiled out) + the Whittle -2 log L of the periodogram bins above the
/// blocks' first null up to wMax [rad/sample] (none when high is nullptr). `flicker`: whether
/// models with flicker will be evaluated (its components are built once). +inf where a bin's
/// expectation is not positive.
class BlockObjective {
 public:
  BlockObjective(const BlockMeans& b, const WhittleBins* high, double wMax, bool flicker);
  double operator()(const LatentModel& m, bool drift) const;

 private:
  const BlockMeans& b_;
  const WhittleBins* high_;
  std::vector<BlockComponent> flicker_;
  std::size_t b0_ = 0, b1_ = 0;  ///< the bins used, [b0_, b1_)
};

/// One set's fit (step 4). high: the Whittle bins (nullptr: blocks alone); wMax [rad/sample] the
/// highest frequency used; minT, maxT [s] the GM tau range.
struct BlockSetFit {
  LatentModel model;      ///< without drift
  double m2LogLik = 0.0;  ///< -2 log L (blocks + bins) of `model`, the level profiled out
  BlockLikelihood blocks; ///< the blocks' likelihood of `model`
  LatentModel modelDrift; ///< with a drift's slope profiled out too (its drift field 0)
  double m2LogLikDrift = 0.0;
  bool valid = false;
};
/// The chi^2_1 1 % point: the cost of a drift (the sign of a ramp is free: no boundary).
inline constexpr double kDriftSlopeChi2 = 6.635;
BlockSetFit blockFitSet(const BlockMeans& b, const WhittleBins* high, double wMax, const LatentTermSet& set,
                        const LatentModel& start, double minT, double maxT);

/// Blocks the block likelihood aims at (step 1): 2^12 keep a GM of T >= ~3 L at 20 min; a Kalman
/// step costs O(states^2) until its gain is steady.
inline constexpr std::size_t kTargetBlocks = 4096;
/// Fewer blocks than this: the Whittle choice stands (the block means say little).
inline constexpr std::size_t kMinBlocks = 64;
/// B of step 1 for N samples whose first fitted Allan point is m1.
inline std::size_t blockSize(std::size_t samples, std::size_t m1) {
  return std::max<std::size_t>({1, samples / kTargetBlocks, m1});
}

/// Sets further than this above the best Whittle score are not scored by the blocks.
inline constexpr double kBlockScoredRange = 15.0;

}  // namespace sinsim::errormodels::fit
