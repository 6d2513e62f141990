// Outliers: one-step prediction residuals of an AR(4) fitted to the record itself (whitens the
// correlated part), robust scale (MAD), isolated samples beyond z_t with 2 N Phi(-z_t) = 1e-3
// (Bonferroni over the record).
#include "errormodels/diagnose/detector.hpp"
#include "errormodels/diagnose/significance.hpp"

#include <algorithm>
#include <cmath>

#include "errormodels/fit/ar_fit.hpp"

namespace sinsim::errormodels::diagnose::detail {

namespace {

constexpr std::size_t kOrder = 4;  // of the whitening AR

/// One-step prediction residuals of a Burg AR(4) of y (0 for the first 4 samples).
std::vector<double> predictionResiduals(const std::vector<double>& y) {
  const auto ar = fit::burg(y, kOrder);
  std::vector<double> e(y.size(), 0.0);
  for (std::size_t k = kOrder; k < y.size(); ++k) {
    double v = y[k] - ar.mean;
    for (std::size_t i = 1; i <= kOrder; ++i) v += ar.a[i] * (y[k - i] - ar.mean);
    e[k] = v;
  }
  return e;
}

/// Local peaks of |e - med| / sigma beyond zt (and, on a lattice, beyond 4 LSB: rounding makes
/// the residual discrete), with no other such sample within 5 samples.
std::vector<std::size_t> isolatedPeaks(const std::vector<double>& e, double med, double sigma,
                                       double zt, double lattice) {
  const std::size_t N = e.size();
  std::vector<std::size_t> flagged;
  for (std::size_t k = kOrder; k < N; ++k) {
    const double z = std::fabs(e[k] - med) / sigma;
    if (z <= zt || std::fabs(e[k] - med) <= 4 * lattice) continue;
    const double zl = std::fabs(e[k - 1] - med) / sigma;
    const double zr = k + 1 < N ? std::fabs(e[k + 1] - med) / sigma : 0;
    if (z >= zl && z >= zr) flagged.push_back(k);
  }
  std::vector<std::size_t> iso;
  for (std::size_t i = 0; i < flagged.size(); ++i) {
    const bool left = i > 0 && flagged[i] - flagged[i - 1] <= 5;
    const bool right = i + 1 < flagged.size() && flagged[i + 1] - flagged[i] <= 5;
    if (!left && !right) iso.push_back(flagged[i]);
  }
  return iso;
}

}  // namespace

std::vector<Candidate> detect_outliers(const DetectorContext& ctx) {
  const std::size_t N = ctx.N;
  if (N < 64) return {};
  const auto e = predictionResiduals(ctx.y);
  std::vector<double> absd(e.begin() + kOrder, e.end());
  const double med = median(absd);
  for (double& v : absd) v = std::fabs(v - med);
  const double sigma = 1.482602218505602 * median(absd);
  if (!(sigma > 0)) return {};
  const double zt = zFromTwoSidedP(1e-3 / double(N));  // erfc(z/sqrt2) = 1e-3 / N
  const auto iso = isolatedPeaks(e, med, sigma, zt, ctx.lattice);
  if (iso.empty()) return {};
  double zmax = 0, sumsq = 0;
  std::vector<double> sig(N, 0.0);
  for (auto k : iso) {
    zmax = std::max(zmax, std::fabs(e[k] - med) / sigma);
    sumsq += (e[k] - med) * (e[k] - med);
    sig[k] = e[k] - med;
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
               " robust sigma of the one-step prediction residual (largest " + num(zmax, 4) +
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
