#include "errormodels/stats/spectrum.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cstdlib>
#include <cmath>
#include <complex>
#include <limits>
#include <memory>
#include <mutex>
#include <string>

#include "common/error.hpp"
#include "common/constants.hpp"

namespace sinsim::errormodels {
namespace {


/// FFTW's planner is not thread-safe (FFTW manual 5.4): plans are made and destroyed under
/// this lock; executing a plan on its own arrays is safe.
std::mutex& plannerMutex() {
  static std::mutex m;
  return m;
}

struct FftwFree {
  void operator()(void* p) const { fftw_free(p); }
};
using RealBuffer = std::unique_ptr<double[], FftwFree>;
using ComplexBuffer = std::unique_ptr<fftw_complex[], FftwFree>;

/// FFTW aborts the process (an assertion in its alloc.c) when its planner cannot allocate the
/// plan's twiddles and buffers: under a memory limit `analyze` died with SIGABRT, taking a Python
/// interpreter with it. Before planning a transform of n points, more than the plan takes is
/// allocated and freed: where that fails the planner would, and the caller gets a NumericalError
/// instead. `perPoint` bytes a point cover a 2-3-5-7-smooth length (measured: a real transform of
/// 11 M points planned within 8 bytes a point, aborted within 4); another length takes Rader's or
/// Bluestein's algorithm, whose buffers are several times the transform: 8x that.
void requirePlanHeadroom(std::size_t n, std::size_t perPoint, const std::string& what) {
  std::size_t r = n;
  for (const std::size_t f : {2u, 3u, 5u, 7u})
    while (r > 1 && r % f == 0) r /= f;
  const std::size_t bytes = perPoint * n * (r == 1 ? 1 : 8);
  void* p = std::malloc(bytes);
  if (!p)
    throw NumericalError(what + ": out of memory (" + std::to_string(bytes >> 20) +
                         " MiB more needed to plan the transform)");
  std::free(p);
}

/// A real-to-complex plan of length n with its own buffers (and optionally the inverse).
class RealFft {
 public:
  explicit RealFft(std::size_t n, bool inverse = false) : n_(n) {
    in_.reset(static_cast<double*>(fftw_malloc(sizeof(double) * n)));
    out_.reset(static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * (n / 2 + 1))));
    if (!in_ || !out_) throw NumericalError("FFT: out of memory for length " + std::to_string(n));
    requirePlanHeadroom(n, sizeof(double), "FFT of length " + std::to_string(n));
    std::lock_guard<std::mutex> lock(plannerMutex());
    const int ni = static_cast<int>(n);
    forward_ = fftw_plan_dft_r2c_1d(ni, in_.get(), out_.get(), FFTW_ESTIMATE);
    if (inverse) backward_ = fftw_plan_dft_c2r_1d(ni, out_.get(), in_.get(), FFTW_ESTIMATE);
  }
  ~RealFft() {
    std::lock_guard<std::mutex> lock(plannerMutex());
    if (forward_) fftw_destroy_plan(forward_);
    if (backward_) fftw_destroy_plan(backward_);
  }
  RealFft(const RealFft&) = delete;
  RealFft& operator=(const RealFft&) = delete;

  double* in() { return in_.get(); }
  fftw_complex* out() { return out_.get(); }
  void forward() { fftw_execute(forward_); }
  void backward() { fftw_execute(backward_); }  // c2r overwrites out(); unnormalised
  std::size_t size() const { return n_; }

 private:
  std::size_t n_;
  RealBuffer in_;
  ComplexBuffer out_;
  fftw_plan forward_ = nullptr;
  fftw_plan backward_ = nullptr;
};

/// Smallest 2^a 3^b 5^c 7^d >= n: lengths FFTW handles with its fastest codelets.
std::size_t goodFftSize(std::size_t n) {
  for (std::size_t m = n;; ++m) {
    std::size_t r = m;
    for (std::size_t p : {2, 3, 5, 7})
      while (r % p == 0) r /= p;
    if (r == 1) return m;
  }
}

/// Largest 2^a 3^b 5^c 7^d <= n (n >= 1): within ~1 % of n for n >= 1e4.
std::size_t goodFftSizeBelow(std::size_t n) {
  for (std::size_t m = n;; --m) {
    std::size_t r = m;
    for (std::size_t p : {2, 3, 5, 7})
      while (r % p == 0) r /= p;
    if (r == 1) return m;
  }
}

