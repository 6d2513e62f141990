// Refit of the base AR with the added effects taken out (base_refit.hpp).
#include "errormodels/diagnose/base_refit.hpp"

#include <algorithm>
#include <cmath>

#include "common/error.hpp"
#include "errormodels/diagnose/channels.hpp"
#include "errormodels/fit/allan_fit.hpp"
#include "errormodels/fit/ar_fit.hpp"
#include "errormodels/fit/composite_fit.hpp"

namespace sinsim::errormodels::diagnose::detail {

namespace {

/// The channel with the added signals and a random walk's smoothed level subtracted; `any` says
/// whether anything was.
std::vector<double> withoutAddedEffects(const Record& record, int channel,
                                        const std::vector<const Candidate*>& set,
                                        const AllanSolution& sol, bool& any) {
  std::vector<double> x = channelData(record, channel);
  any = false;
  for (std::size_t j = 0; j < set.size(); ++j) {
    if (!set[j]->signal.empty()) {
      for (std::size_t k = 0; k < x.size(); ++k) x[k] -= set[j]->signal[k];
      any = true;
    } else if (set[j]->effect == "random_walk" && sol.theta[j] > 0) {
      double m = 0, v = 0;
      for (double xv : x) m += xv;
      m /= double(x.size());
      for (double xv : x) v += (xv - m) * (xv - m);
      v /= double(x.size());
      const auto level = fit::localLevelSmoother(x, sol.theta[j] / record.rate_hz, v);
      for (std::size_t k = 0; k < x.size(); ++k) x[k] -= level[k];
      any = true;
    }
  }
  return x;
}

/// Biased autocovariance of y - mean(y) at lags 0..order.
std::vector<double> centredAutocovariance(const std::vector<double>& y, std::size_t order) {
  double m = 0;
  for (double v : y) m += v;
  m /= double(y.size());
  std::vector<double> x(y.size());
  for (std::size_t k = 0; k < y.size(); ++k) x[k] = y[k] - m;
  return fit::biasedAutocovariance(x, order);
}

/// Yule-Walker on the autocovariance r; false when it fails or is not stable.
bool yuleWalker(const std::vector<double>& r, std::size_t order, std::size_t n,
                std::vector<double>& a, double& E) {
  try {
    const auto f = fit::yuleWalkerFromAutocovariance(r, order, n);
    if (!(f.drivingVariance > 0) || fit::arMaxPoleMagnitude(f.a) >= 1) return false;
    a = f.a;
    E = f.drivingVariance;
    return true;
  } catch (const Error&) {
    return false;
  }
}

/// Base AR with a lattice quantization taken out of its autocovariance: Yule-Walker on
/// r_y(k) - r_q(k), r_q the rounding noise's autocovariance [SI^2]: per-sample rounding
/// r_q(0) = the candidate's roundingVar (q^2/12 on a fine lattice); carried remainder (rate error
/// (d_{k-1} - d_k)/dt, d uniform) r_q(0) = q^2/6, r_q(1) = -q^2/12 (q the rate LSB). Returns
/// a = [1, a1..ap] and the driving variance.
bool arWithoutQuantization(const std::vector<double>& y, std::size_t order, const Candidate& c,
                           std::vector<double>& a, double& E) {
  const double q = c.lsbRate;
  const bool carry = c.carry;
  auto r = centredAutocovariance(y, order);
  r[0] -= carry ? q * q / 6 : c.roundingVar;
  if (carry && r.size() > 1) r[1] += q * q / 12;
  if (!(r[0] > 0)) return false;
  return yuleWalker(r, order, y.size(), a, E);
}

/// The Allan chi-square of `set` (sizes started at theta, refitted) beside the AR a = [1, a1..ap]
/// with driving variance E as the base, at its stated level.
double chi2BesideAr(const ChannelWork& w, const std::vector<double>& a, double E,
                    const std::vector<const Candidate*>& set, const std::vector<double>& theta) {
  const auto av = fit::arAllanVariance(a, E, w.factors);
  AllanProblem p = w.prob;
  for (std::size_t k = 0; k < av.size(); ++k) p.mu[k] = av[k];
  return solveAllan(p, set, theta, true).chi2;
}

/// A refitted AR: a = [1, a1..ap] and its driving variance E (a empty: none).
struct ArFit {
  std::vector<double> a;
  double E = 0.0;
};

/// The lattice candidate of set replaced by the variant whose refitted AR fits the Allan curve
/// best; false when none refits.
bool refitWithoutQuantization(const ChannelWork& w, const std::vector<double>& x, std::size_t order,
                              std::vector<const Candidate*>& set, const AllanSolution& sol,
                              ArFit& out) {
  const Candidate* lat = nullptr;
  for (auto* c : set)
    if (c->lsbRate > 0) lat = c;
  if (!lat) return false;
  double bestChi = INFINITY;
  const Candidate* bestC = nullptr;
  for (const auto& c : w.cands) {
    if (!(c.lsbRate > 0)) continue;
    ArFit f;
    if (!arWithoutQuantization(x, order, c, f.a, f.E)) continue;
    std::vector<const Candidate*> s2;
    for (auto* c2 : set) s2.push_back(c2 == lat ? &c : c2);
    const double chi2 = chi2BesideAr(w, f.a, f.E, s2, sol.theta);
    if (chi2 < bestChi) bestChi = chi2, out = f, bestC = &c;
  }
  if (!bestC) return false;
  std::replace(set.begin(), set.end(), lat, bestC);
  return true;
}

/// Yule-Walker on the record's autocovariance minus the added terms' (theta_j acov_j); false when
/// no added term has one or the fit fails.
bool refitWithoutAutocovariance(const std::vector<double>& x, std::size_t order,
                                const std::vector<const Candidate*>& set, const AllanSolution& sol,
                                ArFit& out) {
  std::vector<double> rSub;
  for (std::size_t j = 0; j < set.size(); ++j)
    if (set[j]->acov && sol.theta[j] > 0) {
      const auto r = set[j]->acov(order);
      rSub.resize(order + 1, 0.0);
      for (std::size_t k = 0; k <= order; ++k) rSub[k] += sol.theta[j] * r[k];
    }
  if (rSub.empty()) return false;
  auto r = centredAutocovariance(x, order);
  for (std::size_t k = 0; k <= order; ++k) r[k] -= rSub[k];
  return yuleWalker(r, order, x.size(), out.a, out.E);
}

}  // namespace

std::vector<double> refitBaseAr(const ChannelWork& w, const Record& record, std::size_t order,
                                std::vector<const Candidate*>& set, AllanSolution& sol) {
  bool any = false;
  const std::vector<double> x = withoutAddedEffects(record, w.channel, set, sol, any);
  const auto given = set;
  ArFit f;
  if (!refitWithoutQuantization(w, x, order, set, sol, f) &&
      !refitWithoutAutocovariance(x, order, set, sol, f) && any) {
    const auto refit = fit::burg(x, order);
    f = {refit.a, refit.drivingVariance};
  }
  if (f.a.empty() || !(chi2BesideAr(w, f.a, f.E, set, sol.theta) < sol.chi2)) {
    set = given;
    return {};
  }
  sol.s = 1.0;
  std::vector<double> out(f.a.begin() + 1, f.a.end());  // [a1..ap, sqrt(E)]
  out.push_back(std::sqrt(f.E));
  return out;
}

}  // namespace sinsim::errormodels::diagnose::detail
