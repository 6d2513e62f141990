// Gaussian-equivalent z of p-values and t statistics (significance.hpp).
#include "errormodels/diagnose/significance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "errormodels/diagnose/series_tools.hpp"
#include "errormodels/stats/special.hpp"

namespace sinsim::errormodels::diagnose::detail {

double zFromTwoSidedP(double p) {
  if (!(p > 0)) return kMaxScore;
  if (p >= 1) return 0.0;
  return std::min(kMaxScore, normalTwoSidedCritical(p));
}

double zFromStudentT(double t, double nu) {
  if (!(nu > 0)) return 0.0;
  if (std::isinf(nu)) return t;
  return std::sqrt(nu * std::log1p(t * t / nu)) * (8 * nu + 1) / (8 * nu + 3);
}

double satterthwaiteDof(double estimated, double dof, double known) {
  if (!(estimated > 0)) return std::numeric_limits<double>::infinity();
  const double r = 1.0 + std::max(0.0, known) / estimated;
  return dof * r * r;
}

namespace {

/// The window-mean increments of one averaging factor m, their median and robust scale.
struct Increments {
  std::size_t m = 0;
  std::vector<double> d;
  double median = 0, scale = 0;
  double zMax = 0;  // the largest |d - median| / scale
};

std::vector<double> prefixSums(const std::vector<double>& y) {
  std::vector<double> P(y.size() + 1, 0.0);
  for (std::size_t k = 0; k < y.size(); ++k) P[k + 1] = P[k] + y[k];
  return P;
}

/// Increments of every factor of `factors` with 32..4096 of them (the jump test's windows), from
/// the prefix sums P of the series.
std::vector<Increments> incrementScan(const std::vector<double>& P, const std::vector<std::size_t>& factors) {
  const std::size_t N = P.size() - 1;
  std::vector<Increments> out;
  for (auto m : factors) {
    const std::size_t windows = m ? N / m : 0;
    if (windows < 33 || windows > 4097) continue;
    Increments in;
    in.m = m;
    in.d.resize(windows - 1);
    for (std::size_t j = 0; j + 1 < windows; ++j)
      in.d[j] = (P[(j + 2) * m] - 2 * P[(j + 1) * m] + P[j * m]) / double(m);
    in.median = median(in.d);
    std::vector<double> dev(in.d.size());
    for (std::size_t j = 0; j < in.d.size(); ++j) dev[j] = std::fabs(in.d[j] - in.median);
    in.scale = kSdPerMad * median(dev);  // robustSd, with the deviations kept for zMax
    if (in.scale > 0) in.zMax = *std::max_element(dev.begin(), dev.end()) / in.scale;
    out.push_back(std::move(in));
  }
  return out;
}

std::size_t incrementCount(const std::vector<Increments>& scan) {
  std::size_t n = 0;
  for (const auto& in : scan) n += in.d.size();
  return n;
}

/// The bias steps behind the increments of `in` beyond zEach robust sigma, as (sample, size):
/// a run of consecutive such increments is a step when its net change is beyond the limit too
/// (a spike or a short burst inside one window moves one window mean and back: no step), located
/// within one window of the run where the means of m samples before and after differ most, and
/// sized by the means of up to 8 m samples on each side (not across a neighbouring step; the
/// drift of the other increments over that span removed, so a ramp stays in the record). On a value
/// lattice of step q a change of one level is what rounding makes of any slow drift (a ramp
/// under noise below the LSB is a staircase of single-LSB steps): only steps beyond 1.5 q count.
std::vector<std::pair<std::size_t, double>> stepsAt(const std::vector<double>& P, const Increments& in,
                                                    double zEach, double lattice) {
  const std::size_t N = P.size() - 1, m = in.m;
  auto mean = [&P](std::size_t a, std::size_t b) { return (P[b] - P[a]) / double(b - a); };
  auto flagged = [&](std::size_t j) { return std::fabs(in.d[j] - in.median) > zEach * in.scale; };
  double drift = 0;  // per sample: the mean of the increments that are no jump (a staircase's median is 0)
  std::size_t calm = 0;
  for (std::size_t j = 0; j < in.d.size(); ++j)
    if (!flagged(j)) drift += in.d[j], ++calm;
  drift /= double(std::max<std::size_t>(calm, 1)) * double(m);
  std::vector<std::size_t> at;
  for (std::size_t j = 0; j < in.d.size(); ++j) {
    if (!flagged(j)) continue;
    std::size_t j1 = j;
    double net = 0;
    for (; j1 < in.d.size() && flagged(j1); ++j1) net += in.d[j1] - in.median;
    const std::size_t r = j1 - j;
    const std::size_t from = j * m + (j ? 0 : m), to = std::min(N - m, (j1 + 1) * m);
    j = j1;
    if (!(std::fabs(net) > zEach * in.scale * std::sqrt(double(r)))) continue;
    std::size_t best = from;
    double dBest = -1;
    for (std::size_t k = from; k <= to; ++k) {
      const double dk = std::fabs(mean(k, k + m) - mean(k - m, k) - drift * double(m));
      if (dk > dBest) dBest = dk, best = k;
    }
    if (at.empty() || best >= at.back() + m) at.push_back(best);
  }
  std::vector<std::pair<std::size_t, double>> steps;
  for (std::size_t i = 0; i < at.size(); ++i) {
    const std::size_t before = std::min({8 * m, at[i], i ? at[i] - at[i - 1] : N});
    const std::size_t after = std::min({8 * m, N - at[i], i + 1 < at.size() ? at[i + 1] - at[i] : N});
    const double size = mean(at[i], at[i] + after) - mean(at[i] - before, at[i]) - drift * 0.5 * double(before + after);
    if (std::fabs(size) > 1.5 * lattice) steps.emplace_back(at[i], size);
  }
  return steps;
}

}  // namespace

double jumpZ(const std::vector<double>& y, const std::vector<std::size_t>& factors) {
  const auto scan = incrementScan(prefixSums(y), factors);
  double zMax = 0;
  for (const auto& in : scan) zMax = std::max(zMax, in.zMax);
  const std::size_t tested = incrementCount(scan);
  return tested ? zFromTwoSidedP(double(tested) * std::erfc(zMax / std::sqrt(2.0))) : 0.0;
}

std::vector<double> levelSteps(const std::vector<double>& y, const std::vector<std::size_t>& factors,
                               double zLimit, double lattice, int maxPasses) {
  std::vector<double> x = y, steps;
  for (int pass = 0; pass < maxPasses; ++pass) {
    const auto P = prefixSums(x);
    auto scan = incrementScan(P, factors);
    const std::size_t tested = incrementCount(scan);
    if (tested == 0) break;
    // the per-increment limit that keeps the whole scan's false-alarm probability at zLimit's
    const double zEach = normalTwoSidedCritical(std::erfc(zLimit / std::sqrt(2.0)) / double(tested));
    std::sort(scan.begin(), scan.end(), [](const Increments& a, const Increments& b) { return a.zMax > b.zMax; });
    std::vector<std::pair<std::size_t, double>> found;
    for (const auto& in : scan) {  // the window size with the largest jump that is a step
      if (!(in.zMax > zEach)) break;
      if (!(found = stepsAt(P, in, zEach, lattice)).empty()) break;
    }
    if (found.empty()) break;
    if (steps.empty()) steps.assign(x.size(), 0.0);
    double level = 0;
    for (std::size_t k = 0, i = 0; k < x.size(); ++k) {
      for (; i < found.size() && found[i].first == k; ++i) level += found[i].second;
      x[k] -= level, steps[k] += level;
    }
  }
  return steps;
}

std::vector<LevelStep> jumpsOf(const std::vector<double>& steps, double rate) {
  std::vector<LevelStep> out;
  for (std::size_t k = 1; k < steps.size(); ++k)
    if (steps[k] != steps[k - 1]) out.push_back({double(k) / rate, steps[k] - steps[k - 1]});
  return out;
}

bool revertingSteps(const std::vector<LevelStep>& jumps) {
  double largest = 0;
  for (const auto& j : jumps) largest = std::max(largest, std::fabs(j.size));
  int changes = 0;
  double last = 0;
  for (const auto& j : jumps) {
    if (!(std::fabs(j.size) > 0.25 * largest)) continue;
    changes += last != 0 && (j.size > 0) != (last > 0);
    last = j.size;
  }
  return changes >= 4;
}

}  // namespace sinsim::errormodels::diagnose::detail
