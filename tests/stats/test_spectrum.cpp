// Autocorrelation and Welch PSD against closed forms, identities and statistical bounds.
#include <catch2/catch.hpp>

#include <cmath>
#include <complex>
#include <random>
#include <vector>

#include "common/error.hpp"
#include "errormodels/stats/spectral_lines.hpp"
#include "errormodels/stats/spectrum.hpp"

using namespace sinsim::errormodels;

namespace {

/// n draws of d from rng.
std::vector<double> draws(std::mt19937_64& rng, std::normal_distribution<double>& d, std::size_t n) {
  std::vector<double> x(n);
  for (auto& v : x) v = d(rng);
  return x;
}

}  // namespace

TEST_CASE("FFT autocorrelation equals the direct sum (no circular wrap)", "[acf]") {
  std::mt19937_64 rng(11);  // stream "acf-fft"
  std::normal_distribution<double> g(3.0, 2.0);
  for (std::size_t n : {2u, 7u, 1000u, 4097u}) {
    const std::vector<double> x = draws(rng, g, n);
    const std::size_t lags = n - 1;  // every lag, including the last with a single product
    const Autocorrelation d = autocorrelation(x, 50.0, lags, AcfScaling::Biased, AcfMethod::Direct);
    const Autocorrelation f = autocorrelation(x, 50.0, lags, AcfScaling::Biased, AcfMethod::Fft);
    // FFT round-off: ~eps log2(L) r(0) per lag; 1e-12 r(0) leaves a factor > 100 of margin,
    // while a wrapped (unpadded) correlation errs by O(r(0)) at the large lags.
    for (std::size_t k = 0; k <= lags; ++k) CHECK(std::abs(d.r[k] - f.r[k]) <= 1e-12 * d.r[0]);
    CHECK(d.lag[1] == Approx(0.02));
  }
}

TEST_CASE("ACF of an AR(1) record follows phi^k within Bartlett's bound", "[acf]") {
  // x_n = phi x_{n-1} + e_n has rho(k) = phi^k. Bartlett's formula for AR(1):
  // var r_k ~ [(1 + phi^2)(1 - phi^2k) / (1 - phi^2) - 2 k phi^2k] / N; 4 sd per lag over 20
  // lags keeps the family-wise false-alarm rate < 0.2 %. The biased estimator's -k/N rho_k
  // bias (< 1e-4 here) is far inside.
  const double phi = 0.9;
  const std::size_t n = 200000;
  std::mt19937_64 rng(12);  // stream "acf-ar1"
  std::normal_distribution<double> g;
  std::vector<double> x(n);
  double s = 0;
  for (std::size_t i = 0; i < 1000; ++i) s = phi * s + g(rng);  // burn-in to stationarity
  for (auto& v : x) v = s = phi * s + g(rng);
  const Autocorrelation a = autocorrelation(x, 1.0, 200);  // FFT path
  CHECK(a.r[0] == 1.0);
  CHECK(a.variance == Approx(1.0 / (1 - phi * phi)).epsilon(0.05));  // 3.5 sd of the variance
  for (int k = 1; k <= 20; ++k) {
    const double p2k = std::pow(phi, 2 * k);
    const double var = ((1 + phi * phi) * (1 - p2k) / (1 - phi * phi) - 2 * k * p2k) / n;
    CHECK(std::abs(a.r[k] - std::pow(phi, k)) <= 4 * std::sqrt(var));
  }
}

TEST_CASE("autocorrelation bad input", "[acf]") {
  CHECK_THROWS_AS(autocorrelation({1.0}, 1.0, 0), sinsim::InputError);
  CHECK_THROWS_AS(autocorrelation({1.0, 2.0}, 1.0, 2), sinsim::InputError);
  CHECK_THROWS_AS(autocorrelation({1.0, 1.0, 1.0}, 1.0, 1), sinsim::InputError);  // constant
  CHECK_THROWS_AS(autocorrelation({1.0, INFINITY, 1.0}, 1.0, 1), sinsim::InputError);
  CHECK_THROWS_AS(autocorrelation({1.0, 2.0, 1.0}, -1.0, 1), sinsim::InputError);
}

