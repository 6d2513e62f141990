// Gaussian-equivalent significance: the common scale of every candidate's score.
#pragma once

namespace sinsim::errormodels::diagnose::detail {

/// Scores are capped here (a p-value beyond it underflows and says nothing more).
constexpr double kMaxScore = 40.0;

/// z with P(|Z| > z) = p (two-sided; stats/special.hpp normalTwoSidedCritical), capped at
/// kMaxScore (also when p underflows to 0); 0 for p >= 1.
double zFromTwoSidedP(double p);
/// Student-t statistic with nu dof -> Gaussian-equivalent z (Wallace 1959):
/// z = sqrt(nu ln(1 + t^2/nu)) (8 nu + 1) / (8 nu + 3).
double zFromStudentT(double t, double nu);

}  // namespace sinsim::errormodels::diagnose::detail
