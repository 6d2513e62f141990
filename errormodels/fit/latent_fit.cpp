#include "errormodels/fit/latent_fit.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <optional>

#include "common/constants.hpp"
#include "common/error.hpp"
#include "common/number_text.hpp"
#include "common/progress.hpp"
#include "errormodels/fit/allan_fit.hpp"
#include "errormodels/fit/ar_fit.hpp"
#include "errormodels/fit/block_likelihood.hpp"
#include "errormodels/fit/drift_gls.hpp"
#include "errormodels/fit/golden_section.hpp"
#include "errormodels/fit/nnls.hpp"
#include "errormodels/fit/whittle_selection.hpp"
#include "errormodels/stats/allan.hpp"
#include "errormodels/stats/special.hpp"

namespace sinsim::errormodels::fit {

std::size_t LatentTermSet::parameterCount() const {
  return std::size_t(quantization) + std::size_t(white) + 2 * std::size_t(gm) + std::size_t(flicker) +
         std::size_t(randomWalk) + std::size_t(drift) + std::size_t(ar);
}

std::size_t LatentTermSet::termCount() const {
  return std::size_t(quantization) + std::size_t(white) + std::size_t(gm) + std::size_t(flicker) +
         std::size_t(randomWalk) + std::size_t(drift) + std::size_t(ar);
}

std::string LatentTermSet::name() const {
  LatentModel m;
  m.quantization = quantization, m.white = white, m.flicker = flicker;
  m.randomWalk = randomWalk, m.drift = drift, m.arVariance = ar;
  m.gm.resize(static_cast<std::size_t>(gm));
  return m.termNames();
}

bool LatentTermSet::operator==(const LatentTermSet& o) const {
  return quantization == o.quantization && white == o.white && gm == o.gm && flicker == o.flicker &&
         randomWalk == o.randomWalk && drift == o.drift && ar == o.ar;
}

std::vector<LatentTermSet> latentCandidateSets(bool quantization, int maxGm, bool flicker,
                                               bool randomWalk, bool drift) {
  std::vector<LatentTermSet> out;
  for (int q = 0; q <= int(quantization); ++q)
    for (int g = 0; g <= std::clamp(maxGm, 0, 2); ++g)
      for (int b = 0; b <= int(flicker); ++b)
        for (int k = 0; k <= int(randomWalk); ++k)
          for (int r = 0; r <= int(drift); ++r) out.push_back({q == 1, true, g, b == 1, k == 1, r == 1});
  return out;
}

double latentPenalty(const LatentTermSet& set, const LatentFitOptions& options) {
  return options.penaltyPerTerm * double(set.termCount()) +
         options.penaltyPerParameter * double(set.parameterCount());
}

namespace {
template <class P>
bool insideInterval(const P& p, double truth, double k) {
  if (std::fabs(truth - p.value) <= k * p.stdError) return true;
  if (!(p.logScale && truth > 0.0)) return false;
  const double d = std::log(truth) - p.logCenter;
  return d >= -k * p.logLower && d <= k * p.logUpper;
}
}  // namespace

bool LatentParameter::covers(double truth, double k) const { return insideInterval(*this, truth, k); }

bool LatentAveragedParameter::covers(double truth, double k) const { return insideInterval(*this, truth, k); }

const LatentParameter& LatentFit::parameter(const std::string& name) const {
  for (const auto& p : parameters)
    if (p.name == name) return p;
  throw InputError("latent fit has no parameter \"" + name + "\" (model: " + terms.name() + ")");
}

bool offBelowStart(const LatentFit& fit) {
  return std::fabs(std::log(fit.belowStartRatio)) > std::log(kBelowStartTolerance);
}

std::string uncertaintyWarningLead(const std::string& name) { return name + ": 1-sigma uncertainty "; }

std::string uncertaintyWarning(const LatentParameter& p) {
  return uncertaintyWarningLead(p.name) + significant(p.stdError, 4) + " exceeds the value " + significant(p.value, 4);
}

double worstAdevLogRatio(const LatentFit& fit) {
  double worst = std::fabs(std::log(fit.belowStartRatio));
  for (std::size_t i = 0; i < fit.avar.size() && i < fit.modelAvar.size(); ++i)
    if (fit.avar[i] > 0.0 && fit.modelAvar[i] > 0.0)
      worst = std::max(worst, 0.5 * std::fabs(std::log(fit.modelAvar[i] / fit.avar[i])));
  return worst;
}

double worstAllanZ(const LatentModel& model, const LatentAllanPoints& record, std::size_t samples, double dt) {
  const std::vector<double> predicted = latentAllanVariance(model, dt, record.m);
  double worst = 0.0;
  for (std::size_t i = 0; i < record.m.size(); ++i) {
    if (!(record.avar[i] > 0.0 && predicted[i] > 0.0)) continue;
    const double edf = greenhallEdf(0, 2, double(record.m[i]), double(samples) + 1.0, true, false);
    worst = std::max(worst, std::fabs(std::log(predicted[i] / record.avar[i])) / std::sqrt(2.0 / edf));
  }
  return worst;
}

const LatentCandidate* LatentFit::runnerUp() const {
  int seen = 0;
  for (const auto& c : candidates)
    if (c.valid && ++seen == 2) return &c;
  return nullptr;
}

namespace {

std::string fmt(double v, int digits = 4) {
  return significant(v, digits);
}

/// The Allan points and the current whitening W (Omega^-1 = W' W).
struct Problem {
  std::vector<std::size_t> m;
  std::vector<double> tau;
  Eigen::VectorXd y;  ///< Allan variance [U^2]
  double dt = 0.0;
  std::size_t N = 0;
  double minT = 0.0;  ///< [s] shortest GM tau searched
  Eigen::MatrixXd W;
  /// The five non-GM Allan basis columns at the points (allanColumn), computed once: they do not
  /// depend on the GM taus the search varies.
  std::array<Eigen::VectorXd, kAllanTermCount> basis;
  RoundingLattice lattice;           ///< of the quantization term (LatentFitOptions::lattice)
  /// Where that lattice's rounding is correlated: its estimates' covariance beyond the Gaussian
  /// one at the first roundingExcess.rows() points (latticeExcess), added to every Omega.
  Eigen::MatrixXd roundingExcess;
  bool latticeMotionRead = false;    ///< the lattice's motion read from the record (motionShape)
  std::vector<double> arPolynomial;  ///< of the AR term (LatentFitOptions::arPolynomial)
  Eigen::VectorXd arColumn;          ///< its Allan variance at unit driving variance
  double arVarianceMax = 0.0;        ///< LatentFitOptions::arVarianceMax
  bool gmAveraged = false;           ///< GM terms as averaged samples (GmTerm::averaged)
  /// The flicker column with the flicker sampled at each instant (flickerSampledAllanVariance at
  /// unit B^2), computed once where a candidate set has flicker: the other discretisation of
  /// basis[2] (discretisationShifts).
  Eigen::VectorXd flickerSampledColumn;
};

/// Column of a five-term Allan basis function (index in AllanTermKind order) at the points; the
/// quantization's at unit Q^2 on the problem's lattice where that is active.
Eigen::VectorXd allanColumn(const Problem& p, std::size_t kind) {
  if (kind == 0 && p.lattice.active()) {
    LatentModel unit;
    unit.quantization = 1.0, unit.lattice = p.lattice;
    const std::vector<double> a = latentAllanVariance(unit, p.dt, p.m);
    return Eigen::Map<const Eigen::VectorXd>(a.data(), Eigen::Index(a.size()));
  }
  std::array<double, kAllanTermCount> th{};
  th[kind] = 1.0;
  const std::vector<double> a = allanModelAdev(th, p.tau);
  Eigen::VectorXd c(static_cast<Eigen::Index>(a.size()));
  for (std::size_t i = 0; i < a.size(); ++i) c(Eigen::Index(i)) = a[i] * a[i];
  return c;
}

/// A fit of one term set: the variance coefficients in design order (Q, N, AR, gm..., B, K, R).
struct SetFit {
  LatentTermSet set;
  std::vector<double> T;      ///< GM correlation times [s]
  Eigen::VectorXd theta;      ///< variance coefficients
  double chi2 = std::numeric_limits<double>::infinity();
  bool allPositive = false;
};

/// The design matrix of a set: one column per variance coefficient, in the order Q, N, AR, gm...,
/// B, K, R (parameterCount() - gm columns: a GM's tau is not a column).
Eigen::MatrixXd design(const Problem& p, const LatentTermSet& s, const std::vector<double>& T) {
  const auto n = static_cast<Eigen::Index>(p.m.size());
  Eigen::MatrixXd X(n, static_cast<Eigen::Index>(s.parameterCount() - T.size()));
  Eigen::Index j = 0;
  if (s.quantization) X.col(j++) = p.basis[0];
  if (s.white) X.col(j++) = p.basis[1];
  if (s.ar) X.col(j++) = p.arColumn;
  for (double t : T) {
    const GmTerm unit{1.0, t, p.gmAveraged};
    for (Eigen::Index i = 0; i < n; ++i) X(i, j) = gmAllanVariance(unit, p.dt, p.m[std::size_t(i)]);
    ++j;
  }
  if (s.flicker) X.col(j++) = p.basis[2];
  if (s.randomWalk) X.col(j++) = p.basis[3];
  if (s.drift) X.col(j++) = p.basis[4];
  return X;
}

SetFit solveFixedT(const Problem& p, const LatentTermSet& s, const std::vector<double>& T) {
  const Eigen::MatrixXd X = design(p, s, T);
  NnlsResult r = nnls(p.W * X, p.W * p.y);
  const Eigen::Index ar = Eigen::Index(s.quantization) + Eigen::Index(s.white);
  if (s.ar && p.arVarianceMax > 0.0 && r.x(ar) > p.arVarianceMax) {
    // The AR's driving variance held at its bound (LatentFitOptions::arVarianceMax), the others
    // refitted: the problem is convex, so its optimum under the bound lies on the bound.
    r.x(ar) = p.arVarianceMax;
    if (X.cols() > 1) {
      Eigen::MatrixXd rest(X.rows(), X.cols() - 1);
      rest << X.leftCols(ar), X.rightCols(X.cols() - ar - 1);
      const NnlsResult o = nnls(p.W * rest, p.W * (p.y - p.arVarianceMax * X.col(ar)));
      r.x << o.x.head(ar), p.arVarianceMax, o.x.tail(o.x.size() - ar);
      r.free << o.free.head(ar), true, o.free.tail(o.free.size() - ar);
    }
  }
  SetFit f;
  f.set = s;
  f.T = T;
  f.theta = r.x;
  f.chi2 = (p.W * (p.y - X * r.x)).squaredNorm();
  f.allPositive = r.free.all();
  return f;
}

/// Golden-section minimum of chi2 over log T_k in [lo, hi] (T_other fixed).
SetFit goldenT(const Problem& p, const LatentTermSet& s, std::vector<double> T, std::size_t k,
               double lo, double hi) {
  auto at = [&](double u) { T[k] = std::exp(u); return solveFixedT(p, s, T); };
  return goldenSectionLog(lo, hi, 28, at, [](const SetFit& f) { return f.chi2; });
}

SetFit fitSet(const Problem& p, const LatentTermSet& s) {
  if (s.gm == 0) return solveFixedT(p, s, {});
  // A GM is identified only when its hump (near 1.9 T) falls inside the fitted tau range; a slower
  // one is a random walk or drift there and would only compete with them (seen: white + GM + RW
  // fitted as two GMs). So T <= the largest tau used.
  const double tLo = p.minT, tHi = std::max(p.tau.back(), 2.0 * p.minT);
  SetFit best;
  if (s.gm == 1) {
    const double step = std::sqrt(2.0);
    for (double t = tLo; t <= tHi; t *= step) {
      SetFit f = solveFixedT(p, s, {t});
      if (f.chi2 < best.chi2) best = f;
    }
    return goldenT(p, s, best.T, 0, std::max(tLo, best.T[0] / step), std::min(tHi, best.T[0] * step));
  }
  for (double t1 = tLo; t1 <= tHi; t1 *= 2.0)
    for (double t2 = 2.0 * t1; t2 <= tHi; t2 *= 2.0) {
      SetFit f = solveFixedT(p, s, {t1, t2});
      if (f.chi2 < best.chi2) best = f;
    }
  // Coordinate-wise golden sections; the two taus trade off along a valley, so several rounds
  // with narrowing brackets (stops when a round improves chi2 by < 1e-10 relative).
  for (int round = 0; round < 12; ++round) {
    const double r = round == 0 ? 2.0 : round == 1 ? std::sqrt(2.0) : 1.2;
    const double before = best.chi2;
    const double t1 = best.T[0], t2 = best.T[1];
    best = goldenT(p, s, best.T, 0, std::max(tLo, t1 / r), std::min(t2 / 1.5, t1 * r));
    best = goldenT(p, s, best.T, 1, std::max(1.5 * best.T[0], t2 / r), std::min(tHi, t2 * r));
    if (round >= 2 && best.chi2 >= before * (1.0 - 1e-10)) break;
  }
  return best;
}

LatentModel modelOf(const Problem& p, const SetFit& f) {
  LatentModel m;
  m.lattice = p.lattice;
  Eigen::Index j = 0;
  auto next = [&]() { return std::sqrt(std::max(f.theta(j++), 0.0)); };
  if (f.set.quantization) m.quantization = next();
  if (f.set.white) m.white = next();
  if (f.set.ar) {
    m.arPolynomial = p.arPolynomial;
    m.arVariance = f.theta(j++);
  }
  for (double t : f.T) m.gm.push_back({next(), t, p.gmAveraged});
  if (f.set.flicker) m.flicker = next();
  if (f.set.randomWalk) m.randomWalk = next();
  if (f.set.drift) m.drift = next();
  return m;
}

/// Diagonal whitening from levels (the Allan variance a point is expected to have): the
/// variance of an estimate with nu EDF is 2 level^2 / nu; nu of white noise (fit::edfOverlappingWhite).
Eigen::MatrixXd diagonalWhitening(const Problem& p, const Eigen::VectorXd& level) {
  Eigen::VectorXd w(level.size());
  for (Eigen::Index i = 0; i < level.size(); ++i) {
    const double nu = edfOverlappingWhite(p.N, p.m[std::size_t(i)]);
    w(i) = std::sqrt(nu / 2.0) / level(i);
  }
  return w.asDiagonal();
}

/// The whitening L^-1 of a covariance C = L L' of the Allan estimates (its correlation's Cholesky
/// factor scaled by the sd), or nothing where C is not positive definite.
std::optional<Eigen::MatrixXd> whiteningOf(const Eigen::MatrixXd& C) {
  const Eigen::VectorXd sd = C.diagonal().cwiseMax(0.0).cwiseSqrt();
  if (!(sd.minCoeff() > 0.0)) return std::nullopt;
  const Eigen::MatrixXd R = correlationOfCovariance(C);
  const Eigen::MatrixXd Cp = sd.asDiagonal() * R * sd.asDiagonal();
  Eigen::LLT<Eigen::MatrixXd> llt(Cp);
  if (llt.info() != Eigen::Success) return std::nullopt;
  const auto n = C.rows();
  return Eigen::MatrixXd(llt.matrixL().solve(Eigen::MatrixXd::Identity(n, n)));
}

/// Whitening from the covariance of the Allan estimates under `model` (GLS), with the lattice
/// rounding's non-Gaussian excess where there is one. The excess (Monte Carlo of the lattice's
/// motion rounded, minus its Gaussian covariance: latticeExcess) can be negative; beside a model
/// whose variance at those points is below the record's (a trial set without the terms the
/// rounding needs), the sum is then no covariance — a record with 98 % of its samples on one
/// level (the diagnosis challenge's quantization of 5 sd) failed every fit with "zero modelled
/// Allan variance". That model is whitened without the excess.
Eigen::MatrixXd modelWhitening(const Problem& p, const LatentModel& model) {
  const LatentSpectrum psd(model, p.dt);
  const Eigen::MatrixXd C = allanEstimateCovariance([&](double w, double s) { return psd(w, s); }, p.m, p.N);
  const Eigen::Index k = p.roundingExcess.rows();
  if (k > 0) {
    Eigen::MatrixXd withExcess = C;
    withExcess.topLeftCorner(k, k) += p.roundingExcess;
    if (auto W = whiteningOf(withExcess)) return *W;
  }
  if (auto W = whiteningOf(C)) return *W;
  throw NumericalError("latent fit: the covariance of the Allan points is not positive definite (a zero modelled "
                       "Allan variance)");
}

Eigen::VectorXd modelLevels(const Problem& p, const LatentModel& m) {
  const std::vector<double> v = latentAllanVariance(m, p.dt, p.m);
  Eigen::VectorXd l(static_cast<Eigen::Index>(v.size()));
  for (std::size_t i = 0; i < v.size(); ++i) l(Eigen::Index(i)) = v[i] > 0.0 ? v[i] : p.y(Eigen::Index(i));
  return l;
}


/// The motion s read from the record's Allan variance at tau = dt (fitOnLattice) carries that
/// estimate's error (variance var1) into the rounding's shape at every correlated point: J = d
/// AVAR_e(m) / ds x sd(s), sd(s) = sqrt(var1) / |d AVAR(1) / ds| (AVAR(1) = s^2 / dt^2 +
/// AVAR_e(1)); J J' is its covariance, the white noise's part being free in the fit.
Eigen::VectorXd motionShape(const Problem& p, const std::vector<std::size_t>& m, double var1) {
  const double s = p.lattice.motion, h = 1e-3 * s;
  RoundingLattice up = p.lattice, down = p.lattice;
  up.motion = s + h, down.motion = s - h;
  auto slope = [&](std::size_t f) {
    return (latticeQuantizationAllanVariance(up, p.dt, f) - latticeQuantizationAllanVariance(down, p.dt, f)) / (2.0 * h);
  };
  const double sdS = std::sqrt(std::max(var1, 0.0)) / std::fabs(2.0 * s / (p.dt * p.dt) + slope(1));
  Eigen::VectorXd J(static_cast<Eigen::Index>(m.size()));
  for (std::size_t i = 0; i < m.size(); ++i) J(Eigen::Index(i)) = slope(m[i]) * sdS;
  return J;
}

/// The covariance the lattice rounding adds beyond the Gaussian (Isserlis) one at the points where
/// it is correlated (exp(-2 pi^2 m s^2 / D^2) > 1e-3, m <= 2^18 / 10): Monte Carlo of white
/// increments of the lattice's motion rounded on it (latticeAllanCovariance, 160 records: with
/// fewer the small eigenvalues of that correlated block come out low) minus the Gaussian
/// covariance of the same PSD (the model white + the lattice's own quantization); plus the
/// motion's estimation error (motionShape) where the motion was read from the record.
Eigen::MatrixXd latticeExcess(const Problem& p) {
  const double r = p.lattice.motion / p.lattice.step;
  std::vector<std::size_t> m;  // a prefix of p.m: the condition falls with m
  for (std::size_t f : p.m) {
    if (!(std::exp(-2.0 * kPi * kPi * double(f) * r * r) > 1e-3) || f * 10 > (std::size_t(1) << 18)) break;
    m.push_back(f);
  }
  if (m.empty()) return {};
  LatentModel q;
  q.white = p.lattice.motion / std::sqrt(p.dt);
  q.quantization = p.lattice.step / std::sqrt(12.0);
  q.lattice = p.lattice;
  const LatentSpectrum psd(q, p.dt);
  const Eigen::MatrixXd gauss = allanEstimateCovariance([&](double w, double s) { return psd(w, s); }, m, p.N);
  const Eigen::MatrixXd mc = latticeAllanCovariance(p.lattice, p.dt, p.N, m, 160, 0x1a77ce);
  Eigen::MatrixXd excess = mc - gauss;
  if (p.latticeMotionRead && m.front() == 1) {
    const Eigen::VectorXd J = motionShape(p, m, mc(0, 0));
    excess += J * J.transpose();
  }
  return excess;
}

/// Best valid set under the current p.W (every set fitted); all fits returned, best first.
std::vector<LatentCandidate> scoreAll(const Problem& p, const std::vector<LatentTermSet>& sets,
                                      const LatentFitOptions& penalty, std::vector<SetFit>* fits) {
  std::vector<LatentCandidate> out;
  for (const auto& s : sets) {
    if (s.parameterCount() + 1 > p.m.size()) continue;  // needs dof >= 1
    SetFit f = fitSet(p, s);
    LatentCandidate c;
    c.terms = s;
    c.model = modelOf(p, f);
    c.chi2 = f.chi2;
    c.score = f.chi2 + latentPenalty(s, penalty);
    c.valid = f.allPositive && std::isfinite(f.chi2);
    out.push_back(c);
    if (fits) fits->push_back(f);
  }
  std::vector<std::size_t> idx(out.size());
  for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = i;
  std::stable_sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) {
    if (out[a].valid != out[b].valid) return out[a].valid;
    return out[a].score < out[b].score;
  });
  std::vector<LatentCandidate> sorted;
  std::vector<SetFit> sortedFits;
  for (std::size_t i : idx) {
    sorted.push_back(out[i]);
    if (fits) sortedFits.push_back((*fits)[i]);
  }
  if (fits) *fits = sortedFits;
  return sorted;
}

