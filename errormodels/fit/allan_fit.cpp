#include "errormodels/fit/allan_fit.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

#include "common/constants.hpp"
#include "common/error.hpp"
#include "errormodels/fit/nnls.hpp"
#include "errormodels/stats/special.hpp"

namespace sinsim::errormodels::fit {

std::string toString(AllanTermKind kind) {
  switch (kind) {
    case AllanTermKind::Quantization: return "quantization";
    case AllanTermKind::White: return "white";
    case AllanTermKind::BiasInstability: return "bias_instability";
    case AllanTermKind::RandomWalk: return "random_walk";
    case AllanTermKind::Ramp: return "ramp";
  }
  return "?";
}

namespace {

// Row of the design matrix: d sigma^2 / d theta_j at tau (IEEE Std 952-1997 Annex C).
std::array<double, kAllanTermCount> basis(double tau) {
  return {3.0 / (tau * tau), 1.0 / tau, 2.0 * std::log(2.0) / kPi, tau / 3.0, tau * tau / 2.0};
}

}  // namespace

std::vector<double> allanModelAdev(const std::array<double, kAllanTermCount>& theta,
                                   const std::vector<double>& tau) {
  std::vector<double> out;
  out.reserve(tau.size());
  for (double t : tau) {
    const auto b = basis(t);
    double v = 0.0;
    for (std::size_t j = 0; j < kAllanTermCount; ++j) v += b[j] * theta[j];
    out.push_back(std::sqrt(v));
  }
  return out;
}

namespace {

// Composite Simpson of f on [a, b] with n (even) intervals.
template <class F>
double simpson(const F& f, double a, double b, int n) {
  if (!(b > a)) return 0.0;
  const double h = (b - a) / n;
  double s = f(a) + f(b);
  for (int i = 1; i < n; ++i) s += f(a + i * h) * (i % 2 ? 4.0 : 2.0);
  return s * h / 3.0;
}
// Simpson in u = ln w (for smooth power-law integrands over decades).
template <class F>
double simpsonLog(const F& f, double a, double b, int n) {
  if (!(b > a)) return 0.0;
  return simpson([&](double u) { const double w = std::exp(u); return f(w) * w; }, std::log(a),
                 std::log(b), n);
}

// (1/pi) int_0^pi S^2 |G_a|^2 |G_b|^2 dw for averaging factors ma <= mb. Oscillating factors
// sin^4(m w / 2) are integrated exactly over their first 20 periods and replaced by their mean
// beyond: 3/8 each, 35/128 for the product when ma == mb, 7/64 when mb == 2 ma (the only ratios
// with resonant harmonics; sin^4 has harmonics 0, 2, 4 only).
//
// The PSD is the costly part (a fitted AR(20) model: a complex Horner per node), and the nodes of
// a pair's first segment [0, 40 pi / mb] and of its log tails [40 pi / m, pi] depend on one factor
// only: they are evaluated once per factor (FactorNodes) and shared by every pair, with the same
// nodes and the same arithmetic as a pair on its own (the covariance is unchanged to the bit).
constexpr int kExactIntervals = 1600, kTailIntervals = 800;

double sin4(double x) { const double s = std::sin(x); return s * s * s * s; }

// sin(x0 + k dx) for k = 0..n into out (n + 1 values): a rotation per step, re-seeded from
// std::sin / std::cos every 32 steps, so the error stays a few ulp (the pair integrals call this
// for 1601 nodes each; one libm sine per node was a sixth of a whole latent fit's time).
void sineSteps(double x0, double dx, int n, std::vector<double>& out) {
  out.resize(static_cast<std::size_t>(n) + 1);
  const double cd = std::cos(dx), sd = std::sin(dx);
  double c = 1.0, si = 0.0;
  for (int k = 0; k <= n; ++k) {
    if (k % 32 == 0) {
      const double x = x0 + k * dx;
      c = std::cos(x), si = std::sin(x);
    } else {
      const double cn = c * cd - si * sd;
      si = si * cd + c * sd, c = cn;
    }
    out[static_cast<std::size_t>(k)] = si;
  }
}

// 4 S^2 / (ma^2 mb^2 sin^4(w/2)), from S = psd(w) and s = sin(w/2)
double envelopeOf(double S, double s, double a, double b) {
  return 4.0 * S * S / (a * a * b * b * s * s * s * s);
}

struct FactorNodes {
  double c = 0.0;                          // min(pi, 40 pi / m): the end of the exact segment
  std::vector<double> w, S, s, sin4m;      // Simpson nodes on [0, c] (w = i h, the last one c)
  std::vector<double> tw, tS, ts;          // Simpson nodes in ln w on [c, pi] (empty when c = pi)
};

// psd(w, s), s = sin(w / 2) (allanEstimateCovariance's second form)
using PsdOfWs = std::function<double(double, double)>;

FactorNodes factorNodes(const PsdOfWs& psd, std::size_t mf) {
  FactorNodes f;
  const double m = static_cast<double>(mf);
  f.c = std::min(kPi, 40.0 * kPi / m);
  const double h = f.c / kExactIntervals;
  for (int i = 0; i <= kExactIntervals; ++i) {
    const double w = i == kExactIntervals ? f.c : 0.0 + i * h;
    const double s = std::sin(0.5 * w);
    f.w.push_back(w);
    f.S.push_back(w <= 0.0 ? 0.0 : psd(w, s));
    f.s.push_back(s);
    f.sin4m.push_back(sin4(0.5 * m * w));
  }
  if (f.c < kPi) {
    const double la = std::log(f.c), lb = std::log(kPi), hl = (lb - la) / kTailIntervals;
    for (int i = 0; i <= kTailIntervals; ++i) {
      const double w = std::exp(i == 0 ? la : i == kTailIntervals ? lb : la + i * hl);
      const double s = std::sin(0.5 * w);
      f.tw.push_back(w);
      f.tS.push_back(psd(w, s));
      f.ts.push_back(s);
    }
  }
  return f;
}

// Simpson's weights over n + 1 node values g(i), times h / 3.
template <class G>
double simpsonNodes(const G& g, int n, double h) {
  double sum = g(0) + g(n);
  for (int i = 1; i < n; ++i) sum += g(i) * (i % 2 ? 4.0 : 2.0);
  return sum * h / 3.0;
}

// int over [c, pi] in ln w of the envelope (the tail of `t`'s nodes), for the pair (a, b)
double tailIntegral(const FactorNodes& t, double a, double b) {
  if (t.tw.empty()) return 0.0;
  const double hl = (std::log(kPi) - std::log(t.c)) / kTailIntervals;
  return simpsonNodes([&](int i) {
    const auto k = static_cast<std::size_t>(i);
    return envelopeOf(t.tS[k], t.ts[k], a, b) * t.tw[k];
  }, kTailIntervals, hl);
}

double pairIntegral(const PsdOfWs& psd, const FactorNodes& lo, const FactorNodes& hi,
                    std::size_t ma, std::size_t mb) {
  const double a = static_cast<double>(ma), b = static_cast<double>(mb);
  const double cb = hi.c, ca = lo.c;
  thread_local std::vector<double> sa, sw;
  // Segment A: both exact. hi's nodes are w = i cb / n (the last one cb), so sin(a w / 2) steps.
  sineSteps(0.0, 0.5 * a * cb / kExactIntervals, kExactIntervals, sa);
  double I = simpsonNodes([&](int i) {
    const auto k = static_cast<std::size_t>(i);
    const double t = sa[k] * sa[k];
    return hi.w[k] <= 0.0 ? 0.0 : envelopeOf(hi.S[k], hi.s[k], a, b) * (t * t) * hi.sin4m[k];
  }, kExactIntervals, cb / kExactIntervals);
  if (cb < kPi) {
    if (mb == ma || mb == 2 * ma) {
      const double avg = mb == ma ? 35.0 / 128.0 : 7.0 / 64.0;
      I += avg * tailIntegral(hi, a, b);
    } else {
      // sin^4(b w/2) -> 3/8; sin^4(a w/2) exact up to ca, then 3/8 as well.
      const double h = (ca - cb) / kExactIntervals;
      sineSteps(0.5 * cb, 0.5 * h, kExactIntervals, sw);
      sineSteps(0.5 * a * cb, 0.5 * a * h, kExactIntervals, sa);
      I += 0.375 * simpsonNodes([&](int i) {
        const auto k = static_cast<std::size_t>(i);
        const double w = i == 0 ? cb : i == kExactIntervals ? ca : cb + i * h, s = sw[k], t = sa[k] * sa[k];
        return envelopeOf(psd(w, s), s, a, b) * (t * t);
      }, kExactIntervals, h);
      I += 0.375 * 0.375 * tailIntegral(lo, a, b);
    }
  }
  return I / kPi;
}

}  // namespace

double allanTermsPsd(const std::array<double, kAllanTermCount>& th, double dt, double w) {
  return allanTermsPsd(th, dt, w, std::sin(0.5 * w));
}

double allanTermsPsd(const std::array<double, kAllanTermCount>& th, double dt, double w, double s) {
  const double s2 = s * s;
  return th[0] * 4.0 * s2 / (dt * dt) + th[1] / dt + th[2] / w + th[3] * dt / (4.0 * s2);
}

Eigen::MatrixXd allanEstimateCovariance(const std::array<double, kAllanTermCount>& theta,
                                        const std::vector<std::size_t>& m, double dt,
                                        std::size_t M) {
  if (!(std::isfinite(dt) && dt > 0.0)) throw InputError("Allan covariance: dt must be > 0");
  return allanEstimateCovariance([&](double w, double s) { return allanTermsPsd(theta, dt, w, s); }, m, M);
}

Eigen::MatrixXd allanEstimateCovariance(const std::function<double(double)>& psd,
                                        const std::vector<std::size_t>& m, std::size_t M) {
  return allanEstimateCovariance([&](double w, double) { return psd(w); }, m, M);
}

Eigen::MatrixXd allanEstimateCovariance(const std::function<double(double w, double s)>& psd,
                                        const std::vector<std::size_t>& m, std::size_t M) {
  const auto n = static_cast<Eigen::Index>(m.size());
  for (std::size_t f : m)
    if (f == 0 || 2 * f >= M) throw InputError("Allan covariance: need 1 <= m < M / 2");
  std::vector<FactorNodes> nodes;
  nodes.reserve(m.size());
  for (std::size_t f : m) nodes.push_back(factorNodes(psd, f));
  Eigen::MatrixXd C(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j <= i; ++j) {
      const auto ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j);
      const bool iHi = m[ui] >= m[uj];
      const std::size_t lo = iHi ? uj : ui, hi = iHi ? ui : uj;
      const double L = static_cast<double>(M - 2 * m[lo]);  // the shorter filter's term count (header)
      C(i, j) = C(j, i) = 2.0 / L * pairIntegral(psd, nodes[lo], nodes[hi], m[lo], m[hi]);
    }
  return C;
}

