// Level-shift test in the one-step prediction residuals (level_shift.hpp).
#include "errormodels/diagnose/level_shift.hpp"

#include <algorithm>
#include <cmath>

#include "errormodels/diagnose/series_stats.hpp"
#include "errormodels/diagnose/series_tools.hpp"
#include "errormodels/fit/ar_fit.hpp"

namespace sinsim::errormodels::diagnose::detail {

namespace {

/// rho >= 1: the largest ratio of the residuals' long-run variance at block size m (robust, from
/// the increments of their block means, as an Allan variance) to their one-sample variance.
double longRunRatio(const std::vector<double>& e, double sigma) {
  double rho = 1.0;
  for (std::size_t m = 2; e.size() / m >= 33; m *= 2) {
    std::vector<double> mean(e.size() / m, 0.0), inc(mean.size() - 1);
    for (std::size_t j = 0; j < mean.size(); ++j) {
      for (std::size_t k = j * m; k < (j + 1) * m; ++k) mean[j] += e[k];
      mean[j] /= double(m);
    }
    for (std::size_t j = 0; j + 1 < mean.size(); ++j) inc[j] = mean[j + 1] - mean[j];
    const double s = robustSd(inc);
    rho = std::max(rho, double(m) * s * s / (2.0 * sigma * sigma));
  }
  return rho;
}

/// The inflation at a shift splitting the record into a and b samples, beyond the grid: the
/// statistic is (ab/N) (mean after - mean before), whose variance under a walk of per-sample
/// increment variance q is q a^2 b^2 / (3N) against the white part's sigma^2 ab/N, so it needs
/// 1 + q ab / (3 sigma^2) -- while the Allan ratio at m shows 1 + q m^2 / (3 sigma^2): 16x less
/// excess at the grid's top (N/8) for a shift at N/2. The ratio beyond N/8 is measured on the
/// record without the shift, which takes the largest wander of a walk with it; at the grid's
/// scales one shift changes little. So the excess R(m) = ratio - 1 at the grid's top is carried
/// to sqrt(ab) with its log-log slope over the grid's top octaves (least squares, clamped to
/// [0, 2]: a walk's 2, flat for white noise or a Gauss-Markov the grid saturates), when it is
/// clearly there (R > 1 at the top: the ratio's scatter there is ~0.5).
double beyondGrid(const std::vector<double>& avar, const std::vector<double>& arAvar,
                  const std::vector<std::size_t>& factors, std::size_t grid, std::size_t at, std::size_t n) {
  grid = std::min({grid, avar.size(), arAvar.size(), factors.size()});
  if (grid < 4 || !(arAvar[grid - 1] > 0)) return 1.0;
  const double top = avar[grid - 1] / arAvar[grid - 1] - 1, m = double(factors[grid - 1]);
  const double scale2 = double(at) * double(n - at) / (m * m);
  if (!(top > 1) || !(scale2 > 1)) return 1.0;
  double sx = 0, sy = 0, sxx = 0, sxy = 0, k = 0;
  for (std::size_t j = grid > 6 ? grid - 6 : 0; j < grid; ++j) {
    const double r = arAvar[j] > 0 ? avar[j] / arAvar[j] - 1 : 0.0;
    if (!(r > 0)) continue;
    const double x = std::log(double(factors[j])), v = std::log(r);
    sx += x, sy += v, sxx += x * x, sxy += x * v, k += 1;
  }
  const double det = k * sxx - sx * sx;
  const double slope = k >= 3 && det > 0 ? (k * sxy - sx * sy) / det : 0.0;
  return 1 + top * std::pow(scale2, 0.5 * std::clamp(slope, 0.0, 2.0));
}

}  // namespace

std::optional<LevelShift> levelShift(const std::vector<double>& y, std::size_t order, double zLimit,
                                     const std::vector<std::size_t>& factors,
                                     const std::vector<double>& modelAvar) {
  if (y.size() < 20 * (order + 2)) return std::nullopt;
  const auto ar = fit::burg(y, order);
  const std::size_t p = order, M = y.size() - p;
  std::vector<double> e(M);
  double eMean = 0;
  for (std::size_t t = 0; t < M; ++t) {
    double v = 0;
    for (std::size_t i = 0; i <= p; ++i) v += ar.a[i] * (y[t + p - i] - ar.mean);
    e[t] = v, eMean += v;
  }
  eMean /= double(M);
  for (double& v : e) v -= eMean;
  double sigma = robustSd(e);
  if (!(sigma > 0)) return std::nullopt;
  // The grid `factors`, then the half-octave factors beyond it up to N/4: the statistic sums e
  // over up to the whole record, the grid stops at the diagnosis' longest tau (N/8), and under a
  // walk-like excess (its Allan ratio to the AR growing as m^2) the ratio at N/8 understates the
  // sums' variance up to 16x -- a walk's realised wander passes for a step. N/4 is the
  // overlapping estimator's last factor with N/2 differences (few dof, but a real step is taken
  // out before the record's ratio is measured there, below).
  std::vector<std::size_t> longFactors = factors;
  for (std::size_t m : halfOctaveFactors(y.size() / 4))
    if (longFactors.empty() || m > longFactors.back()) longFactors.push_back(m);
  const auto arAvar = fit::arAllanVariance(ar.a, ar.drivingVariance, longFactors);
  auto ratioTo = [&arAvar](const std::vector<double>& avar, double rho) {
    for (std::size_t k = 0; k < arAvar.size() && k < avar.size(); ++k)
      if (arAvar[k] > 0) rho = std::max(rho, avar[k] / arAvar[k]);
    return rho;
  };
  double rho = longRunRatio(e, sigma);
  if (modelAvar.size() == factors.size()) rho = ratioTo(modelAvar, rho);
  std::vector<double> c(p + 1), c2(p + 2, 0.0), c1(p + 2, 0.0);  // c_j; prefix sums of c_j^2, c_j
  double a2 = 0;
  for (std::size_t j = 0; j <= p; ++j) {
    c[j] = (j ? c[j - 1] : 0.0) + ar.a[j];
    a2 += ar.a[j] * ar.a[j];
  }
  for (std::size_t j = 0; j < p; ++j) c2[j + 1] = c2[j] + c[j] * c[j], c1[j + 1] = c1[j] + c[j];
  const double A1 = c[p];
  std::vector<double> tail(M + 1, 0.0);  // sum of e from t on
  for (std::size_t t = M; t-- > 0;) tail[t] = tail[t + 1] + e[t];
  LevelShift best;
  double bestZ = -1, bestLongShare = 0;
  for (std::size_t k = p + 1; k + p + 1 < M; ++k) {
    double s = A1 * tail[k + p];
    for (std::size_t j = 0; j < p; ++j) s += c[j] * e[k + j];
    const double L = double(M - k), longPart = L - double(p);
    const double sumSq = c2[p] + A1 * A1 * longPart, sum = c1[p] + A1 * longPart;
    const double norm2 = sumSq - sum * sum / double(M);  // |u_k| after the mean is taken out
    if (!(norm2 > 0)) continue;
    const double z = std::fabs(s) / (sigma * std::sqrt(rho * norm2));
    if (z > bestZ) bestZ = z, best.at = k + p, best.size = s / norm2, bestLongShare = A1 * A1 * longPart / sumSq;
  }
  if (!(bestZ > zLimit)) return std::nullopt;
  // the record's own Allan variance without the shift (a scalar rho: the argmax stays)
  std::vector<double> rest = y;
  for (std::size_t k = best.at; k < rest.size(); ++k) rest[k] -= best.size;
  Setup setup;
  setup.rate = 1.0;  // an Allan variance of rates does not depend on the sample interval
  setup.n = rest.size();
  setup.factors = longFactors;
  const auto restAvar = allanVariance(rest, setup);
  // Beyond the grid the excess inflates only the long part of the statistic (A(1) times the
  // residuals' tail sum), not the p samples of its start: a walk the AR follows (A(1) ~ 0) leaves
  // a step as one large residual, whatever the walk's wander.
  const double beyond = beyondGrid(restAvar, arAvar, longFactors, factors.size(), best.at, y.size());
  const double rhoAll = std::max(ratioTo(restAvar, rho), 1 + bestLongShare * (beyond - 1));
  bestZ *= std::sqrt(rho / rhoAll);
  best.rho = rho = rhoAll;
  if (!(bestZ > zLimit)) return std::nullopt;
  best.z = bestZ;
  const std::size_t k = best.at - p;
  double spike = 0;
  for (std::size_t j = 0; j <= p && k + j < M; ++j) spike += ar.a[j] * e[k + j];
  best.zSpike = std::fabs(spike) / (sigma * std::sqrt(rho * a2));
  if (!(best.z > best.zSpike)) return std::nullopt;
  return best;
}

}  // namespace sinsim::errormodels::diagnose::detail
