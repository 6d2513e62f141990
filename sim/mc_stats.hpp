// Statistics of Monte Carlo batches: sample moments and percentiles across runs, and the paired
// tests that say whether two error models give different drifts. Everything here is a pure
// function of its inputs in the order given (no scheduling dependence).
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

namespace sinsim::sim::mcstats {

/// Mean, sample standard deviation (n − 1 in the denominator; 0 for n < 2) and root mean square
/// of x, accumulated in index order in double precision (two passes for the deviation).
struct Moments {
  std::size_t n = 0;
  double mean = 0.0, sd = NAN, rms = 0.0;  // sd: sample sd (n - 1), undefined below 2 values
};
Moments moments(const std::vector<double>& x);

/// Percentile p ∈ [0, 100] of x by linear interpolation between order statistics, the
/// "type 7" definition of Hyndman & Fan 1996 (numpy's and R's default): with the sorted values
/// x(0) ≤ … ≤ x(n−1), h = (n − 1) p / 100, result x(⌊h⌋) + (h − ⌊h⌋)(x(⌊h⌋+1) − x(⌊h⌋)).
/// `sorted` must be sorted ascending and non-empty.
double percentileSorted(const std::vector<double>& sorted, double p);

/// Regularized incomplete beta function I_x(a, b), a, b > 0, 0 ≤ x ≤ 1 (continued fraction by
/// the modified Lentz method, Numerical Recipes 3rd ed. §6.4, eq. 6.4.5). Relative accuracy
/// ~1e-13 for the arguments Student's t needs.
double regularizedBeta(double x, double a, double b);

/// Two-sided p-value of Student's t statistic with nu > 0 degrees of freedom:
/// P(|T| ≥ |t|) = I_{nu/(nu+t²)}(nu/2, 1/2) (Abramowitz & Stegun 26.7.1 with 26.5.27).
double studentTwoSidedP(double t, double nu);

/// Two-sided p-value of a standard normal statistic: erfc(|z|/√2).
double normalTwoSidedP(double z);

/// Paired t-test on differences d_k = a_k − b_k (Student 1908): t = mean(d) / (sd(d)/√n),
/// n − 1 degrees of freedom; also the 95 % confidence interval of the mean difference.
struct PairedT {
  std::size_t n = 0;
  double meanDiff = 0.0, sdDiff = 0.0;
  double ciLow = 0.0, ciHigh = 0.0;  // 95 % two-sided interval of the mean difference
  double t = 0.0, p = 1.0;           // p = 1 when every difference is equal (sd 0) and the mean 0
};
PairedT pairedT(const std::vector<double>& a, const std::vector<double>& b);

/// Wilcoxon signed-rank test on the same differences (Wilcoxon 1945): zero differences dropped
/// (Wilcoxon's convention), average ranks for ties of |d|. W+ = sum of the ranks of positive
/// differences. p-value: exact distribution of W+ (enumerated by dynamic programming) when the
/// remaining n ≤ 50 and there are no ties; otherwise the normal approximation with tie-corrected
/// variance n(n+1)(2n+1)/24 − Σ(t³ − t)/48 and a continuity correction of 0.5 (Lehmann 1975,
/// §3.2). Two-sided.
struct SignedRank {
  std::size_t n = 0;       // non-zero differences used
  double wPlus = 0.0;
  double z = 0.0;          // normal-approximation statistic (reported also when exact)
  double p = 1.0;
  bool exact = false;
};
SignedRank wilcoxonSignedRank(const std::vector<double>& a, const std::vector<double>& b);

/// Fraction of x strictly below v plus half the fraction equal to v, in percent (the
/// mid-rank percentile of v within the sample x). 50 when x is empty.
double percentileOf(const std::vector<double>& sortedX, double v);

}  // namespace sinsim::sim::mcstats
