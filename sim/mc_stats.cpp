#include "sim/mc_stats.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/error.hpp"

namespace sinsim::sim::mcstats {

Moments moments(const std::vector<double>& x) {
  Moments m;
  m.n = x.size();
  if (x.empty()) return m;
  double s = 0.0, s2 = 0.0;
  for (double v : x) {
    s += v;
    s2 += v * v;
  }
  m.mean = s / double(m.n);
  m.rms = std::sqrt(s2 / double(m.n));
  if (m.n > 1) {
    double d2 = 0.0;
    for (double v : x) d2 += (v - m.mean) * (v - m.mean);
    m.sd = std::sqrt(d2 / double(m.n - 1));
  }
  return m;
}

double percentileSorted(const std::vector<double>& sorted, double p) {
  if (sorted.empty()) return NAN;
  const double h = (double(sorted.size()) - 1.0) * p / 100.0;
  const double fl = std::floor(h);
  const std::size_t i = std::size_t(fl);
  if (i + 1 >= sorted.size()) return sorted.back();
  return sorted[i] + (h - fl) * (sorted[i + 1] - sorted[i]);
}

namespace {

// Continued fraction of I_x(a, b) (NR 3rd ed. eq. 6.4.5, modified Lentz).
double betaContinuedFraction(double x, double a, double b) {
  constexpr double tiny = 1e-300, eps = 1e-15;
  const double qab = a + b, qap = a + 1.0, qam = a - 1.0;
  double c = 1.0, d = 1.0 - qab * x / qap;
  if (std::abs(d) < tiny) d = tiny;
  d = 1.0 / d;
  double h = d;
  for (int m = 1; m <= 10000; ++m) {
    const int m2 = 2 * m;
    double aa = m * (b - m) * x / ((qam + m2) * (a + m2));
    d = 1.0 + aa * d;
    if (std::abs(d) < tiny) d = tiny;
    c = 1.0 + aa / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1.0 / d;
    h *= d * c;
    aa = -(a + m) * (qab + m) * x / ((a + m2) * (qap + m2));
    d = 1.0 + aa * d;
    if (std::abs(d) < tiny) d = tiny;
    c = 1.0 + aa / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1.0 / d;
    const double del = d * c;
    h *= del;
    if (std::abs(del - 1.0) < eps) return h;
  }
  throw NumericalError("incomplete beta continued fraction did not converge");
}

}  // namespace

double regularizedBeta(double x, double a, double b) {
  if (!(a > 0 && b > 0 && x >= 0 && x <= 1))
    throw NumericalError("regularizedBeta: arguments out of domain");
  if (x == 0.0 || x == 1.0) return x;
  // Prefactor x^a (1-x)^b / (a B(a, b)) in logs (NR eq. 6.4.5); the fraction converges fast for
  // x < (a + 1)/(a + b + 2), otherwise use the symmetry I_x(a, b) = 1 − I_{1−x}(b, a).
  const double lbt = std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) +
                     b * std::log1p(-x);
  if (x < (a + 1.0) / (a + b + 2.0)) return std::exp(lbt) * betaContinuedFraction(x, a, b) / a;
  return 1.0 - std::exp(lbt) * betaContinuedFraction(1.0 - x, b, a) / b;
}

double studentTwoSidedP(double t, double nu) {
  if (!(nu > 0)) throw NumericalError("studentTwoSidedP: degrees of freedom must be positive");
  if (std::isnan(t)) return NAN;
  if (std::isinf(t)) return 0.0;
  return regularizedBeta(nu / (nu + t * t), 0.5 * nu, 0.5);
}

double normalTwoSidedP(double z) { return std::erfc(std::abs(z) / std::sqrt(2.0)); }

