#include "errormodels/fit/drift_gls.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/error.hpp"
#include "common/limits.hpp"
#include "errormodels/fit/block_likelihood.hpp"
#include "errormodels/fit/golden_section.hpp"

namespace sinsim::errormodels::fit {

namespace {

/// A parameter's value R, 1-sigma sd and its ln-space interval to first order (sd / R each side).
template <class P>
void setSize(P& p, double R, double sd) {
  p.value = R, p.stdError = sd;
  p.logScale = true;
  p.logCenter = std::log(R), p.logLower = p.logUpper = sd / R;
}

/// The "drift" rows of fit.parameters and fit.averaged (its weight of inclusion kept: the Allan
/// scores' statement on whether a drift is there; added with weight 0 where none held one), and
/// its log-space variance Var ln(R^2) = (2 sd / R)^2, its covariance with the other parameters 0
/// (the slope is estimated given them).
void setDrift(LatentFit& fit, double R, double sd) {
  for (std::size_t k = 0; k < fit.parameters.size(); ++k) {
    LatentParameter& p = fit.parameters[k];
    if (p.name != "drift") continue;
    setSize(p, R, sd);
    p.gmConventionShift = p.flickerConventionShift = 0.0;
    const auto i = Eigen::Index(k);
    if (i < fit.logCovariance.rows() && i < fit.logCovariance.cols()) {
      fit.logCovariance.row(i).setZero();
      fit.logCovariance.col(i).setZero();
      fit.logCovariance(i, i) = (2.0 * sd / R) * (2.0 * sd / R);
    }
  }
  bool averaged = false;
  for (LatentAveragedParameter& a : fit.averaged)
    if (a.name == "drift") setSize(a, R, sd), averaged = true;
  // Added from the trend alone: no set of the Allan scores held a drift, its weight there is 0.
  if (!averaged && !fit.averaged.empty()) {
    fit.averaged.push_back({"drift", 0.0, 0.0, 0.0});
    setSize(fit.averaged.back(), R, sd);
  }
}

/// The drift's warning where a walk explains its trend nearly as well (driftWalkAlternative).
std::string walkWarning(const DriftWalkAlternative& w) {
  return "drift: a random walk explains the record's trend nearly as well (-2 log L " + limits::fmt(w.gap, 3) +
         " above the ramp's, within the ramp's own cost " + limits::fmt(kDriftSlopeChi2, 3) + "; the walk's K " +
         limits::fmt(w.K, 4) + " (SI), in the file's unit in its drift comment): a ramp is the same in every "
         "Monte Carlo run of this model, a walk's trend differs from run to run; if this sensor's trend does not "
         "repeat, write the walk in place of the ramp";
}

/// The drift term added to a fit whose Allan fit held none (LatentFit::trendDrift): the set, a
/// "drift" parameter row last (logParameters' order) and its row and column in logCovariance.
void addDriftTerm(LatentFit& fit) {
  fit.terms.drift = true;
  fit.parameters.push_back({"drift", 0.0, 0.0});
  const Eigen::Index n = fit.logCovariance.rows();
  Eigen::MatrixXd c = Eigen::MatrixXd::Zero(n + 1, n + 1);
  c.topLeftCorner(n, n) = fit.logCovariance;
  fit.logCovariance = c;
}

}  // namespace

void driftFromTrend(LatentFit& fit, const std::vector<double>& x, bool slopeTest) {
  const bool test = slopeTest && !fit.terms.drift && !fit.trendDrift;
  bool add = fit.trendDrift && !fit.terms.drift;
  fit.trendDrift = false;
  if (!(fit.terms.drift || add || test) || fit.terms.ar || fit.m.empty()) return;
  const std::size_t B = blockSize(x.size(), fit.m.front());
  if (x.size() / B < kMinBlocks) return;
  LatentModel others = fit.model;
  others.drift = 0.0;
  BlockLikelihood gls;
  BlockMeans means;
  try {
    means = blockMeans(x, fit.sampleInterval, B);
    gls = blockLikelihood(means, others);
  } catch (const Error&) {
    return;
  }
  const double R = std::fabs(gls.slope), sd = std::sqrt(gls.slopeVariance);
  if (!(std::isfinite(R) && R > 0.0 && std::isfinite(sd) && sd > 0.0)) return;
  if (test) {  // the block choice's S against S + drift: slope^2 / variance beyond the chi^2_1 1 % point
    if (!(R * R > kDriftSlopeChi2 * gls.slopeVariance)) return;
    add = true;
  }
  if (add) addDriftTerm(fit), fit.trendDrift = true;
  fit.driftSlope = gls.slope;
  fit.model.drift = R;
  setDrift(fit, R, sd);
  fit.modelAvar = latentAllanVariance(fit.model, fit.sampleInterval, fit.m);
  // The fit's sanity warning on the drift was the Allan fit's: restated for the trend's.
  const std::string stale = uncertaintyWarningLead("drift");
  fit.warnings.erase(std::remove_if(fit.warnings.begin(), fit.warnings.end(),
                                    [&](const std::string& w) { return w.rfind(stale, 0) == 0; }),
                     fit.warnings.end());
  if (sd > R) fit.warnings.push_back(uncertaintyWarning(fit.parameter("drift")));
  try {
    const DriftWalkAlternative walk = driftWalkAlternative(means, others, gls, R);
    fit.driftWalkGap = walk.gap, fit.driftWalkK = walk.K;
    if (walk.gap < kDriftSlopeChi2) fit.warnings.push_back(walkWarning(walk));
  } catch (const Error&) {
  }
}

DriftWalkAlternative driftWalkAlternative(const BlockMeans& means, const LatentModel& others,
                                          const BlockLikelihood& scored, double R) {
  const double T = means.dt * double(means.perBlock * means.y.size());
  const double K0 = R * std::sqrt(T);
  const double lo = others.randomWalk > 0.0 ? others.randomWalk : K0 / 1000.0;
  const double hi = std::max(100.0 * K0, 10.0 * lo);
  auto at = [&](double u) {
    LatentModel m = others;
    m.randomWalk = std::exp(u);
    return std::make_pair(m.randomWalk, blockLikelihood(means, m).m2LogLik);
  };
  const auto best = goldenSectionLog(lo, hi, 48, at, [](const auto& f) { return f.second; });
  // The set's own walk (or none) is one end of the range: never worse than what the set had.
  if (scored.m2LogLik <= best.second) return {scored.m2LogLik - scored.m2LogLikDrift, others.randomWalk};
  return {best.second - scored.m2LogLikDrift, best.first};
}

}  // namespace sinsim::errormodels::fit