TEST_CASE("Welch PSD: Parseval identity and white-noise level", "[psd]") {
  // White noise of sd 2 at 100 Hz: the one-sided density is 2 sigma^2 / fs = 0.08 u^2/Hz.
  const double fs = 100.0, sigma = 2.0;
  const std::size_t n = 1 << 18;
  std::mt19937_64 rng(13);  // stream "psd-white"
  std::normal_distribution<double> g(5.0, sigma);
  std::vector<double> x(n);
  for (auto& v : x) v = g(rng);
  WelchOptions opt;
  opt.segment_length = 1024;
  const PowerSpectrum p = welchPsd(x, fs, opt);
  REQUIRE(p.segments == (n - 1024) / 512 + 1);
  REQUIRE(p.f.size() == 513);
  CHECK(p.f.back() == Approx(fs / 2));
  CHECK(p.enbw_hz == Approx(1.5 * fs / 1024).epsilon(1e-12));  // Hann: 1.5 bins
  // Parseval, an identity: sum psd df = mean over segments of sum (w (x - mean))^2 / sum w^2.
  double integral = 0;
  for (double v : p.psd) integral += v * p.df;
  double expect = 0;
  std::vector<double> w(1024);
  double sw2 = 0;
  for (std::size_t i = 0; i < 1024; ++i) {
    w[i] = 0.5 - 0.5 * std::cos(2 * M_PI * i / 1024.0);
    sw2 += w[i] * w[i];
  }
  for (std::size_t s = 0; s < p.segments; ++s) {
    double mean = 0;
    for (std::size_t i = 0; i < 1024; ++i) mean += x[s * 512 + i];
    mean /= 1024;
    double e = 0;
    for (std::size_t i = 0; i < 1024; ++i) e += std::pow(w[i] * (x[s * 512 + i] - mean), 2);
    expect += e / sw2;
  }
  expect /= p.segments;
  CHECK(integral == Approx(expect).epsilon(1e-12));  // rounding of ~1e6 terms
  // ... and that is the variance: 511 segments of ~1024 samples, Hann-weighted, give a relative
  // standard error ~ sqrt(2 / (511 * 1024 / 1.9)) = 0.3 %; 1.5 % is 5 sd.
  CHECK(integral == Approx(sigma * sigma).epsilon(0.015));
  // Level: mean over bins 1..511 of a chi2 average; relative sd ~ 0.3 %, 1.5 % = 5 sd.
  double level = 0;
  for (std::size_t k = 1; k < 512; ++k) level += p.psd[k];
  level /= 511;
  CHECK(level == Approx(2 * sigma * sigma / fs).epsilon(0.015));
}

TEST_CASE("Welch PSD: a bin-centred sinusoid puts A^2/2 into three bins", "[psd]") {
  // x = A cos(2 pi k0 n / L): the periodic Hann spectrum of a bin-centred tone has exactly the
  // bins k0 - 1, k0, k0 + 1 (weights 1/4, 1/2, 1/4 in amplitude), so their integral is A^2/2 to
  // rounding and every other bin is zero to rounding.
  const std::size_t len = 256, k0 = 20;
  const double fs = 50.0, amp = 3.0;
  std::vector<double> x(len * 16);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = amp * std::cos(2 * M_PI * k0 * i / len);
  WelchOptions opt;
  opt.segment_length = len;
  const PowerSpectrum p = welchPsd(x, fs, opt);
  const double peak = (p.psd[k0 - 1] + p.psd[k0] + p.psd[k0 + 1]) * p.df;
  CHECK(peak == Approx(amp * amp / 2).epsilon(1e-12));
  CHECK(p.f[k0] == Approx(k0 * fs / len));
  for (std::size_t k = 0; k < p.psd.size(); ++k) {
    if (k + 1 < k0 || k > k0 + 1) CHECK(p.psd[k] <= 1e-20 * p.psd[k0]);
  }
}