/// Pass 1: each set with diagonal weights from its own model levels (two reweightings).
LatentModel preliminaryModel(Problem p, const std::vector<LatentTermSet>& sets, const LatentFitOptions& penalty) {
  const Eigen::MatrixXd W0 = diagonalWhitening(p, p.y);
  std::optional<LatentCandidate> best;
  for (const auto& s : sets) {
    if (s.parameterCount() + 1 > p.m.size()) continue;
    p.W = W0;
    SetFit f = fitSet(p, s);
    for (int it = 0; it < 2 && f.allPositive; ++it) {
      p.W = diagonalWhitening(p, modelLevels(p, modelOf(p, f)));
      f = fitSet(p, s);
    }
    if (!f.allPositive) continue;
    const double score = f.chi2 + latentPenalty(s, penalty);
    if (!best || score < best->score) {
      best = LatentCandidate{};
      best->terms = s, best->model = modelOf(p, f), best->chi2 = f.chi2, best->score = score, best->valid = true;
    }
  }
  if (!best) throw NumericalError("latent fit: no candidate set has all its terms positive");
  return best->model;
}

/// The profile-likelihood 1-sigma bounds of GM g's ln T in the fit f (LatentParameter::logLower,
/// logUpper): the distances below and above ln T_g at which the chi^2 minimised over every other
/// parameter (the variances by NNLS, the other GM's T by golden section within a factor 4 of its
/// fit, T2 >= 1.5 T1 kept) exceeds its value at f's T by `target` (the Birge scale: Delta chi^2 = 1 for one
/// parameter, Wilks; scaled as the Gauss-Newton covariance is). Found by doubling from `step`
/// (the delta method's sd), then bisection; a side that stays below the target within e^8 says so
/// with 8 (the data bound T only on the other side).
std::pair<double, double> profileLogTauBounds(const Problem& p, const SetFit& f, std::size_t g, double target,
                                              double step) {
  constexpr double kFar = 8.0;
  const double u0 = std::log(f.T[g]);
  auto profile = [&](double u) {
    std::vector<double> T = f.T;
    T[g] = std::exp(u);
    if (T.size() == 1) return solveFixedT(p, f.set, T).chi2;
    const std::size_t o = 1 - g;
    double lo = f.T[o] / 4.0, hi = f.T[o] * 4.0;
    if (o == 1) lo = std::max(lo, 1.5 * T[0]);
    else hi = std::min(hi, T[1] / 1.5);
    if (!(hi > lo * 1.001)) return std::numeric_limits<double>::infinity();
    return goldenSectionLog(lo, hi, 20, [&](double v) { T[o] = std::exp(v); return solveFixedT(p, f.set, T); },
                            [](const SetFit& s) { return s.chi2; }).chi2;
  };
  // The baseline under p's weights (the averaging states a set's 1-sigma under its own Omega, not
  // the one it was fitted under).
  const double base = profile(u0);
  auto rise = [&](double u) { return profile(u) - base; };
  auto side = [&](double dir) {
    double inner = 0.0, outer = std::clamp(step, 0.01, 1.0);
    while (!(rise(u0 + dir * outer) >= target)) {
      inner = outer, outer *= 2.0;
      if (outer > kFar) return kFar;
    }
    for (int k = 0; k < 12; ++k) {
      const double mid = 0.5 * (inner + outer);
      (rise(u0 + dir * mid) >= target ? outer : inner) = mid;
    }
    return 0.5 * (inner + outer);
  };
  return {side(-1.0), side(1.0)};
}