Eigen::MatrixXd allanEstimateCorrelation(const std::array<double, kAllanTermCount>& theta,
                                         const std::vector<std::size_t>& m, double dt,
                                         std::size_t M) {
  return correlationOfCovariance(allanEstimateCovariance(theta, m, dt, M));
}

Eigen::MatrixXd correlationOfCovariance(const Eigen::MatrixXd& C) {
  const Eigen::VectorXd d = C.diagonal().cwiseSqrt().cwiseInverse();
  Eigen::MatrixXd R = d.asDiagonal() * C * d.asDiagonal();
  // The quadrature of the pair integrals is least accurate for random-walk-dominated points at
  // the largest m (neighbour correlations of 1.01 seen at m = 65536 / 131072 of M = 720000), which
  // makes R indefinite and the GLS impossible. Project onto the correlation matrices: eigenvalues
  // floored at 1e-3, then rescaled to a unit diagonal (a no-op when R is already well inside).
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(R);
  if (es.info() == Eigen::Success && es.eigenvalues().minCoeff() < 1e-3) {
    const Eigen::VectorXd ev = es.eigenvalues().cwiseMax(1e-3);
    R = es.eigenvectors() * ev.asDiagonal() * es.eigenvectors().transpose();
    const Eigen::VectorXd s = R.diagonal().cwiseSqrt().cwiseInverse();
    R = s.asDiagonal() * R * s.asDiagonal();
  }
  return R;
}

