// Small tools on one recorded series shared by the detectors: window and block means, the median
// and a least-squares solve (the value lattice and the trend: errormodels/stats/lattice.hpp, trend.hpp).
#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Dense>

#include "errormodels/stats/lattice.hpp"
#include "errormodels/stats/trend.hpp"

namespace sinsim::errormodels::diagnose::detail {

/// Mean of y over consecutive windows of m samples.
std::vector<double> windowMeans(const std::vector<double>& y, std::size_t m);

/// Means of consecutive blocks of `size` samples and the times of their centres [s].
struct BlockMeans {
  std::vector<double> t, m;
  std::size_t size = 1;
};
/// At most `blocks` blocks of y sampled every dt [s].
BlockMeans blockMeans(const std::vector<double>& y, double dt, std::size_t blocks);

/// Mean and sample variance (n - 1) of at least two values.
struct Moments {
  double mean = 0, var = 0;
};
Moments moments(const std::vector<double>& v);
/// Median (the upper one for an even count); 0 for an empty vector.
double median(std::vector<double> v);
/// The Gaussian sd per median absolute deviation, 1 / Φ⁻¹(3/4).
constexpr double kSdPerMad = 1.482602218505602;
/// Robust standard deviation 1.4826 MAD (the sd for Gaussian values; spikes and steps barely move it).
double robustSd(const std::vector<double>& v);
/// Least squares y ~ X beta; returns the residual sum of squares.
double leastSquares(const Eigen::MatrixXd& X, const Eigen::VectorXd& y, Eigen::VectorXd& beta);

}  // namespace sinsim::errormodels::diagnose::detail
