#include "errormodels/fit/ar_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "common/error.hpp"
#include "errormodels/ar_model.hpp"

namespace sinsim::errormodels::fit {

std::string toString(ArMethod method) {
  return method == ArMethod::Burg ? "burg" : "yule-walker";
}

namespace {

// Throws InputError naming the first non-finite sample; called only when a sum was not finite.
void throwNonFinite(const double* x, std::size_t n, const char* what) {
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(x[i])) {
      std::ostringstream s;
      s << what << ": sample " << i << " is not finite (" << x[i] << ")";
      throw InputError(s.str());
    }
  }
  throw InputError(std::string(what) + ": the series overflows double precision");
}

void checkOrder(std::size_t n, std::size_t order, const char* what) {
  if (order < 1 || order + 2 >= n + 0 || n < 3) {
    std::ostringstream s;
    s << what << ": order must satisfy 1 <= p < N - 2 (arburg's limit), got p = " << order
      << " with N = " << n << " samples";
    throw InputError(s.str());
  }
}

// Sample mean with the finite check folded in.
double meanOf(const std::vector<double>& x, const char* what) {
  double s = 0.0;
  for (double v : x) s += v;
  if (!std::isfinite(s)) throwNonFinite(x.data(), x.size(), what);
  return s / static_cast<double>(x.size());
}

// Lagged products c_d = sum_{u=0}^{N-1-d} (x[u] - mu)(x[u+d] - mu), d = 0..maxLag. Cache-blocked:
// each block (plus maxLag samples of overlap) is centred into a small buffer once and visited for
// all lags; block partial sums are added to the totals, which keeps the rounding error near
// eps * (block + N / block) instead of eps * N, and avoids writing a centred copy of x.
std::vector<double> laggedProducts(const double* x, std::size_t n, std::size_t maxLag, double mu) {
  std::vector<double> c(maxLag + 1, 0.0);
  constexpr std::size_t kBlock = 2048;
  std::vector<double> buf(kBlock + maxLag);
  for (std::size_t start = 0; start < n; start += kBlock) {
    const std::size_t end = std::min(n, start + kBlock);
    const std::size_t bufLen = std::min(n, end + maxLag) - start;
    for (std::size_t i = 0; i < bufLen; ++i) buf[i] = x[start + i] - mu;
    for (std::size_t d = 0; d <= maxLag; ++d) {
      // u runs over [start, end) with u + d < n
      const std::size_t uEnd = std::min(end, n > d ? n - d : 0);
      if (uEnd <= start) continue;
      const auto len = static_cast<Eigen::Index>(uEnd - start);
      c[d] += Eigen::Map<const Eigen::VectorXd>(buf.data(), len)
                  .dot(Eigen::Map<const Eigen::VectorXd>(buf.data() + d, len));
    }
  }
  return c;
}

// Fills the uncertainty fields from a, E and n.
void finishUncertainty(ArFit& fit) {
  fit.covariance = arCoefficientCovariance(fit.a, fit.n);
  fit.stdError.resize(fit.order);
  for (std::size_t i = 0; i < fit.order; ++i)
    fit.stdError[i] = std::sqrt(std::max(0.0, fit.covariance(static_cast<Eigen::Index>(i),
                                                             static_cast<Eigen::Index>(i))));
  fit.drivingVarianceStdError = std::sqrt(2.0 / static_cast<double>(fit.n)) * fit.drivingVariance;
}

// a^(m+1)_i = a^(m)_i + k a^(m)_{m+1-i}, a_0 = 1 (Levinson step, real data).
void levinsonStep(std::vector<double>& a, double k) {
  const std::size_t m = a.size() - 1;
  std::vector<double> next(m + 2, 0.0);
  next[0] = 1.0;
  for (std::size_t i = 1; i <= m; ++i) next[i] = a[i] + k * a[m + 1 - i];
  next[m + 1] = k;
  a.swap(next);
}