namespace {

// One weighted NNLS fit with the terms in `model`; upper bounds for every term in `requested`.
AllanFit fitOnce(const std::vector<double>& tau, const std::vector<double>& adev,
                 const std::vector<double>& edf, const std::vector<std::size_t>& use,
                 const std::vector<std::size_t>& mFactor,
                 const std::array<bool, kAllanTermCount>& model,
                 const std::array<bool, kAllanTermCount>& requested,
                 const AllanFitOptions& options) {
  std::vector<Eigen::Index> cols;
  for (std::size_t j = 0; j < kAllanTermCount; ++j)
    if (model[j]) cols.push_back(static_cast<Eigen::Index>(j));
  const auto m = static_cast<Eigen::Index>(use.size());
  const auto nc = static_cast<Eigen::Index>(cols.size());
  Eigen::MatrixXd Xall(m, static_cast<Eigen::Index>(kAllanTermCount));
  Eigen::VectorXd y(m), nu(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    const std::size_t k = use[static_cast<std::size_t>(i)];
    const auto b = basis(tau[k]);
    for (std::size_t j = 0; j < kAllanTermCount; ++j) Xall(i, static_cast<Eigen::Index>(j)) = b[j];
    y(i) = adev[k] * adev[k];
    nu(i) = edf[k];
  }
  Eigen::MatrixXd X(m, nc);
  for (Eigen::Index c = 0; c < nc; ++c) X.col(c) = Xall.col(cols[c]);

  const bool correlated = !mFactor.empty();
  auto thetaOf = [&](const Eigen::VectorXd& x) {
    std::array<double, kAllanTermCount> th{};
    for (Eigen::Index c = 0; c < nc; ++c) th[static_cast<std::size_t>(cols[c])] = x(c);
    return th;
  };
  // Whitening W (C^-1 = W' W) for the variances 2 sigma^4 / nu, sigma^2 from `level`.
  auto whitening = [&](const Eigen::VectorXd& level, const Eigen::VectorXd* x) {
    const Eigen::VectorXd sd = (2.0 / nu.array()).sqrt() * level.array();
    if (!correlated || x == nullptr) return Eigen::MatrixXd(sd.cwiseInverse().asDiagonal());
    const Eigen::MatrixXd R = allanEstimateCorrelation(thetaOf(*x), mFactor,
                                                       options.sampleInterval, options.recordLength);
    const Eigen::MatrixXd C = sd.asDiagonal() * R * sd.asDiagonal();
    Eigen::LLT<Eigen::MatrixXd> llt(C);
    if (llt.info() != Eigen::Success)
      throw NumericalError("Allan fit: covariance of the points is not positive definite");
    return Eigen::MatrixXd(llt.matrixL().solve(Eigen::MatrixXd::Identity(m, m)));
  };

  // Iteratively reweighted NNLS: weights from the model (not the noisy data, whose low points
  // would weigh more); the first pass from the data with independent points.
  Eigen::MatrixXd W = whitening(y, nullptr);
  NnlsResult sol;
  Eigen::VectorXd prev;
  for (int it = 0; it < std::max(2, options.maxReweight); ++it) {
    sol = nnls(W * X, W * y);
    Eigen::VectorXd level = X * sol.x;
    for (Eigen::Index i = 0; i < m; ++i)
      if (!(level(i) > 0.0)) level(i) = y(i);
    W = whitening(level, &sol.x);
    if (it > 0 && (sol.x - prev).norm() <= 1e-7 * sol.x.norm()) break;
    prev = sol.x;
  }

  AllanFit fit;
  fit.pointsUsed = use.size();
  fit.correlated = correlated;
  const Eigen::MatrixXd XallW = W * Xall;
  const Eigen::MatrixXd Xw = W * X;
  const Eigen::VectorXd yw = W * y;
  fit.chi2 = (yw - Xw * sol.x).squaredNorm();
  const auto nFree = static_cast<std::size_t>(sol.free.count());
  fit.dof = use.size() > nFree ? use.size() - nFree : 0;
  fit.birgeScale = fit.dof > 0 ? std::max(1.0, fit.chi2 / static_cast<double>(fit.dof)) : 1.0;

  // Covariance over a set of term indices (0..4) of the whitened design.
  auto covarianceOf = [&](const std::vector<Eigen::Index>& terms) {
    Eigen::MatrixXd Xf(m, static_cast<Eigen::Index>(terms.size()));
    for (std::size_t k = 0; k < terms.size(); ++k) Xf.col(static_cast<Eigen::Index>(k)) = XallW.col(terms[k]);
    const Eigen::MatrixXd cov = (Xf.transpose() * Xf).inverse() * fit.birgeScale;
    return std::make_pair(Xf, cov);
  };
  std::vector<Eigen::Index> freeTerms;
  for (Eigen::Index c = 0; c < nc; ++c)
    if (sol.free(c)) freeTerms.push_back(cols[c]);
  fit.thetaCovariance = Eigen::MatrixXd::Zero(kAllanTermCount, kAllanTermCount);
  if (!freeTerms.empty()) {
    const auto cov = covarianceOf(freeTerms).second;
    for (std::size_t a = 0; a < freeTerms.size(); ++a)
      for (std::size_t b = 0; b < freeTerms.size(); ++b)
        fit.thetaCovariance(freeTerms[a], freeTerms[b]) =
            cov(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b));
  }

