// The trend test's scatter when part of it is known exactly (significance.hpp satterthwaiteDof,
// selection.cpp currentTrendVar): after a noise is accepted, its share of a trend's variance is a
// closed form and only the base's share is the mean square of a few realisations. The
// Gaussian-equivalent z of the trend must then keep its Gaussian tail: neither the realisations'
// dof (conservative: a real trend beside a large accepted noise is missed) nor an infinite dof
// (anti-conservative while the realised share dominates).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "errormodels/diagnose/low_frequency.hpp"
#include "errormodels/diagnose/series_tools.hpp"
#include "errormodels/diagnose/significance.hpp"
#include "errormodels/stats/trend.hpp"

namespace d = sinsim::errormodels::diagnose::detail;
namespace em = sinsim::errormodels;

namespace {

/// Of `draws` null trends: a slope ~ N(0, a + known) judged against a + known's estimate, a's
/// share the mean square of `dof` realisations N(0, a); the count with z beyond zLimit when the
/// estimate's dof is `nu(E)` (std::mt19937_64, not the code under test).
template <class Nu>
int exceedances(double a, double known, int dof, double zLimit, int draws, Nu nu, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n01(0.0, 1.0);
  int count = 0;
  for (int i = 0; i < draws; ++i) {
    double e = 0;
    for (int r = 0; r < dof; ++r) {
      const double x = n01(rng) * std::sqrt(a);
      e += x * x / dof;
    }
    const double slope = n01(rng) * std::sqrt(a + known);
    const double z = d::zFromStudentT(std::fabs(slope) / std::sqrt(e + known), nu(e));
    count += z > zLimit;
  }
  return count;
}

}  // namespace

// Closed forms: nothing known leaves the realisations' dof; a share C beside E multiplies it by
// (1 + C/E)^2 (Satterthwaite 1946, nu = 2 E[V]^2 / Var V with Var V = 2 E^2 / dof); all known is
// infinite, and there z is t itself.
TEST_CASE("Satterthwaite dof of a variance partly known exactly", "[diagnose][trend]") {
  CHECK(d::satterthwaiteDof(2.0, 16, 0.0) == 16.0);
  CHECK(d::satterthwaiteDof(1.0, 16, 3.0) == Approx(256.0).epsilon(1e-14));
  CHECK(std::isinf(d::satterthwaiteDof(0.0, 16, 1.0)));
  CHECK(d::zFromStudentT(4.2, std::numeric_limits<double>::infinity()) == 4.2);
}

// 20000 null trends each, 16 realisations: the share of z > 2.576 must be the Gaussian 1 % (200
// expected, binomial sd 14.1; bounds +-3.5 sd = [151, 249]) when the closed-form share is 0, equal
// to, or 9x the realised one. Judged with the realisations' 16 dof whatever is known, the 9x case
// gives ~0.35 % (t nearly Gaussian, z > 2.576 only for t > 2.92: ~70), below the bound; judged
// as if all were known (z = t), the case with nothing known gives P(|t16| > 2.576) = 2.0 %
// (~400), above it.
TEST_CASE("a trend beside a known noise keeps the Gaussian tail", "[diagnose][trend]") {
  constexpr int draws = 20000, dof = 16;
  constexpr double zLimit = 2.576;  // two-sided 1 %
  const auto satterthwaite = [](double known) {
    return [known](double e) { return d::satterthwaiteDof(e, dof, known); };
  };
  for (double known : {0.0, 1.0, 9.0}) {
    INFO("closed-form share " << known << " x the realised one");
    const int n = exceedances(1.0, known, dof, zLimit, draws, satterthwaite(known), 20261125u);
    CHECK(n >= 151);
    CHECK(n <= 249);
  }
  const int old = exceedances(1.0, 9.0, dof, zLimit, draws, [](double) { return double(dof); }, 20261125u);
  CHECK(old < 151);  // the realisations' dof alone: the conservative tail this change removes
  const int naive = exceedances(1.0, 0.0, dof, zLimit, draws,
                                [](double) { return std::numeric_limits<double>::infinity(); }, 20261125u);
  CHECK(naive > 249);  // an infinite dof where nothing is known: the anti-conservative tail
}

// The variance of a regressor's coefficient from the cosines (coefficientVarianceOf) against the
// exact x'Sigma x / (x'x)^2. A random walk of K from the first sample has Sigma_jk = K^2 dt
// min(j + 1, k + 1), so x'Sigma x = K^2 dt sum_m (sum_{k >= m} x_k)^2 (tail sums); its Allan
// variance is K^2 tau / 3. For a settling exp(-t / tau_w) the cosine sum must meet the exact value
// (its cosine coefficients are uncorrelated; 3 % allows the block sums and the discrete walk),
// where the trend-based bound (Var_trend t't / x'x, detector.cpp) overstates it many times for a
// short settling. White noise: 12/pi^2 of the exact sigma^2 / x'x (the high side the cosine
// variance documents), within 3 %.
TEST_CASE("a regressor's variance from the cosines meets the exact one", "[diagnose][trend]") {
  constexpr std::size_t n = 20000;
  const double dt = 0.01, T = double(n) * dt, K = 2e-3;
  std::vector<double> tau;
  for (std::size_t m = 1; m <= n / 8; m *= 2) tau.push_back(double(m) * dt);
  std::vector<double> gWalk(tau.size()), gWhite(tau.size());
  const double sigma = 0.05;
  for (std::size_t i = 0; i < tau.size(); ++i) gWalk[i] = K * K * tau[i] / 3, gWhite[i] = sigma * sigma * dt / tau[i];
  for (double tw : {T / 4, T / 20, T / 100}) {
    INFO("settling time constant T/" << T / tw);
    std::vector<double> x(n);
    double mean = 0;
    for (std::size_t k = 0; k < n; ++k) x[k] = std::exp(-(double(k) + 0.5) * dt / tw), mean += x[k] / double(n);
    double xx = 0, tail = 0, xSx = 0;
    for (std::size_t k = 0; k < n; ++k) xx += (x[k] - mean) * (x[k] - mean);
    for (std::size_t m = n; m-- > 0;) tail += x[m] - mean, xSx += tail * tail;
    const double exactWalk = K * K * dt * xSx / (xx * xx);
    const auto spec = d::cosineSpectrum(x);
    CHECK(d::coefficientVarianceOf(spec, gWalk, tau, T, dt) / exactWalk == Approx(1.0).epsilon(0.03));
    const double exactWhite = sigma * sigma / xx;
    CHECK(d::coefficientVarianceOf(spec, gWhite, tau, T, dt) / exactWhite == Approx(12 / (M_PI * M_PI)).epsilon(0.03));
  }
}

