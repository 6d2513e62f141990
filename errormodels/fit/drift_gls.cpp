#include "errormodels/fit/drift_gls.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/error.hpp"
#include "errormodels/fit/block_likelihood.hpp"

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
  try {
    gls = blockLikelihood(blockMeans(x, fit.sampleInterval, B), others);
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
}

}  // namespace sinsim::errormodels::fit
