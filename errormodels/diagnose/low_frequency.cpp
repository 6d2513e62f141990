// The walk's test given the model (low_frequency.hpp).
#include "errormodels/diagnose/low_frequency.hpp"

#include <algorithm>
#include <cmath>
#include <limits>


namespace sinsim::errormodels::diagnose::detail {

namespace {

constexpr std::size_t kBlocks = 1024;  // block sums: the slowest shapes vary little within one
constexpr int kCosines = 6;            // half-periods T/1 .. T/6
/// Settling time constants of the nuisance exponentials, as fractions of T: the warm-up detector
/// searches T/2 down to a few blocks; three spread over it keep a settling out of the cosines.
constexpr double kSettling[] = {1.0 / 4, 1.0 / 12, 1.0 / 40};
constexpr double kKeep = 0.01;  // a cosine whose part beyond the nuisances is < 1 % of its norm^2 is dropped

double dot(const std::vector<double>& a, const std::vector<double>& b, const std::vector<double>& w) {
  double s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) s += w[i] * a[i] * b[i];
  return s;
}

/// v minus its projection on the orthonormal q (twice: modified Gram-Schmidt, re-orthogonalised).
void orthogonalise(std::vector<double>& v, const std::vector<std::vector<double>>& q, const std::vector<double>& w) {
  for (int pass = 0; pass < 2; ++pass)
    for (const auto& e : q) {
      const double p = dot(v, e, w);
      for (std::size_t i = 0; i < v.size(); ++i) v[i] -= p * e[i];
    }
}

}  // namespace

LowFrequencyBasis lowFrequencyBasis(std::size_t n, const std::vector<double>& temperature) {
  LowFrequencyBasis b;
  b.block = std::max<std::size_t>(1, (n + kBlocks - 1) / kBlocks);
  const std::size_t nb = (n + b.block - 1) / b.block;
  std::vector<double> s(nb), temp(temperature.empty() ? 0 : nb, 0.0);
  b.count.assign(nb, 0.0);
  for (std::size_t j = 0; j < nb; ++j) {
    const std::size_t a = j * b.block, e = std::min(n, a + b.block);
    b.count[j] = double(e - a);
    s[j] = (0.5 * double(a + e)) / double(n);  // block centre as a fraction of the record
    if (!temp.empty()) {
      for (std::size_t k = a; k < e; ++k) temp[j] += temperature[k];
      temp[j] /= b.count[j];
    }
  }
  std::vector<std::vector<double>> nuisance{std::vector<double>(nb, 1.0), s};
  for (double f : kSettling) {
    std::vector<double> x(nb);
    for (std::size_t j = 0; j < nb; ++j) x[j] = std::exp(-s[j] / f);
    nuisance.push_back(x);
  }
  if (!temp.empty()) {
    nuisance.push_back(temp);
    auto t2 = temp;
    for (double& v : t2) v *= v;
    nuisance.push_back(t2);
  }
  std::vector<std::vector<double>> q;
  for (auto& v : nuisance) {
    const double raw = dot(v, v, b.count);
    orthogonalise(v, q, b.count);
    const double left = dot(v, v, b.count);
    if (!(left > 1e-10 * raw)) continue;  // a constant temperature: nothing new
    for (double& x : v) x /= std::sqrt(left);
    q.push_back(std::move(v));
  }
  for (int k = 1; k <= kCosines; ++k) {
    std::vector<double> v(nb);
    for (std::size_t j = 0; j < nb; ++j) v[j] = std::cos(M_PI * double(k) * s[j]);
    const double raw = dot(v, v, b.count);
    orthogonalise(v, q, b.count);
    const double left = dot(v, v, b.count);
    if (!(left > kKeep * raw)) continue;
    for (double& x : v) x /= std::sqrt(left);
    q.push_back(v);
    b.u.push_back(std::move(v));
    b.k.push_back(double(k));
  }
  return b;
}

