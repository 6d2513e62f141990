// Power-law noise identification by the lag-1 autocorrelation (W. J. Riley & C. A. Greenhall,
// "Power law noise identification using the lag 1 autocorrelation", Proc. 18th EFTF, 2004): the
// noise type alpha (S_y ~ f^alpha) that chooses the EDF of each Allan point.
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "common/error.hpp"
#include "errormodels/stats/allan.hpp"
#include "errormodels/stats/allan_internal.hpp"

namespace sinsim::errormodels {
namespace {

/// r1 = sum (z_k - zbar)(z_{k+1} - zbar) / sum (z_k - zbar)^2, Riley & Greenhall (2004) eq. (2).
double lag1(const std::vector<double>& z) {
  const std::size_t n = z.size();
  double mean = 0;
  for (double v : z) mean += v;
  mean /= static_cast<double>(n);
  double num = 0, den = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double a = z[k] - mean;
    den += a * a;
    if (k + 1 < n) num += a * (z[k + 1] - mean);
  }
  return den > 0 ? num / den : 0.0;
}

NoiseId noiseIdResult(double rho, int d, int alpha_min) {
  NoiseId id;
  id.d = d;
  id.rho = rho;
  id.alpha_real = -2.0 * (rho + d);
  id.alpha = std::clamp(static_cast<int>(-std::lround(2.0 * rho)) - 2 * d, alpha_min, 2);
  return id;
}

}  // namespace

namespace detail {

/// Lag-1 noise identification on the block means z_k = (x_{(k+1)m} - x_{km}) / m of the phase:
/// remove the least-squares line (frequency drift), then difference until rho = r1 / (1 + r1)
/// < 0.25 or d = d_max; alpha = -round(2 rho) - 2d (Riley & Greenhall 2004, sec. 3, for
/// frequency data). The undifferenced step runs on the fly (two passes, no copy): it is the
/// common case, and on a 1 M-sample record at m = 1 it is most of the cost.
std::optional<NoiseId> identifyFromPhase(const std::vector<double>& x, std::size_t m, int d_max,
                                         int alpha_min) {
  const std::size_t nb = (x.size() - 1) / m;
  if (nb < 30) return std::nullopt;  // Riley & Greenhall (2004): at least 30 points
  const double inv_m = 1.0 / static_cast<double>(m);
  const double* X = x.data();
  auto zval = [&](std::size_t k) { return (X[(k + 1) * m] - X[k * m]) * inv_m; };
  const double c = 0.5 * static_cast<double>(nb - 1);  // centred abscissa
  // Two interleaved accumulator sets break the add-latency chains (the loops are latency bound).
  double sz0 = 0, stz0 = 0, sz1 = 0, stz1 = 0;
  std::size_t k = 0;
  for (; k + 2 <= nb; k += 2) {
    const double t = static_cast<double>(k) - c;
    const double z0 = zval(k), z1 = zval(k + 1);
    sz0 += z0;
    stz0 += t * z0;
    sz1 += z1;
    stz1 += (t + 1.0) * z1;
  }
  for (; k < nb; ++k) {
    const double z = zval(k);
    sz0 += z;
    stz0 += (static_cast<double>(k) - c) * z;
  }
  const double sz = sz0 + sz1, stz = stz0 + stz1;
  const double nn = static_cast<double>(nb);
  const double stt = nn * (nn * nn - 1.0) / 12.0;  // sum of (k - c)^2, closed form
  const double mean = sz / nn;
  const double slope = stt > 0 ? stz / stt : 0.0;
  auto resid = [&](std::size_t j) { return zval(j) - mean - slope * (static_cast<double>(j) - c); };
  // Residuals of a fit with intercept have zero mean up to rounding; keep the exact formula
  // anyway by accumulating their sum.
  double se0 = 0, see0 = 0, sl0 = 0, se1 = 0, see1 = 0, sl1 = 0;
  double prev = resid(0);
  se0 += prev;
  see0 += prev * prev;
  k = 1;
  for (; k + 2 <= nb; k += 2) {
    const double e0 = resid(k), e1 = resid(k + 1);
    se0 += e0;
    see0 += e0 * e0;
    sl0 += prev * e0;
    se1 += e1;
    see1 += e1 * e1;
    sl1 += e0 * e1;
    prev = e1;
  }
  for (; k < nb; ++k) {
    const double e = resid(k);
    se0 += e;
    see0 += e * e;
    sl0 += prev * e;
    prev = e;
  }
  const double se = se0 + se1, see = see0 + see1, sl = sl0 + sl1;
  const double n = static_cast<double>(nb);
  const double eb = se / n;
  const double e0 = resid(0), el = prev;
  const double den = see - n * eb * eb;
  const double num = sl - eb * (2 * se - e0 - el) + (n - 1) * eb * eb;
  const double r1 = den > 0 ? num / den : 0.0;
  double rho = r1 / (1.0 + r1);
  if (rho < 0.25 || d_max <= 0) return noiseIdResult(rho, 0, alpha_min);
  std::vector<double> z(nb);
  for (std::size_t k = 0; k < nb; ++k) z[k] = resid(k);
  for (int d = 1;; ++d) {
    for (std::size_t k = 0; k + 1 < z.size(); ++k) z[k] = z[k + 1] - z[k];
    z.pop_back();
    const double r = lag1(z);
    rho = r / (1.0 + r);
    if (rho < 0.25 || d >= d_max) return noiseIdResult(rho, d, alpha_min);
  }
}

}  // namespace detail

std::optional<NoiseId> identifyNoise(const std::vector<double>& y, std::size_t m, int d_max,
                                     int alpha_min) {
  if (m == 0) throw InputError("noise identification: averaging factor must be >= 1");
  return detail::identifyFromPhase(detail::phaseOf(y), m, d_max, alpha_min);
}

}  // namespace sinsim::errormodels
