#include "errormodels/stats/line_fit.hpp"

#include <algorithm>
#include <cmath>

namespace sinsim::errormodels {

LinePeriodogram::LinePeriodogram(const std::vector<double>& y, double mean, double dt, double fc,
                                 double halfWidth)
    : dt_(dt), N_(y.size()) {
  wc_ = 2 * M_PI * fc * dt;
  const double dmax = 2 * M_PI * halfWidth * dt;
  B_ = std::size_t(std::clamp(0.5 / std::max(dmax, 1e-300), 1.0, 65536.0));
  const std::size_t N = N_, nb = (N + B_ - 1) / B_;
  U_.assign(nb * kTerms, {0.0, 0.0});
  for (std::size_t b = 0; b < nb; ++b) {
    const std::size_t k0 = b * B_, k1 = std::min(N, k0 + B_);
    // e^{-i wc (k + 1/2)} by rotation from the block's start (B <= 65536 steps: drift ~1e-12)
    std::complex<double> e = std::polar(1.0, -wc_ * (double(k0) + 0.5));
    const std::complex<double> step = std::polar(1.0, -wc_);
    std::complex<double>* Ub = &U_[b * kTerms];
    for (std::size_t k = k0; k < k1; ++k, e *= step) {
      const std::complex<double> u = (y[k] - mean) * e;
      const double x = double(k - k0) / double(B_);
      double xm = 1;
      for (std::size_t m = 0; m < kTerms; ++m, xm *= x) Ub[m] += xm * u;
    }
  }
}

double LinePeriodogram::power(double f) const {
  const double d = 2 * M_PI * f * dt_ - wc_;
  std::array<std::complex<double>, kTerms> coef;
  std::complex<double> c = 1.0;
  for (std::size_t m = 0; m < kTerms; ++m) {
    coef[m] = c;
    c *= std::complex<double>(0.0, -d * double(B_)) / double(m + 1);
  }
  std::complex<double> X = 0.0, rot = std::polar(1.0, -d * 0.5);
  const std::complex<double> blockStep = std::polar(1.0, -d * double(B_));
  const std::size_t nb = U_.size() / kTerms;
  for (std::size_t b = 0; b < nb; ++b, rot *= blockStep) {
    const std::complex<double>* Ub = &U_[b * kTerms];
    std::complex<double> s = 0.0;
    for (std::size_t m = 0; m < kTerms; ++m) s += coef[m] * Ub[m];
    X += rot * s;
  }
  const double a = 2 * X.real() / double(N_), bb = -2 * X.imag() / double(N_);
  return a * a + bb * bb;
}

LineWindow welchLineWindow(double freq, double bin, double rate) {
  return {std::max(bin * 0.25, freq - 1.5 * bin), std::min(0.5 * rate, freq + 1.5 * bin)};
}

double refineLineFrequency(const LinePeriodogram& pg, const LineWindow& w, std::size_t N, std::size_t L) {
  const double fa = w.fa, fb = w.fb;
  const int scan = int(std::min(2000.0, std::max(50.0, 6 * double(N) / double(L))));
  double bestF = 0.5 * (fa + fb), bestP = -1;
  for (int i = 0; i <= scan; ++i) {
    const double f = fa + (fb - fa) * i / scan;
    const double pw = pg.power(f);
    if (pw > bestP) bestP = pw, bestF = f;
  }
  double a = std::max(fa, bestF - (fb - fa) / scan), b = std::min(fb, bestF + (fb - fa) / scan);
  const double gr = (std::sqrt(5.0) - 1) / 2;
  for (int i = 0; i < 50; ++i) {
    const double c1 = b - gr * (b - a), c2 = a + gr * (b - a);
    if (pg.power(c1) > pg.power(c2)) b = c2;
    else a = c1;
  }
  return 0.5 * (a + b);
}

FittedLine fitLineAt(const std::vector<double>& y, double mean, double dt, double f) {
  // y - mean ~ a cos(w t) + b sin(w t), t = (k + 0.5) dt; cos/sin by a rotation recurrence
  // re-anchored every 4096 samples.
  const std::size_t N = y.size();
  const double w = 2 * M_PI * f * dt;
  double c = 0, s = 0;
  for (std::size_t k0 = 0; k0 < N; k0 += 4096) {
    double ck = std::cos(w * (double(k0) + 0.5)), sk = std::sin(w * (double(k0) + 0.5));
    const double cw = std::cos(w), sw = std::sin(w);
    for (std::size_t k = k0; k < std::min(N, k0 + 4096); ++k) {
      const double v = y[k] - mean;
      c += v * ck, s += v * sk;
      const double cn = ck * cw - sk * sw;
      sk = sk * cw + ck * sw, ck = cn;
    }
  }
  const double a = N > 0 ? 2 * c / double(N) : 0.0, b = N > 0 ? 2 * s / double(N) : 0.0;
  FittedLine out;
  out.frequency = f;
  out.sampled = std::hypot(a, b);
  const double x = M_PI * f * dt;
  const double sinc = x > 0 ? std::sin(x) / x : 1.0;  // the interval average of a sinusoid
  out.amplitude = out.sampled / sinc;
  out.phase = std::atan2(a, b);
  return out;
}

std::vector<double> lineSamples(const FittedLine& line, double dt, std::size_t N) {
  std::vector<double> sig(N);
  for (std::size_t k = 0; k < N; ++k)
    sig[k] = line.sampled * std::sin(2 * M_PI * line.frequency * (double(k) + 0.5) * dt + line.phase);
  return sig;
}

double sinusoidAllanVariance(double A, double f, double tau) {
  const double x = M_PI * f * tau;
  if (!(x > 0)) return 0.0;
  const double s = std::sin(x);
  return A * A * s * s * s * s / (x * x);
}

}  // namespace sinsim::errormodels
