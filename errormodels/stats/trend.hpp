// The least-squares trend of a series and its scatter under a stationary noise: a ramp's size in
// the diagnosis, and the sign `fit` gives a fitted drift (the Allan variance holds its square).
#pragma once

#include <cstddef>
#include <vector>

namespace sinsim::errormodels {

/// Least-squares slope of y against t = (k + 0.5) dt [SI/s].
double trendSlope(const std::vector<double>& y, double dt);
/// Variance of trendSlope over n samples of a stationary series whose autocovariance at lags
/// 0, 1, ... is acov [SI^2] (0 beyond its end, which may be shorter than n): exact, the sum over
/// lags of acov(h) times the trend weights' autocorrelation (a cubic in h) [SI^2/s^2]. White
/// noise of variance s2: 12 s2 / (dt^2 n (n^2 - 1)).
double trendVarianceFromAcov(const std::vector<double>& acov, std::size_t n, double dt);

}  // namespace sinsim::errormodels