  for (std::size_t j = 0; j < kAllanTermCount; ++j) {
    AllanTerm& t = fit.terms[j];
    t.kind = static_cast<AllanTermKind>(j);
    t.enabled = requested[j];
    if (!requested[j]) continue;
    const auto J = static_cast<Eigen::Index>(j);
    const auto it = std::find(cols.begin(), cols.end(), J);
    const bool isFree = it != cols.end() && sol.free(it - cols.begin());
    if (isFree) {
      t.theta = sol.x(it - cols.begin());
      t.thetaStdError = std::sqrt(fit.thetaCovariance(J, J));
      t.value = std::sqrt(t.theta);
      t.stdError = t.thetaStdError / (2.0 * t.value);
      t.upperBound = std::sqrt(t.theta + 2.0 * t.thetaStdError);
      t.detected = t.theta > options.detectionSigma * t.thetaStdError;
    } else {
      // Held at zero or left out: refit with this term unconstrained (linear WLS with the free
      // set plus j, weights fixed) to see how large it could be.
      std::vector<Eigen::Index> plus = freeTerms;
      plus.push_back(J);
      const auto [Xf, cov] = covarianceOf(plus);
      const Eigen::VectorXd thetaFree = Xf.colPivHouseholderQr().solve(yw);
      const auto last = static_cast<Eigen::Index>(plus.size() - 1);
      t.thetaStdError = std::sqrt(cov(last, last));
      t.upperBound = std::sqrt(std::max(thetaFree(last), 0.0) + 2.0 * t.thetaStdError);
    }
  }
  std::array<double, kAllanTermCount> theta{};
  for (std::size_t j = 0; j < kAllanTermCount; ++j) theta[j] = fit.terms[j].theta;
  for (std::size_t k : use) fit.tau.push_back(tau[k]);
  fit.modelAdev = allanModelAdev(theta, fit.tau);
  return fit;
}

}  // namespace

