#include "errormodels/stats/spectral_lines.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "errormodels/stats/special.hpp"

namespace sinsim::errormodels {

std::vector<WelchLine> welchLineTest(const PowerSpectrum& p, std::size_t count) {
  const std::size_t nbins = p.psd.size();
  if (nbins < 40) return {};
  const double nu = 2.0 * double(p.segments) / 1.056;
  const double medFactor = std::pow(1 - 2 / (9 * nu), 3);  // median of chi2_nu / nu (Wilson-Hilferty)
  std::vector<WelchLine> hits;  // p of the bin alone first
  std::size_t tested = 0;
  for (std::size_t k = 3; k + 3 < nbins; ++k) {
    std::vector<double> nb;
    for (std::ptrdiff_t d = -12; d <= 12; ++d) {
      if (std::abs(d) < 3) continue;
      const std::ptrdiff_t j = std::ptrdiff_t(k) + d;
      if (j >= 1 && j < std::ptrdiff_t(nbins)) nb.push_back(p.psd[std::size_t(j)]);
    }
    std::nth_element(nb.begin(), nb.begin() + std::ptrdiff_t(nb.size() / 2), nb.end());
    const double ref = nb[nb.size() / 2] / medFactor;
    if (!(ref > 0)) continue;
    ++tested;
    const double ratio = p.psd[k] / ref;
    if (ratio < 4) continue;
    hits.push_back({regularizedGammaQ(nu / 2, ratio * nu / 2), ratio, p.f[k], k});  // P(chi2_nu / nu > ratio)
  }
  std::sort(hits.begin(), hits.end(), [](const WelchLine& a, const WelchLine& b) {
    return a.p != b.p ? a.p < b.p : a.ratio > b.ratio;
  });
  std::vector<WelchLine> out;
  for (WelchLine h : hits) {
    h.p = std::min(1.0, double(tested) * h.p);
    if (h.p >= 1 || out.size() >= count) break;
    bool near = false;
    for (const WelchLine& t : out) near = near || (h.bin > t.bin ? h.bin - t.bin : t.bin - h.bin) <= 3;
    if (!near) out.push_back(h);
  }
  return out;
}

std::size_t lineTestSegment(std::size_t n) {
  std::size_t L = 16;
  while (L * 2 <= n / 8 && L * 2 <= 4096) L *= 2;
  return L;
}

double welchLineAmplitude(double psd, double ratio, double enbw_hz) {
  return std::sqrt(2.0 * std::max(0.0, psd - psd / ratio) * enbw_hz);
}

namespace {

/// The continuum at ordinate j of a periodogram I predicted from its neighbours j +- 3..24 (from
/// j = 3 up, positive ones only): the least-squares line in ln I over ln j at j, ln S_j - gamma,
/// and that prediction's sd (the ordinates' ln has variance pi^2 / 6). Unset below 20 neighbours.
struct Continuum {
  double logLevel = 0, sd = 0;
};
std::optional<Continuum> continuumAt(const std::vector<double>& I, std::size_t j) {
  constexpr std::ptrdiff_t kReach = 24;
  constexpr double kVarLogExp = M_PI * M_PI / 6;
  double sx = 0, sy = 0, sxx = 0, sxy = 0, m = 0;
  for (std::ptrdiff_t d = -kReach; d <= kReach; ++d) {
    if (std::abs(d) < 3 || std::ptrdiff_t(j) + d < 3) continue;
    const double v = I[std::size_t(std::ptrdiff_t(j) + d)];
    if (!(v > 0)) continue;
    const double x = std::log(double(std::ptrdiff_t(j) + d) / double(j)), y = std::log(v);
    sx += x, sy += y, sxx += x * x, sxy += x * y, m += 1;
  }
  if (m < 20) return std::nullopt;
  const double xm = sx / m, Sxx = sxx - sx * xm;
  const double b = Sxx > 0 ? (sxy - sx * sy / m) / Sxx : 0.0;
  return Continuum{sy / m - b * xm, std::sqrt(kVarLogExp * (1 / m + (Sxx > 0 ? xm * xm / Sxx : 0.0)))};
}

/// P(Exp(1) e^{-e} > r) = E exp(-r e^e), e ~ N(0, s^2): midpoint rule over +-8 s.
double exceedance(double r, double s) {
  double p = 0;
  const int steps = 800;
  for (int i = 0; i < steps; ++i) {
    const double u = -8.0 + 16.0 * (i + 0.5) / steps;
    p += std::exp(-r * std::exp(u * s) - 0.5 * u * u) * (16.0 / steps) / std::sqrt(2 * M_PI);
  }
  return p;
}

}  // namespace

LowLine lowLineTest(const std::vector<double>& y, double rate, std::size_t segment, std::size_t lowestBin,
                    const std::vector<double>& taken, double skip) {
  if (y.size() < 16 || segment == 0) return {};
  const Periodogram pg = taperedPeriodogram(y, 0.1, Detrend::Linear);
  const std::size_t n = pg.taper.size();
  constexpr std::size_t kReach = 24, jLo = 12;
  const std::size_t jHi = std::min(pg.I.size() > kReach + 1 ? pg.I.size() - kReach - 1 : 0,
                                   std::size_t(std::ceil(double(lowestBin) * double(n) / double(segment))) + 2);
  if (jHi < jLo) return {};
  constexpr double kGamma = 0.5772156649015329;  // -E ln of an Exp(1) ordinate
  auto nearTaken = [&](std::size_t j) {
    const double f = double(j) * rate / double(n);
    return std::any_of(taken.begin(), taken.end(), [&](double t) { return std::fabs(f - t) <= skip; });
  };
  double bestR = 0, bestS = 0;
  std::size_t bestJ = 0;
  for (std::size_t j = jLo; j <= jHi; ++j) {
    if (nearTaken(j)) continue;
    const std::optional<Continuum> c = continuumAt(pg.I, j);
    if (!c) continue;
    const double r = pg.I[j] / std::exp(c->logLevel + kGamma);
    if (r > bestR) bestR = r, bestJ = j, bestS = c->sd;
  }
  if (bestJ == 0) return {};
  return {std::min(1.0, exceedance(bestR, bestS) * double(jHi - jLo + 1)), bestR, double(bestJ) * rate / double(n), bestJ};
}

}  // namespace sinsim::errormodels
