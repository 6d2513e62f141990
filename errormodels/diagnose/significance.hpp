// Gaussian-equivalent significance: the common scale of every candidate's score.
#pragma once

#include <cstddef>
#include <vector>

#include "errormodels/diagnose/diagnose.hpp"

namespace sinsim::errormodels::diagnose::detail {

/// Scores are capped here (a p-value beyond it underflows and says nothing more).
constexpr double kMaxScore = 40.0;

/// z with P(|Z| > z) = p (two-sided; stats/special.hpp normalTwoSidedCritical), capped at
/// kMaxScore (also when p underflows to 0); 0 for p >= 1.
double zFromTwoSidedP(double p);
/// Student-t statistic with nu dof -> Gaussian-equivalent z (Wallace 1959):
/// z = sqrt(nu ln(1 + t^2/nu)) (8 nu + 1) / (8 nu + 3).
/// nu = infinity: z = t.
double zFromStudentT(double t, double nu);
/// Effective degrees of freedom of a variance estimate V = E + C, E the mean square of `dof`
/// Gaussian realisations (E ~ E[E] chi2_dof / dof) and C >= 0 known exactly (Satterthwaite 1946:
/// nu = 2 E[V]^2 / Var V): dof (1 + C/E)^2; infinity when E = 0 (all of V known).
double satterthwaiteDof(double estimated, double dof, double known);

/// A jump in the record: the largest robust z = |D - median D| / (1.4826 MAD) of the window-mean
/// increments D_j = ybar_{j+1} - ybar_j, over the windows m of `factors` with 32..4096
/// increments, as a Gaussian-equivalent z corrected for every increment and window tested
/// (Bonferroni). The increments of a Gaussian process (white, random walk, flicker, Gauss-Markov)
/// are Gaussian, so none stands out; a bias step, a telegraph switch or a warm-up's first window
/// puts one far beyond the rest. 0 when no window qualifies.
double jumpZ(const std::vector<double>& y, const std::vector<std::size_t>& factors);

/// The bias steps of the record, as a piecewise-constant series (empty when there are none):
/// while the jump test finds increments beyond the limit that keeps the whole scan at the
/// two-sided z `zLimit` (Bonferroni over every increment tested), the window size with the
/// largest one that marks a level change (a run of such increments whose net change is beyond
/// the limit too; a spike moves one window mean and back) gives its steps, each located to the
/// sample and sized by the means on either side; they are taken out and the record scanned again,
/// at most maxPasses times. y minus the steps is the record as a Gaussian process with spikes
/// would have made it, up to the steps' sizes: a step's Allan excess is gone, a random walk's or a
/// flicker's stays. `lattice`: the record's value lattice step q [its unit] (0: none); a change of
/// one lattice level is rounding, not a jump, and only steps beyond 1.5 q are kept.
std::vector<double> levelSteps(const std::vector<double>& y, const std::vector<std::size_t>& factors,
                               double zLimit, double lattice = 0.0, int maxPasses = 8);

/// The jumps of the piecewise-constant series `steps` (empty: none), with their times at `rate`
/// [Hz].
std::vector<LevelStep> jumpsOf(const std::vector<double>& steps, double rate);

/// Whether level steps go back and forth: those above a quarter of the largest (a step located in
/// two pieces is one) change sign at least four times. One bias step has none, a few disturbances
/// up, down, up two; a telegraph's switches alternate (a switch the test misses leaves the others
/// alternating), and so does a series of excursions that come back. Such steps are a switching
/// process' realisation, which a candidate with its second-order statistics
/// (Candidate::switching) explains.
bool revertingSteps(const std::vector<LevelStep>& jumps);

}  // namespace sinsim::errormodels::diagnose::detail
