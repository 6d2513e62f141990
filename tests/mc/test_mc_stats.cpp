// The statistics a Monte Carlo report rests on, against closed forms and independent enumeration.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "sim/mc_stats.hpp"

using namespace sinsim::sim::mcstats;

TEST_CASE("percentiles: Hyndman-Fan type 7 by hand, mid-rank percentile of a value") {
  const std::vector<double> x{1, 2, 3, 4};
  // h = (n − 1) p/100: p50 → h = 1.5 → 2.5; p68 → h = 2.04 → 3.04 (numpy.percentile's default).
  CHECK(percentileSorted(x, 0) == 1.0);
  CHECK(percentileSorted(x, 50) == Approx(2.5).epsilon(1e-15));
  CHECK(percentileSorted(x, 68) == Approx(3.04).epsilon(1e-15));
  CHECK(percentileSorted(x, 100) == 4.0);
  CHECK(percentileSorted({7.0}, 95) == 7.0);  // one run
  CHECK(percentileOf({1, 2, 3}, 2) == Approx(50.0).epsilon(1e-15));
  CHECK(percentileOf({1, 2, 3}, 0.5) == 0.0);
  CHECK(percentileOf({1, 2, 3}, 9) == 100.0);
  const Moments m = moments({1, 2, 3, 4});
  CHECK(m.mean == 2.5);
  CHECK(m.sd == Approx(std::sqrt(5.0 / 3.0)).epsilon(1e-15));  // Σ(x−x̄)² = 5, n − 1 = 3
  CHECK(m.rms == Approx(std::sqrt(7.5)).epsilon(1e-15));        // Σx²/n = 30/4
}

TEST_CASE("regularized incomplete beta and Student t against closed forms") {
  // I_x(a, 1) = x^a, I_x(1, b) = 1 − (1 − x)^b (NR eq. 6.4.1 with B(a,1) = 1/a).
  for (double x : {0.01, 0.3, 0.5, 0.77, 0.999}) {
    CHECK(regularizedBeta(x, 2.5, 1.0) == Approx(std::pow(x, 2.5)).epsilon(1e-13));
    CHECK(regularizedBeta(x, 1.0, 3.5) == Approx(1 - std::pow(1 - x, 3.5)).epsilon(1e-13));
  }
  // ν = 1 (Cauchy): P(|T| ≥ t) = 1 − (2/π) atan t; ν = 2: 1 − t/√(2 + t²).
  for (double t : {0.0, 0.1, 1.0, 2.5, 10.0, 300.0}) {
    const double p1 = 1 - 2 / M_PI * std::atan(t), p2 = 1 - t / std::sqrt(2 + t * t);
    CHECK(studentTwoSidedP(t, 1) == Approx(p1).epsilon(1e-12).margin(1e-15));
    CHECK(studentTwoSidedP(-t, 2) == Approx(p2).epsilon(1e-12).margin(1e-15));
  }
  // Quantiles t(0.975; ν) from Abramowitz & Stegun Table 26.10, to the digits printed there and
  // confirmed with mpmath (betainc, 30 digits): ν = 10: 2.228138852, ν = 120: 1.979930405,
  // ν = 1000: 1.962339081; z(0.975) = 1.959963985 (normal). The 10-digit rounding of t moves p by
  // at most ~1e-10 relative.
  CHECK(studentTwoSidedP(2.228138852, 10) == Approx(0.05).epsilon(1e-8));
  CHECK(studentTwoSidedP(1.979930405, 120) == Approx(0.05).epsilon(1e-8));
  CHECK(studentTwoSidedP(1.962339081, 1000) == Approx(0.05).epsilon(1e-8));
  CHECK(normalTwoSidedP(1.959963985) == Approx(0.05).epsilon(1e-8));
}

TEST_CASE("paired t-test by hand") {
  // d = {1, 2, 3}: mean 2, sd 1, t = 2/(1/√3) = 2√3 with ν = 2: p = 1 − t/√(2 + t²) = 1 − √(12/14).
  const PairedT r = pairedT({11, 12, 13}, {10, 10, 10});
  CHECK(r.meanDiff == Approx(2.0).epsilon(1e-15));
  CHECK(r.t == Approx(2 * std::sqrt(3.0)).epsilon(1e-14));
  CHECK(r.p == Approx(1 - std::sqrt(12.0 / 14.0)).epsilon(1e-12));
  // 95 % interval: 2 ± t(0.975; 2)/√3 with t(0.975; 2) = 4.302652730 (A&S Table 26.10).
  CHECK(r.ciHigh - 2.0 == Approx(4.302652730 / std::sqrt(3.0)).epsilon(1e-8));
  // All differences equal and zero: no evidence of a difference at all.
  CHECK(pairedT({1, 2}, {1, 2}).p == 1.0);
}

TEST_CASE("Wilcoxon signed-rank: exact p-value against brute-force enumeration of the signs") {
  // n = 12 distinct |d|: the exact null distribution is that of Σ k s_k over all 2^12 sign
  // patterns; enumerate them directly (independent of the dynamic programme under test).
  const std::vector<double> d{0.3, -1.2, 2.5, 0.7, -0.1, 3.3, 1.9, -2.2, 0.45, 4.1, -0.05, 1.5};
  std::vector<double> a = d, b(d.size(), 0.0);
  const SignedRank r = wilcoxonSignedRank(a, b);
  REQUIRE(r.exact);
  // ranks of |d|: sort by magnitude
  std::vector<double> mag;
  for (double v : d) mag.push_back(std::abs(v));
  double wPlus = 0;
  for (double v : d) {
    if (v <= 0) continue;
    int rank = 1;
    for (double m : mag) rank += m < std::abs(v) ? 1 : 0;
    wPlus += rank;
  }
  CHECK(r.wPlus == wPlus);
  const int n = int(d.size());
  const double total = n * (n + 1) / 2.0;
  const double w = std::min(wPlus, total - wPlus);
  long long atMost = 0;
  for (int mask = 0; mask < (1 << n); ++mask) {
    int s = 0;
    for (int k = 0; k < n; ++k)
      if (mask & (1 << k)) s += k + 1;
    atMost += s <= w ? 1 : 0;
  }
  CHECK(r.p == Approx(2.0 * double(atMost) / double(1 << n)).epsilon(1e-14));
  // n = 3 all positive: P(W+ = 6) = 1/8, two-sided 1/4.
  CHECK(wilcoxonSignedRank({1, 2, 3}, {0, 0, 0}).p == Approx(0.25).epsilon(1e-15));
}

TEST_CASE("Wilcoxon signed-rank: normal approximation close to the exact law at n = 50") {
  // Differences k·(−1)^(k mod 3 == 0) for k = 1..50: no ties, exact p available; the normal
  // approximation with continuity correction is within 0.005 of it at this n (Lehmann 1975 §3.2
  // notes agreement to about two decimals from n ≈ 20).
  std::vector<double> a, b;
  for (int k = 1; k <= 50; ++k) {
    a.push_back(k % 3 == 0 ? -k : k);
    b.push_back(0);
  }
  const SignedRank r = wilcoxonSignedRank(a, b);
  REQUIRE(r.exact);
  CHECK(std::abs(r.p - normalTwoSidedP(r.z)) < 0.005);
  // One tie and n = 51: the normal approximation is used.
  a.push_back(50);
  b.push_back(0);
  CHECK_FALSE(wilcoxonSignedRank(a, b).exact);
}
