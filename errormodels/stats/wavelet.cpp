#include "errormodels/stats/wavelet.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

#include "common/error.hpp"

namespace sinsim::errormodels {
namespace {

Wavelet fromScaling(std::string name, std::vector<double> rec_lo) {
  Wavelet w;
  w.name = std::move(name);
  const std::size_t f = rec_lo.size();
  w.rec_lo = rec_lo;
  w.dec_lo.assign(rec_lo.rbegin(), rec_lo.rend());
  w.dec_hi.resize(f);
  for (std::size_t k = 0; k < f; ++k) w.dec_hi[k] = (k % 2 ? 1.0 : -1.0) * rec_lo[k];
  w.rec_hi.assign(w.dec_hi.rbegin(), w.dec_hi.rend());
  return w;
}

const std::map<std::string, Wavelet>& registry() {
  static const std::map<std::string, Wavelet> table = [] {
    std::map<std::string, Wavelet> t;
    const double r2 = std::sqrt(2.0), r3 = std::sqrt(3.0);
    t["db1"] = fromScaling("db1", {1 / r2, 1 / r2});
    // Daubechies (1992), Ten Lectures on Wavelets, eq. 6.1.12 (N = 2), closed form.
    t["db2"] = fromScaling("db2", {(1 + r3) / (4 * r2), (3 + r3) / (4 * r2), (3 - r3) / (4 * r2),
                                   (1 - r3) / (4 * r2)});
    // Daubechies (1992) Table 6.1, N = 5 (minimum phase), normalised to sum sqrt(2), as
    // tabulated in PyWavelets' wavelets_coeffs.template.h (rec_lo of pywt.Wavelet("db5")),
    // here to 17 significant digits; tests/stats/test_wavelet.cpp checks them against the
    // fixture and the orthonormality / vanishing-moment conditions.
    t["db5"] = fromScaling("db5", {0.16010239797419293, 0.6038292697971896, 0.7243085284377729,
                                   0.13842814590132074, -0.24229488706638203,
                                   -0.032244869584638375, 0.07757149384004572,
                                   -0.006241490212798274, -0.012580751999081999,
                                   0.0033357252854737712});
    t["haar"] = t["db1"];
    t["haar"].name = "haar";
    return t;
  }();
  return table;
}

/// Half-sample symmetric index for period 2n: ..., x1, x0 | x0, x1, ..., x_{n-1} | x_{n-1}, ...
inline std::size_t reflect(long k, long n) {
  const long p = 2 * n;
  k %= p;
  if (k < 0) k += p;
  if (k >= n) k = p - 1 - k;
  return static_cast<std::size_t>(k);
}

inline std::size_t wrap(long k, long n) {
  k %= n;
  if (k < 0) k += n;
  return static_cast<std::size_t>(k);
}

/// One analysis step, PyWavelets downsampling_convolution: a[o] = sum_j lo[j] ext(x)[2o+s-j].
/// Symmetric: s = 1, ext = reflect, (n + F - 1) / 2 outputs. Periodization: the input has even
/// length (odd inputs are extended by their last sample before), s = F/2, n/2 outputs.
template <int F>
void analysisStep(const double* x, long n, const double* lo, const double* hi, WaveletBoundary mode,
                  std::vector<double>& a, std::vector<double>& d) {
  const long filt = static_cast<long>(F);
  const bool sym = mode == WaveletBoundary::Symmetric;
  const long s = sym ? 1 : filt / 2;
  const long nout = sym ? (n + filt - 1) / 2 : n / 2;
  a.resize(static_cast<std::size_t>(nout));
  d.resize(static_cast<std::size_t>(nout));
  // Interior: 0 <= 2o + s - (F-1) and 2o + s <= n - 1.
  const long o_lo = std::max(0L, (filt - 1 - s + 1) / 2);
  const long o_hi = (n - 1 - s) >= 0 ? (n - 1 - s) / 2 : -1;  // inclusive
  auto boundary = [&](long o) {
    double sa = 0, sd = 0;
    for (long j = 0; j < filt; ++j) {
      const long k = 2 * o + s - j;
      const double v = x[sym ? reflect(k, n) : wrap(k, n)];
      sa += lo[j] * v;
      sd += hi[j] * v;
    }
    a[static_cast<std::size_t>(o)] = sa;
    d[static_cast<std::size_t>(o)] = sd;
  };
  long o = 0;
  for (; o < std::min(o_lo, nout); ++o) boundary(o);
  for (; o <= std::min(o_hi, nout - 1); ++o) {
    const double* xp = x + 2 * o + s;
    double sa = 0, sd = 0;
    for (long j = 0; j < filt; ++j) {
      sa += lo[j] * xp[-j];
      sd += hi[j] * xp[-j];
    }
    a[static_cast<std::size_t>(o)] = sa;
    d[static_cast<std::size_t>(o)] = sd;
  }
  for (; o < nout; ++o) boundary(o);
}

void analysis(const std::vector<double>& x, const Wavelet& w, WaveletBoundary mode,
              std::vector<double>& a, std::vector<double>& d) {
  const double* px = x.data();
  long n = static_cast<long>(x.size());
  std::vector<double> padded;
  if (mode == WaveletBoundary::Periodization && n % 2 == 1) {
    padded.assign(x.begin(), x.end());
    padded.push_back(x.back());
    px = padded.data();
    ++n;
  }
  const double* lo = w.dec_lo.data();
  const double* hi = w.dec_hi.data();
  switch (w.length()) {
    case 2: analysisStep<2>(px, n, lo, hi, mode, a, d); break;
    case 4: analysisStep<4>(px, n, lo, hi, mode, a, d); break;
    case 10: analysisStep<10>(px, n, lo, hi, mode, a, d); break;
    default: throw NumericalError("wavelet: unsupported filter length");
  }
}

/// One synthesis step. Symmetric (PyWavelets upsampling_convolution_valid_sf): 2n - F + 2
/// outputs, r[2q + e] = sum_{j<F/2} rlo[2j+e] a[q + F/2 - 1 - j] + rhi[2j+e] d[...], e = 0, 1.
/// Periodization: the transpose of the analysis step, 2n outputs.
template <int F>
void synthesisStep(const std::vector<double>& a, const std::vector<double>& d, const Wavelet& w,
                   WaveletBoundary mode, std::vector<double>& r) {
  const long filt = F;
  const long n = static_cast<long>(a.size());
  if (mode == WaveletBoundary::Symmetric) {
    const long nout = 2 * n - filt + 2;
    if (nout <= 0) throw InputError("wavelet reconstruction: too few coefficients for the filter");
    r.assign(static_cast<std::size_t>(nout), 0.0);
    const double* rlo = w.rec_lo.data();
    const double* rhi = w.rec_hi.data();
    const long h = filt / 2;
    for (long i = h - 1, q = 0; i < n; ++i, ++q) {
      double se = 0, so = 0;
      for (long j = 0; j < h; ++j) {
        const double av = a[static_cast<std::size_t>(i - j)];
        const double dv = d[static_cast<std::size_t>(i - j)];
        se += rlo[2 * j] * av + rhi[2 * j] * dv;
        so += rlo[2 * j + 1] * av + rhi[2 * j + 1] * dv;
      }
      r[static_cast<std::size_t>(2 * q)] = se;
      r[static_cast<std::size_t>(2 * q + 1)] = so;
    }
    return;
  }
  const long np = 2 * n;
  const long s = filt / 2;
  r.assign(static_cast<std::size_t>(np), 0.0);
  const double* lo = w.dec_lo.data();
  const double* hi = w.dec_hi.data();
  double* out = r.data();
  for (long o = 0; o < n; ++o) {
    const double av = a[static_cast<std::size_t>(o)];
    const double dv = d[static_cast<std::size_t>(o)];
    const long base = 2 * o + s;
    if (base - (filt - 1) >= 0 && base < np) {
      double* rp = out + base;
      for (long j = 0; j < filt; ++j) rp[-j] += lo[j] * av + hi[j] * dv;
    } else {
      for (long j = 0; j < filt; ++j) out[wrap(base - j, np)] += lo[j] * av + hi[j] * dv;
    }
  }
}

void synthesis(const std::vector<double>& a, const std::vector<double>& d, const Wavelet& w,
               WaveletBoundary mode, std::vector<double>& r) {
  switch (w.length()) {
    case 2: synthesisStep<2>(a, d, w, mode, r); break;
    case 4: synthesisStep<4>(a, d, w, mode, r); break;
    case 10: synthesisStep<10>(a, d, w, mode, r); break;
    default: throw NumericalError("wavelet: unsupported filter length");
  }
}

/// numpy.median: the mean of the two middle values for an even count.
double median(std::vector<double> v) {
  const std::size_t n = v.size();
  auto mid = v.begin() + static_cast<std::ptrdiff_t>(n / 2);
  std::nth_element(v.begin(), mid, v.end());
  const double upper = *mid;
  if (n % 2 == 1) return upper;
  const double lower = *std::max_element(v.begin(), mid);
  return 0.5 * (lower + upper);
}

/// pywt.threshold(mode="soft"): c (1 - t/|c|) where |c| > t, else 0.
void softThreshold(std::vector<double>& c, double t) {
  for (double& v : c) {
    const double m = std::abs(v);
    v = m > t ? v * (1.0 - t / m) : 0.0;
  }
}

/// pywt.threshold(mode="hard"): zero where |c| < t.
void hardThreshold(std::vector<double>& c, double t) {
  for (double& v : c) {
    if (std::abs(v) < t) v = 0.0;
  }
}

/// SURE threshold of one level (see the header): sigma sqrt(s_k*) for the minimising k.
double sureThreshold(const std::vector<double>& c, double sigma) {
  const std::size_t n = c.size();
  if (n == 0 || sigma <= 0) return 0.0;
  std::vector<double> s(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = c[i] / sigma;
    s[i] = x * x;
  }
  std::sort(s.begin(), s.end());
  double cum = 0, best = std::numeric_limits<double>::infinity();
  std::size_t kbest = 0;
  const double nd = static_cast<double>(n);
  for (std::size_t k = 0; k < n; ++k) {
    cum += s[k];
    const double risk = (nd - 2.0 * (k + 1) + cum + (nd - k - 1) * s[k]) / nd;
    if (risk < best) {
      best = risk;
      kbest = k;
    }
  }
  return sigma * std::sqrt(s[kbest]);
}

}  // namespace

const Wavelet& waveletByName(const std::string& name) {
  const auto& t = registry();
  auto it = t.find(name);
  if (it == t.end()) {
    std::string known;
    for (const auto& kv : t) known += (known.empty() ? "" : ", ") + kv.first;
    throw InputError("unknown wavelet \"" + name + "\"; known: " + known);
  }
  return it->second;
}

WaveletBoundary waveletBoundaryByName(const std::string& name) {
  if (name == "symmetric") return WaveletBoundary::Symmetric;
  if (name == "periodization") return WaveletBoundary::Periodization;
  throw InputError("unknown wavelet boundary mode \"" + name + "\"; known: symmetric, periodization");
}

int waveletMaxLevel(std::size_t n, std::size_t filter_length) {
  if (filter_length < 2 || n < filter_length - 1) return 0;
  // pywt: int(np.log2(n / (filter_length - 1))); integer form avoids log2 rounding.
  int level = 0;
  std::size_t q = n / (filter_length - 1);
  while (q >= 2) {
    q /= 2;
    ++level;
  }
  return level;
}

WaveletCoefficients wavedec(const std::vector<double>& x, const Wavelet& w, WaveletBoundary mode,
                            int level) {
  if (x.empty()) throw InputError("wavelet decomposition: empty signal");
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i]))
      throw InputError("wavelet decomposition: sample " + std::to_string(i) + " is not finite");
  }
  const int max_level = waveletMaxLevel(x.size(), w.length());
  if (level < 0) level = max_level;
  if (level > max_level) {
    throw InputError("wavelet decomposition: level " + std::to_string(level) + " exceeds " +
                     std::to_string(max_level) + ", the deepest useful level for " +
                     std::to_string(x.size()) + " samples and " + w.name);
  }
  WaveletCoefficients c;
  c.coeffs.resize(static_cast<std::size_t>(level) + 1);
  std::vector<double> a = x, na;
  for (int l = 1; l <= level; ++l) {
    std::vector<double>& d = c.coeffs[static_cast<std::size_t>(level - l + 1)];
    analysis(a, w, mode, na, d);
    a.swap(na);
  }
  c.coeffs[0] = std::move(a);
  return c;
}

