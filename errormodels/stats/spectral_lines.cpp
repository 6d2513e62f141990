#include "errormodels/stats/spectral_lines.hpp"

#include <algorithm>
#include <cmath>

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

}  // namespace sinsim::errormodels
