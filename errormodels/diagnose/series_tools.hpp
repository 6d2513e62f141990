// Small tools on one recorded series shared by the detectors: window and block means, the median
// and a least-squares solve (the value lattice: errormodels/stats/lattice.hpp).
#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Dense>

#include "errormodels/stats/lattice.hpp"

namespace sinsim::errormodels::diagnose::detail {

/// Least-squares slope of y against t = (k + 0.5) dt [SI/s]: a ramp's size, and the trend whose
/// scatter under the model the ramp's conditional test compares it with.
double trendSlope(const std::vector<double>& y, double dt);
/// Variance of trendSlope over n samples of a stationary series whose autocovariance at lags
/// 0, 1, ... is acov [SI^2] (0 beyond its end, which may be shorter than n): exact, the sum over
/// lags of acov(h) times the trend weights' autocorrelation (a cubic in h) [SI^2/s^2]. White
/// noise of variance s2: 12 s2 / (dt^2 n (n^2 - 1)).
double trendVarianceFromAcov(const std::vector<double>& acov, std::size_t n, double dt);
/// Mean of y over consecutive windows of m samples.
std::vector<double> windowMeans(const std::vector<double>& y, std::size_t m);

/// Means of consecutive blocks of `size` samples and the times of their centres [s].
struct BlockMeans {
  std::vector<double> t, m;
  std::size_t size = 1;
};
/// At most `blocks` blocks of y sampled every dt [s].
BlockMeans blockMeans(const std::vector<double>& y, double dt, std::size_t blocks);

/// Median (the upper one for an even count); 0 for an empty vector.
double median(std::vector<double> v);
/// The Gaussian sd per median absolute deviation, 1 / Φ⁻¹(3/4).
constexpr double kSdPerMad = 1.482602218505602;
/// Robust standard deviation 1.4826 MAD (the sd for Gaussian values; spikes and steps barely move it).
double robustSd(const std::vector<double>& v);
/// Least squares y ~ X beta; returns the residual sum of squares.
double leastSquares(const Eigen::MatrixXd& X, const Eigen::VectorXd& y, Eigen::VectorXd& beta);

}  // namespace sinsim::errormodels::diagnose::detail