/// The parameters of a set's fit with their 1-sigma: p = log of every variance coefficient and
/// T_j, covariance (J' W' W J)^-1 of p (Gauss-Newton at the optimum, J by central differences in
/// p: the model is smooth and p is log scale) scaled by the Birge ratio max(1, chi2 / dof).
struct ParameterTable {
  std::vector<LatentParameter> parameters;
  Eigen::MatrixXd logCovariance;
  double birgeScale = 1.0;
};

/// A set fit's parameters by name: p = ln of a variance coefficient (amplitude) or of a GM's T.
struct LogParameter {
  std::string name;
  double p;
  bool amplitude;
  double value() const { return amplitude ? std::exp(0.5 * p) : std::exp(p); }
};

std::vector<LogParameter> logParameters(const SetFit& f) {
  std::vector<LogParameter> pars;
  Eigen::Index j = 0;
  auto var = [&](const std::string& name) { pars.push_back({name, std::log(f.theta(j++)), true}); };
  if (f.set.quantization) var("quantization");
  if (f.set.white) var("white");
  if (f.set.ar) var("ar.sigma");
  for (std::size_t g = 0; g < f.T.size(); ++g) {
    const std::string gn = "gm" + std::to_string(g + 1);
    var(gn + ".sigma");
    pars.push_back({gn + ".tau", std::log(f.T[g]), false});
  }
  if (f.set.flicker) var("flicker");
  if (f.set.randomWalk) var("random_walk");
  if (f.set.drift) var("drift");
  return pars;
}

