// First-order Gauss-Markov fit (sigma, tau) from an autocovariance sequence.
//
// Model: R(lag) = sigma^2 exp(-|lag| / tau) (the first-order GM / Ornstein-Uhlenbeck process;
// sampled at dt it is AR(1) with phi = exp(-dt/tau)). Fitted by nonlinear least squares
// (Gauss-Newton with step halving) of sigma^2 exp(-k dt / tau) to acf[k], k = first..maxLag.
//
// Uncertainty. Sample autocovariances at neighbouring lags are strongly correlated, so the
// residual-based LS covariance s^2 (J'J)^-1 is far too small. When the record length N is given,
// the covariance is the sandwich (J'J)^-1 J' C J (J'J)^-1 with C Bartlett's covariance of the
// sample autocovariances of the fitted process (Bartlett 1946; Priestley 1981, eq. 5.3.22):
//   Cov(c_h, c_k) = sigma^4 / N [phi^|h-k| (kappa + |h-k|) + phi^(h+k) (kappa + h + k)],
//   kappa = (1 + phi^2) / (1 - phi^2)   (the closed form of the Bartlett sum for AR(1)).
// Without N only the LS covariance can be given, and the result says so.
#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Dense>

namespace sinsim::errormodels::fit {

struct GaussMarkovFitOptions {
  /// Last lag used (in samples). 0: automatic, the first lag at which acf[k] / acf[first] falls
  /// to exp(-3) (about 3 tau; further lags carry mostly estimation noise), at least 3 lags.
  std::size_t maxLag = 0;
  /// Leave lag 0 out: white noise on top of the GM process adds only to lag 0.
  bool skipLagZero = false;
  /// Samples in the record the ACF was computed from; enables the Bartlett covariance.
  std::size_t recordLength = 0;
};

struct GaussMarkovFit {
  double sigma = 0.0;          ///< [U]
  double tau = 0.0;            ///< correlation time [s]
  double sigmaStdError = 0.0;  ///< [U]
  double tauStdError = 0.0;    ///< [s]
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();  ///< of (sigma, tau)
  std::size_t firstLag = 0, lastLag = 0;                 ///< lags used
  double rmsResidual = 0.0;                              ///< [U^2]
  bool bartlettCovariance = false;  ///< false: residual-based LS covariance (underestimates)
};

/// acf[k]: autocovariance [U^2] at lag k * lagStep [s] (k = 0..), biased or not, mean removed.
/// Throws InputError for non-finite values, lagStep <= 0, acf[first] <= 0, or fewer than 3 lags.
GaussMarkovFit fitGaussMarkov(const std::vector<double>& acf, double lagStep,
                              const GaussMarkovFitOptions& options = {});

}  // namespace sinsim::errormodels::fit