AllanFit fitAllanTerms(const std::vector<double>& tau, const std::vector<double>& adev,
                       const std::vector<double>& edf, const AllanFitOptions& options) {
  if (tau.size() != adev.size() || tau.size() != edf.size()) {
    std::ostringstream s;
    s << "Allan fit: tau, adev and edf must have the same length (got " << tau.size() << ", "
      << adev.size() << ", " << edf.size() << ")";
    throw InputError(s.str());
  }
  for (std::size_t i = 0; i < tau.size(); ++i) {
    if (!(std::isfinite(tau[i]) && tau[i] > 0.0) || !(std::isfinite(adev[i]) && adev[i] > 0.0) ||
        !(std::isfinite(edf[i]) && edf[i] > 0.0)) {
      std::ostringstream s;
      s << "Allan fit: point " << i << " (tau " << tau[i] << ", adev " << adev[i] << ", edf "
        << edf[i] << ") must have finite, positive tau, adev and edf";
      throw InputError(s.str());
    }
    if (i > 0 && !(tau[i] > tau[i - 1]))
      throw InputError("Allan fit: tau must increase (point " + std::to_string(i) + ")");
  }
  std::vector<std::size_t> use;
  for (std::size_t i = 0; i < tau.size(); ++i)
    if (tau[i] >= options.tauMin && tau[i] <= options.tauMax) use.push_back(i);
  std::size_t nTerms = 0;
  for (bool e : options.enabled) nTerms += e ? 1 : 0;
  if (nTerms == 0) throw InputError("Allan fit: no term enabled");
  if (use.size() < nTerms + 1) {
    std::ostringstream s;
    s << "Allan fit: " << use.size() << " points in [" << options.tauMin << ", "
      << options.tauMax << "] s for " << nTerms << " terms (need at least terms + 1)";
    throw InputError(s.str());
  }
  std::vector<std::size_t> mFactor;  // non-empty: correlated (GLS) mode
  if (options.sampleInterval > 0.0 && options.recordLength > 0) {
    for (std::size_t k : use) {
      const double r = tau[k] / options.sampleInterval;
      const double mr = std::round(r);
      if (!(mr >= 1.0) || std::abs(r - mr) > 1e-6 * r || 2 * mr >= double(options.recordLength)) {
        std::ostringstream s;
        s << "Allan fit: tau " << tau[k] << " s (point " << k << ") is not a multiple m of the "
          << "sample interval " << options.sampleInterval << " s with m < recordLength / 2";
        throw InputError(s.str());
      }
      mFactor.push_back(static_cast<std::size_t>(mr));
    }
  }
  // Backward elimination: refit without the terms the data do not support, so that terms held
  // at the zero bound do not bias the correlated ones (NNLS truncation); the removed terms are
  // reported with their upper bounds from the final model.
  std::array<bool, kAllanTermCount> model = options.enabled;
  AllanFit fit = fitOnce(tau, adev, edf, use, mFactor, model, options.enabled, options);
  for (std::size_t round = 0; options.eliminateUndetected && round < kAllanTermCount; ++round) {
    std::array<bool, kAllanTermCount> next{};
    std::size_t kept = 0;
    for (std::size_t j = 0; j < kAllanTermCount; ++j) {
      next[j] = model[j] && fit.terms[j].detected;
      kept += next[j] ? 1 : 0;
    }
    if (next == model || kept == 0) break;
    model = next;
    fit = fitOnce(tau, adev, edf, use, mFactor, model, options.enabled, options);
  }
  return fit;
}