std::vector<double> lowFrequencyCoefficients(const std::vector<double>& y, const LowFrequencyBasis& b) {
  if (b.u.empty() || b.block == 0) return {};
  std::vector<double> sums(b.count.size(), 0.0);
  for (std::size_t j = 0, k = 0; j < sums.size(); ++j) {
    const std::size_t e = j + 1 == sums.size() ? y.size() : std::min(y.size(), k + b.block);
    for (; k < e; ++k) sums[j] += y[k];
  }
  std::vector<double> c(b.u.size(), 0.0);
  for (std::size_t d = 0; d < b.u.size(); ++d)
    for (std::size_t j = 0; j < sums.size(); ++j) c[d] += b.u[d][j] * sums[j];
  return c;
}

double allanTermAt(const std::vector<double>& g, const std::vector<double>& tau, double t) {
  const std::size_t K = g.size();
  if (K == 0 || !(g[K - 1] > 0)) return 0.0;
  std::size_t e = 0;
  while (e + 1 < K && tau[e] < t) ++e;
  const std::size_t a = e > 0 ? e - 1 : 0;
  const std::size_t b = e > 0 ? e : std::min<std::size_t>(1, K - 1);
  double slope = 1.0;
  if (b != a && g[a] > 0 && g[b] > 0) slope = std::clamp(std::log(g[b] / g[a]) / std::log(tau[b] / tau[a]), -1.0, 2.0);
  return g[b] * std::pow(t / tau[b], slope);
}

double lowFrequencyVarianceOf(const std::vector<double>& g, const std::vector<double>& tau, double T,
                              double dt, double k) {
  const double tk = T / (2.0 * k);
  return 12.0 / (M_PI * M_PI) * (tk / dt) * allanTermAt(g, tau, tk);
}

double lowFrequencyNll(const std::vector<double>& c, const std::vector<double>& var, double dof) {
  double nll = 0;
  for (std::size_t d = 0; d < c.size() && d < var.size(); ++d) {
    if (!(var[d] > 0)) return 0.0;
    nll += (dof + 1) * std::log1p(c[d] * c[d] / (dof * var[d])) + std::log(var[d]);
  }
  return nll;
}

CosineSpectrum cosineSpectrum(const std::vector<double>& x, std::size_t maxCosines) {
  CosineSpectrum s;
  const std::size_t n = x.size();
  if (n < 4) return s;
  double mean = 0;
  for (double v : x) mean += v / double(n);
  for (double v : x) s.norm2 += (v - mean) * (v - mean);
  const std::size_t K = std::min(maxCosines, n / 2);
  const std::size_t block = std::max<std::size_t>(1, n / (16 * K));  // >= 16 blocks per period
  const std::size_t nb = (n + block - 1) / block;
  std::vector<double> sum(nb, 0.0), centre(nb);
  for (std::size_t j = 0; j < nb; ++j) {
    const std::size_t a = j * block, e = std::min(n, a + block);
    for (std::size_t k = a; k < e; ++k) sum[j] += x[k] - mean;
    centre[j] = 0.5 * double(a + e);  // (t + 1/2) at the block's centre, in samples
  }
  s.a.resize(K), s.a2.resize(K);
  double captured = 0;
  const double scale = std::sqrt(2.0 / double(n));
  for (std::size_t k = 1; k <= K; ++k) {
    const double w = M_PI * double(k) / double(n);
    // cos(w c_j) over the equally spaced centres by rotation (the last block may be shorter).
    const double cr = std::cos(w * double(block)), sr = std::sin(w * double(block));
    double c = std::cos(w * centre[0]), sn = std::sin(w * centre[0]), a = 0;
    for (std::size_t j = 0; j + 1 < nb; ++j) {
      a += sum[j] * c;
      const double c1 = c * cr - sn * sr;
      sn = sn * cr + c * sr, c = c1;
    }
    a += sum[nb - 1] * std::cos(w * centre[nb - 1]);
    s.a[k - 1] = scale * a;
    s.a2[k - 1] = scale * scale * a * a;
    captured += s.a2[k - 1];
  }
  s.tail = std::max(0.0, s.norm2 - captured);
  return s;
}

