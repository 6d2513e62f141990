// Wavelet transform and denoising against PyWavelets 1.1.1 (fixtures from
// fixtures/make_wavelet_fixtures.py) and against the defining properties of the filters.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "common/error.hpp"
#include "errormodels/stats/wavelet.hpp"

using namespace sinsim::errormodels;

namespace {

using Sections = std::map<std::string, std::vector<double>>;

Sections readFixture(const std::string& name) {
  const std::string path = std::string(SINSIM_SOURCE_DIR) + "/tests/stats/fixtures/" + name;
  std::ifstream in(path);
  REQUIRE(in.good());
  Sections s;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    REQUIRE(line[0] == '[');
    const std::size_t close = line.find(']');
    const std::string key = line.substr(1, close - 1);
    const std::size_t count = std::stoul(line.substr(close + 1));
    std::vector<double>& v = s[key];
    for (std::size_t i = 0; i < count; ++i) {
      REQUIRE(std::getline(in, line));
      v.push_back(std::stod(line));
    }
  }
  return s;
}

/// Largest |a - b|, and a size check.
double maxAbsDiff(const std::vector<double>& a, const std::vector<double>& b) {
  REQUIRE(a.size() == b.size());
  double m = 0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

// The issue asks for 1e-9. The signals are O(1); the transforms are sums of <= 10 products per
// level through <= 6 levels, so double rounding differences with PyWavelets' C loops are
// ~1e-15. 1e-12 is asked here (1000x tighter than the issue, 1000x looser than rounding).
constexpr double kTol = 1e-12;

void checkCase(const std::string& file, WaveletBoundary mode) {
  const Sections s = readFixture(file);
  const Wavelet& w = waveletByName("db5");
  CHECK(maxAbsDiff(w.dec_lo, s.at("dec_lo")) == 0.0);  // the very same doubles
  CHECK(maxAbsDiff(w.dec_hi, s.at("dec_hi")) == 0.0);
  CHECK(maxAbsDiff(w.rec_lo, s.at("rec_lo")) == 0.0);
  CHECK(maxAbsDiff(w.rec_hi, s.at("rec_hi")) == 0.0);
  const std::vector<double>& x = s.at("signal");
  const int level = static_cast<int>(s.at("level")[0]);
  const WaveletCoefficients c = wavedec(x, w, mode, level);
  REQUIRE(static_cast<int>(c.level()) == level);
  double worst = 0;
  for (int i = 0; i <= level; ++i) {
    INFO(file << " coefficient array c" << i);
    const double e = maxAbsDiff(c.coeffs[i], s.at("c" + std::to_string(i)));
    worst = std::max(worst, e);
    CHECK(e <= kTol);
  }
  CHECK(maxAbsDiff(waverec(c, w, mode), s.at("recon")) <= kTol);
  // Perfect reconstruction (orthogonal filters): waverec(wavedec(x)) = x on the first n samples.
  const std::vector<double> r = waverec(c, w, mode);
  for (std::size_t i = 0; i < x.size(); ++i) CHECK(std::abs(r[i] - x[i]) <= kTol);

  DenoiseOptions opt;
  opt.boundary = mode;
  opt.level = level;
  for (ThresholdMode tm : {ThresholdMode::Soft, ThresholdMode::Hard}) {
    opt.mode = tm;
    const DenoiseResult d = waveletDenoise(x, opt);
    CHECK(d.sigma == Approx(s.at("sigma")[0]).epsilon(1e-14));
    CHECK(d.thresholds[0] == Approx(s.at("universal_threshold")[0]).epsilon(1e-14));
    INFO(file << (tm == ThresholdMode::Soft ? " soft" : " hard"));
    const double e = maxAbsDiff(d.signal, s.at(tm == ThresholdMode::Soft ? "denoised_soft" : "denoised_hard"));
    worst = std::max(worst, e);
    CHECK(e <= kTol);
  }
  opt.mode = ThresholdMode::Soft;
  opt.rule = ThresholdRule::Sure;
  const DenoiseResult sure = waveletDenoise(x, opt);
  const std::vector<double>& st = s.at("sure_thresholds");  // coarsest first
  REQUIRE(st.size() == sure.thresholds.size());
  for (std::size_t j = 0; j < st.size(); ++j)
    CHECK(sure.thresholds[j] == Approx(st[st.size() - 1 - j]).epsilon(1e-13));
  CHECK(maxAbsDiff(sure.signal, s.at("denoised_sure_soft")) <= kTol);
  WARN(file << ": largest difference from PyWavelets " << worst);
}

}  // namespace

TEST_CASE("db5 wavedec/waverec/denoise equal PyWavelets, symmetric mode", "[wavelet][pywt]") {
  checkCase("wavelet_sym_n1000.txt", WaveletBoundary::Symmetric);
  checkCase("wavelet_sym_n2048_l4.txt", WaveletBoundary::Symmetric);
  // 37 samples: shorter than 4 filter lengths, the extension reflects more than once.
  checkCase("wavelet_sym_n37.txt", WaveletBoundary::Symmetric);
}

