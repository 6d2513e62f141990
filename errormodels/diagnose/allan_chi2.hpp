// The Allan chi-square fit that scores candidates (diagnose.hpp, "chi2" and "score"): the
// measurement's ln AVAR against ln(s mu + sum theta_j g_j), weighted by the inverse covariance
// of ln AVAR estimates under the model.
#pragma once

#include <vector>

#include <Eigen/Dense>

#include "errormodels/diagnose/candidate.hpp"

namespace sinsim::errormodels::diagnose::detail {

/// The standard deviation of ln s, the model's variance factor, that the fit assumes before seeing
/// the record: a model's stated level is known to a factor 1.5 in Allan variance (1.22 in Allan
/// deviation). Without it the level is free, and on a channel whose Allan curve is white over the
/// measured tau a missing white noise of 4-6x is only a level (the `level:` line, no finding).
/// A level 3x off in Allan deviation costs (ln 9 / ln 1.5)^2 = 29; with a candidate's penalty
/// (ln K) the prior alone names an effect (score 5.5) from ~3.2x on.
constexpr double kLevelLnSd = 0.405;  // ln 1.5 = 0.4055, to three digits

/// The Allan chi-square problem of one channel.
struct AllanProblem {
  std::vector<double> L;     // ln AVAR of the measurement
  std::vector<double> mu;    // model mean AVAR [SI^2]
  std::vector<double> bias;  // E[ln AVAR_est] - ln mu under the model (Monte Carlo)
  Eigen::MatrixXd W;         // inverse covariance of ln AVAR estimates
};
struct AllanSolution {
  double s = 1.0;             // variance factor of the model
  std::vector<double> theta;  // one per candidate in the set (1 for fixed ones)
  double chi2 = 0.0;
};
/// AVAR of the fitted model s mu + sum theta g at each tau.
std::vector<double> modelAvarOf(const AllanProblem& p, const std::vector<const Candidate*>& set,
                                const AllanSolution& sol);
/// Least squares over the level s (unless fixLevel: s = 1) and the free sizes theta >= 0; chi2 is
/// r' W r + (ln s / kLevelLnSd)^2, the level's prior term included.
/// thetaStart[j] >= 0 starts candidate j there; a missing or negative entry starts it from a grid.
AllanSolution solveAllan(const AllanProblem& p, const std::vector<const Candidate*>& set,
                         const std::vector<double>& thetaStart = {}, bool fixLevel = false);

}  // namespace sinsim::errormodels::diagnose::detail
