// Outliers: one-step prediction residuals of an AR(4) fitted to the record itself (whitens the
// correlated part), each sample's additive-outlier estimate from them (the matched filter of the
// AR polynomial), robust scale (MAD), isolated samples beyond z_t with 2 N Phi(-z_t) = 1e-3
// (Bonferroni over the record) and against the noise around them; not the burst a level shift
// makes in those residuals (below).
#include "errormodels/diagnose/detector.hpp"
#include "errormodels/diagnose/level_shift.hpp"
#include "errormodels/diagnose/significance.hpp"

#include <algorithm>
#include <cmath>

#include "errormodels/fit/ar_fit.hpp"

namespace sinsim::errormodels::diagnose::detail {

namespace {

constexpr std::size_t kOrder = 4;  // of the whitening AR
constexpr std::size_t kNear = 5;   // samples within which two flagged samples are not isolated

/// An additive outlier s at sample k enters the one-step residuals e = A(q)(y - mean) as
/// s (1, a1, ..., a4) at k..k+4. Its least-squares estimate from them, in units of its own
/// standard deviation sigma_e / |a| (Chang, Tiao & Chen 1988's lambda_A), and that of the
/// estimate itself.
struct AdditiveOutliers {
  std::vector<double> z;     // per sample, in units of the residual scale
  std::vector<double> size;  // per sample [SI]
  std::vector<double> rho;   // correlation of the estimates at lags 0..kOrder
  std::vector<double> e;     // the one-step residuals [SI]
};

/// The estimates for the record y on the value lattice `lattice` (0: none); sigma: the residuals'
/// robust scale [SI].
AdditiveOutliers additiveOutliers(const std::vector<double>& y, double lattice, double& sigma) {
  const auto ar = fit::burg(y, kOrder);
  const std::size_t N = y.size();
  std::vector<double> e(N, 0.0);
  for (std::size_t k = kOrder; k < N; ++k) {
    double v = y[k] - ar.mean;
    for (std::size_t i = 1; i <= kOrder; ++i) v += ar.a[i] * (y[k - i] - ar.mean);
    e[k] = v;
  }
  const std::vector<double> tail(e.begin() + kOrder, e.end());
  const double med = median(tail);
  // On a lattice coarser than the noise most residuals are 0 and their MAD is 0 (or a fraction of
  // the step): the residual scale is at least the rounding's, q / sqrt(12) (a one-level flip
  // stays below isolatedPeaks' 4 LSB).
  sigma = std::max(robustSd(tail), lattice / std::sqrt(12.0));
  double norm2 = 0;
  for (std::size_t i = 0; i <= kOrder; ++i) norm2 += ar.a[i] * ar.a[i];
  AdditiveOutliers out;
  out.z.assign(N, 0.0);
  out.size.assign(N, 0.0);
  for (std::size_t k = kOrder; k + kOrder < N; ++k) {
    double v = 0;
    for (std::size_t i = 0; i <= kOrder; ++i) v += ar.a[i] * (e[k + i] - med);
    out.size[k] = v / norm2;
    out.z[k] = sigma > 0 ? v / (sigma * std::sqrt(norm2)) : 0.0;
  }
  for (std::size_t l = 0; l <= kOrder; ++l) {
    double r = 0;
    for (std::size_t i = 0; i + l <= kOrder; ++i) r += ar.a[i] * ar.a[i + l];
    out.rho.push_back(r / norm2);
  }
  out.e = std::move(e);
  return out;
}

/// Drops the samples that stand out only against the record's scale, not against the noise
/// around them: an outlier is one against its own neighbourhood. The local scale is the larger
/// of the residuals' robust scales over kLocal samples either side (a sample at the edge of a
/// louder stretch has it on one side), never below the record's. A noise whose level rises for a
/// while (a vibration burst) made hundreds of its samples "isolated outliers" against the calm
/// rest (a blind probe's 5x noise over 20 % of a 2-h record: 407, written by --add as
/// `outliers`; bench/blind_probe/long60).
void dropLocallyOrdinary(std::vector<std::size_t>& iso, const AdditiveOutliers& ao, double sigma, double zt,
                         double lattice) {
  constexpr std::size_t kLocal = 1024;
  const std::size_t N = ao.e.size();
  auto scale = [&](std::size_t from, std::size_t to) {  // [from, to), kOrder.. only (e is 0 before)
    from = std::max(from, kOrder);
    if (to <= from + 32) return 0.0;
    return std::max(robustSd(std::vector<double>(ao.e.begin() + long(from), ao.e.begin() + long(to))),
                    lattice / std::sqrt(12.0));
  };
  iso.erase(std::remove_if(iso.begin(), iso.end(),
                           [&](std::size_t k) {
                             const double left = scale(k > kLocal ? k - kLocal : 0, k);
                             const double right = scale(k + 1, std::min(N, k + 1 + kLocal));
                             const double local = std::max({sigma, left, right});
                             return std::fabs(ao.z[k]) * sigma / local <= zt;
                           }),
            iso.end());
}

/// Samples whose |z| exceeds zt (and, on a lattice, whose size exceeds 4 LSB: rounding makes the
/// residual discrete), largest first; one within kNear samples of a larger one is its side lobe
/// when what is left after the larger one's (z rho) is within zt, and otherwise makes both part of
/// a burst, not isolated.
std::vector<std::size_t> isolatedPeaks(const AdditiveOutliers& ao, double zt, double lattice) {
  std::vector<std::size_t> flagged;
  for (std::size_t k = 0; k < ao.z.size(); ++k)
    if (std::fabs(ao.z[k]) > zt && std::fabs(ao.size[k]) > 4 * lattice) flagged.push_back(k);
  std::stable_sort(flagged.begin(), flagged.end(),
                   [&](std::size_t a, std::size_t b) { return std::fabs(ao.z[a]) > std::fabs(ao.z[b]); });
  std::vector<std::size_t> kept;
  std::vector<bool> burst;
  for (auto k : flagged) {
    bool lobe = false, clash = false;
    for (std::size_t j = 0; j < kept.size(); ++j) {
      const std::size_t lag = k > kept[j] ? k - kept[j] : kept[j] - k;
      if (lag > kNear) continue;
      const double r = lag <= kOrder ? ao.rho[lag] : 0.0;
      if (std::fabs(ao.z[k] - r * ao.z[kept[j]]) <= zt) lobe = true;
      else clash = true, burst[j] = true;
    }
    if (clash || !lobe) kept.push_back(k), burst.push_back(clash);
  }
  std::vector<std::size_t> iso;
  for (std::size_t j = 0; j < kept.size(); ++j)
    if (!burst[j]) iso.push_back(kept[j]);
  std::sort(iso.begin(), iso.end());
  return iso;
}

}  // namespace

std::vector<Candidate> detect_outliers(const DetectorContext& ctx) {
  const std::size_t N = ctx.N;
  if (N < 64) return {};
  double sigma = 0;
  const auto ao = additiveOutliers(ctx.y, ctx.lattice, sigma);
  if (!(sigma > 0)) return {};
  const double zt = zFromTwoSidedP(1e-3 / double(N));  // erfc(z/sqrt2) = 1e-3 / N
  auto iso = isolatedPeaks(ao, zt, ctx.lattice);
  dropLocallyOrdinary(iso, ao, sigma, zt, ctx.lattice);
  // A bias step enters the residuals as h (c_0, c_1, ...), c_j = a_0 + ... + a_j: on a base whose
  // AR has A(1) ~ 0 (a slow, nearly integrated noise) that is one short burst, whose spike
  // estimate (~h/2) passes the test above (challenge record r0473: a 3x step under an AR(5) with
  // A(1) = 0.05 was named `outliers`). Of an additive outlier and a level shift the larger
  // statistic decides (Chang, Tiao & Chen 1988; Chen & Liu 1993): a flagged sample within kNear
  // of the shift the level-shift test finds at the same level (level_shift.hpp: significant
  // against every long-run variance the record shows) is its burst when the shift's lambda_L
  // (z sqrt(rho)) exceeds the sample's lambda_A. A spike under such a base is itself a step up and
  // one down a sample later, so the shift test may place a shift beside it; its lambda_A is then
  // the larger (|a| s against ~s / |u|) and it stays an outlier.
  if (const auto shift = iso.empty() ? std::nullopt : levelShift(ctx.y, kLevelShiftOrder, zt, ctx.setup.factors)) {
    const double lambdaL = shift->z * std::sqrt(shift->rho);
    iso.erase(std::remove_if(iso.begin(), iso.end(),
                             [&](std::size_t k) {
                               const std::size_t lag = k > shift->at ? k - shift->at : shift->at - k;
                               return lag <= kNear && lambdaL > std::fabs(ao.z[k]);
                             }),
              iso.end());
  }
  if (iso.empty()) return {};
  double zmax = 0, sumsq = 0;
  std::vector<double> sig(N, 0.0);
  for (auto k : iso) {
    zmax = std::max(zmax, std::fabs(ao.z[k]));
    sumsq += ao.size[k] * ao.size[k];
    sig[k] = ao.size[k];
  }
  const double amp = std::sqrt(sumsq / double(iso.size()));
  const double rate = double(iso.size()) / ctx.T;
  const Units& u = ctx.units;
  Candidate c;
  c.effect = "outliers";
  c.freeSize = false;
  c.parameters = 2;  // rate and amplitude
  c.g = allanVariance(sig, ctx.setup);
  c.signal = sig;
  // p of the largest |z| among N Gaussian residuals (Bonferroni).
  c.zSpecial = zFromTwoSidedP(double(N) * std::erfc(zmax / std::sqrt(2.0)));
  c.evidence = std::to_string(iso.size()) + " isolated samples beyond " + num(zt, 3) +
               " robust sigma of their additive-outlier estimate from the one-step prediction residual (largest " + num(zmax, 4) +
               " sigma, sigma " + quantity(sigma, u.level) + ")";
  const Dimension signalDim = ctx.signal;
  c.describe = [rate, amp, u, signalDim](double, Finding& f) {
    f.size = num(rate, 4) + " Hz of +-" + quantity(amp, u.level);
    f.spec = EffectSpec::make("outliers",
                              {ParamSpec::quantity("rate", stated(rate, "Hz"), Dimension::frequency()),
                               ParamSpec::quantity("amplitude", stated(amp, u.level), signalDim)});
    f.params["rate"] = rate;
    f.params["amplitude"] = amp;
  };
  return {c};
}

}  // namespace sinsim::errormodels::diagnose::detail
