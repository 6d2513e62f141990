// Drift of a static run per octave τ band of its sensor errors (drift_bands.hpp).
#include "sim/drift_bands.hpp"

#include <cmath>
#include <numeric>

#include "common/error.hpp"

namespace sinsim::sim {
namespace {

// Response Σ_k w_k s'_j[k] of the block means s_j (blocks of 2^j samples from k = 0) with the
// bias window's mean removed, s'_j = s_j − mean of s_j over the first nw samples, for every level
// j = 0..levels−1, from the prefix sums of x and w. Removing the window's mean per band (not from
// x first) attributes the calibration error to the band that causes it (τ about the window).
std::vector<double> levelResponses(const std::vector<double>& x, const std::vector<double>& w,
                                   std::size_t levels, std::size_t nw) {
  const std::size_t n = x.size();
  std::vector<double> px(n + 1, 0.0), pw(n + 1, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    px[k + 1] = px[k] + x[k];
    pw[k + 1] = pw[k] + w[k];
  }
  std::vector<double> r(levels, 0.0);
  for (std::size_t j = 0; j < levels; ++j) {
    const std::size_t m = std::size_t(1) << j;
    double window = 0.0;  // Σ of s_j over the first nw samples
    for (std::size_t b = 0; b < n; b += m) {
      const std::size_t e = std::min(n, b + m);
      const double mean = (px[e] - px[b]) / double(e - b);
      r[j] += mean * (pw[e] - pw[b]);
      if (b < nw) window += mean * double(std::min(e, nw) - b);
    }
    if (nw > 0) r[j] -= window / double(nw) * pw[n];
  }
  return r;
}

}  // namespace

std::vector<double> driftBandTaus(std::size_t n, double rate) {
  std::vector<double> tau;
  for (std::size_t m = 1; m <= n; m *= 2) tau.push_back(double(m) / rate);
  return tau;
}

std::vector<std::array<double, 2>> driftByBand(const ErrorSignal& x, const DriftKernel& k) {
  const std::size_t n = x.gyro[0].size();
  for (int a = 0; a < 3; ++a)
    if (x.gyro[a].size() != n || x.accel[a].size() != n)
      throw InputError("drift bands: the six error channels differ in length");
  if (n == 0 || !(x.rate > 0)) throw InputError("drift bands: an empty error signal");
  const std::size_t levels = driftBandTaus(n, x.rate).size();
  const double dt = 1.0 / x.rate, T = double(n) * dt;

  // Nav axes.
  std::array<std::vector<double>, 3> wn, an;  // ω_n [rad/s], a_n [m/s²]
  for (int a = 0; a < 3; ++a) wn[a].assign(n, 0.0), an[a].assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 w = k.C_nb * Vec3(x.gyro[0][i], x.gyro[1][i], x.gyro[2][i]);
    const Vec3 f = k.C_nb * Vec3(x.accel[0][i], x.accel[1][i], x.accel[2][i]);
    for (int a = 0; a < 3; ++a) wn[a][i] = w[a], an[a][i] = f[a];
  }
  const auto nw = std::min(n, std::size_t(std::llround(k.biasWindow * x.rate)));

  // Kernel weights at the interval midpoints.
  std::vector<double> ka(n), kg(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double u = T - (double(i) + 0.5) * dt;
    const double s = k.schuler;
    ka[i] = (s > 0 ? std::sin(s * u) / s : u) * dt;
    kg[i] = (s > 0 ? 2.0 * std::pow(std::sin(0.5 * s * u), 2) / (s * s) : 0.5 * u * u) * dt;
  }
  const auto aN = levelResponses(an[0], ka, levels, nw), aE = levelResponses(an[1], ka, levels, nw);
  const auto gN = levelResponses(wn[0], kg, levels, nw), gE = levelResponses(wn[1], kg, levels, nw);
  std::vector<std::array<double, 2>> level(levels);
  for (std::size_t j = 0; j < levels; ++j)
    level[j] = {aN[j] - k.g * gE[j], aE[j] + k.g * gN[j]};
  std::vector<std::array<double, 2>> band(levels);
  for (std::size_t j = 0; j < levels; ++j)
    for (int c = 0; c < 2; ++c)
      band[j][c] = j + 1 < levels ? level[j][c] - level[j + 1][c] : level[j][c];
  return band;
}

std::pair<std::size_t, std::size_t> drivingBands(const std::vector<double>& share) {
  const std::size_t nb = share.size();
  for (std::size_t width = 1; width <= nb; ++width) {
    std::size_t best = nb;
    double bestSum = -1.0;
    for (std::size_t lo = 0; lo + width <= nb; ++lo) {
      const double sum = std::accumulate(share.begin() + long(lo), share.begin() + long(lo + width), 0.0);
      if (sum > bestSum) bestSum = sum, best = lo;
    }
    if (bestSum >= 0.5 || width == nb) return {best, best + width - 1};
  }
  return {0, 0};  // no band at all (nb = 0): the caller has none to report
}

}  // namespace sinsim::sim