// Burg by the lattice recursion over stored forward/backward errors (Burg 1975; the loop of
// Octave signal's arburg.m). Returns reflection coefficients and sum(f^2 + b^2) per stage.
void burgDirect(const double* x, std::size_t n, std::size_t order, std::vector<double>& k,
                std::vector<double>& denominators) {
  // f[i] = f_m[i + m + 1], b[i] = b_m[i + m] for i = 0..N-m-2: the pairs (f_m[n], b_m[n-1]).
  std::vector<double> f(x + 1, x + n), b(x, x + n - 1);
  for (std::size_t m = 0; m < order; ++m) {
    const std::size_t len = n - m - 1;
    Eigen::Map<Eigen::VectorXd> fv(f.data(), static_cast<Eigen::Index>(len));
    Eigen::Map<Eigen::VectorXd> bv(b.data(), static_cast<Eigen::Index>(len));
    const double num = fv.dot(bv);
    const double den = fv.squaredNorm() + bv.squaredNorm();
    const double km = den > 0.0 ? -2.0 * num / den : 0.0;
    k.push_back(km);
    denominators.push_back(den);
    if (m + 1 == order) break;
    // f_{m+1}[n] = f_m[n] + k b_m[n-1];  b_{m+1}[n] = b_m[n-1] + k f_m[n]  (n = m+1..N-1);
    // the next stage pairs f_{m+1}[n] (n >= m+2) with b_{m+1}[n-1] (n-1 >= m+1).
    for (std::size_t i = 0; i + 1 < len; ++i) {
      const double fNext = f[i + 1] + km * b[i + 1];
      const double bNext = b[i] + km * f[i];
      f[i] = fNext;
      b[i] = bNext;
    }
  }
}

// Burg from lagged products. For the order-m polynomial a (a_0 = 1) the three sums of a Burg
// stage over n = m+1..N-1,
//   F = sum f_m[n]^2,  B = sum b_m[n-1]^2,  C = sum f_m[n] b_m[n-1],
// with f_m[n] = sum_i a_i x[n-i] and b_m[n-1] = sum_i a_i x[n-1-m+i], are quadratic forms in a
// whose entries are partial lagged-product sums G(s, e, d) = sum_{u=s}^{e} x[u] x[u+d], obtained
// from c_d minus at most m+1 head and tail products (Vos 2013 uses the same idea).
// c = laggedProducts(x, n, order, mu); x is centred by mu on the fly.
void burgFast(const double* x, std::size_t n, double mu, const std::vector<double>& c,
              std::size_t order, std::vector<double>& k, std::vector<double>& denominators) {
  // G(s, e, d) with 0 <= s, e + d <= n - 1.
  auto G = [&](std::size_t s, std::size_t e, std::size_t d) {
    double head = 0.0, tail = 0.0;
    for (std::size_t u = 0; u < s; ++u) head += (x[u] - mu) * (x[u + d] - mu);
    for (std::size_t u = e + 1; u + d < n; ++u) tail += (x[u] - mu) * (x[u + d] - mu);
    return c[d] - head - tail;
  };
  std::vector<double> a{1.0};
  for (std::size_t m = 0; m < order; ++m) {
    double F = 0.0, B = 0.0, C = 0.0;
    for (std::size_t i = 0; i <= m; ++i) {
      for (std::size_t j = 0; j <= m; ++j) {
        const double w = a[i] * a[j];
        const std::size_t lo = std::min(i, j), hi = std::max(i, j);
        F += w * G(m + 1 - hi, n - 1 - hi, hi - lo);
        B += w * G(lo, n - 2 - m + lo, hi - lo);
        // x[n-i] x[n-1-m+j]: lag delta = i + j - 1 - m
        if (i + j >= m + 1)
          C += w * G(m + 1 - i, n - 1 - i, i + j - 1 - m);
        else
          C += w * G(j, n - 2 - m + j, m + 1 - i - j);
      }
    }
    const double den = F + B;
    const double km = den > 0.0 ? -2.0 * C / den : 0.0;
    k.push_back(km);
    denominators.push_back(den);
    levinsonStep(a, km);
  }
}

}  // namespace