ParameterTable parameterTable(const Problem& p, const SetFit& f) {
  using Par = LogParameter;
  const std::vector<Par> pars = logParameters(f);

  auto modelAt = [&](const std::vector<double>& pv) {
    std::vector<double> T;
    Eigen::VectorXd th(f.theta.size());
    Eigen::Index k = 0;
    for (std::size_t i = 0; i < pars.size(); ++i) {
      if (pars[i].amplitude) th(k++) = std::exp(pv[i]);
      else T.push_back(std::exp(pv[i]));
    }
    return Eigen::VectorXd(design(p, f.set, T) * th);
  };
  std::vector<double> p0;
  for (const auto& q : pars) p0.push_back(q.p);
  const auto n = static_cast<Eigen::Index>(p.m.size()), k = static_cast<Eigen::Index>(pars.size());
  Eigen::MatrixXd J(n, k);
  for (Eigen::Index c = 0; c < k; ++c) {
    std::vector<double> a = p0, b = p0;
    const double h = 1e-5;
    a[std::size_t(c)] += h, b[std::size_t(c)] -= h;
    J.col(c) = (modelAt(a) - modelAt(b)) / (2.0 * h);
  }
  const Eigen::MatrixXd Jw = p.W * J;
  ParameterTable t;
  const std::size_t dof = p.m.size() - f.set.parameterCount();
  t.birgeScale = dof > 0 ? std::max(1.0, f.chi2 / double(dof)) : 1.0;
  t.logCovariance = (Jw.transpose() * Jw).ldlt().solve(Eigen::MatrixXd::Identity(k, k)) * t.birgeScale;
  std::size_t g = 0;  // GM index of the next tau
  for (Eigen::Index c = 0; c < k; ++c) {
    const Par& q = pars[std::size_t(c)];
    const double sdp = std::sqrt(std::max(t.logCovariance(c, c), 0.0));
    const double value = q.value();
    t.parameters.push_back({q.name, value, q.amplitude ? 0.5 * value * sdp : value * sdp});
    LatentParameter& par = t.parameters.back();
    par.logScale = true;
    if (q.amplitude) {  // ln amplitude = p / 2: the covariance's own space, symmetric there
      par.logCenter = 0.5 * q.p, par.logLower = par.logUpper = 0.5 * sdp;
    } else {
      const auto [lower, upper] = profileLogTauBounds(p, f, g++, t.birgeScale, sdp);
      par.logCenter = q.p, par.logLower = lower, par.logUpper = upper;
    }
  }
  return t;
}

/// The set `best` (fitted under p.W) refitted under the same whitening with one term in its other
/// discretisation: its GMs averaged over each interval (`gm`) or its flicker sampled (else); each
/// parameter's change, 0 where the set lacks that term (LatentParameter::gmConventionShift,
/// flickerConventionShift).
std::vector<double> discretisationShifts(const Problem& p, const SetFit& best, const std::vector<LatentParameter>& parameters,
                                         bool gm) {
  std::vector<double> shift(parameters.size(), 0.0);
  if (gm ? best.set.gm == 0 : !best.set.flicker) return shift;
  Problem q = p;
  if (gm) q.gmAveraged = true;
  else q.basis[2] = p.flickerSampledColumn;
  const std::vector<LogParameter> other = logParameters(fitSet(q, best.set));
  for (std::size_t k = 0; k < parameters.size(); ++k)
    for (const LogParameter& a : other)
      if (a.name == parameters[k].name && std::isfinite(a.p) && parameters[k].value > 0.0)
        shift[k] = a.value() - parameters[k].value;
  return shift;
}

/// The record cannot tell a GM sampled from one averaged over each interval, nor a flicker
/// averaged from one sampled (latent_fit.hpp, LatentParameter::gmConventionShift): each
/// parameter's change under the other discretisation widens its 1-sigma and its ln interval, in
/// quadrature.
void includeDiscretisation(const Problem& p, const SetFit& best, std::vector<LatentParameter>& parameters) {
  const std::vector<double> gm = discretisationShifts(p, best, parameters, true);
  const std::vector<double> flicker = discretisationShifts(p, best, parameters, false);
  for (std::size_t k = 0; k < parameters.size(); ++k) {
    LatentParameter& par = parameters[k];
    par.gmConventionShift = gm[k], par.flickerConventionShift = flicker[k];
    const double shift = std::hypot(gm[k], flicker[k]);
    if (!(shift > 0.0)) continue;
    par.stdError = std::hypot(par.stdError, shift);
    // In ln the change is ln(v_other / v) (v_other = v + shift > 0), not shift / v: a tau the
    // other convention moves 100-fold (a GM the record hardly bounds) is ln 100 = 4.6 wider in ln,
    // where the first-order shift / v = 99 had stated a 1-sigma interval of e^-99..e^99 times it.
    const double dl = std::hypot(std::log1p(gm[k] / par.value), std::log1p(flicker[k] / par.value));
    if (std::isfinite(dl)) par.logLower = std::hypot(par.logLower, dl), par.logUpper = std::hypot(par.logUpper, dl);
  }
}

/// Sets further than this above the best score are left out of the averaging: their weight is
/// below exp(-10) = 4.5e-5. (At 40 the six-channel benchmark took 2.2x the CPU of the fit alone:
/// Omega of each set's own model is a quadrature per set.)
constexpr double kAveragedScoreRange = 20.0;

/// Selection-aware parameters (latent_fit.hpp, LatentAveragedParameter) from the fits of every
/// valid set, all scored under the same Omega (comparable weights, p.W from omegaModel); each
/// set's 1-sigma with Omega from its own model. Sets more than kAveragedScoreRange above the best score are skipped.
std::vector<LatentAveragedParameter> averageOverSets(const Problem& p, const std::vector<LatentCandidate>& cands,
                                                     const std::vector<SetFit>& fits, const LatentModel& omegaModel) {
  const std::vector<double> omegaAvar = latentAllanVariance(omegaModel, p.dt, p.m);
  struct Entry { double weight; std::vector<LatentParameter> parameters; };
  std::vector<Entry> entries;
  double total = 0.0;
  for (std::size_t i = 0; i < cands.size(); ++i) {
    const double delta = cands[i].score - cands.front().score;
    if (!cands[i].valid || !(delta <= kAveragedScoreRange)) continue;
    // The set's 1-sigma under its own hypothesis: Omega from its own fitted model. Under the
    // winner's Omega a term the winner lacks (a random walk) adds no variance at long tau, and
    // that term's 1-sigma in the other sets comes out several times too small.
    // (A set whose model Allan variance is within 5 % of Omega's model at every point keeps p.W:
    // Omega is then the same to ~10 %, and the quadrature per set is what costs.)
    Problem own = p;
    const std::vector<double> mine = latentAllanVariance(cands[i].model, p.dt, p.m);
    double worst = 0.0;
    for (std::size_t k = 0; k < mine.size(); ++k) worst = std::max(worst, std::fabs(mine[k] / omegaAvar[k] - 1.0));
    if (!(worst <= 0.05)) own.W = modelWhitening(p, cands[i].model);
    std::vector<LatentParameter> parameters = parameterTable(own, fits[i]).parameters;
    includeDiscretisation(own, fits[i], parameters);
    entries.push_back({std::exp(-0.5 * delta), std::move(parameters)});
    total += entries.back().weight;
  }
  std::vector<std::string> names;
  for (const auto& e : entries)
    for (const auto& q : e.parameters)
      if (std::find(names.begin(), names.end(), q.name) == names.end()) names.push_back(q.name);
  std::vector<LatentAveragedParameter> out;
  for (const auto& name : names) {
    double w = 0.0, mean = 0.0;
    bool logScale = false;
    for (const auto& e : entries)
      for (const auto& q : e.parameters)
        if (q.name == name) w += e.weight, mean += e.weight * q.value, logScale = q.logScale;
    mean /= w;
    double sd = 0.0;  // Buckland, Burnham & Augustin 1997, eq. (9)
    for (const auto& e : entries)
      for (const auto& q : e.parameters)
        if (q.name == name) sd += e.weight / w * std::hypot(q.stdError, q.value - mean);
    LatentAveragedParameter a{name, w / total, mean, sd};
    if (logScale) {  // the ln-space interval, the same formula on ln v, each side
      a.logScale = true;
      for (const auto& e : entries)
        for (const auto& q : e.parameters)
          if (q.name == name) a.logCenter += e.weight / w * q.logCenter;
      for (const auto& e : entries)
        for (const auto& q : e.parameters)
          if (q.name == name) {
            const double d = q.logCenter - a.logCenter;
            a.logLower += e.weight / w * std::hypot(q.logLower, d);
            a.logUpper += e.weight / w * std::hypot(q.logUpper, d);
          }
    }
    out.push_back(a);
  }
  return out;
}

