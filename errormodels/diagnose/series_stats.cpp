// AVAR, banded PSD and ACF of one series on the grids of the comparison (series_stats.hpp).
#include "errormodels/diagnose/series_stats.hpp"
#include "errormodels/stats/spectral_lines.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/error.hpp"
#include "errormodels/diagnose/series_tools.hpp"
#include "errormodels/stats/allan.hpp"
#include "errormodels/stats/spectrum.hpp"

namespace sinsim::errormodels::diagnose::detail {

namespace {

/// Log-spaced bands over bins 1..L/2 (DC left out: every segment's mean is removed).
void psdBands(Setup& s, std::size_t bands) {
  const std::size_t L = s.psdSegment, kMax = L / 2;
  const double lo = std::log(1.0), hi = std::log(double(kMax) + 1.0);
  std::vector<std::size_t> current;
  std::size_t band = 0;
  const std::size_t nb = std::max<std::size_t>(4, bands);
  for (std::size_t k = 1; k <= kMax; ++k) {
    const auto b = std::min(nb - 1, std::size_t((std::log(double(k)) - lo) / (hi - lo) * double(nb)));
    if (b != band && !current.empty()) {
      s.psdBandBins.push_back(current);
      current.clear();
    }
    band = b;
    current.push_back(k);
  }
  if (!current.empty()) s.psdBandBins.push_back(current);
  for (const auto& bins : s.psdBandBins) {
    double f = 0;
    for (auto k : bins) f += double(k);
    s.psdBandFreq.push_back(f / double(bins.size()) * s.rate / double(L));
  }
}

/// ACF from the averaged Welch spectrum (Wiener-Khinchin): r(k) = df [P0 + P_{L/2} (-1)^k +
/// sum_{j=1}^{L/2-1} P_j cos(2 pi j k / L)], divided by the window's normalised autocorrelation
/// w2(k) = sum w_n w_{n+k} / sum w_n^2 (the taper's bias; Percival & Walden 1993 sec. 6.18), then
/// by r(0). Costs O(L lags) instead of an FFT of the whole record, and treats the measurement
/// and every realisation alike. Lags are limited to L/4, where w2 >= 0.6.
std::vector<double> acfFromWelch(const std::vector<double>& psd, const Setup& s) {
  const std::size_t L = s.psdSegment, half = L / 2;
  std::vector<double> w(L), w2(s.acfLags + 1, 0.0);
  for (std::size_t n = 0; n < L; ++n) w[n] = 0.5 - 0.5 * std::cos(2 * M_PI * double(n) / double(L));
  for (std::size_t k = 0; k <= s.acfLags; ++k)
    for (std::size_t n = 0; n + k < L; ++n) w2[k] += w[n] * w[n + k];
  std::vector<double> cosTable(L);
  for (std::size_t m = 0; m < L; ++m) cosTable[m] = std::cos(2 * M_PI * double(m) / double(L));
  std::vector<double> acf(s.acfLags + 1, 0.0);
  for (std::size_t k = 0; k <= s.acfLags; ++k) {
    double r = psd[0] + psd[half] * (k % 2 ? -1.0 : 1.0);
    for (std::size_t j = 1; j < half; ++j) r += psd[j] * cosTable[(j * k) % L];
    acf[k] = r / (w2[k] / w2[0]);
  }
  const double r0 = acf[0];
  for (double& v : acf) v = r0 > 0 ? v / r0 : 0.0;
  return acf;
}

}  // namespace

std::vector<std::size_t> halfOctaveFactors(std::size_t maxM) {
  std::vector<std::size_t> factors;
  for (int j = 0;; ++j) {
    const auto m = std::size_t(std::llround(std::pow(2.0, 0.5 * j)));
    if (m > maxM) break;
    if (factors.empty() || m != factors.back()) factors.push_back(m);
  }
  return factors;
}

Setup makeSetup(double rate, std::size_t n, const DiagnoseOptions& o) {
  Setup s;
  s.rate = rate;
  s.n = n;
  s.factors = halfOctaveFactors(std::max<std::size_t>(1, std::size_t(double(n) * o.maxFactorFraction)));
  std::size_t L = o.psdSegment;
  if (L == 0) L = lineTestSegment(n);
  if (L > n) throw InputError("PSD segment of " + std::to_string(L) + " samples exceeds the record");
  s.psdSegment = L;
  psdBands(s, o.psdBands);
  s.acfLags = o.acfMaxLag ? o.acfMaxLag : std::min<std::size_t>(n / 20, 500);
  s.acfLags = std::max<std::size_t>(1, std::min(s.acfLags, L / 4));
  return s;
}

std::vector<double> allanVariance(const std::vector<double>& y, const Setup& s) {
  AllanOptions ao;
  ao.factors = s.factors;
  ao.confidence_intervals = false;
  const auto c = allanDeviation(y, s.rate, AllanVariant::Overlapping, ao);
  std::vector<double> v(c.dev.size());
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = c.dev[i] * c.dev[i];
  return v;
}

SeriesStats seriesStats(const std::vector<double>& y, const Setup& s) {
  SeriesStats out;
  out.avar = allanVariance(y, s);
  WelchOptions wo;
  wo.segment_length = s.psdSegment;
  const auto p = welchPsd(y, s.rate, wo);
  for (const auto& bins : s.psdBandBins) {
    double sum = 0;
    for (auto k : bins) sum += p.psd[k];
    out.psd.push_back(sum / double(bins.size()));
  }
  out.acf = acfFromWelch(p.psd, s);
  out.trend = trendSlope(y, 1.0 / s.rate);
  out.lowFreq = lowFrequencyCoefficients(y, s.lowFreq);
  out.levelBlocks = noiseLevelBlocks(y);
  return out;
}

}  // namespace sinsim::errormodels::diagnose::detail
