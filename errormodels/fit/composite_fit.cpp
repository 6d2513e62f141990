#include "errormodels/fit/composite_fit.hpp"

#include <algorithm>
#include <cmath>

#include "common/error.hpp"

namespace sinsim::errormodels::fit {

std::vector<double> localLevelSmoother(const std::vector<double>& x, double q, double r,
                                       double* gainOut) {
  if (x.empty()) throw InputError("local-level smoother: empty series");
  if (!(q > 0.0 && r > 0.0 && std::isfinite(q) && std::isfinite(r)))
    throw InputError("local-level smoother: variances must be positive and finite");
  const double P = 0.5 * (q + std::sqrt(q * q + 4.0 * q * r));
  const double g = P / (P + r);
  if (gainOut) *gainOut = g;
  std::vector<double> f(x.size());
  // Start the level at the mean of the first ~1/g samples (the filter's memory).
  const std::size_t head = std::min<std::size_t>(x.size(), static_cast<std::size_t>(1.0 / g) + 1);
  double l = 0.0;
  for (std::size_t i = 0; i < head; ++i) l += x[i];
  l /= static_cast<double>(head);
  for (std::size_t i = 0; i < x.size(); ++i) {
    l += g * (x[i] - l);
    f[i] = l;
  }
  for (std::size_t i = x.size() - 1; i-- > 0;) f[i] += (1.0 - g) * (f[i + 1] - f[i]);
  return f;
}

ArRandomWalkFit fitArPlusRandomWalk(const std::vector<double>& x, const std::vector<double>& tau,
                                    const std::vector<double>& adev, const std::vector<double>& edf,
                                    const ArRandomWalkFitOptions& options) {
  const double dt = options.sampleInterval;
  if (!(std::isfinite(dt) && dt > 0.0))
    throw InputError("AR + random walk fit: sampleInterval must be a positive time");
  if (adev.empty()) throw InputError("AR + random walk fit: empty Allan curve");
  ArRandomWalkFit out;

  AllanFitOptions af;
  af.enabled = {false, true, false, true, false};
  af.sampleInterval = dt;
  af.recordLength = x.size();
  af.tauMin = options.tauMin;
  if (!(af.tauMin > 0.0)) {
    // 30 x the tau of the AR hump (first local maximum of the ADEV; the first point when the
    // curve falls from the start).
    std::size_t peak = 0;
    for (std::size_t i = 1; i + 1 < adev.size(); ++i)
      if (adev[i] >= adev[i - 1] && adev[i] > adev[i + 1]) {
        peak = i;
        break;
      }
    af.tauMin = 30.0 * tau[peak];
  }
  out.allan = fitAllanTerms(tau, adev, edf, af);
  out.randomWalk = out.allan.term(AllanTermKind::RandomWalk);
  out.whiteEquivalent = out.allan.term(AllanTermKind::White);
  out.randomWalkDetected = out.randomWalk.detected && out.whiteEquivalent.value > 0.0;

  OrderSelectionOptions os = options.order;
  os.sampleInterval = dt;
  if (out.randomWalkDetected) {
    const double K = out.randomWalk.value, N = out.whiteEquivalent.value;
    const std::vector<double> level = localLevelSmoother(x, K * K * dt, N * N / dt, &out.smootherGain);
    out.smootherTimeConstant = dt / out.smootherGain;
    std::vector<double> u(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) u[i] = x[i] - level[i];
    out.ar = selectArOrder(u, os);
  } else {
    out.ar = selectArOrder(x, os);
  }
  out.arCorrelationTime = arCorrelationTime(out.ar.fit.a, dt);
  out.separated = !out.randomWalkDetected || out.smootherTimeConstant >= 10.0 * out.arCorrelationTime;
  return out;
}

}  // namespace sinsim::errormodels::fit