void checkSamples(const std::vector<double>& x, double rate_hz, const char* who) {
  if (!(std::isfinite(rate_hz) && rate_hz > 0))
    throw InputError(std::string(who) + ": sample rate must be a positive number of Hz");
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i]))
      throw InputError(std::string(who) + ": sample " + std::to_string(i) + " is not finite");
  }
}

}  // namespace

Autocorrelation autocorrelation(const std::vector<double>& x, double rate_hz, std::size_t max_lag,
                                AcfScaling scaling, AcfMethod method) {
  checkSamples(x, rate_hz, "autocorrelation");
  const std::size_t n = x.size();
  if (n < 2) throw InputError("autocorrelation: need at least 2 samples");
  if (max_lag >= n)
    throw InputError("autocorrelation: max lag " + std::to_string(max_lag) + " must be below the " +
                     std::to_string(n) + " samples");
  Autocorrelation a;
  a.samples = n;
  a.dt = 1.0 / rate_hz;
  a.scaling = scaling;
  double mean = 0;
  for (double v : x) mean += v;
  mean /= static_cast<double>(n);
  a.mean = mean;
  a.r.assign(max_lag + 1, 0.0);
  if (method == AcfMethod::Auto) method = max_lag < 64 ? AcfMethod::Direct : AcfMethod::Fft;
  if (method == AcfMethod::Direct) {
    std::vector<double> z(n);
    for (std::size_t i = 0; i < n; ++i) z[i] = x[i] - mean;
    for (std::size_t k = 0; k <= max_lag; ++k) {
      double s = 0;
      for (std::size_t i = 0; i + k < n; ++i) s += z[i] * z[i + k];
      a.r[k] = s / static_cast<double>(n);
    }
  } else {
    // Wiener-Khinchin on the zero-padded record: padding to L >= N + max_lag makes the
    // circular correlation equal the linear one for every lag <= max_lag.
    const std::size_t len = goodFftSize(n + max_lag);
    RealFft fft(len, true);
    double* in = fft.in();
    for (std::size_t i = 0; i < n; ++i) in[i] = x[i] - mean;
    for (std::size_t i = n; i < len; ++i) in[i] = 0.0;
    fft.forward();
    fftw_complex* c = fft.out();
    for (std::size_t k = 0; k <= len / 2; ++k) {
      c[k][0] = c[k][0] * c[k][0] + c[k][1] * c[k][1];
      c[k][1] = 0.0;
    }
    fft.backward();
    const double scale = 1.0 / (static_cast<double>(len) * static_cast<double>(n));
    for (std::size_t k = 0; k <= max_lag; ++k) a.r[k] = in[k] * scale;
  }
  a.variance = a.r[0];
  if (scaling == AcfScaling::Normalised) {
    if (a.variance > 0) {
      const double inv = 1.0 / a.variance;
      for (double& v : a.r) v *= inv;
    } else {
      throw InputError("autocorrelation: the record is constant, its normalised ACF is undefined");
    }
  }
  a.lag.resize(max_lag + 1);
  for (std::size_t k = 0; k <= max_lag; ++k) a.lag[k] = static_cast<double>(k) * a.dt;
  return a;
}