/// Parameters, their log-space covariance and the sanity warnings of the final fit.
void describe(const Problem& p, const SetFit& f, LatentFit& out) {
  const LatentModel& m = out.model;
  ParameterTable t = parameterTable(p, f);
  includeDiscretisation(p, f, t.parameters);
  out.parameters = std::move(t.parameters);
  out.logCovariance = std::move(t.logCovariance);
  out.birgeScale = t.birgeScale;
  const double duration = p.dt * double(p.N);
  const double tLo = p.minT, tHi = std::max(p.tau.back(), 2.0 * p.minT);  // the GM range searched
  for (std::size_t g = 0; g < m.gm.size(); ++g) {
    const double T = m.gm[g].tau;
    // A tau on a bound of its search is a bound, not an estimate (a slow GM pinned at the largest
    // Allan tau held a sigma 6x too small; a white record's GM pinned at the bottom stood in for
    // white noise): said, since the T/3 test below cannot fire past the range's top.
    if (T <= 1.01 * tLo)
      out.warnings.push_back("gm" + std::to_string(g + 1) + ".tau " + fmt(T) + " s sits at the lowest tau searched (" +
                             fmt(tLo) + " s: two sample intervals or half the fitted range's first tau): a bound, not "
                             "an estimate; the record's correlation there is faster than the fit can follow");
    if (T >= 0.99 * tHi)
      out.warnings.push_back("gm" + std::to_string(g + 1) + ".tau " + fmt(T) + " s sits at the highest tau searched (" +
                             fmt(tHi) + " s, the record's largest Allan tau): a bound, not an estimate; a slower "
                             "correlation is not determined by this record and acts as a random walk (--kind latent or "
                             "auto can write one)");
    if (T < 2.0 * p.dt)
      out.warnings.push_back("gm" + std::to_string(g + 1) + ".tau " + fmt(T) + " s is below two sample intervals (" +
                             fmt(2.0 * p.dt) + " s): the GM is indistinguishable from white noise there");
    if (T > duration / 3.0)
      out.warnings.push_back("gm" + std::to_string(g + 1) + ".tau " + fmt(T) + " s is above a third of the record (" +
                             fmt(duration / 3.0) + " s): poorly determined, it acts as a random walk");
  }
  for (const auto& q : out.parameters)
    if (q.stdError > q.value) out.warnings.push_back(uncertaintyWarning(q));
}


/// firstValid's choice: the index into cands, its i in `order`, and whether the likelihood wanted
/// S + drift where only S's Allan fit is valid (the Allan variance, which sees a ramp through its
/// last octaves alone, put the drift at zero): S chosen, its drift then the record's trend's alone
/// (LatentCandidate::trendDrift, drift_gls.hpp).
struct ValidChoice {
  std::size_t chosen = 0, i = 0;
  bool trendDrift = false;
};

/// In `order` (indices into cands, best first), the first set S, or S + drift where drift(i), whose
/// Allan fit is valid (the other of the two when only it is).
template <class Drift>
std::optional<ValidChoice> firstValid(const std::vector<LatentCandidate>& cands, const std::vector<std::size_t>& order,
                                      Drift drift) {
  auto find = [&](const LatentTermSet& t, bool valid) -> std::optional<std::size_t> {
    for (std::size_t k = 0; k < cands.size(); ++k)
      if (cands[k].terms == t && (cands[k].valid || !valid)) return k;
    return std::nullopt;
  };
  for (std::size_t i : order) {
    LatentTermSet withDrift = cands[i].terms;
    withDrift.drift = true;
    const auto plain = find(cands[i].terms, true), drifted = find(withDrift, true);
    const bool want = drift(i);
    const auto chosen = want ? (drifted ? drifted : plain) : (plain ? plain : drifted);
    if (chosen) return ValidChoice{*chosen, i, want && !drifted && find(withDrift, false).has_value()};
  }
  return std::nullopt;
}

/// cands reordered: the chosen (its trendDrift set, every other's cleared), then `order` without
/// it, then the sets in neither.
std::vector<LatentCandidate> chosenFirst(const std::vector<LatentCandidate>& cands, const ValidChoice& chosen,
                                         const std::vector<std::size_t>& order) {
  std::vector<LatentCandidate> out{cands[chosen.chosen]};
  std::vector<bool> placed(cands.size(), false);
  placed[chosen.chosen] = true;
  for (std::size_t i : order)
    if (!placed[i]) out.push_back(cands[i]), placed[i] = true;
  for (std::size_t i = 0; i < cands.size(); ++i)
    if (!placed[i]) out.push_back(cands[i]);
  for (auto& c : out) c.trendDrift = false;
  out.front().trendDrift = chosen.trendDrift;
  return out;
}

/// `order` (indices into cands, best first by `score`) without the sets whose slowest GM the record
/// cannot tell from a random walk. A random walk is the T -> inf limit of a GM (sigma^2 = K^2 T / 2),
/// so a set S with a GM and no walk contains, at the boundary 1/T = 0, the set S' with that GM
/// replaced by the walk: S against S' is one parameter (1/T) at a boundary, and S only says more
/// than S' when its -2 log L is lower by that boundary test's 1 % point, the cost of a
/// one-parameter term (5.41; the additive costs charge the swap only the GM's second parameter,
/// 2.41, which lets a walk pass for a slow GM in ~6 % of records, P(chi^2_1 / 2 > 2.41)). S is then
/// really S', as a set whose fit puts a variance at zero is really a smaller set. S' must be in
/// `order`. One rule for both likelihood choices: `score` is the block or the Whittle score, a
/// -2 log L plus latentPenalty. (Not the Allan choice: its points stop at N dt / 10, where a GM
/// whose hump lies in the last octaves and a walk differ by a point or two; there the rule turned
/// real GMs into walks, docs/fitting-log.md, "The walk-for-GM rule in the Whittle choice too".)
template <class Score>
std::vector<std::size_t> withoutWalkLikeGms(const std::vector<LatentCandidate>& cands,
                                            const std::vector<std::size_t>& order, const LatentFitOptions& penalty,
                                            Score score) {
  const double nested = walkForGmCost(penalty);
  auto raw = [&](std::size_t i) { return score(cands[i]) - latentPenalty(cands[i].terms, penalty); };
  std::vector<std::size_t> out;
  for (std::size_t i : order) {
    const LatentTermSet& t = cands[i].terms;
    bool walkLike = false;
    if (t.gm > 0 && !t.randomWalk) {
      LatentTermSet walk = t;
      walk.gm -= 1;
      walk.randomWalk = true;
      for (std::size_t k : order)
        if (cands[k].terms == walk) walkLike = raw(k) - raw(i) < nested;
    }
    if (!walkLike) out.push_back(i);
  }
  return out;
}

/// The Whittle choice (latent_fit.hpp step 7): every set without drift or AR scored by
/// whittleFitSet from its Allan fit. In Whittle order, the first set S for which S (or S + drift
/// when the removed line's slope b is significant under S's Whittle model: b^2 / v_S > the chi^2_1
/// 1 % point, v_S = whittleSlopeVariance) has a valid Allan fit; the other of the two when only it
/// is valid. Returns cands reordered: the chosen first, then the Whittle-scored sets by Whittle
/// score, then the rest as they were. Unchanged when no set qualifies.
std::vector<LatentCandidate> whittleChoice(const Problem& p, const WhittleBins& bins,
                                           std::vector<LatentCandidate> cands, const LatentFitOptions& penalty) {
  const double wMax = kPi * p.dt / p.tau.front();  // f = 1 / (2 tau) at the first Allan point
  const double tHi = std::max(p.tau.back(), 2.0 * p.minT);  // the Allan fit's GM range
  for (auto& c : cands) {
    if (c.terms.drift || c.terms.ar) continue;
    const WhittleSetFit w = whittleFitSet(bins, wMax, c.terms, c.model, p.minT, tHi);
    if (w.valid) c.whittleScore = w.m2LogLik + latentPenalty(c.terms, penalty);
    c.whittleModel = w.model;
  }
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < cands.size(); ++i)
    if (std::isfinite(cands[i].whittleScore)) order.push_back(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return cands[a].whittleScore < cands[b].whittleScore; });
  order = withoutWalkLikeGms(cands, order, penalty, [](const LatentCandidate& c) { return c.whittleScore; });
  const auto chosen = firstValid(cands, order, [&](std::size_t i) {
    return bins.slope * bins.slope > kDriftSlopeChi2 * whittleSlopeVariance(bins, cands[i].whittleModel);
  });
  return chosen ? chosenFirst(cands, *chosen, order) : cands;
}

