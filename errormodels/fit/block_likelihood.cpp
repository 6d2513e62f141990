#include "errormodels/fit/block_likelihood.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

#include "common/constants.hpp"
#include "common/error.hpp"
#include "errormodels/flicker_gms.hpp"

namespace sinsim::errormodels::fit {

BlockMeans blockMeans(const std::vector<double>& x, double dt, std::size_t perBlock) {
  if (!(std::isfinite(dt) && dt > 0.0)) throw InputError("block likelihood: sample interval must be > 0");
  if (perBlock == 0) throw InputError("block likelihood: a block needs at least one sample");
  const std::size_t M = x.size() / perBlock;
  if (M < 8) throw InputError("block likelihood: " + std::to_string(M) + " blocks, need at least 8");
  BlockMeans b;
  b.dt = dt;
  b.perBlock = perBlock;
  b.y.resize(M);
  for (std::size_t j = 0; j < M; ++j) {
    double s = 0.0;
    for (std::size_t k = j * perBlock; k < (j + 1) * perBlock; ++k) s += x[k];
    if (!std::isfinite(s)) throw InputError("block likelihood: non-finite sample in block " + std::to_string(j));
    b.y[j] = s / double(perBlock);
  }
  return b;
}

namespace {

using Component = BlockComponent;

/// The discrete AR(1) at dt of variance s2 and correlation time T, averaged over B samples.
Component gmComponent(double s2, double T, double dt, std::size_t B) {
  const double phi = std::exp(-dt / T);
  const double eta = -s2 * std::expm1(-2.0 * dt / T);  // sigma^2 (1 - phi^2)
  double g = 0.0, pr = 1.0, sg2 = 0.0, spg = 0.0;      // g_r, phi^(r-1)
  for (std::size_t r = 1; r <= B; ++r) {
    g = 1.0 + phi * g;
    sg2 += g * g;
    spg += pr * g;
    pr *= phi;
  }
  const double Bd = double(B);
  Component k;
  k.f = std::pow(phi, Bd);
  k.h = phi * g / Bd;
  k.q = -s2 * std::expm1(-2.0 * Bd * dt / T);
  k.r = eta * sg2 / (Bd * Bd);
  k.c = eta * spg / Bd;
  k.p0 = s2;
  return k;
}

/// Unit-B^2 flicker as GMs two per decade (flicker_gms.hpp, as the bias_instability effect), from
/// dt / 10 to 10 N dt; those faster than L / 4 are white at the block level and folded into r.
std::vector<Component> flickerComponents(double dt, std::size_t B, std::size_t M) {
  const double s2 = flickerGmVariance();
  const double L = dt * double(B), lo = dt / 10.0, hi = 10.0 * L * double(M);
  std::vector<Component> out;
  Component folded;
  for (int j = 0;; ++j) {
    const double T = flickerGmTau(lo, j);
    if (T > hi) break;
    const Component k = gmComponent(s2, T, dt, B);
    if (T < L / 4.0) folded.r += k.r + k.h * k.h * k.p0;  // its block-mean variance
    else out.push_back(k);
  }
  out.push_back(folded);  // a state-less component: h = f = q = c = 0
  return out;
}

/// The components of `model` (flicker from the unit components `flicker`).
std::vector<Component> componentsOf(const LatentModel& model, double dt, std::size_t B,
                                    const std::vector<Component>& flicker) {
  const double L = dt * double(B);
  std::vector<Component> out;
  Component white;
  white.r = model.white * model.white / L;
  out.push_back(white);
  if (model.quantization > 0.0) {
    const double Q2 = model.quantization * model.quantization;
    out.push_back({0.0, -1.0 / L, Q2, Q2 / L, Q2 / (L * L), Q2});
  }
  for (const GmTerm& g : model.gm) out.push_back(gmComponent(g.sigma * g.sigma, g.tau, dt, B));
  if (model.flicker > 0.0) {
    const double b2 = model.flicker * model.flicker;
    for (Component k : flicker) {
      k.q *= b2, k.c *= b2, k.r *= b2, k.p0 *= b2;
      out.push_back(k);
    }
  }
  if (model.randomWalk > 0.0) {
    const double K2 = model.randomWalk * model.randomWalk;
    out.push_back({1.0, 1.0, K2 * L, K2 * L / 2.0, K2 * L / 3.0, 0.0});
  }
  return out;
}

/// The augmented Kalman filter over the block means (block_likelihood.hpp step 3) with the
/// columns z_j = (y_j, 1, t_j, extra_0j, ...), t_j the block's centre from the record's middle:
/// the innovations' cross-products A = sum e e' / F (lower triangle) and sum ln F. P is kept in
/// full (n <= ~16 states); once the gain is steady only the column means are propagated. False
/// where an innovation variance is not positive.
bool whitenColumns(const BlockMeans& b, const std::vector<Component>& comps,
                   const std::vector<std::vector<double>>& extra, Eigen::MatrixXd& A, double& sumLogF) {
  std::vector<double> f, h, q, c, P;
  double r = 0.0;
  for (const Component& k : comps) {
    r += k.r;
    if (k.h == 0.0 && k.c == 0.0) continue;  // no state
    f.push_back(k.f), h.push_back(k.h), q.push_back(k.q), c.push_back(k.c);
  }
  const std::size_t n = f.size(), cols = 3 + extra.size();
  P.assign(n * n, 0.0);
  {
    std::size_t i = 0;
    for (const Component& k : comps)
      if (k.h != 0.0 || k.c != 0.0) P[i * n + i] = k.p0, ++i;
  }
  std::vector<double> Ph(n), g(n), m(cols * n, 0.0), z(cols), e(cols);  // m: the columns' state means
  A = Eigen::MatrixXd::Zero(Eigen::Index(cols), Eigen::Index(cols));
  const std::size_t M = b.y.size();
  const double L = b.dt * double(b.perBlock), mid = 0.5 * double(M - 1);
  double F = 0.0, logF = 0.0;
  sumLogF = 0.0;
  bool steady = false;
  for (std::size_t j = 0; j < M; ++j) {
    if (!steady) {
      F = r;
      for (std::size_t i = 0; i < n; ++i) {
        double s = 0.0;
        for (std::size_t k = 0; k < n; ++k) s += P[i * n + k] * h[k];
        Ph[i] = s;
        F += h[i] * s;
      }
      if (!(F > 0.0) || !std::isfinite(F)) return false;
      logF = std::log(F);
      for (std::size_t i = 0; i < n; ++i) g[i] = (f[i] * Ph[i] + c[i]) / F;
      double change = 0.0, scale = 1e-300;
      // P stays symmetric: the upper triangle updated, mirrored to the lower.
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t k = i; k < n; ++k) {
          double& pik = P[i * n + k];
          const double v = f[i] * f[k] * pik - F * g[i] * g[k] + (i == k ? q[i] : 0.0);
          change = std::max(change, std::fabs(v - pik));
          if (i == k) scale = std::max(scale, std::fabs(v));
          pik = P[k * n + i] = v;
        }
      // Steady: the covariance moved by < 1e-11 of the largest variance in a step.
      steady = j > 0 && change <= 1e-11 * scale;
    }
    z[0] = b.y[j], z[1] = 1.0, z[2] = (double(j) - mid) * L;
    for (std::size_t col = 3; col < cols; ++col) z[col] = extra[col - 3][j];
    for (std::size_t col = 0; col < cols; ++col) {
      double* mc = m.data() + col * n;  // (m is empty without states)
      double pred = 0.0;
      for (std::size_t i = 0; i < n; ++i) pred += h[i] * mc[i];
      e[col] = z[col] - pred;
      for (std::size_t i = 0; i < n; ++i) mc[i] = f[i] * mc[i] + g[i] * e[col];
    }
    sumLogF += logF;
    for (std::size_t u = 0; u < cols; ++u)
      for (std::size_t v = 0; v <= u; ++v) A(Eigen::Index(u), Eigen::Index(v)) += e[u] * e[v] / F;
  }
  return true;
}

/// The restricted likelihoods and the GLS slope (block_likelihood.hpp step 3).
BlockLikelihood filter(const BlockMeans& b, const std::vector<Component>& comps) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  Eigen::MatrixXd A;
  double sumLogF = 0.0;
  if (!whitenColumns(b, comps, {}, A, sumLogF)) return {kInf, kInf, 0.0, 0.0};
  // Columns 1 and t: X = their innovation products, a their products with y's. Without drift the
  // level alone is profiled out (X = [1]); with drift the level and the slope.
  const double x11 = A(1, 1), x12 = A(2, 1), x22 = A(2, 2), a1 = A(1, 0), a2 = A(2, 0);
  const double det = x11 * x22 - x12 * x12;
  if (!(det > 0.0 && x11 > 0.0)) return {kInf, kInf, 0.0, 0.0};
  const double beta1 = (x22 * a1 - x12 * a2) / det, beta2 = (x11 * a2 - x12 * a1) / det;
  BlockLikelihood out;
  out.m2LogLik = sumLogF + A(0, 0) - a1 * a1 / x11 + std::log(x11);
  out.m2LogLikDrift = sumLogF + A(0, 0) - (a1 * beta1 + a2 * beta2) + std::log(x11);
  out.slope = beta2;
  out.slopeVariance = x11 / det;
  return out;
}