TEST_CASE("Welch PSD bad input and defaults", "[psd]") {
  CHECK_THROWS_AS(welchPsd(std::vector<double>(10, 1.0), 1.0, WelchOptions{64, 0.5, true}), sinsim::InputError);
  CHECK_THROWS_AS(welchPsd(std::vector<double>(100, 1.0), 1.0, WelchOptions{16, 1.0, true}), sinsim::InputError);
  CHECK_THROWS_AS(welchPsd(std::vector<double>(100, 1.0), 0.0), sinsim::InputError);
  const PowerSpectrum p = welchPsd(std::vector<double>(100000, 1.0), 1.0);
  CHECK(p.segment_length == 8192);  // largest power of two <= N / 8
  for (double v : p.psd) CHECK(v == 0.0);  // a constant has no power once its mean is removed
}

TEST_CASE("padded power sum equals the zero-padded DFT summed directly", "[psd][padded]") {
  // Against G(w) = sum_j g_j e^{-i w j} evaluated term by term at every w_k = 2 pi k / M (no FFT),
  // for odd and even lengths and paddings whose interleaved sets do and do not pair up (pad 1..5).
  std::mt19937_64 rng(23);  // stream "padded-power"
  std::normal_distribution<double> z(0.0, 1.0);
  for (std::size_t n : {2u, 37u, 64u, 105u}) {
    const std::vector<double> g = draws(rng, z, n);
    for (std::size_t pad : {1u, 2u, 3u, 4u, 5u}) {
      const std::size_t M = pad * n;
      const auto weight = [](double w) { return 1.0 / w + 0.3 * w * w; };
      double direct = 0.0, parseval = 0.0;
      for (std::size_t k = 1; k < M; ++k) {
        const double w = 2.0 * 3.141592653589793 * double(k) / double(M);
        std::complex<double> G = 0.0;
        for (std::size_t j = 0; j < n; ++j) G += g[j] * std::polar(1.0, -w * double(j));
        direct += std::norm(G) * weight(w > 3.141592653589793 ? 2.0 * 3.141592653589793 - w : w);
        parseval += std::norm(G);
      }
      const double sum = paddedPowerSum(g, pad, weight);
      CHECK(sum == Approx(direct).epsilon(1e-11));
      // Parseval on the M-point grid: sum_{k=1}^{M-1} |G_k|^2 = M sum g^2 - (sum g)^2, a closed form.
      double s1 = 0.0, s2 = 0.0;
      for (double v : g) s1 += v, s2 += v * v;
      CHECK(paddedPowerSum(g, pad, [](double) { return 1.0; }) == Approx(double(M) * s2 - s1 * s1).epsilon(1e-11));
      CHECK(parseval == Approx(double(M) * s2 - s1 * s1).epsilon(1e-11));
    }
  }
  CHECK_THROWS_AS(paddedPowerSum(std::vector<double>(8, 1.0), 0, [](double) { return 1.0; }), sinsim::InputError);
  CHECK_THROWS_AS(paddedPowerSum(std::vector<double>(1, 1.0), 4, [](double) { return 1.0; }), sinsim::InputError);
}