namespace {

// t with studentTwoSidedP(t, nu) = p (bisection; the p-value is monotone in |t|).
double studentQuantileTwoSided(double p, double nu) {
  double lo = 0.0, hi = 1.0;
  while (studentTwoSidedP(hi, nu) > p) hi *= 2.0;
  for (int i = 0; i < 200 && hi - lo > 1e-14 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (studentTwoSidedP(mid, nu) > p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

PairedT pairedT(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) throw InputError("pairedT: samples of different sizes");
  std::vector<double> d(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) d[i] = a[i] - b[i];
  const Moments m = moments(d);
  PairedT r;
  r.n = m.n;
  r.meanDiff = m.mean;
  r.sdDiff = m.sd;
  if (m.n < 2) {
    r.t = NAN;
    r.p = NAN;
    r.ciLow = r.ciHigh = NAN;
    return r;
  }
  const double se = m.sd / std::sqrt(double(m.n));
  const double nu = double(m.n - 1);
  if (se == 0.0) {
    r.t = m.mean == 0.0 ? 0.0 : std::copysign(std::numeric_limits<double>::infinity(), m.mean);
    r.p = m.mean == 0.0 ? 1.0 : 0.0;
    r.ciLow = r.ciHigh = m.mean;
    return r;
  }
  r.t = m.mean / se;
  r.p = studentTwoSidedP(r.t, nu);
  const double tq = studentQuantileTwoSided(0.05, nu);
  r.ciLow = m.mean - tq * se;
  r.ciHigh = m.mean + tq * se;
  return r;
}

SignedRank wilcoxonSignedRank(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) throw InputError("wilcoxonSignedRank: samples of different sizes");
  std::vector<double> d;
  d.reserve(a.size());
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i] != b[i]) d.push_back(a[i] - b[i]);
  SignedRank r;
  r.n = d.size();
  if (d.empty()) return r;
  const std::size_t n = d.size();
  std::vector<std::size_t> idx(n);
  for (std::size_t i = 0; i < n; ++i) idx[i] = i;
  std::stable_sort(idx.begin(), idx.end(),
                   [&](std::size_t i, std::size_t j) { return std::abs(d[i]) < std::abs(d[j]); });
  double tieTerm = 0.0;
  bool ties = false;
  for (std::size_t i = 0; i < n;) {
    std::size_t j = i;
    while (j + 1 < n && std::abs(d[idx[j + 1]]) == std::abs(d[idx[i]])) ++j;
    const double rank = 0.5 * double(i + j) + 1.0;  // average of ranks i+1 .. j+1
    const double tcount = double(j - i + 1);
    if (tcount > 1) {
      ties = true;
      tieTerm += tcount * tcount * tcount - tcount;
    }
    for (std::size_t k = i; k <= j; ++k)
      if (d[idx[k]] > 0) r.wPlus += rank;
    i = j + 1;
  }
  const double nn = double(n);
  const double mean = nn * (nn + 1.0) / 4.0;
  const double var = nn * (nn + 1.0) * (2.0 * nn + 1.0) / 24.0 - tieTerm / 48.0;
  const double dev = std::abs(r.wPlus - mean);
  r.z = var > 0 ? std::copysign(std::max(0.0, dev - 0.5) / std::sqrt(var), r.wPlus - mean) : 0.0;
  if (n <= 50 && !ties) {
    // Exact null distribution: W+ = Σ k·s_k over independent fair signs s_k ∈ {0, 1}; count the
    // subsets of {1..n} by their sum (counts up to 2^50 fit a double exactly).
    const std::size_t maxW = n * (n + 1) / 2;
    std::vector<double> count(maxW + 1, 0.0);
    count[0] = 1.0;
    for (std::size_t k = 1; k <= n; ++k)
      for (std::size_t w = maxW; w >= k; --w) count[w] += count[w - k];
    const double total = std::ldexp(1.0, int(n));
    const double w = std::min(r.wPlus, double(maxW) - r.wPlus);  // lower tail by symmetry
    double tail = 0.0;
    for (std::size_t v = 0; double(v) <= w + 1e-9; ++v) tail += count[v];
    r.p = std::min(1.0, 2.0 * tail / total);
    r.exact = true;
  } else {
    r.p = var > 0 ? normalTwoSidedP(r.z) : 1.0;
  }
  return r;
}

double percentileOf(const std::vector<double>& sortedX, double v) {
  if (sortedX.empty()) return 50.0;
  const auto lo = std::lower_bound(sortedX.begin(), sortedX.end(), v);
  const auto hi = std::upper_bound(sortedX.begin(), sortedX.end(), v);
  const double below = double(lo - sortedX.begin());
  const double equal = double(hi - lo);
  return 100.0 * (below + 0.5 * equal) / double(sortedX.size());
}

}  // namespace sinsim::sim::mcstats