std::vector<double> waverec(const WaveletCoefficients& c, const Wavelet& w, WaveletBoundary mode) {
  if (c.coeffs.empty()) throw InputError("wavelet reconstruction: no coefficients");
  std::vector<double> a = c.coeffs[0], r;
  for (std::size_t l = 1; l < c.coeffs.size(); ++l) {
    const std::vector<double>& d = c.coeffs[l];
    if (a.size() == d.size() + 1) a.pop_back();  // pywt.waverec trims the odd-length extra
    if (a.size() != d.size())
      throw InputError("wavelet reconstruction: coefficient lengths do not match at level " +
                       std::to_string(c.coeffs.size() - l));
    synthesis(a, d, w, mode, r);
    a.swap(r);
  }
  return a;
}

DenoiseResult waveletDenoise(const std::vector<double>& x, const DenoiseOptions& options) {
  const Wavelet& w = waveletByName(options.wavelet);
  const std::size_t n = x.size();
  const int max_level = waveletMaxLevel(n, w.length());
  if (max_level < 1) {
    throw InputError("wavelet denoising: " + std::to_string(n) + " samples are too few for " +
                     w.name + " (need at least " + std::to_string(2 * (w.length() - 1)) + ")");
  }
  WaveletCoefficients c = wavedec(x, w, options.boundary, options.level < 0 ? max_level : options.level);
  const int level = static_cast<int>(c.level());
  if (level < 1) throw InputError("wavelet denoising: level must be at least 1");
  DenoiseResult res;
  res.level = level;
  const std::vector<double>& finest = c.coeffs.back();
  std::vector<double> mag(finest.size());
  for (std::size_t i = 0; i < finest.size(); ++i) mag[i] = std::abs(finest[i]);
  res.sigma = median(std::move(mag)) / 0.6744897501960817;  // Phi^-1(0.75)
  const double universal = res.sigma * std::sqrt(2.0 * std::log(static_cast<double>(n)));
  res.thresholds.resize(static_cast<std::size_t>(level));
  for (int j = 1; j <= level; ++j) {  // detail level j (1 = finest) is coeffs[level - j + 1]
    std::vector<double>& d = c.coeffs[static_cast<std::size_t>(level - j + 1)];
    const double t = options.rule == ThresholdRule::Universal ? universal : sureThreshold(d, res.sigma);
    res.thresholds[static_cast<std::size_t>(j - 1)] = t;
    if (options.mode == ThresholdMode::Soft) softThreshold(d, t);
    else hardThreshold(d, t);
  }
  res.signal = waverec(c, w, options.boundary);
  res.signal.resize(n);
  return res;
}

}  // namespace sinsim::errormodels