TEST_CASE("Welch line test: a sinusoid is found and sized, white and red continua raise no line",
          "[psd][lines]") {
  // Records of 2^17 samples at 100 Hz, Welch segments of 4096 (31 bins per Hz: df = 0.0244 Hz).
  const double fs = 100.0;
  const std::size_t n = std::size_t(1) << 17;
  WelchOptions wo;
  wo.segment_length = 4096;
  std::mt19937_64 rng(2027);  // stream "welch-lines"
  std::normal_distribution<double> g(0.0, 1.0);
  // A line in unit white noise: at a bin's centre its amplitude is exact up to the noise; half a
  // bin off, the Hann window's scalloping loss (1.42 dB: 0.849 of the amplitude) at most.
  const double df = fs / double(wo.segment_length);
  for (const auto& [bin, A] : {std::pair{300.5, 0.2}, std::pair{300.0, 0.2}, std::pair{1500.0, 0.1}}) {
    std::vector<double> x = draws(rng, g, n);
    const double f = bin * df;
    for (std::size_t k = 0; k < n; ++k) x[k] += A * std::sin(2 * M_PI * f * double(k) / fs + 0.3);
    const PowerSpectrum p = welchPsd(x, fs, wo);
    const std::vector<WelchLine> lines = welchLineTest(p, 4);
    REQUIRE_FALSE(lines.empty());
    INFO("bin " << bin << " amplitude " << A);
    CHECK(lines[0].p < 1e-6);
    CHECK(std::fabs(lines[0].freq - f) <= df);
    const double a = welchLineAmplitude(p.psd[lines[0].bin], lines[0].ratio, p.enbw_hz);
    CHECK(a / A > (bin == std::floor(bin) ? 0.9 : 0.8));
    CHECK(a / A < 1.1);
  }
  // Continua: 300 white records, 100 first-order GM (tau 20 samples to 20 s) and 100 random walks;
  // a line at p < 1e-3 from bin 12 up (the fit's warning) may come at most at that rate: <= 3 of
  // 300 (binomial, P(> 3) = 2.6e-4 at 1e-3 each), <= 2 of 100.
  auto warned = [&](const std::vector<double>& x) {
    for (const WelchLine& l : welchLineTest(welchPsd(x, fs, wo), 4))
      if (l.p < 1e-3 && l.bin >= 12) return true;
    return false;
  };
  int white = 0, gm = 0, walk = 0;
  for (int s = 0; s < 300; ++s) white += warned(draws(rng, g, n));
  for (int s = 0; s < 100; ++s) {
    const double a = std::exp(-1.0 / (std::pow(10.0, 1.3 + 2.0 * s / 100.0)));
    std::vector<double> x = draws(rng, g, n), y(n), w(n);
    double v = 0.0, acc = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      v = a * v + std::sqrt(1 - a * a) * g(rng);
      y[k] = x[k] + 3.0 * v;
      acc += 0.01 * g(rng);
      w[k] = x[k] + acc;
    }
    gm += warned(y);
    walk += warned(w);
  }
  CHECK(white <= 3);
  CHECK(gm <= 2);
  CHECK(walk <= 2);
}

// The line test below the Welch bins (lowLineTest): records of 2^15 samples at 100 Hz (T 328 s),
// segments of 4096, Welch bin 12: ordinates 12..98 scanned. On 200 white records its p is at
// least as large as its law says (Bonferroni over the ordinates is conservative): p < 0.05 on at
// most 20 (expected <= 10; binomial P(> 20) = 1e-3), p < 0.01 on at most 6. A line of 40 cycles
// (0.1 x the white sd: its ordinate ~N A^2 / 4 = 80 times the continuum) is found at its
// frequency (within 1 / T) at p < 1e-8; given as taken (skipped within 5 / T), the next line,
// 70 cycles at 0.05, is found instead; with both taken, nothing at p < 1e-3.
TEST_CASE("low-line test: conservative on white noise, a line at its ordinate, a taken one skipped",
          "[psd][lines]") {
  const double fs = 100.0;
  const std::size_t n = std::size_t(1) << 15;
  const double T = double(n) / fs;
  std::mt19937_64 rng(2031);  // stream "low-lines"
  std::normal_distribution<double> g(0.0, 1.0);
  int below05 = 0, below01 = 0;
  for (int s = 0; s < 200; ++s) {
    const LowLine l = lowLineTest(draws(rng, g, n), fs, 4096, 12);
    REQUIRE(l.ordinate >= 12);
    REQUIRE(l.ordinate <= 98);
    below05 += l.p < 0.05;
    below01 += l.p < 0.01;
  }
  INFO("white: p < 0.05 on " << below05 << ", p < 0.01 on " << below01 << " of 200");
  CHECK(below05 <= 20);
  CHECK(below01 <= 6);
  for (int s = 0; s < 5; ++s) {
    std::vector<double> x = draws(rng, g, n);
    const double f0 = 40 / T, f1 = 70 / T;
    for (std::size_t k = 0; k < n; ++k) {
      const double t = double(k) / fs;
      x[k] += 0.1 * std::sin(2 * M_PI * f0 * t + s) + 0.05 * std::sin(2 * M_PI * f1 * t + 2 * s);
    }
    const LowLine first = lowLineTest(x, fs, 4096, 12);
    CHECK(first.p < 1e-8);
    CHECK(std::fabs(first.freq - f0) <= 1 / T);
    const LowLine second = lowLineTest(x, fs, 4096, 12, {f0}, 5 / T);
    CHECK(second.p < 1e-3);
    CHECK(std::fabs(second.freq - f1) <= 1 / T);
    CHECK(lowLineTest(x, fs, 4096, 12, {f0, f1}, 5 / T).p > 1e-3);
  }
}