TEST_CASE("db5 wavedec/waverec/denoise equal PyWavelets, periodization mode", "[wavelet][pywt]") {
  // n = 1000 gives odd lengths (125, 63) on the way down; 37 is odd from the start.
  checkCase("wavelet_per_n1000.txt", WaveletBoundary::Periodization);
  checkCase("wavelet_per_n37.txt", WaveletBoundary::Periodization);
}

TEST_CASE("db5 filter obeys the Daubechies conditions", "[wavelet]") {
  // Daubechies (1992) ch. 6: sum h = sqrt 2, sum h_k h_{k+2l} = delta_l, and N = 5 vanishing
  // moments sum (-1)^k k^p h_k = 0 for p < 5. The 17-digit coefficients meet them to ~1e-15
  // times the size of the terms (k^4 up to 6561 for the 4th moment).
  for (const char* name : {"db1", "db2", "db5"}) {
    const std::vector<double>& h = waveletByName(name).rec_lo;
    const int f = static_cast<int>(h.size());
    double sum = 0;
    for (double v : h) sum += v;
    CHECK(sum == Approx(std::sqrt(2.0)).epsilon(1e-15));
    for (int l = 0; 2 * l < f; ++l) {
      double dot = 0;
      for (int k = 0; k + 2 * l < f; ++k) dot += h[k] * h[k + 2 * l];
      CHECK(dot == Approx(l == 0 ? 1.0 : 0.0).margin(2e-15));
    }
    for (int p = 0; p < f / 2; ++p) {
      double mom = 0;
      for (int k = 0; k < f; ++k) mom += (k % 2 ? -1.0 : 1.0) * std::pow(k, p) * h[k];
      CHECK(mom == Approx(0.0).margin(1e-15 * std::pow(f, p) * 10));
    }
  }
}

TEST_CASE("wavelet edge cases and bad input", "[wavelet]") {
  const Wavelet& w = waveletByName("db5");
  CHECK(waveletMaxLevel(1000, 10) == 6);  // pywt.dwt_max_level(1000, 10)
  CHECK(waveletMaxLevel(8, 10) == 0);
  CHECK(waveletMaxLevel(1000000, 10) == 16);
  CHECK_THROWS_AS(waveletByName("db7"), sinsim::InputError);
  CHECK_THROWS_AS(waveletBoundaryByName("zero"), sinsim::InputError);
  CHECK_THROWS_AS(wavedec({}, w), sinsim::InputError);
  CHECK_THROWS_AS(wavedec(std::vector<double>(100, 1.0), w, WaveletBoundary::Symmetric, 5),
                  sinsim::InputError);
  CHECK_THROWS_AS(waveletDenoise(std::vector<double>(10, 1.0)), sinsim::InputError);
  CHECK_THROWS_AS(waveletDenoise({1.0, NAN, 2.0, 3.0, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1}),
                  sinsim::InputError);
  // A constant is untouched by denoising (all details vanish in the interior; the symmetric
  // extension of a constant is constant, so the boundary details vanish too).
  const std::vector<double> flat(500, 2.5);
  const DenoiseResult d = waveletDenoise(flat);
  for (double v : d.signal) CHECK(v == Approx(2.5).epsilon(1e-12));
}

TEST_CASE("universal soft thresholding removes white noise from a smooth signal", "[wavelet]") {
  // Statistical check of what denoising is for: sine + white noise (sigma 0.5, seed fixed).
  // The estimated sigma must match 0.5 within 3 standard errors of the MAD estimator
  // (1.67 sigma / sqrt(n/2) for the 2^15 finest details: 0.013 -> 0.04), and the denoised error
  // must be several times below the noise (Donoho & Johnstone: risk ~ sigma^2 log n / n per
  // coefficient for smooth signals): we ask a factor 3 in RMS.
  std::mt19937_64 rng(42);  // stream "wavelet-denoise"
  std::normal_distribution<double> g(0.0, 0.5);
  const std::size_t n = 1 << 16;
  std::vector<double> truth(n), x(n);
  for (std::size_t i = 0; i < n; ++i) {
    truth[i] = std::sin(2 * M_PI * i / 4096.0);
    x[i] = truth[i] + g(rng);
  }
  const DenoiseResult d = waveletDenoise(x);
  CHECK(d.sigma == Approx(0.5).margin(0.04));
  double e2 = 0;
  for (std::size_t i = 0; i < n; ++i) e2 += (d.signal[i] - truth[i]) * (d.signal[i] - truth[i]);
  CHECK(std::sqrt(e2 / n) < 0.5 / 3);
}