/// The block choice (block_likelihood.hpp steps 4-5) over the Whittle-ordered candidates `cands`
/// (whittleChoice's output): the drift-free sets within kBlockScoredRange of the best Whittle
/// score rescored; in block-score order, the first set S (S + drift where that scores lower) with
/// a valid Allan fit. Returns cands reordered (the chosen, the block-scored by score, the rest);
/// unchanged when the record is too short or no set qualifies.
std::vector<LatentCandidate> blockChoice(const Problem& p, const WhittleBins& bins, const std::vector<double>& x,
                                         std::vector<LatentCandidate> cands, const LatentFitOptions& penalty) {
  const std::size_t B = blockSize(x.size(), p.m.front());
  if (x.size() / B < kMinBlocks) return cands;
  const BlockMeans means = blockMeans(x, p.dt, B);
  const double wMax = kPi * p.dt / p.tau.front();
  const double tHi = std::max(p.tau.back(), 2.0 * p.minT);
  double bestWhittle = std::numeric_limits<double>::infinity();
  for (const auto& c : cands)
    if (std::isfinite(c.whittleScore)) bestWhittle = std::min(bestWhittle, c.whittleScore);
  std::vector<bool> drift(cands.size(), false);
  std::vector<std::size_t> order;
  // Quantization is a sample-level term: averaged over a block it is (e_end - e_start) / L, far
  // below the white noise. Where no periodogram bin above the blocks is in the fitted range
  // (B >= 2 m_1: the Allan range starts at the blocks' scale, as on real accelerometers whose
  // short-tau features the start scan skips), the blocks alone would read it as a block-scale
  // MA(1); its presence then stays the Whittle's decision.
  const bool seesQuantization = 2.0 * kPi / double(B) < wMax;
  const bool whittleQuantization = cands.front().terms.quantization;
  for (std::size_t i = 0; i < cands.size(); ++i) {
    auto& c = cands[i];
    if (!(c.whittleScore - bestWhittle <= kBlockScoredRange)) continue;
    if (!seesQuantization && c.terms.quantization != whittleQuantization) continue;
    const BlockSetFit f = blockFitSet(means, &bins, wMax, c.terms, c.whittleModel, p.minT, tHi);
    if (!f.valid) continue;
    // S or S + drift, whichever scores lower (a drift costs the chi^2_1 1 % point).
    c.blockModel = f.model;
    const double plain = f.m2LogLik, drifted = f.m2LogLikDrift + kDriftSlopeChi2;
    drift[i] = drifted < plain;
    c.blockScore = std::min(plain, drifted) + latentPenalty(c.terms, penalty);
    order.push_back(i);
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return cands[a].blockScore < cands[b].blockScore; });
  order = withoutWalkLikeGms(cands, order, penalty, [](const LatentCandidate& c) { return c.blockScore; });
  const auto chosen = firstValid(cands, order, [&](std::size_t i) { return bool(drift[i]); });
  if (!chosen) return cands;
  cands[chosen->chosen].blockScore = cands[chosen->i].blockScore;  // S + drift: S's score
  return chosenFirst(cands, *chosen, order);
}

/// The Allan fit of set s with each GM tau within a factor 2 of the likelihood model's (in their
/// order, 1.5x apart), by coordinate golden sections from the likelihood's taus.
SetFit fitNearTaus(const Problem& q, const LatentTermSet& s, const LatentModel& likelihood) {
  std::vector<double> T0;
  for (const auto& g : likelihood.gm) T0.push_back(g.tau);
  SetFit near = solveFixedT(q, s, T0);
  const double tHi = std::max(q.tau.back(), 2.0 * q.minT);
  for (int round = 0; round < 4; ++round)
    for (std::size_t k = 0; k < near.T.size(); ++k) {
      const double lo = std::max({q.minT, T0[k] / 2.0, k > 0 ? 1.5 * near.T[k - 1] : 0.0});
      const double hi = std::min({tHi, 2.0 * T0[k], k + 1 < near.T.size() ? near.T[k + 1] / 1.5 : tHi});
      if (lo < hi) near = goldenT(q, s, near.T, k, lo, hi);
    }
  return near;
}

/// " (GM tau a s, b s)" of a fit, empty without GMs: the model file's note.
std::string gmTauList(const SetFit& f) {
  std::string t;
  for (double T : f.T) t += (t.empty() ? "GM tau " : ", ") + fmt(T) + " s";
  return t.empty() ? std::string() : " (" + t + ")";
}

/// The chosen set's Allan fit where the block likelihood does not reject it (Estimator,
/// "Parameters the likelihood rejects"). The GLS on the octave Allan points can settle on a
/// parameterisation whose long-tau end lies below every point there (strongly correlated
/// estimates: alt null record 11 of seed 4, white + gm + gm + flicker with both GMs under 0.5 s and
/// the ADEV 2.2x below the record from 5 s up, chi2 22 / 10), while the likelihood's own fit of the
/// same set has its second GM at 17 s. Rejected: -2 log L (blocks + periodogram above them) at the
/// Allan parameters exceeds the likelihood's optimum by more than the chi^2_k 0.1 % point (k the
/// set's parameters: a likelihood-ratio test of the Allan fit as a fixed point). Then the Allan fit
/// under Omega from the likelihood's model, globally and with each GM tau within a factor 2 of the
/// likelihood's, and the one the likelihood prefers is written where the likelihood accepts it.
/// Where it rejects both, the set's terms miss the record's shape (ADIS16405 runs 1 and 2, `--kind
/// gm`: 136-160 above, either fit) and the Allan fit stays. `W` becomes that Omega's whitening.
SetFit likelihoodCheckedFit(Problem& p, const WhittleBins& bins, const std::vector<double>& x,
                            const LatentCandidate& chosen, const SetFit& allan, LatentModel& omegaModel,
                            std::string& note) {
  const LatentTermSet& s = chosen.terms;
  if (s.drift || s.ar || chosen.trendDrift || !std::isfinite(chosen.blockScore) ||
      chosen.blockModel.gm.size() != std::size_t(s.gm))
    return allan;
  const BlockMeans means = blockMeans(x, p.dt, blockSize(x.size(), p.m.front()));
  const BlockObjective objective(means, &bins, kPi * p.dt / p.tau.front(), s.flicker);
  const double optimum = objective(chosen.blockModel, false);
  auto excess = [&](const SetFit& f) { return objective(modelOf(p, f), false) - optimum; };
  const double limit = chiSquareQuantile(0.999, double(s.parameterCount()));
  const double before = excess(allan);
  if (!std::isfinite(optimum) || !(before > limit)) return allan;
  Problem q = p;
  LatentModel omega = chosen.blockModel;
  omega.lattice = p.lattice;
  q.W = modelWhitening(q, omega);
  SetFit best = fitSet(q, s);
  double bestExcess = excess(best);
  const SetFit near = fitNearTaus(q, s, chosen.blockModel);
  if (const double e = excess(near); e < bestExcess) best = near, bestExcess = e;
  if (!(bestExcess <= limit)) return allan;  // the set itself misses the record (ADIS16405's gyros)
  p.W = q.W;
  omegaModel = omega;
  note = "the Allan fit's optimum" + gmTauList(allan) + " is rejected by the block likelihood (-2 log L " +
         fmt(before, 3) + " above its optimum, beyond the chi2_" + std::to_string(s.parameterCount()) +
         " 0.1 % point " + fmt(limit, 3) + "): the Allan fit nearest the likelihood's optimum is written" +
         gmTauList(best) + ", " + fmt(bestExcess, 3) + " above it";
  return best;
}

}  // namespace