ArFit burg(const std::vector<double>& x, std::size_t order, const ArOptions& options) {
  const std::size_t n = x.size();
  checkOrder(n, order, "burg");
  ArFit fit;
  fit.method = ArMethod::Burg;
  fit.order = order;
  fit.n = n;
  const double mean = meanOf(x, "burg");  // also rejects non-finite samples
  const double mu = options.demean ? mean : 0.0;
  fit.mean = mu;
  const auto nd = static_cast<double>(n);

  std::vector<double> denominators;
  double r0 = 0.0;
  bool done = false;
  if (options.burgAlgorithm != BurgAlgorithm::Direct) {
    const std::vector<double> c = laggedProducts(x.data(), n, order, mu);
    r0 = c[0] / nd;
    if (!std::isfinite(r0)) throwNonFinite(x.data(), n, "burg");
    if (!(r0 > 0.0)) throw InputError("burg: the series is constant (zero variance" +
                                      std::string(options.demean ? " after mean removal)" : ")"));
    burgFast(x.data(), n, mu, c, order, fit.reflection, denominators);
    done = true;
    if (options.burgAlgorithm == BurgAlgorithm::Auto) {
      // Predicted relative error of the fast form (see BurgAlgorithm): eps * gain * (sum|a|)^2.
      std::vector<double> a{1.0};
      double E = r0, mass = 0.0;
      for (double km : fit.reflection) {
        levinsonStep(a, km);
        E *= 1.0 - km * km;
      }
      for (double v : a) mass += std::abs(v);
      const double kappa = std::numeric_limits<double>::epsilon() * (r0 / E) * mass * mass;
      if (!(kappa <= 1e-11)) done = false;
    }
  }
  if (!done) {
    std::vector<double> centred;
    const double* data = x.data();
    if (mu != 0.0) {
      centred.resize(n);
      for (std::size_t i = 0; i < n; ++i) centred[i] = x[i] - mu;
      data = centred.data();
    }
    r0 = Eigen::Map<const Eigen::VectorXd>(data, static_cast<Eigen::Index>(n)).squaredNorm() / nd;
    if (!std::isfinite(r0)) throwNonFinite(x.data(), n, "burg");
    if (!(r0 > 0.0)) throw InputError("burg: the series is constant (zero variance" +
                                      std::string(options.demean ? " after mean removal)" : ")"));
    fit.reflection.clear();
    denominators.clear();
    burgDirect(data, n, order, fit.reflection, denominators);
  }

  fit.a = {1.0};
  fit.drivingVariancePath = {r0};
  double E = r0;
  for (double km : fit.reflection) {
    if (!(std::abs(km) <= 1.0))
      throw NumericalError("burg: reflection coefficient out of [-1, 1]; the data are degenerate");
    levinsonStep(fit.a, km);
    E *= 1.0 - km * km;  // arburg: new_v = v (1 - |k|^2)
    fit.drivingVariancePath.push_back(E);
  }
  fit.drivingVariance = E;
  const double kp = fit.reflection.back();
  // sum(f_p^2 + b_p^2) over n = p..N-1 equals (1 - k_p^2) times the stage-p denominator
  // (the Burg identity; statsmodels' pacf_burg uses it the same way).
  fit.residualVariance = (1.0 - kp * kp) * denominators.back() / (2.0 * (nd - double(order)));
  finishUncertainty(fit);
  return fit;
}

std::vector<double> biasedAutocovariance(const std::vector<double>& x, std::size_t maxLag) {
  if (x.empty()) throw InputError("autocovariance: empty series");
  if (maxLag >= x.size()) throw InputError("autocovariance: maxLag must be < N");
  std::vector<double> c = laggedProducts(x.data(), x.size(), maxLag, 0.0);
  for (double& v : c) v /= static_cast<double>(x.size());
  if (!std::isfinite(c[0])) throwNonFinite(x.data(), x.size(), "autocovariance");
  return c;
}

LevinsonResult levinsonDurbin(const std::vector<double>& r, std::size_t order) {
  if (r.size() <= order)
    throw InputError("levinsonDurbin: need autocovariance lags 0..p (" + std::to_string(order) +
                     "), got " + std::to_string(r.size()));
  if (!(std::isfinite(r[0]) && r[0] > 0.0))
    throw InputError("levinsonDurbin: r[0] must be positive and finite");
  LevinsonResult out;
  out.a = {1.0};
  out.variancePath = {r[0]};
  double E = r[0];
  for (std::size_t m = 1; m <= order; ++m) {
    double acc = r[m];
    for (std::size_t i = 1; i < m; ++i) acc += out.a[i] * r[m - i];
    const double km = -acc / E;
    if (!(std::abs(km) < 1.0))
      throw InputError("levinsonDurbin: autocovariance is not positive definite at lag " +
                       std::to_string(m));
    out.reflection.push_back(km);
    levinsonStep(out.a, km);
    E *= 1.0 - km * km;
    out.variancePath.push_back(E);
  }
  return out;
}

