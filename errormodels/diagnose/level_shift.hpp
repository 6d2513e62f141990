// A single level shift tested in the record's one-step prediction residuals (Chang, Tiao & Chen
// 1988's lambda_L): the time-domain test of a bias step that the window-mean jump test
// (significance.hpp, levelSteps) is too coarse for.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

namespace sinsim::errormodels::diagnose::detail {

/// The order of the whitening AR the level-shift test uses (selection's step finder, the outlier
/// detector's step check).
constexpr std::size_t kLevelShiftOrder = 10;

struct LevelShift {
  std::size_t at = 0;  ///< first sample at the new level
  double size = 0;     ///< new level minus the old [the series' unit]
  double z = 0;        ///< |lambda_L| at `at`, in units of its own standard deviation
  double zSpike = 0;   ///< |lambda_A| (an additive outlier) at the same sample
  double rho = 1;      ///< the variance inflation applied (>= 1; below): z sqrt(rho) is lambda_L
};

/// The largest level-shift statistic of y over every sample k (the first and last `order` + 1
/// excluded). y is whitened by its own Burg AR(order): e = A(q)(y - mean). A step h at k enters e
/// as h u_k with u_k(t) = c_(t-k), c_j = 1 + a_1 + ... + a_min(j,p) (so A(1) from lag p on); its
/// least-squares estimate against e (both demeaned: the bias is unknown) has standard deviation
/// sigma / |u_k|. sigma: the residuals' robust scale (1.4826 MAD), inflated by their largest
/// long-run variance ratio rho = m Var_robust(block-mean increments) / (2 sigma^2) over the
/// octave block sizes m with >= 33 blocks -- an AR of low order leaves slow correlation in e
/// (a white + slow Gauss-Markov record), and the statistic sums e over up to the whole record.
/// The record's AR alone cannot tell a step from a slow excursion longer than its blocks (a
/// Gauss-Markov of tau ~ T/40 under white noise, a weak random walk): rho is also at least the
/// largest ratio, over the averaging factors `factors`, of the model's Allan variance `modelAvar`
/// (when given) and of the record's own without the shift found (y minus it: a step must not
/// hide behind its own Allan excess) to the whitening AR's (fit::arAllanVariance), the record's on
/// `factors` and on the half-octave factors beyond them up to N/4 (the statistic's sums reach
/// N/2, and a walk's Allan ratio to the AR grows as m^2). At the shift found, a walk-like excess
/// at the grid's top is also carried to the split's own scale sqrt(a b) (a | b samples on either
/// side) along its log-log slope, for the statistic's long part (level_shift.cpp, beyondGrid).
/// The shift must stand out against every variance the model or the record shows at long tau.
std::optional<LevelShift> levelShift(const std::vector<double>& y, std::size_t order, double zLimit,
                                     const std::vector<std::size_t>& factors,
                                     const std::vector<double>& modelAvar = {});

}  // namespace sinsim::errormodels::diagnose::detail