// The exact trend variance from an autocovariance (stats/trend.hpp trendVarianceFromAcov) against
// its definition, Var(sum a_i y_i) = sum_ij a_i a_j acov(|i - j|) with the least-squares weights
// a_i = (t_i - mean t) / sum (t - mean t)^2 summed directly (O(N^2)); white noise against the
// closed form 12 s2 / (dt^2 N (N^2 - 1)).
TEST_CASE("the exact trend variance of a stationary noise is its definition", "[diagnose][trend]") {
  const double dt = 0.01;
  for (std::size_t N : {2u, 3u, 17u, 400u}) {
    std::vector<double> white(N, 0.0);
    white[0] = 2.5;
    const double n = double(N);
    CHECK(em::trendVarianceFromAcov(white, N, dt) == Approx(12 * 2.5 / (dt * dt * n * (n * n - 1))).epsilon(1e-10));
    for (double phi : {0.3, 0.95, 0.999}) {
      std::vector<double> gm(N);
      for (std::size_t h = 0; h < N; ++h) gm[h] = 0.7 * std::pow(phi, double(h));
      std::vector<double> a(N);
      double tm = 0, stt = 0;
      for (std::size_t i = 0; i < N; ++i) tm += (double(i) + 0.5) * dt / n;
      for (std::size_t i = 0; i < N; ++i) stt += ((double(i) + 0.5) * dt - tm) * ((double(i) + 0.5) * dt - tm);
      for (std::size_t i = 0; i < N; ++i) a[i] = ((double(i) + 0.5) * dt - tm) / stt;
      double direct = 0;
      for (std::size_t i = 0; i < N; ++i)
        for (std::size_t j = 0; j < N; ++j) direct += a[i] * a[j] * gm[i > j ? i - j : j - i];
      CHECK(em::trendVarianceFromAcov(gm, N, dt) == Approx(direct).epsilon(1e-9));
    }
    // An autocovariance given only where it is not negligible (the rest 0): the same.
    CHECK(em::trendVarianceFromAcov({2.5}, N, dt) == Approx(12 * 2.5 / (dt * dt * n * (n * n - 1))).epsilon(1e-10));
  }
  std::vector<double> gm(400), head(40);
  for (std::size_t h = 0; h < gm.size(); ++h) gm[h] = std::pow(0.3, double(h));
  std::copy(gm.begin(), gm.begin() + 40, head.begin());  // 0.3^40 = 1.2e-21
  CHECK(em::trendVarianceFromAcov(head, 400, dt) == Approx(em::trendVarianceFromAcov(gm, 400, dt)).epsilon(1e-14));
}

// ... and against the scatter of simulated trends: 4000 stationary AR(1) records of 500 samples
// (phi = 0.98, a correlation time of 50 samples; std::mt19937_64), whose least-squares slopes
// (trendSlope) have a mean square within 3.5 sd of its chi-square(4000) scatter of the exact value
// (relative sd sqrt(2 / 4000) = 2.2 %); the white-noise formula of the same variance would be 99x
// too small, and the on-the-high-side bound from the Allan variance (trendVarianceOf) is not
// tested here.
TEST_CASE("the exact trend variance of a Gauss-Markov matches simulated trends", "[diagnose][trend]") {
  const std::size_t N = 500, R = 4000;
  const double phi = 0.98, s2 = 1.0, dt = 0.01;
  std::vector<double> acov(N);
  for (std::size_t h = 0; h < N; ++h) acov[h] = s2 * std::pow(phi, double(h));
  const double exact = em::trendVarianceFromAcov(acov, N, dt);
  std::mt19937_64 rng(20261201);
  std::normal_distribution<double> n01(0.0, 1.0);
  double ms = 0;
  std::vector<double> y(N);
  for (std::size_t r = 0; r < R; ++r) {
    y[0] = n01(rng) * std::sqrt(s2);
    for (std::size_t k = 1; k < N; ++k) y[k] = phi * y[k - 1] + n01(rng) * std::sqrt(s2 * (1 - phi * phi));
    const double b = em::trendSlope(y, dt);
    ms += b * b / double(R);
  }
  CHECK(std::fabs(ms / exact - 1) < 3.5 * std::sqrt(2.0 / double(R)));
  const double whiteOnly = 12 * s2 / (dt * dt * double(N) * (double(N) * double(N) - 1));
  CHECK(exact > 20 * whiteOnly);
}