namespace {

/// A fit at one start of the tau range, and the work of its selection-aware parameters
/// (LatentFit::averaged), left for the start a scan keeps: with an AR term it is a third of a start's
/// cost, and a scan tries up to a dozen starts.
struct RangeFit {
  LatentFit fit;
  std::function<std::vector<LatentAveragedParameter>()> averaging;
  LatentFit withAveraged() && {
    fit.averaged = averaging();
    return std::move(fit);
  }
};

RangeFit fitRange(const std::vector<std::size_t>& m, const std::vector<double>& avar,
                  std::size_t samples, const LatentFitOptions& options, const WhittleBins* bins,
                  const std::vector<double>* record) {
  const double dt = options.sampleInterval;
  if (!(std::isfinite(dt) && dt > 0.0)) throw InputError("latent fit: sample interval must be > 0");
  if (m.size() != avar.size()) throw InputError("latent fit: m and avar differ in length");
  Problem p;
  p.dt = dt;
  p.N = samples;
  if (!(options.minGmTauSamples > 0.0)) throw InputError("latent fit: minGmTauSamples must be > 0");
  p.minT = options.minGmTauSamples * dt;
  if (options.lattice.active()) p.lattice = options.lattice;
  p.latticeMotionRead = options.latticeMotionRead;
  std::vector<double> y;
  for (std::size_t i = 0; i < m.size(); ++i) {
    if (m[i] < 1 || (i > 0 && m[i] <= m[i - 1]))
      throw InputError("latent fit: averaging factors must be >= 1 and increasing");
    const double tau = double(m[i]) * dt;
    if (10 * m[i] > samples || tau < options.tauMin || tau > options.tauMax) continue;
    if (!(std::isfinite(avar[i]) && avar[i] > 0.0)) continue;
    p.m.push_back(m[i]);
    p.tau.push_back(tau);
    y.push_back(avar[i]);
  }
  p.y = Eigen::Map<Eigen::VectorXd>(y.data(), Eigen::Index(y.size()));
  // A GM much faster than the range's first tau is white noise there, and outside the range
  // (below it, where a scanned start left points out) it would remove the short-tau noise the
  // record has: the 1000-s ADIS16405 windows' accelerometers were written as a GM of tau 0.15 s
  // fitted from 1.28 s up, 13x below the record at 10 ms. The GM is searched from half the first
  // tau up (unchanged on a range from the first point, where that is half a sample).
  if (!p.tau.empty()) p.minT = std::max(p.minT, 0.5 * p.tau.front());
  for (std::size_t kind = 0; kind < kAllanTermCount; ++kind) p.basis[kind] = allanColumn(p, kind);
  if (p.lattice.correlated()) p.roundingExcess = latticeExcess(p);
  const std::vector<LatentTermSet> sets =
      options.candidates.empty() ? latentCandidateSets(true, 2, true, true, true) : options.candidates;
  if (std::any_of(sets.begin(), sets.end(), [](const LatentTermSet& s) { return s.flicker; })) {
    p.flickerSampledColumn.resize(Eigen::Index(p.m.size()));
    for (std::size_t i = 0; i < p.m.size(); ++i)
      p.flickerSampledColumn(Eigen::Index(i)) = flickerSampledAllanVariance(1.0, p.m[i]);
  }
  if (std::any_of(sets.begin(), sets.end(), [](const LatentTermSet& s) { return s.ar; })) {
    if (options.arPolynomial.size() < 2 || options.arPolynomial.front() != 1.0)
      throw InputError("latent fit: a set with an AR term needs its polynomial [1, a1..ap] (p >= 1)");
    p.arPolynomial = options.arPolynomial;
    p.arVarianceMax = options.arVarianceMax;
    const std::vector<double> col = arAllanVariance(p.arPolynomial, 1.0, p.m);
    p.arColumn = Eigen::Map<const Eigen::VectorXd>(col.data(), Eigen::Index(col.size()));
  }
  std::size_t minPar = 1000;
  for (const auto& s : sets) minPar = std::min(minPar, s.parameterCount());
  if (p.m.size() < minPar + 1)
    throw InputError("latent fit: " + std::to_string(p.m.size()) + " Allan points in the range (m <= N/10, tau in [" +
                     fmt(options.tauMin) + ", " + fmt(options.tauMax) + "] s): too few for " +
                     std::to_string(minPar) + " parameters");
  const LatentFitOptions& penalty = options;
  if (!(std::isfinite(options.penaltyPerTerm) && options.penaltyPerTerm >= 0.0 &&
        std::isfinite(options.penaltyPerParameter) && options.penaltyPerParameter >= 0.0))
    throw InputError("latent fit: penalties must be >= 0");

  // Pass 2 with Omega from the preliminary model; repeated (at most 3 times) while the winner
  // changes, as Omega depends on the model.
  LatentModel omegaModel = preliminaryModel(p, sets, penalty);
  std::vector<LatentCandidate> cands;
  std::vector<SetFit> fits;
  for (int it = 0; it < 3; ++it) {
    p.W = modelWhitening(p, omegaModel);
    fits.clear();
    cands = scoreAll(p, sets, penalty, &fits);
    if (cands.empty() || !cands.front().valid) throw NumericalError("latent fit: no valid candidate set");
    const bool same = cands.front().model.termNames() == omegaModel.termNames();
    omegaModel = cands.front().model;
    if (same) break;
  }
  const bool whittle = bins != nullptr && options.whittleSelection;
  if (whittle) {
    cands = whittleChoice(p, *bins, cands, penalty);
    if (options.blockSelection && record) cands = blockChoice(p, *bins, *record, cands, penalty);
    omegaModel = cands.front().model;
  }
  // Final: Omega from the winner, the winner refitted; every set rescored under that Omega for
  // the selection-aware parameters (so that a winner of weight ~1 states its own fit).
  p.W = modelWhitening(p, omegaModel);
  SetFit best = fitSet(p, cands.front().terms);
  std::string parameterNote;
  if (whittle && options.blockSelection && options.likelihoodCheckedParameters && record)
    best = likelihoodCheckedFit(p, *bins, *record, cands.front(), best, omegaModel, parameterNote);
  // Only the sets within kAveragedScoreRange of the best pass-2 score are rescored.
  std::vector<LatentTermSet> near;
  double bestScore = cands.front().score;
  for (const auto& c : cands)
    if (c.valid) bestScore = std::min(bestScore, c.score);
  for (const auto& c : cands)
    if (c.valid && c.score - bestScore <= kAveragedScoreRange) near.push_back(c.terms);
  auto averaging = [p, near, penalty, omegaModel] {
    std::vector<SetFit> finalFits;
    const std::vector<LatentCandidate> finalCands = scoreAll(p, near, penalty, &finalFits);
    return averageOverSets(p, finalCands, finalFits, omegaModel);
  };

  LatentFit out;
  out.terms = best.set;
  out.model = modelOf(p, best);
  out.chi2 = best.chi2;
  out.dof = p.m.size() - best.set.parameterCount();
  out.pValue = out.dof > 0 ? 1.0 - chiSquareCdf(out.chi2, double(out.dof)) : 1.0;
  out.sampleInterval = dt;
  out.samples = samples;
  out.m = p.m;
  out.tau = p.tau;
  out.avar = y;
  out.modelAvar = latentAllanVariance(out.model, dt, p.m);
  out.candidates = cands;
  out.whittleSelected = whittle && std::isfinite(cands.front().whittleScore);
  out.blockSelected = whittle && std::isfinite(cands.front().blockScore);
  out.consistent = out.pValue >= 1e-3;
  out.trendDrift = cands.front().trendDrift && !best.set.drift;
  out.parameterNote = parameterNote;
  if (!best.allPositive) out.warnings.push_back("final refit put a variance at zero");
  describe(p, best, out);
  return {std::move(out), averaging};
}

}  // namespace