/// Log parameters of a set: log Q^2, log N^2, (log sigma^2, log T) per GM, log B^2, log K^2.
std::vector<double> logParameters(const LatentTermSet& s, const LatentModel& m) {
  std::vector<double> p;
  auto v = [&](double a) { p.push_back(std::log(std::max(a * a, 1e-300))); };
  if (s.quantization) v(m.quantization);
  if (s.white) v(m.white);
  for (const GmTerm& g : m.gm) v(g.sigma), p.push_back(std::log(g.tau));
  if (s.flicker) v(m.flicker);
  if (s.randomWalk) v(m.randomWalk);
  return p;
}

LatentModel modelOf(const LatentTermSet& s, const std::vector<double>& p) {
  LatentModel m;
  std::size_t i = 0;
  auto v = [&]() { return std::exp(0.5 * p[i++]); };
  if (s.quantization) m.quantization = v();
  if (s.white) m.white = v();
  for (int k = 0; k < s.gm; ++k) {
    const double sigma = v();
    m.gm.push_back({sigma, std::exp(p[i++])});
  }
  if (s.flicker) m.flicker = v();
  if (s.randomWalk) m.randomWalk = v();
  return m;
}

/// BFGS on a smooth function of a few log parameters: central-difference gradient, the start's
/// inverse Hessian from the central second differences, backtracking line search.
template <class Fn>
std::vector<double> minimiseBfgs(Fn fn, std::vector<double> x0, double& fx) {
  const auto n = static_cast<Eigen::Index>(x0.size());
  Eigen::VectorXd x = Eigen::Map<Eigen::VectorXd>(x0.data(), n);
  auto at = [&](const Eigen::VectorXd& v) { return fn(std::vector<double>(v.data(), v.data() + v.size())); };
  constexpr double h = 5e-3;
  fx = at(x);
  if (!std::isfinite(fx)) return x0;
  Eigen::VectorXd grad(n), curv(n);
  auto gradient = [&](const Eigen::VectorXd& v, double fv, bool wantCurv) {
    for (Eigen::Index i = 0; i < n; ++i) {
      Eigen::VectorXd a = v, b = v;
      a(i) += h, b(i) -= h;
      const double fa = at(a), fb = at(b);
      grad(i) = (fa - fb) / (2.0 * h);
      if (wantCurv) curv(i) = (fa - 2.0 * fv + fb) / (h * h);
    }
  };
  gradient(x, fx, true);
  if (!grad.allFinite()) return x0;
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index i = 0; i < n; ++i) H(i, i) = 1.0 / std::max(curv(i), 1.0);
  for (int it = 0; it < 40; ++it) {
    Eigen::VectorXd step = -H * grad;
    const double maxStep = step.cwiseAbs().maxCoeff();
    if (maxStep > 2.0) step *= 2.0 / maxStep;  // at most a factor e^2 per iteration
    double fn1 = std::numeric_limits<double>::infinity();
    Eigen::VectorXd x1 = x;
    for (int k = 0; k < 20; ++k) {
      x1 = x + step;
      fn1 = at(x1);
      if (fn1 <= fx + 1e-4 * grad.dot(step)) break;
      step *= 0.5;
    }
    if (!(fn1 < fx)) break;
    const Eigen::VectorXd g0 = grad;
    const double gain = fx - fn1;
    x = x1, fx = fn1;
    gradient(x, fx, false);
    if (!grad.allFinite()) break;
    if (gain < 1e-4) break;
    const Eigen::VectorXd s = step, y = grad - g0;
    const double sy = s.dot(y);
    if (sy > 1e-12) {
      const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(n, n);
      const double rho = 1.0 / sy;
      H = (I - rho * s * y.transpose()) * H * (I - rho * y * s.transpose()) + rho * s * s.transpose();
    }
  }
  return std::vector<double>(x.data(), x.data() + n);
}

}  // namespace

