#include "errormodels/fit/whittle_selection.hpp"

#include <algorithm>
#include <complex>
#include <cmath>
#include <limits>

#include "common/constants.hpp"
#include "common/error.hpp"
#include "common/once_cache.hpp"
#include "errormodels/fit/golden_section.hpp"
#include "errormodels/fit/nnls.hpp"
#include "errormodels/stats/spectrum.hpp"

namespace sinsim::errormodels::fit {

namespace {

/// Split-cosine taper fraction: 10 % (5 % at each end) is the usual compromise (Bloomfield 1976,
/// sec. 5.2): the end effect falls by ~pi^2 / (8 L) (L the ramp length, ~1e-4 here), the variance
/// inflation is 1.06.
constexpr double kTaperFraction = 0.1;
constexpr std::size_t kSingleOrdinates = 16;  ///< lowest Fourier frequencies kept alone
constexpr double kBinWidth = 0.1;             ///< relative width of the other bins
constexpr std::size_t kNodes = 8;             ///< frequencies f_b is averaged over

/// The bins' columns of a set, in the order Q, N, gm..., B, K (its variance coefficients).
Eigen::MatrixXd design(const WhittleBins& b, std::size_t nb, const LatentTermSet& s,
                       const std::vector<double>& T) {
  const auto cols = static_cast<Eigen::Index>(s.parameterCount() - T.size());
  Eigen::MatrixXd X(static_cast<Eigen::Index>(nb), cols);
  Eigen::Index c = 0;
  auto fixed = [&](const std::vector<double>& v) {
    for (std::size_t i = 0; i < nb; ++i) X(Eigen::Index(i), c) = v[i];
    ++c;
  };
  if (s.quantization) fixed(b.quantization);
  if (s.white) fixed(b.white);
  for (double t : T) {
    LatentModel g;
    g.gm.push_back({1.0, t});
    const LatentSpectrum psd(g, b.dt);
    for (std::size_t i = 0; i < nb; ++i) {
      double sum = 0.0;
      for (std::size_t k = 0; k < b.nodes[i].size(); ++k) sum += psd(b.nodes[i][k], b.nodeSin[i][k]);
      X(Eigen::Index(i), c) = b.lowFactor[i] * sum / double(b.nodes[i].size());
    }
    ++c;
  }
  if (s.flicker) fixed(b.flicker);
  if (s.randomWalk) fixed(b.randomWalk);
  return X;
}

/// -2 log L of the bins at model levels f (infinite if any f <= 0).
double m2LogLik(const WhittleBins& b, const Eigen::VectorXd& f) {
  double s = 0.0;
  for (Eigen::Index i = 0; i < f.size(); ++i) {
    if (!(f(i) > 0.0)) return std::numeric_limits<double>::infinity();
    s += b.count[std::size_t(i)] * (std::log(f(i)) + b.level[std::size_t(i)] / f(i));
  }
  return 2.0 * s;
}

struct Profile {
  Eigen::VectorXd theta;
  double m2ll = std::numeric_limits<double>::infinity();
  bool allPositive = false;
};

/// The variances maximising the likelihood for fixed taus: Fisher scoring, i.e. NNLS of I_b on the
/// columns with weights c_b / f_b^2 at the current f, iterated (step halved while -2 log L rises).
Profile profileVariances(const WhittleBins& b, const Eigen::MatrixXd& X, Eigen::VectorXd theta) {
  const Eigen::Index nb = X.rows();
  const Eigen::Map<const Eigen::VectorXd> I(b.level.data(), nb);
  Profile p;
  // A start with a zero level somewhere (a variance at 0) is replaced by the bins' own levels.
  Eigen::VectorXd f = X * theta;
  if (!(f.minCoeff() > 0.0)) {
    Eigen::VectorXd wt(nb);
    for (Eigen::Index i = 0; i < nb; ++i) wt(i) = std::sqrt(b.count[std::size_t(i)]) / std::max(I(i), 1e-300);
    theta = nnls(wt.asDiagonal() * X, wt.asDiagonal() * I).x;
    f = X * theta;
  }
  double cur = m2LogLik(b, f);
  for (int it = 0; it < 40; ++it) {
    Eigen::VectorXd wt(nb);
    for (Eigen::Index i = 0; i < nb; ++i) wt(i) = std::sqrt(b.count[std::size_t(i)]) / f(i);
    const NnlsResult r = nnls(wt.asDiagonal() * X, wt.asDiagonal() * I);
    Eigen::VectorXd step = r.x - theta;
    double next = std::numeric_limits<double>::infinity();
    Eigen::VectorXd cand = theta;
    for (int h = 0; h < 8; ++h) {
      cand = theta + step;
      next = m2LogLik(b, X * cand);
      if (next <= cur) break;
      step *= 0.5;
    }
    if (!(next <= cur)) break;
    const double gain = cur - next;
    theta = cand, cur = next, f = X * theta;
    if (gain < 1e-7) break;
  }
  p.theta = theta;
  p.m2ll = cur;
  p.allPositive = (theta.array() > 0.0).all();
  return p;
}

struct TauFit {
  std::vector<double> T;
  Profile profile;
};

TauFit evaluate(const WhittleBins& b, std::size_t nb, const LatentTermSet& s, const std::vector<double>& T,
                const Eigen::VectorXd& start) {
  return {T, profileVariances(b, design(b, nb, s, T), start)};
}

/// Golden-section minimum of -2 log L over log T_k in [lo, hi] (the other taus fixed).
TauFit goldenT(const WhittleBins& b, std::size_t nb, const LatentTermSet& s, TauFit best, std::size_t k,
               double lo, double hi) {
  if (!(hi > lo)) return best;
  std::vector<double> T = best.T;
  auto at = [&](double u) { T[k] = std::exp(u); return evaluate(b, nb, s, T, best.profile.theta); };
  const TauFit m = goldenSectionLog(lo, hi, 18, at, [](const TauFit& f) { return f.profile.m2ll; });
  return m.profile.m2ll < best.profile.m2ll ? m : best;
}

}  // namespace

namespace {

/// Exact E I_j / variance of white noise (per sample 1/dt), quantization and the random walk at
/// Fourier frequency j (whittle_selection.hpp step 2): the tapered, detrended DFT is
/// U_j = sum_k a_k x_k, a_k = h_k z^k - (c h_k + d h_k k), z = e^{-i w_j}, [c d] = [H G] M^-1,
/// H = sum h_k z^k, G = sum h_k k z^k, M the normal matrix of the h-weighted line.
struct ExactColumns { double white, quantization, randomWalk; };
ExactColumns exactColumns(const std::vector<double>& h, double w, double dt) {
  using C = std::complex<double>;
  const std::size_t n = h.size();
  double s0 = 0, s1 = 0, s2 = 0, sh2 = 0;
  C H = 0, G = 0;
  const C step = std::polar(1.0, -w);
  C z = 1.0;
  for (std::size_t k = 0; k < n; ++k) {
    const double kk = double(k);
    s0 += h[k], s1 += h[k] * kk, s2 += h[k] * kk * kk, sh2 += h[k] * h[k];
    H += h[k] * z, G += h[k] * kk * z;
    z *= step;
    if ((k & 1023) == 1023) z = std::polar(1.0, -w * double(k + 1));  // no drift of |z|
  }
  const double det = s0 * s2 - s1 * s1;
  const C c = (H * s2 - G * s1) / det, d = (G * s0 - H * s1) / det;
  // Walk: A(i) = sum_{k>=i} a_k for i = 1..n-1, accumulated from the end.
  double white = 0, quant = 0, walk = 0;
  C tail = 0, next = 0;  // a_{k+1}
  const C back = std::conj(step);
  C zk = std::polar(1.0, -w * double(n - 1));
  for (std::size_t kk = n; kk-- > 0;) {
    const double k = double(kk);
    if ((kk & 1023) == 0) zk = std::polar(1.0, -w * k);  // no drift of |z^k|
    const C a = h[kk] * (zk - c - d * k);
    zk *= back;
    white += std::norm(a);
    quant += std::norm(a - next);
    tail += a;
    if (kk >= 1) walk += std::norm(tail);
    next = a;
  }
  quant += std::norm(next);  // the e_{-1} term: coefficient -a_0
  return {white / (dt * sh2), quant / (dt * dt * sh2), walk * dt / sh2};
}

/// exactColumns at dt = 1 for j = 1..kExactOrdinates of a record of n samples, cached: they depend
/// on n only (the taper and the line), so the channels of one record share them, computed once even
/// when two threads' channels ask at the same moment (OnceCache). White scales as 1/dt,
/// quantization as 1/dt^2, the walk as dt. (Never evicted: a process sees a few lengths.)
const std::vector<ExactColumns>& exactColumnsCached(const std::vector<double>& h) {
  static OnceCache<std::size_t, std::vector<ExactColumns>> cache;
  return cache.get(h.size(), [&] {
    std::vector<ExactColumns> cols;
    for (std::size_t j = 1; j <= kExactOrdinates; ++j)
      cols.push_back(exactColumns(h, 2.0 * kPi * double(j) / double(h.size()), 1.0));
    return cols;
  });
}

/// The slope's weights g and the per-unit variances of the fixed terms (whittleSlopeVariance) at
/// dt = 1, cached by n like exactColumnsCached.
struct SlopeKernel {
  std::shared_ptr<std::vector<double>> g;
  double white = 0, quantization = 0, walk = 0, flicker = 0;
};
SlopeKernel slopeKernel(const std::vector<double>& h) {
  const std::size_t n = h.size();
  double s0 = 0, s1 = 0, s2 = 0;
  for (std::size_t k = 0; k < n; ++k) s0 += h[k], s1 += h[k] * double(k), s2 += h[k] * double(k) * double(k);
  SlopeKernel K;
  K.g = std::make_shared<std::vector<double>>(n);
  std::vector<double>& g = *K.g;
  for (std::size_t k = 0; k < n; ++k) g[k] = h[k] * (s0 * double(k) - s1) / (s0 * s2 - s1 * s1);
  double tail = 0.0, next = 0.0;
  for (std::size_t k = n; k-- > 0;) {
    K.white += g[k] * g[k];
    K.quantization += (g[k] - next) * (g[k] - next);
    tail += g[k];
    if (k >= 1) K.walk += tail * tail;
    next = g[k];
  }
  K.quantization += next * next;
  // S(w) = 1 / |w| at B^2 = 1, by the rule of a four-fold zero-padded transform (G(0) = 0: the
  // weights sum to zero).
  K.flicker = paddedPowerSum(g, 4, [](double w) { return 1.0 / w; }) / (4.0 * double(n));
  return K;
}
const SlopeKernel& slopeKernelCached(const std::vector<double>& h) {
  static OnceCache<std::size_t, SlopeKernel> cache;
  return cache.get(h.size(), [&] { return slopeKernel(h); });
}

}  // namespace

std::vector<double> whittleExpectedLevels(const WhittleBins& bins, const LatentModel& model) {
  LatentTermSet s{model.quantization > 0.0, model.white > 0.0, int(model.gm.size()), model.flicker > 0.0,
                  model.randomWalk > 0.0, false};
  std::vector<double> T;
  Eigen::VectorXd th(static_cast<Eigen::Index>(s.parameterCount() - model.gm.size()));
  Eigen::Index j = 0;
  if (s.quantization) th(j++) = model.quantization * model.quantization;
  if (s.white) th(j++) = model.white * model.white;
  for (const GmTerm& g : model.gm) th(j++) = g.sigma * g.sigma, T.push_back(g.tau);
  if (s.flicker) th(j++) = model.flicker * model.flicker;
  if (s.randomWalk) th(j++) = model.randomWalk * model.randomWalk;
  const Eigen::VectorXd f = design(bins, bins.level.size(), s, T) * th;
  return std::vector<double>(f.data(), f.data() + f.size());
}

double whittleM2LogLik(const WhittleBins& bins, const std::vector<double>& f) {
  if (f.size() != bins.level.size()) throw InputError("Whittle: one level per bin expected");
  return m2LogLik(bins, Eigen::Map<const Eigen::VectorXd>(f.data(), Eigen::Index(f.size())));
}

double whittleSlopeVariance(const WhittleBins& bins, const LatentModel& model) {
  if (!bins.slopeWeights) throw InputError("Whittle: slope variance of empty bins");
  const std::vector<double>& g = *bins.slopeWeights;
  const double dt = bins.dt;
  double v = bins.slopeWhite * model.white * model.white / dt +
             bins.slopeQuantization * model.quantization * model.quantization / (dt * dt) +
             bins.slopeWalk * model.randomWalk * model.randomWalk * dt +
             bins.slopeFlicker * model.flicker * model.flicker;
  for (const GmTerm& gm : model.gm) {
    const double phi = std::exp(-dt / gm.tau);
    // sum_k g_k y_k, y_k = sum_l phi^|k-l| g_l = f_k + b_k - g_k (forward and backward passes)
    const std::size_t n = g.size();
    std::vector<double> f(n);
    double acc = 0.0;
    for (std::size_t k = 0; k < n; ++k) f[k] = acc = g[k] + phi * acc;
    double b = 0.0, sum = 0.0;
    for (std::size_t k = n; k-- > 0;) {
      b = g[k] + phi * b;
      sum += g[k] * (f[k] + b - g[k]);
    }
    v += gm.sigma * gm.sigma * sum;
  }
  return v / (dt * dt);
}

WhittleBins whittleBins(const std::vector<double>& x, double dt, const RoundingLattice& lattice) {
  if (!(std::isfinite(dt) && dt > 0.0)) throw InputError("Whittle: sample interval must be > 0");
  if (x.size() < 64) throw InputError("Whittle: need at least 64 samples, got " + std::to_string(x.size()));
  const Periodogram p = taperedPeriodogram(x, kTaperFraction, Detrend::Linear);
  WhittleBins b;
  b.dt = dt;
  b.lattice = lattice;
  const std::size_t n = p.taper.size();
  b.slope = p.slope / dt;
  const SlopeKernel& K = slopeKernelCached(p.taper);
  b.slopeWeights = K.g;
  b.slopeWhite = K.white, b.slopeQuantization = K.quantization, b.slopeWalk = K.walk, b.slopeFlicker = K.flicker;
  const std::size_t last = (n % 2 == 0) ? n / 2 - 1 : n / 2;  // Nyquist left out
  const double dw = 2.0 * kPi / double(n);
  LatentModel unit[4];
  unit[0].quantization = 1.0, unit[1].white = 1.0, unit[2].flicker = 1.0, unit[3].randomWalk = 1.0;
  if (lattice.active()) unit[0].quantization = lattice.step / std::sqrt(12.0), unit[0].lattice = lattice;
  const double unitQ2 = unit[0].quantization * unit[0].quantization;
  const LatentSpectrum unitPsd[4] = {{unit[0], dt}, {unit[1], dt}, {unit[2], dt}, {unit[3], dt}};
  for (std::size_t j = 1; j <= last;) {
    const std::size_t width =
        j <= kSingleOrdinates ? 1 : std::max<std::size_t>(1, std::size_t(kBinWidth * double(j)));
    const std::size_t hi = std::min(last + 1, j + width);  // [j, hi)
    double sum = 0.0;
    for (std::size_t i = j; i < hi; ++i) sum += p.I[i];
    const std::size_t cnt = hi - j;
    b.count.push_back(double(cnt) / p.varianceInflation);
    b.level.push_back(sum / double(cnt));
    b.wHigh.push_back(p.w[hi - 1]);
    std::vector<double> nodes, sines;
    const std::size_t m = std::min(cnt, kNodes);
    for (std::size_t q = 0; q < m; ++q)
      nodes.push_back(dw * (double(j) + (double(q) + 0.5) * double(cnt) / double(m) - 0.5));
    for (double w : nodes) sines.push_back(std::sin(0.5 * w));
    double col[4] = {0, 0, 0, 0};
    for (int t = 0; t < 4; ++t) {
      for (std::size_t k = 0; k < nodes.size(); ++k) col[t] += unitPsd[t](nodes[k], sines[k]);
      col[t] /= double(nodes.size());
    }
    col[0] /= unitQ2;
    double factor = 1.0;
    if (cnt == 1 && j <= kExactOrdinates && j < last) {
      const ExactColumns& e = exactColumnsCached(p.taper)[j - 1];
      const double w = dw * double(j), s = std::sin(0.5 * w);
      const double classical = 4.0 * s * s / (dt * dt);  // the classical quantization PSD at unit Q^2
      const double lat = lattice.active() ? latticeQuantizationPsd(lattice, dt, w) / unitQ2 / classical : 1.0;
      col[0] = lat * e.quantization / (dt * dt), col[1] = e.white / dt, col[3] = e.randomWalk * dt;
      factor = col[1] / (1.0 / dt);  // the white PSD is 1/dt at unit N^2
      col[2] *= factor;
    }
    b.nodes.push_back(nodes);
    b.nodeSin.push_back(sines);
    b.lowFactor.push_back(factor);
    b.quantization.push_back(col[0]);
    b.white.push_back(col[1]);
    b.flicker.push_back(col[2]);
    b.randomWalk.push_back(col[3]);
    j = hi;
  }
  return b;
}

WhittleSetFit whittleFitSet(const WhittleBins& bins, double wMax, const LatentTermSet& set,
                            const LatentModel& start, double minT, double maxT) {
  if (set.drift || set.ar) throw InputError("Whittle: sets with drift or AR are not scored");
  if (set.gm != int(start.gm.size())) throw InputError("Whittle: the start lacks the set's GM terms");
  std::size_t nb = 0;
  while (nb < bins.wHigh.size() && bins.wHigh[nb] <= wMax) ++nb;
  WhittleSetFit out;
  if (nb < set.parameterCount() + 2) return out;
  Eigen::VectorXd theta0(static_cast<Eigen::Index>(set.parameterCount() - start.gm.size()));
  std::vector<double> T;
  Eigen::Index j = 0;
  if (set.quantization) theta0(j++) = start.quantization * start.quantization;
  if (set.white) theta0(j++) = start.white * start.white;
  for (const GmTerm& g : start.gm) {
    theta0(j++) = g.sigma * g.sigma;
    T.push_back(std::clamp(g.tau, minT, maxT));
  }
  if (set.flicker) theta0(j++) = start.flicker * start.flicker;
  if (set.randomWalk) theta0(j++) = start.randomWalk * start.randomWalk;

  TauFit best = evaluate(bins, nb, set, T, theta0);
  if (set.gm == 1) {
    best = goldenT(bins, nb, set, best, 0, std::max(minT, T[0] / 4.0), std::min(maxT, T[0] * 4.0));
  } else if (set.gm == 2) {
    for (int round = 0; round < 3; ++round) {
      const double r = round == 0 ? 4.0 : round == 1 ? 2.0 : 1.3;
      const double t1 = best.T[0], t2 = best.T[1];
      best = goldenT(bins, nb, set, best, 0, std::max(minT, t1 / r), std::min(t2 / 1.5, t1 * r));
      best = goldenT(bins, nb, set, best, 1, std::max(1.5 * best.T[0], t2 / r), std::min(maxT, t2 * r));
    }
  }
  LatentModel& m = out.model;
  m.lattice = bins.lattice;
  j = 0;
  const Eigen::VectorXd& th = best.profile.theta;
  auto next = [&]() { return std::sqrt(std::max(th(j++), 0.0)); };
  if (set.quantization) m.quantization = next();
  if (set.white) m.white = next();
  for (double t : best.T) m.gm.push_back({next(), t});
  if (set.flicker) m.flicker = next();
  if (set.randomWalk) m.randomWalk = next();
  out.m2LogLik = best.profile.m2ll;
  out.valid = best.profile.allPositive && std::isfinite(out.m2LogLik);
  return out;
}

}  // namespace sinsim::errormodels::fit