namespace {

/// The record's Allan points below a scanned fit's start (where the model is extrapolated): their
/// averaging factors and Allan variances, the finite positive ones.
struct BelowStart {
  std::vector<std::size_t> m;
  std::vector<double> avar;
};
BelowStart pointsBelowStart(const LatentFit& fit, const std::vector<std::size_t>& m,
                            const std::vector<double>& avar) {
  BelowStart b;
  for (std::size_t i = 0; i < m.size() && !fit.tau.empty(); ++i) {
    if (double(m[i]) * fit.sampleInterval >= fit.tau.front() * (1.0 - 1e-9)) break;
    if (!(std::isfinite(avar[i]) && avar[i] > 0.0)) continue;
    b.m.push_back(m[i]);
    b.avar.push_back(avar[i]);
  }
  return b;
}

/// Whether the record's Allan points below a scanned start refute the fit's quantization: the
/// terms' Allan variances add and none is negative, so no term's own may exceed the whole
/// record's, yet 3 Q^2 / tau^2, fitted from a start far above dt, is extrapolated down with slope
/// -1. On the 1000-s ADIS16405 run-2 window a quantization fitted from 0.64 s up (beside white
/// noise and a walk) was 41x the record's Allan variance at 10 ms (the issue's "an LSB whose noise
/// at one sample is 10x the record's"). Refuted beyond kRefutedBelow: the estimates there scatter
/// by a few % and an internal filter lowers a record's shortest tau by tens of %, not by 2x.
bool quantizationRefutedBelow(const LatentFit& fit, const std::vector<std::size_t>& m,
                              const std::vector<double>& avar) {
  constexpr double kRefutedBelow = 2.0;
  if (!(fit.model.quantization > 0.0)) return false;
  const BelowStart b = pointsBelowStart(fit, m, avar);
  if (b.m.empty()) return false;
  LatentModel q;
  q.quantization = fit.model.quantization;
  q.lattice = fit.model.lattice;
  const std::vector<double> qAvar = latentAllanVariance(q, fit.sampleInterval, b.m);
  for (std::size_t i = 0; i < b.m.size(); ++i)
    if (qAvar[i] > kRefutedBelow * b.avar[i]) return true;
  return false;
}

/// fitRange from a scanned start, again without the quantization sets where the points below
/// the start refute the quantization fitted (quantizationRefutedBelow).
RangeFit fitStart(const std::vector<std::size_t>& m, const std::vector<double>& avar, std::size_t samples,
                  const LatentFitOptions& o, const WhittleBins* bins, const std::vector<double>* record) {
  RangeFit f = fitRange(m, avar, samples, o, bins, record);
  if (!quantizationRefutedBelow(f.fit, m, avar)) return f;
  LatentFitOptions without = o;
  without.candidates.clear();
  for (const LatentTermSet& s : o.candidates.empty() ? latentCandidateSets(true, 2, true, true, true) : o.candidates)
    if (!s.quantization) without.candidates.push_back(s);
  if (without.candidates.empty()) return f;  // (empty would mean every set)
  RangeFit g = fitRange(m, avar, samples, without, bins, record);
  g.fit.warnings.push_back("quantization left out: fitted from " + fmt(f.fit.tau.front()) +
                           " s up, its Allan variance exceeded the whole record's below that start");
  return g;
}

/// A scanned fit's model against the record below its start, where the model is extrapolated:
/// LatentFit::belowStartRatio, warned beyond kBelowStartTolerance. The 1000-s ADIS16405 windows'
/// accelerometers (white noise behind the sensor's low-pass filter) fit from 1.28 s up and their
/// models were 1.3-1.5x the record at 10 ms; the gyros' filter hump left the model 0.72x at 20 ms.
void warnBelowStart(LatentFit& fit, const std::vector<std::size_t>& m, const std::vector<double>& avar) {
  const BelowStart b = pointsBelowStart(fit, m, avar);
  if (b.m.empty()) return;
  const std::vector<double> model = latentAllanVariance(fit.model, fit.sampleInterval, b.m);
  double at = 0.0;
  for (std::size_t i = 0; i < b.m.size(); ++i) {
    const double r = std::sqrt(model[i] / b.avar[i]);
    if (std::fabs(std::log(r)) > std::fabs(std::log(fit.belowStartRatio)))
      fit.belowStartRatio = r, at = double(b.m[i]) * fit.sampleInterval;
  }
  if (!offBelowStart(fit)) return;
  const double worst = fit.belowStartRatio;
  fit.warnings.push_back("below the fitted range (tau < " + fmt(fit.tau.front()) + " s) the model's ADEV is " +
                         fmt(worst, 3) + "x the record's at " + fmt(at) + " s: " +
                         (worst > 1.0 ? "the record falls below the fitted terms there: as behind a sensor's low-pass "
                                        "filter (an AR carries such a shape: --kind ar+slow or auto), or where "
                                        "the set lacks a faster correlated term (a second GM: --kind latent or auto)"
                                      : "the record holds a short-tau feature no term carries"));
}

LatentFit fitScanned(const std::vector<std::size_t>& m, const std::vector<double>& avar, std::size_t samples,
                     const LatentFitOptions& options, const WhittleBins* bins,
                     const std::vector<double>* record = nullptr) {
  RangeFit first = fitRange(m, avar, samples, options, bins, record);
  const LatentFit& fit = first.fit;
  if (!options.scanStart || fit.consistent) return std::move(first).withAveraged();
  RangeFit best = first;
  for (std::size_t start = 1; start < fit.tau.size() && fit.tau.size() - start >= 6; ++start) {
    LatentFitOptions o = options;
    o.tauMin = std::max(options.tauMin, fit.tau[start] * (1.0 - 1e-9));
    RangeFit f;
    progress::checkpoint("scanning the start of the tau range", start, fit.tau.size());
    try {
      f = fitStart(m, avar, samples, o, bins, record);
    } catch (const Error&) {
      break;
    }
    if (f.fit.consistent) {
      LatentFit kept;
      try {  // as when the averaging was part of the start's fit: a failure ends the scan
        kept = std::move(f).withAveraged();
      } catch (const Error&) {
        break;
      }
      warnBelowStart(kept, m, avar);
      return kept;
    }
    if (f.fit.chi2 / double(std::max<std::size_t>(f.fit.dof, 1)) <
        best.fit.chi2 / double(std::max<std::size_t>(best.fit.dof, 1)))
      best = std::move(f);
  }
  LatentFit kept = std::move(best).withAveraged();
  kept.warnings.push_back("no start of the tau range gives a consistent fit (p >= 0.001): least-bad start " +
                          fmt(kept.tau.front()) + " s kept");
  warnBelowStart(kept, m, avar);
  return kept;
}

}  // namespace

LatentFit fitLatentModel(const std::vector<std::size_t>& m, const std::vector<double>& avar,
                         std::size_t samples, const LatentFitOptions& options) {
  return fitScanned(m, avar, samples, options, nullptr);
}

LatentAllanPoints latentAllanPoints(const std::vector<double>& x, double sampleInterval) {
  if (!(std::isfinite(sampleInterval) && sampleInterval > 0.0))
    throw InputError("latent fit: sample interval must be > 0");
  if (x.size() < 40) throw InputError("latent fit: need at least 40 samples, got " + std::to_string(x.size()));
  AllanOptions ao;
  ao.grid = TauGrid::Octave;
  ao.max_factor = x.size() / 10;
  ao.confidence_intervals = false;
  const AllanCurve c = allanDeviation(x, 1.0 / sampleInterval, AllanVariant::Overlapping, ao);
  LatentAllanPoints p{c.m, c.tau, std::vector<double>(c.dev.size()), c.dev};
  for (std::size_t i = 0; i < p.avar.size(); ++i) p.avar[i] = c.dev[i] * c.dev[i];
  return p;
}

namespace {

LatentFit fitRecord(const std::vector<double>& x, const LatentAllanPoints& c, const LatentFitOptions& options) {
  // Correlated lattice rounding is far from Gaussian (a sparse train of LSB steps): the power of
  // the steps a record happens to hold varies by 1-2 % between records of 720 000 samples, where
  // the periodogram's level is known to 0.1 %, so the Whittle and block likelihoods read that
  // spread as structure (a GM of tau ~ 15 samples chosen in 9 of 80 blind quantization + white
  // records); the few octave Allan points choose the set instead.
  LatentFit fit;
  if (!options.whittleSelection || options.lattice.correlated()) {
    fit = fitScanned(c.m, c.avar, x.size(), options, nullptr);
  } else {
    const WhittleBins bins = whittleBins(x, options.sampleInterval, options.lattice);
    fit = fitScanned(c.m, c.avar, x.size(), options, &bins, &x);
  }
  // On a correlated lattice the drift is the one choice the block means still make: third null
  // record 8 gy (seed 4), a ramp of 600 deg/h^2 over 261 s (t = 3.7) under an LSB of the white
  // noise's sd, was white + GM and the diagnosis of the same record named `ramp`.
  driftFromTrend(fit, x, options.whittleSelection && options.lattice.correlated());
  return fit;
}

/// LatentFitOptions::lattice with a step and no motion: the motion from the record's Allan
/// variance at tau = dt (latticeMotionFromAllan: white increments rounded on the lattice), the
/// rounding's exact form where that motion correlates it, else the classical one.
LatentFit fitOnLattice(const std::vector<double>& x, const LatentAllanPoints& c, LatentFitOptions o) {
  o.lattice.motion = 0.0;
  if (!c.m.empty() && c.m.front() == 1)
    o.lattice.motion = latticeMotionFromAllan(o.lattice, o.sampleInterval, c.avar.front());
  if (!o.lattice.correlated()) o.lattice = {};
  o.latticeMotionRead = o.lattice.active();
  return fitRecord(x, c, o);
}

}  // namespace

LatentFit fitLatentModel(const std::vector<double>& x, const LatentFitOptions& options) {
  const LatentAllanPoints c = latentAllanPoints(x, options.sampleInterval);
  if (options.lattice.step > 0.0 && !options.lattice.active()) return fitOnLattice(x, c, options);
  return fitRecord(x, c, options);
}

}  // namespace sinsim::errormodels::fit