TEST_CASE("zero-phase filter: each cosine of the even extension scaled by the gain at its frequency",
          "[psd][filter]") {
  // The DCT-II basis: x_n = cos(pi k (2n + 1) / (2N)) is the record's mirrored extension's cosine
  // at w_k = pi k / N, so the filter returns gain(w_k) x exactly (closed form, no window).
  const std::size_t n = 1000;  // 2^3 5^3, and 997 (a prime) below
  for (std::size_t len : {n, std::size_t(997)}) {
    auto cosine = [&](std::size_t k) {
      std::vector<double> x(len);
      for (std::size_t i = 0; i < len; ++i) x[i] = std::cos(M_PI * double(k) * (2.0 * double(i) + 1.0) / (2.0 * double(len)));
      return x;
    };
    const auto gain = [](double w) { return 1.0 / (1.0 + 10.0 * w * w); };
    for (std::size_t k : {std::size_t(0), std::size_t(1), std::size_t(7), len / 2, len - 1}) {
      const std::vector<double> x = cosine(k), y = zeroPhaseFiltered(x, gain);
      const double g = gain(M_PI * double(k) / double(len));
      for (std::size_t i = 0; i < len; ++i) REQUIRE(y[i] == Approx(g * x[i]).margin(1e-12));
    }
    // Two cosines, a gain that keeps the lower only; and the identity gain returns the record.
    std::vector<double> x = cosine(5), low = x;
    const std::vector<double> high = cosine(len / 3);
    for (std::size_t i = 0; i < len; ++i) x[i] += 2.0 * high[i];
    const std::vector<double> y = zeroPhaseFiltered(x, [&](double w) { return w < M_PI * 10.0 / double(len) ? 1.0 : 0.0; });
    for (std::size_t i = 0; i < len; ++i) REQUIRE(y[i] == Approx(low[i]).margin(1e-12));
    const std::vector<double> same = zeroPhaseFiltered(x, [](double) { return 1.0; });
    for (std::size_t i = 0; i < len; ++i) REQUIRE(same[i] == Approx(x[i]).margin(1e-12));
  }
}

TEST_CASE("zero-phase filter: a ramp through a low-pass has no step at its ends (mirror, not wrap)",
          "[psd][filter]") {
  // The even extension of a ramp of slope s is a triangle wave: no jump, a kink at each end. The
  // gain exp(-(w / w0)^2) is a Gaussian smoother of sd sigma = sqrt(2) / w0 samples, which moves a
  // kink |t| s by s E|T| = s sigma sqrt(2 / pi) (closed form; the discrete sum differs by ~2 %),
  // up at the start and down at the end, and leaves the line unchanged far from both. A periodic
  // (circular) filter would see a sawtooth and smear its jump: ends off by ~0.5 of the range.
  const std::size_t n = 4096;
  const double w0 = 0.05, s = 1.0 / double(n);
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = double(i) * s;
  const std::vector<double> y = zeroPhaseFiltered(x, [&](double w) { return std::exp(-std::pow(w / w0, 2)); });
  const double kink = s * std::sqrt(2.0) / w0 * std::sqrt(2.0 / M_PI);
  CHECK(y.front() - x.front() == Approx(kink).epsilon(0.05));
  CHECK(y.back() - x.back() == Approx(-kink).epsilon(0.05));
  CHECK(std::fabs(y[n / 2] - x[n / 2]) < 1e-9);
}

TEST_CASE("zero-phase filter bad input", "[psd][filter]") {
  CHECK_THROWS_AS(zeroPhaseFiltered({1.0}, [](double) { return 1.0; }), sinsim::InputError);
  CHECK_THROWS_AS(zeroPhaseFiltered({1.0, NAN, 2.0}, [](double) { return 1.0; }), sinsim::InputError);
  CHECK_THROWS_AS(zeroPhaseFiltered({1.0, 2.0, 3.0}, [](double w) { return w > 0 ? NAN : 1.0; }), sinsim::InputError);
}