PowerSpectrum welchPsd(const std::vector<double>& x, double rate_hz, const WelchOptions& options) {
  checkSamples(x, rate_hz, "Welch PSD");
  const std::size_t n = x.size();
  if (!(options.overlap >= 0 && options.overlap < 1))
    throw InputError("Welch PSD: overlap must be in [0, 1)");
  std::size_t len = options.segment_length;
  if (len == 0) {
    len = 16;
    while (len * 2 <= n / 8) len *= 2;
    len = std::min(len, n);
  }
  if (len < 2) throw InputError("Welch PSD: segment length must be at least 2");
  if (len > n)
    throw InputError("Welch PSD: segment of " + std::to_string(len) + " samples is longer than the " +
                     std::to_string(n) + "-sample record");
  const std::size_t noverlap = static_cast<std::size_t>(std::floor(options.overlap * len));
  const std::size_t step = len - noverlap;
  const std::size_t segments = (n - len) / step + 1;  // the tail that does not fill one is dropped

  // Periodic Hann window (scipy.signal.get_window("hann", L), fftbins=True).
  std::vector<double> w(len);
  double sw = 0, sw2 = 0;
  for (std::size_t i = 0; i < len; ++i) {
    w[i] = 0.5 - 0.5 * std::cos(2.0 * kPi * static_cast<double>(i) / static_cast<double>(len));
    sw += w[i];
    sw2 += w[i] * w[i];
  }
  const std::size_t nf = len / 2 + 1;
  PowerSpectrum p;
  p.rate_hz = rate_hz;
  p.segment_length = len;
  p.segments = segments;
  p.df = rate_hz / static_cast<double>(len);
  p.enbw_hz = rate_hz * sw2 / (sw * sw);
  p.f.resize(nf);
  p.psd.assign(nf, 0.0);
  for (std::size_t k = 0; k < nf; ++k) p.f[k] = static_cast<double>(k) * p.df;

  RealFft fft(len);
  double* in = fft.in();
  const fftw_complex* c = fft.out();
  for (std::size_t s = 0; s < segments; ++s) {
    const double* seg = x.data() + s * step;
    double mean = 0;
    if (options.detrend) {
      for (std::size_t i = 0; i < len; ++i) mean += seg[i];
      mean /= static_cast<double>(len);
    }
    for (std::size_t i = 0; i < len; ++i) in[i] = w[i] * (seg[i] - mean);
    fft.forward();
    for (std::size_t k = 0; k < nf; ++k) p.psd[k] += c[k][0] * c[k][0] + c[k][1] * c[k][1];
  }
  const double scale = 1.0 / (rate_hz * sw2 * static_cast<double>(segments));
  for (std::size_t k = 0; k < nf; ++k) {
    const bool single = k == 0 || (len % 2 == 0 && k == len / 2);
    p.psd[k] *= scale * (single ? 1.0 : 2.0);
  }
  return p;
}

Periodogram taperedPeriodogram(const std::vector<double>& x, double taperFraction, Detrend detrend) {
  checkSamples(x, 1.0, "periodogram");
  if (x.size() < 16) throw InputError("periodogram: need at least 16 samples, got " + std::to_string(x.size()));
  if (!(taperFraction >= 0.0 && taperFraction <= 1.0))
    throw InputError("periodogram: taper fraction must be in [0, 1]");
  // The first n samples, n the largest length FFTW transforms with its fast codelets (a length with
  // a large prime factor costs several times more).
  const std::size_t n = goodFftSizeBelow(x.size());
  Periodogram p;
  std::vector<double>& h = p.taper;
  h.assign(n, 1.0);
  const auto L = static_cast<std::size_t>(std::floor(0.5 * taperFraction * double(n)));
  for (std::size_t k = 0; k < L; ++k) h[k] = h[n - 1 - k] = 0.5 - 0.5 * std::cos(kPi * (double(k) + 0.5) / double(L));
  // h-weighted least squares of x on [1, k] (or [1]): normal equations of order 2.
  double s0 = 0, s1 = 0, s2 = 0, b0 = 0, b1 = 0, sh2 = 0, sh4 = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double kk = double(k);
    s0 += h[k], s1 += h[k] * kk, s2 += h[k] * kk * kk, b0 += h[k] * x[k], b1 += h[k] * kk * x[k];
    sh2 += h[k] * h[k], sh4 += h[k] * h[k] * h[k] * h[k];
  }
  double mean = b0 / s0, slope = 0.0;
  if (detrend == Detrend::Linear) {
    const double det = s0 * s2 - s1 * s1;
    mean = (s2 * b0 - s1 * b1) / det;
    slope = (s0 * b1 - s1 * b0) / det;
  }
  p.slope = slope;
  RealFft fft(n);
  double* in = fft.in();
  for (std::size_t k = 0; k < n; ++k) in[k] = h[k] * (x[k] - mean - slope * double(k));
  fft.forward();
  const fftw_complex* c = fft.out();
  p.varianceInflation = double(n) * sh4 / (sh2 * sh2);
  p.w.resize(n / 2 + 1);
  p.I.resize(n / 2 + 1);
  for (std::size_t j = 0; j <= n / 2; ++j) {
    p.w[j] = 2.0 * kPi * double(j) / double(n);
    p.I[j] = (c[j][0] * c[j][0] + c[j][1] * c[j][1]) / sh2;
  }
  return p;
}

