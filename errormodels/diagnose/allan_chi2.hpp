// The Allan chi-square fit that scores candidates (diagnose.hpp, "chi2" and "score"): the
// measurement's ln AVAR against ln(s mu + sum theta_j g_j), weighted by the inverse covariance
// of ln AVAR estimates under the model.
#pragma once

#include <vector>

#include <Eigen/Dense>

#include "errormodels/diagnose/candidate.hpp"

namespace sinsim::errormodels::diagnose::detail {

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
/// Least squares over the level s (unless fixLevel: s = 1) and the free sizes theta >= 0.
/// thetaStart[j] >= 0 starts candidate j there; a missing or negative entry starts it from a grid.
AllanSolution solveAllan(const AllanProblem& p, const std::vector<const Candidate*>& set,
                         const std::vector<double>& thetaStart = {}, bool fixLevel = false);

}  // namespace sinsim::errormodels::diagnose::detail