ArFit yuleWalkerFromAutocovariance(const std::vector<double>& r, std::size_t order,
                                   std::size_t n) {
  checkOrder(n, order, "yuleWalker");
  LevinsonResult lev = levinsonDurbin(r, order);
  ArFit fit;
  fit.method = ArMethod::YuleWalker;
  fit.order = order;
  fit.n = n;
  fit.a = std::move(lev.a);
  fit.reflection = std::move(lev.reflection);
  fit.drivingVariancePath = std::move(lev.variancePath);
  fit.drivingVariance = fit.drivingVariancePath.back();
  fit.residualVariance = fit.drivingVariance;
  finishUncertainty(fit);
  return fit;
}

ArFit yuleWalker(const std::vector<double>& x, std::size_t order, const ArOptions& options) {
  checkOrder(x.size(), order, "yuleWalker");
  const double mean = meanOf(x, "yuleWalker");  // also rejects non-finite samples
  const double mu = options.demean ? mean : 0.0;
  std::vector<double> r = laggedProducts(x.data(), x.size(), order, mu);
  for (double& v : r) v /= static_cast<double>(x.size());
  if (!(r[0] > 0.0)) throw InputError("yuleWalker: the series is constant");
  ArFit fit = yuleWalkerFromAutocovariance(r, order, x.size());
  fit.mean = mu;
  return fit;
}

Eigen::MatrixXd arCoefficientCovariance(const std::vector<double>& a, std::size_t n) {
  if (a.size() < 2 || a[0] != 1.0) throw InputError("AR polynomial must be [1, a1, ..., ap]");
  if (n == 0) throw InputError("AR covariance: n must be positive");
  const auto p = static_cast<Eigen::Index>(a.size() - 1);
  Eigen::MatrixXd L = Eigen::MatrixXd::Zero(p, p), U = Eigen::MatrixXd::Zero(p, p);
  for (Eigen::Index i = 0; i < p; ++i) {
    for (Eigen::Index j = 0; j <= i; ++j) {
      L(i, j) = a[static_cast<std::size_t>(i - j)];
      U(i, j) = a[static_cast<std::size_t>(p - (i - j))];
    }
  }
  return (L * L.transpose() - U * U.transpose()) / static_cast<double>(n);
}

std::vector<double> arCoefficients(const std::vector<double>& a) {
  if (a.size() < 2 || a[0] != 1.0) throw InputError("AR polynomial must be [1, a1, ..., ap]");
  return std::vector<double>(a.begin() + 1, a.end());
}

std::vector<std::complex<double>> arPoles(const std::vector<double>& a) {
  return ar::poles(arCoefficients(a));
}

double arMaxPoleMagnitude(const std::vector<double>& a) {
  return ar::largestPoleMagnitude(arCoefficients(a));
}

double arLongRunVariance(const std::vector<double>& a, double drivingVariance) {
  return ar::longRunVariance(arCoefficients(a), drivingVariance);
}

std::vector<double> arAutocovariance(const std::vector<double>& a, double drivingVariance,
                                     std::size_t maxLag) {
  return ar::autocovarianceOfVariance(arCoefficients(a), drivingVariance, maxLag);
}

std::optional<ArLessWhite> arLessWhite(const std::vector<double>& a, double drivingVariance, double whiteVariance) {
  if (a.size() < 2 || !(whiteVariance >= 0.0 && std::isfinite(whiteVariance))) return std::nullopt;
  const std::size_t p = a.size() - 1;
  std::vector<double> r = arAutocovariance(a, drivingVariance, p);
  r[0] -= whiteVariance;
  if (!(r[0] > 0.0)) return std::nullopt;
  try {
    LevinsonResult l = levinsonDurbin(r, p);
    if (!(l.variancePath.back() > 0.0)) return std::nullopt;
    return ArLessWhite{std::move(l.a), l.variancePath.back()};
  } catch (const InputError&) {
    return std::nullopt;  // not positive definite
  }
}

std::vector<double> arAllanVariance(const std::vector<double>& a, double drivingVariance,
                                    const std::vector<std::size_t>& m) {
  return ar::allanVariance(arCoefficients(a), drivingVariance, m);
}

}  // namespace sinsim::errormodels::fit