BlockLikelihood blockLikelihood(const BlockMeans& b, const LatentModel& model) {
  if (model.arVariance > 0.0) throw InputError("block likelihood: an AR term is not modelled");
  const std::vector<Component> fl =
      model.flicker > 0.0 ? flickerComponents(b.dt, b.perBlock, b.y.size()) : std::vector<Component>{};
  return filter(b, componentsOf(model, b.dt, b.perBlock, fl));
}

Eigen::MatrixXd blockGlsProducts(const BlockMeans& b, const LatentModel& model,
                                 const std::vector<std::vector<double>>& extra) {
  if (model.arVariance > 0.0) throw InputError("block likelihood: an AR term is not modelled");
  for (const auto& col : extra)
    if (col.size() != b.y.size()) throw InputError("block likelihood: a regressor of another length than the blocks");
  const std::vector<Component> fl =
      model.flicker > 0.0 ? flickerComponents(b.dt, b.perBlock, b.y.size()) : std::vector<Component>{};
  Eigen::MatrixXd A;
  double sumLogF = 0.0;
  if (!whitenColumns(b, componentsOf(model, b.dt, b.perBlock, fl), extra, A, sumLogF))
    throw InputError("block likelihood: the model's block variance is not positive");
  return A.selfadjointView<Eigen::Lower>();
}

