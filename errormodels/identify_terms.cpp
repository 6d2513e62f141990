// The Allan-term fit of the identify pipeline (identify_terms.hpp).
#include "errormodels/identify_terms.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "common/error.hpp"
#include "common/number_text.hpp"
#include "errormodels/stats/special.hpp"

namespace sinsim::errormodels::detail {
namespace {

/// One fit of exactly the `enabled` terms (no elimination). correlated = false: independent
/// points (0.02 ms instead of ~40 ms; used for range and term selection).
fit::AllanFit fitTerms(const CurvePoints& p, double dt, std::size_t n,
                       std::array<bool, fit::kAllanTermCount> enabled, double tauMin,
                       bool correlated = true) {
  fit::AllanFitOptions o;
  o.enabled = enabled;
  o.tauMin = tauMin;
  o.eliminateUndetected = false;
  if (!correlated) return fit::fitAllanTerms(p.tau, p.dev, p.edf, o);
  o.sampleInterval = dt;
  o.recordLength = n;
  try {
    return fit::fitAllanTerms(p.tau, p.dev, p.edf, o);
  } catch (const NumericalError&) {
    // The modelled point covariance can be numerically singular: fall back to independent
    // points. AllanFit::correlated is then false, which the model file states.
    o.sampleInterval = 0.0;
    o.recordLength = 0;
    return fit::fitAllanTerms(p.tau, p.dev, p.edf, o);
  }
}

/// Term selection (which of Q, N, B, K, R the data support): every subset of the `allowed` terms
/// is fitted with independent points and scored by BIC, chi^2 + k ln(points) (Schwarz 1978);
/// a subset counts only when each of its terms is detected (theta > 2 sigma). Exhaustive (at
/// most 31 subsets of 0.02 ms each) because backward elimination from all five terms, whose
/// long-tau columns (B, K, R) are nearly collinear, dropped a clear random walk in 4 of 12 white +
/// random-walk records.
fit::AllanFit selectTerms(const CurvePoints& p, double dt, std::size_t n,
                          std::array<bool, fit::kAllanTermCount> allowed, double tauMin) {
  std::optional<fit::AllanFit> best;
  double bestScore = 0.0;
  for (unsigned mask = 1; mask < (1u << fit::kAllanTermCount); ++mask) {
    std::array<bool, fit::kAllanTermCount> en{};
    std::size_t k = 0;
    bool ok = true;
    for (std::size_t j = 0; j < fit::kAllanTermCount; ++j) {
      en[j] = (mask >> j) & 1u;
      if (en[j] && !allowed[j]) ok = false;
      k += en[j];
    }
    if (!ok) continue;
    fit::AllanFit f;
    try {
      f = fitTerms(p, dt, n, en, tauMin, false);
    } catch (const InputError&) {
      continue;  // fewer points than terms
    }
    if (f.dof < 1) continue;
    bool all = true;
    for (std::size_t j = 0; j < fit::kAllanTermCount; ++j)
      if (en[j] && !f.terms[j].detected) all = false;
    if (!all) continue;
    const double score = f.chi2 + static_cast<double>(k) * std::log(static_cast<double>(f.pointsUsed));
    if (!best || score < bestScore) {
      best = f;
      bestScore = score;
    }
  }
  if (!best) throw InputError("Allan-term fit: no term is supported by the points at tau >= " +
                              significant(tauMin, 4) + " s");
  return *best;
}

}  // namespace

CurvePoints usablePoints(const AllanCurve& c) {
  CurvePoints p;
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (!(c.dev[i] > 0.0 && std::isfinite(c.dev[i]))) continue;
    if (i >= c.edf.size() || !(c.edf[i] > 0.0 && std::isfinite(c.edf[i]))) continue;
    if (10 * c.m[i] > c.samples) continue;
    p.tau.push_back(c.tau[i]);
    p.dev.push_back(c.dev[i]);
    p.edf.push_back(c.edf[i]);
  }
  return p;
}

std::size_t pointsAtOrAbove(const CurvePoints& p, double tauMin) {
  return static_cast<std::size_t>(std::count_if(p.tau.begin(), p.tau.end(),
                                                [&](double t) { return t >= tauMin * (1 - 1e-12); }));
}

RangedFit fitTermsFrom(const CurvePoints& p, double dt, std::size_t n,
                       std::array<bool, fit::kAllanTermCount> enabled, double tauStart,
                       std::size_t minPoints) {
  std::optional<RangedFit> best;
  double bestRatio = 0.0;
  for (std::size_t i = 0; i < p.tau.size(); ++i) {
    if (p.tau[i] < tauStart * (1 - 1e-12)) continue;
    if (p.tau.size() - i < minPoints) break;
    RangedFit r{selectTerms(p, dt, n, enabled, p.tau[i]), p.tau[i], false};
    const double dof = static_cast<double>(std::max<std::size_t>(r.fit.dof, 1));
    r.consistent = r.fit.chi2 <= chiSquareQuantile(0.999, dof);
    if (r.consistent) {
      best = r;
      break;
    }
    const double ratio = r.fit.chi2 / dof;
    if (!best || ratio < bestRatio) {
      best = r;
      bestRatio = ratio;
    }
  }
  if (!best)
    throw InputError("Allan-term fit: fewer than " + std::to_string(minPoints) +
                     " Allan points at tau >= " + significant(tauStart, 4) + " s");
  // Final values and uncertainties: correlated GLS of the selected terms, reporting the other
  // allowed terms with their upper bounds (elimination on: a term the GLS no longer supports is
  // dropped).
  std::array<bool, fit::kAllanTermCount> chosen{};
  for (std::size_t j = 0; j < fit::kAllanTermCount; ++j) chosen[j] = best->fit.terms[j].enabled;
  fit::AllanFit gls = fitTerms(p, dt, n, chosen, best->tauMin, true);
  best->fit = gls;
  return *best;
}

std::string describeRange(const RangedFit& r) {
  return "tau >= " + significant(r.tauMin, 4) + " s (" + std::to_string(r.fit.pointsUsed) + " points, chi2 " +
         significant(r.fit.chi2, 4) + " / " + std::to_string(r.fit.dof) + " dof" +
         (r.consistent ? "" : ", NO start consistent at 99.9 %: least-bad start kept") +
         (r.fit.correlated ? ")" : ", independent points)");
}

std::string describeAllan(const fit::AllanFit& f) {
  std::string s;
  for (std::size_t j = 0; j < fit::kAllanTermCount; ++j) {
    const auto& t = f.terms[j];
    if (!t.enabled) continue;
    if (!s.empty()) s += ", ";
    s += fit::toString(t.kind) + (t.detected ? " detected" : " not detected");
  }
  return s;
}

}  // namespace sinsim::errormodels::detail