double coefficientVarianceOf(const CosineSpectrum& s, const std::vector<double>& g, const std::vector<double>& tau,
                             double T, double dt) {
  if (s.a2.empty() || !(s.norm2 > 0)) return 0.0;
  double v = 0, vk = 0;
  for (std::size_t k = 1; k <= s.a2.size(); ++k) {
    vk = lowFrequencyVarianceOf(g, tau, T, dt, double(k));
    v += s.a2[k - 1] * vk;
  }
  return (v + s.tail * vk) / (s.norm2 * s.norm2);
}

double powerLawCosineRatio(double mu) {
  // S(f) = h f^alpha, alpha = -mu - 1: AVAR(tau) = h tau^mu C, C = int_0^inf f^alpha 2 sin^4(pi f)
  // / (pi f)^2 df, by the Mellin transform of sin^4 = (3 - 4 cos 2x + cos 4x) / 8 (Gradshteyn &
  // Ryzhik 3.761.9); the cosine at f_k = 1/(4 tau_k) has variance S(f_k) / (2 dt). Their ratio is
  // (24/pi^2) C 4^alpha. At integer alpha the Gamma's pole and the cosine's zero cancel: nudged.
  // Beyond white and walk slopes the ratio grows (2.0 at mu = -1.5 and 1.7 at +1.5): held at
  // their values there, the variance it gives is on the high side.
  mu = std::clamp(mu, -1.0, 1.0);
  double alpha = -mu - 1;
  if (std::fabs(alpha - std::round(alpha)) < 1e-6) alpha += 1e-6;
  const double s = alpha - 1;
  const double mellin = std::tgamma(s) * std::cos(M_PI * s / 2) * (std::pow(4.0, -s) - 4 * std::pow(2.0, -s)) / 8;
  const double C = 2 / (M_PI * M_PI) * std::pow(M_PI, 1 - alpha) * mellin;
  return 24 / (M_PI * M_PI) * C * std::pow(4.0, alpha);
}

double cosineVarianceOf(const std::vector<double>& g, const std::vector<double>& tau, double T, double dt, double k) {
  const double tk = T / (2.0 * k), lo = allanTermAt(g, tau, tk / 1.25), hi = allanTermAt(g, tau, tk * 1.25);
  const double mu = lo > 0 && hi > 0 ? std::log(hi / lo) / std::log(1.5625) : 1.0;
  return lowFrequencyVarianceOf(g, tau, T, dt, k) / powerLawCosineRatio(mu);
}

GlsTest glsTestOf(const CosineSpectrum& x, const CosineSpectrum& y, const std::vector<double>& estimated,
                  const std::vector<double>& known, double realisations, const std::vector<double>& tau, double T,
                  double dt) {
  std::vector<double> g(tau.size(), 0.0);
  for (const auto* part : {&estimated, &known})
    for (std::size_t k = 0; k < g.size() && k < part->size(); ++k) g[k] += (*part)[k];
  const std::size_t K = std::min(x.a.size(), y.a.size());
  double num = 0, den = 0;
  std::vector<double> w(K), ve(K);
  for (std::size_t k = 1; k <= K; ++k) {
    const double v = cosineVarianceOf(g, tau, T, dt, double(k));
    if (!(v > 0)) return {};
    w[k - 1] = x.a[k - 1] / v;
    num += w[k - 1] * y.a[k - 1];
    den += w[k - 1] * x.a[k - 1];
    ve[k - 1] = estimated.empty() ? 0.0 : std::min(v, cosineVarianceOf(estimated, tau, T, dt, double(k)));
  }
  if (!(den > 0)) return {};
  // Satterthwaite over the octaves: the variance 1/den squared over the sum of each octave's part
  // (its sum of w^2 v_estimated, over den^2) squared over its dof.
  double spread = 0;
  for (std::size_t lo = 1; lo <= K; lo *= 2) {
    double part = 0;
    for (std::size_t k = lo; k < 2 * lo && k <= K; ++k) part += w[k - 1] * w[k - 1] * ve[k - 1];
    spread += part * part / (realisations * double(lo));
  }
  return {std::fabs(num) / std::sqrt(den), spread > 0 ? den * den / spread : std::numeric_limits<double>::infinity()};
}

}  // namespace sinsim::errormodels::diagnose::detail