BlockObjective::BlockObjective(const BlockMeans& b, const WhittleBins* high, double wMax, bool flicker)
    : b_(b), high_(high) {
  if (flicker) flicker_ = flickerComponents(b.dt, b.perBlock, b.y.size());
  if (!high) return;
  const double wLow = 2.0 * kPi / double(b.perBlock);
  while (b0_ < high->wHigh.size() && (b0_ == 0 || high->wHigh[b0_ - 1] < wLow)) ++b0_;
  b1_ = b0_;
  while (b1_ < high->wHigh.size() && high->wHigh[b1_] <= wMax) ++b1_;
}

double BlockObjective::operator()(const LatentModel& m, bool drift) const {
  if (m.flicker > 0.0 && flicker_.empty()) throw InputError("block likelihood: objective built without flicker");
  const BlockLikelihood l = filter(b_, componentsOf(m, b_.dt, b_.perBlock, flicker_));
  double v = drift ? l.m2LogLikDrift : l.m2LogLik;
  if (b1_ > b0_) {
    const std::vector<double> f = whittleExpectedLevels(*high_, m);
    for (std::size_t i = b0_; i < b1_; ++i) {
      if (!(f[i] > 0.0)) return std::numeric_limits<double>::infinity();
      v += 2.0 * high_->count[i] * (std::log(f[i]) + high_->level[i] / f[i]);
    }
  }
  return v;
}

BlockSetFit blockFitSet(const BlockMeans& b, const WhittleBins* high, double wMax, const LatentTermSet& set,
                        const LatentModel& start, double minT, double maxT) {
  if (set.drift || set.ar) throw InputError("block likelihood: sets with drift or AR are not scored");
  if (set.gm != int(start.gm.size())) throw InputError("block likelihood: the start lacks the set's GM terms");
  const BlockObjective objectiveOf(b, high, wMax, set.flicker);
  auto objective = [&](const std::vector<double>& p, bool drift) {
    const LatentModel m = modelOf(set, p);
    for (const GmTerm& g : m.gm)
      if (!(g.tau >= minT && g.tau <= maxT)) return std::numeric_limits<double>::infinity();
    for (std::size_t k = 1; k < m.gm.size(); ++k)
      if (m.gm[k].tau < 1.5 * m.gm[k - 1].tau) return std::numeric_limits<double>::infinity();
    return objectiveOf(m, drift);
  };
  LatentModel s = start;
  for (GmTerm& g : s.gm) g.tau = std::clamp(g.tau, minT, maxT);
  for (std::size_t k = 1; k < s.gm.size(); ++k) s.gm[k].tau = std::max(s.gm[k].tau, 1.6 * s.gm[k - 1].tau);
  BlockSetFit out;
  const std::vector<double> p =
      minimiseBfgs([&](const std::vector<double>& v) { return objective(v, false); }, logParameters(set, s), out.m2LogLik);
  out.model = modelOf(set, p);
  out.blocks = blockLikelihood(b, out.model);
  out.valid = std::isfinite(out.m2LogLik);
  // With drift: refitted only where the slope could pay its cost (at the plain fit its likelihood
  // ratio is within kDriftRefit of the chi^2_1 1 % point; a refit gains a few units at most).
  constexpr double kDriftRefit = 4.0;
  out.m2LogLikDrift = out.m2LogLik - (out.blocks.m2LogLik - out.blocks.m2LogLikDrift);
  out.modelDrift = out.model;
  if (out.valid && out.m2LogLik - out.m2LogLikDrift > kDriftSlopeChi2 - kDriftRefit) {
    const std::vector<double> q =
        minimiseBfgs([&](const std::vector<double>& v) { return objective(v, true); }, p, out.m2LogLikDrift);
    out.modelDrift = modelOf(set, q);
  }
  return out;
}

}  // namespace sinsim::errormodels::fit
