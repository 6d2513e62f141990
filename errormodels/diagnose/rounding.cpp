// Exact moments of a rounded Gaussian and the variance rounding adds to a record (rounding.hpp).
#include "errormodels/diagnose/rounding.hpp"

#include <cmath>
#include <map>

#include "errormodels/stats/special.hpp"

namespace sinsim::errormodels::diagnose::detail {

RoundedMoments roundedMoments(double mu, double sigma, double q) {
  const double m = mu / q, s = sigma / q;  // in LSB
  const long lo = long(std::floor(m - 10.0 * s)) - 1, hi = long(std::ceil(m + 10.0 * s)) + 1;
  double p0 = normalCdf((double(lo) - 0.5 - m) / s), e1 = 0, e2 = 0;
  for (long j = lo; j <= hi; ++j) {
    const double p1 = normalCdf((double(j) + 0.5 - m) / s), p = p1 - p0;
    e1 += p * double(j), e2 += p * double(j) * double(j);
    p0 = p1;
  }
  return {q * e1, q * q * std::max(0.0, e2 - e1 * e1)};
}

namespace {

/// The level mu in [m - 1, m + 1] (in LSB) whose rounded mean is m, for sd s (LSB): bisection
/// (the rounded mean rises with mu).
double levelOfMean(double m, double s) {
  double a = m - 1.0, b = m + 1.0;
  for (int it = 0; it < 50; ++it) {
    const double c = 0.5 * (a + b);
    (roundedMoments(c, s, 1.0).mean < m ? a : b) = c;
  }
  return 0.5 * (a + b);
}

}  // namespace

double levelOfRoundedMean(double mean, double sigma, double q) {
  // At sigma >= q the rounded mean is the input's to exp(-2 pi^2) ~ 3e-9 of q (Widrow & Kollar).
  if (!(sigma < q)) return mean;
  return q * levelOfMean(mean / q, sigma / q);
}


namespace {

/// Mean over the blocks' phases (weights) of the rounded variance at sd s (LSB).
double meanRoundedVariance(const std::map<long, double>& phases, double block, double s) {
  double v = 0;
  for (const auto& [k, w] : phases) v += w * roundedMoments(levelOfMean(double(k) / block, s), s, 1.0).var;
  return v;
}

}  // namespace

double roundingAddedVariance(const std::vector<double>& y, double q, std::size_t block) {
  const std::size_t nb = y.size() / block;
  if (!(q > 0) || nb == 0 || block < 2) return q * q / 12.0;
  // A block's sum is an integer number of LSB from block * y[0]: its mean's phase in the cell is
  // k / block, k = 0..block-1. Only the phase matters (the cells are alike).
  std::map<long, double> phases;
  double v = 0;
  for (std::size_t b = 0; b < nb; ++b) {
    double sum = 0, sum2 = 0;
    for (std::size_t i = b * block; i < (b + 1) * block; ++i) {
      const double u = (y[i] - y[0]) / q;
      sum += u, sum2 += u * u;
    }
    const long k = std::lround(sum), ph = ((k % long(block)) + long(block)) % long(block);
    phases[ph] += 1.0 / double(nb);
    // A block above 2 LSB^2 (sigma > 1.4 q: q^2/12 added whatever its level) counts as 2, so that
    // a few spikes or a step inside blocks cannot pass for a dithering noise over the whole record.
    v += std::min(2.0, (sum2 - sum * sum / double(block)) / double(block - 1)) / double(nb);  // LSB^2
  }
  if (v >= 1.1) return q * q / 12.0;
  double a = 1e-3, b = std::sqrt(v) + 1.0;
  if (meanRoundedVariance(phases, double(block), a) >= v) return q * q * (v - a * a);
  for (int it = 0; it < 40; ++it) {
    const double c = 0.5 * (a + b);
    (meanRoundedVariance(phases, double(block), c) < v ? a : b) = c;
  }
  const double s = 0.5 * (a + b);
  return q * q * (v - s * s);
}

}  // namespace sinsim::errormodels::diagnose::detail