double edfFromConfidenceInterval(double lo, double hi, double confidence) {
  if (!(std::isfinite(lo) && std::isfinite(hi) && lo > 0.0 && hi > lo))
    throw InputError("EDF from confidence interval: need 0 < lo < hi");
  const double z = normalQuantileTwoSided(confidence);
  const double target = (hi / lo) * (hi / lo);  // chi2_{upper} / chi2_{lower}
  // Wilson-Hilferty: chi2_p(nu) ~ nu (1 - 2/(9nu) + z_p sqrt(2/(9nu)))^3.
  auto ratio = [&](double nu) {
    const double c = 1.0 - 2.0 / (9.0 * nu), s = std::sqrt(2.0 / (9.0 * nu));
    const double lower = c - z * s;
    if (lower <= 0.0) return std::numeric_limits<double>::infinity();
    return std::pow((c + z * s) / lower, 3);
  };
  double a = 1e-3, b = 1e12;
  if (ratio(b) > target) return b;  // interval narrower than resolvable: effectively exact
  for (int i = 0; i < 200; ++i) {
    const double mid = std::sqrt(a * b);
    (ratio(mid) > target ? a : b) = mid;
  }
  return std::sqrt(a * b);
}

namespace {
void checkEdfArgs(std::size_t M, std::size_t m) {
  if (m < 1 || 2 * m > M)
    throw InputError("overlapping Allan EDF: need 1 <= m <= M/2 (m = " + std::to_string(m) +
                     ", M = " + std::to_string(M) + ")");
}
}  // namespace

double edfOverlappingWhite(std::size_t M, std::size_t m) {
  checkEdfArgs(M, m);
  const double P = static_cast<double>(M) + 1.0, md = static_cast<double>(m);
  return (3.0 * (P - 1.0) / (2.0 * md) - 2.0 * (P - 2.0) / P) * 4.0 * md * md /
         (4.0 * md * md + 5.0);
}

double edfOverlappingRandomWalk(std::size_t M, std::size_t m) {
  checkEdfArgs(M, m);
  const double P = static_cast<double>(M) + 1.0, md = static_cast<double>(m);
  if (P <= 3.0) throw InputError("overlapping Allan EDF: need at least 3 samples");
  return (P - 2.0) / md * ((P - 1.0) * (P - 1.0) - 3.0 * md * (P - 1.0) + 4.0 * md * md) /
         ((P - 3.0) * (P - 3.0));
}

}  // namespace sinsim::errormodels::fit