std::vector<double> zeroPhaseFiltered(const std::vector<double>& x, const std::function<double(double)>& gain) {
  checkSamples(x, 1.0, "zero-phase filter");
  const std::size_t n = x.size();
  if (n < 2) throw InputError("zero-phase filter: need at least 2 samples");
  if (n > std::size_t(std::numeric_limits<int>::max()))
    throw InputError("zero-phase filter: " + std::to_string(n) + " samples exceed FFTW's int length");
  RealBuffer buf(static_cast<double*>(fftw_malloc(sizeof(double) * n)));
  if (!buf) throw NumericalError("zero-phase filter: out of memory for " + std::to_string(n) + " samples");
  requirePlanHeadroom(n, sizeof(fftw_complex), "zero-phase filter of " + std::to_string(n) + " samples");
  struct Plans {  // the DCT-II and DCT-III in place on buf, destroyed under the planner's lock
    fftw_plan dct = nullptr, idct = nullptr;
    ~Plans() {
      std::lock_guard<std::mutex> lock(plannerMutex());
      if (dct) fftw_destroy_plan(dct);
      if (idct) fftw_destroy_plan(idct);
    }
  } plans;
  {
    std::lock_guard<std::mutex> lock(plannerMutex());
    const int ni = static_cast<int>(n);
    plans.dct = fftw_plan_r2r_1d(ni, buf.get(), buf.get(), FFTW_REDFT10, FFTW_ESTIMATE);
    plans.idct = fftw_plan_r2r_1d(ni, buf.get(), buf.get(), FFTW_REDFT01, FFTW_ESTIMATE);
  }
  if (!plans.dct || !plans.idct) throw NumericalError("zero-phase filter: FFTW made no plan for length " + std::to_string(n));
  std::copy(x.begin(), x.end(), buf.get());
  fftw_execute(plans.dct);
  for (std::size_t k = 0; k < n; ++k) {
    const double w = kPi * double(k) / double(n);
    const double h = gain(w);
    if (!std::isfinite(h))
      throw InputError("zero-phase filter: the gain is not finite at w = " + std::to_string(w) + " rad/sample");
    buf[k] *= h;
  }
  fftw_execute(plans.idct);
  std::vector<double> y(buf.get(), buf.get() + n);
  for (double& v : y) v /= 2.0 * double(n);  // REDFT01(REDFT10(x)) = 2N x
  return y;
}

double paddedPowerSum(const std::vector<double>& g, std::size_t pad, const std::function<double(double)>& weight) {
  const std::size_t n = g.size();
  if (pad < 1 || n < 2) throw InputError("padded power sum: need pad >= 1 and at least 2 weights");
  ComplexBuffer buf(static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * n)));
  if (!buf) throw NumericalError("FFT: out of memory for length " + std::to_string(n));
  requirePlanHeadroom(n, sizeof(fftw_complex), "FFT of length " + std::to_string(n));
  fftw_plan plan;
  {
    std::lock_guard<std::mutex> lock(plannerMutex());
    plan = fftw_plan_dft_1d(static_cast<int>(n), buf.get(), buf.get(), FFTW_FORWARD, FFTW_ESTIMATE);
  }
  const double M = double(pad) * double(n);
  double sum = 0.0;
  for (std::size_t r = 0; 2 * r <= pad; ++r) {
    // Offset r / M of a cycle per sample: g_j e^{-i 2 pi r j / M}, the phase stepped by rotation
    // and set afresh every 1024 samples (no drift of its modulus).
    const double dw = -2.0 * kPi * double(r) / M;
    const std::complex<double> step = std::polar(1.0, dw);
    std::complex<double> z = 1.0;
    for (std::size_t j = 0; j < n; ++j) {
      if ((j & 1023) == 0) z = std::polar(1.0, dw * double(j));
      buf[j][0] = g[j] * z.real(), buf[j][1] = g[j] * z.imag();
      z *= step;
    }
    fftw_execute(plan);
    const double copies = (r == 0 || 2 * r == pad) ? 1.0 : 2.0;  // r and pad - r: the same |w|
    for (std::size_t q = r == 0 ? 1 : 0; q < n; ++q) {  // k = 0 (w = 0) left out
      const double k = double(pad) * double(q) + double(r);
      const double w = 2.0 * kPi * std::min(k, M - k) / M;
      sum += copies * (buf[q][0] * buf[q][0] + buf[q][1] * buf[q][1]) * weight(w);
    }
  }
  std::lock_guard<std::mutex> lock(plannerMutex());
  fftw_destroy_plan(plan);
  return sum;
}

}  // namespace sinsim::errormodels
