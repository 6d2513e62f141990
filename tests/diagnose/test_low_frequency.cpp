// The record's longest scales (errormodels/diagnose/low_frequency.hpp) against closed forms:
// orthonormal directions blind to a constant and a line, white noise's coefficients N(0, s^2), and
// the variance from an Allan term against a random walk's exact cosine variance and white noise's.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "errormodels/diagnose/low_frequency.hpp"

namespace d = sinsim::errormodels::diagnose::detail;

namespace {

/// The direction's value per sample (constant within a block).
std::vector<double> perSample(const d::LowFrequencyBasis& b, std::size_t dir, std::size_t n) {
  std::vector<double> u(n);
  for (std::size_t k = 0; k < n; ++k) u[k] = b.u[dir][std::min(k / b.block, b.count.size() - 1)];
  return u;
}

/// The Allan variances of a walk of increment variance q^2 and of white noise of variance s^2 on
/// the octave grid m = 1..N/8 at dt (closed forms: q^2 tau / (3 dt) and s^2 dt / tau).
struct OctaveTerms {
  std::vector<double> tau, walk, white;
};
OctaveTerms octaveTerms(std::size_t N, double dt, double q, double s) {
  OctaveTerms o;
  for (std::size_t m = 1; m <= N / 8; m *= 2) {
    o.tau.push_back(double(m) * dt);
    o.walk.push_back(q * q * double(m) / 3.0);
    o.white.push_back(s * s / double(m));
  }
  return o;
}

}  // namespace

// Orthonormal in the samples' inner product (Gram-Schmidt, re-orthogonalised: 1e-12 is rounding of
// sums of ~1e3 terms of order 1e-2), and a constant plus a line give coefficients of rounding size:
// a line's sum over a block is exactly its count times its value at the block centre. The record
// length 30001 leaves a shorter last block.
TEST_CASE("the slow directions are orthonormal and blind to a line", "[diagnose][lowfreq]") {
  constexpr std::size_t n = 30001;
  std::vector<double> temp(n);
  for (std::size_t k = 0; k < n; ++k) temp[k] = 300 + 15 * (1 - std::exp(-double(k) / 7000.0));
  const auto b = d::lowFrequencyBasis(n, temp);
  REQUIRE(b.u.size() >= 4);
  for (std::size_t i = 0; i < b.u.size(); ++i)
    for (std::size_t j = 0; j < b.u.size(); ++j) {
      const auto ui = perSample(b, i, n), uj = perSample(b, j, n);
      double s = 0;
      for (std::size_t k = 0; k < n; ++k) s += ui[k] * uj[k];
      CHECK(s == Approx(i == j ? 1.0 : 0.0).margin(1e-12));
    }
  std::vector<double> y(n);
  for (std::size_t k = 0; k < n; ++k) y[k] = 3.0 - 2e-4 * (double(k) + 0.5);
  double norm = 0;
  for (double v : y) norm += v * v;
  for (double c : d::lowFrequencyCoefficients(y, b)) CHECK(std::fabs(c) < 1e-10 * std::sqrt(norm));
}

// On white noise of sd s the coefficients on orthonormal directions are independent N(0, s^2) (the
// variance the selection's likelihood assumes for a white model). 1000 records of 5000 samples
// (std::mt19937_64, not the code under test), every direction: |c| > 2.576 s in 1 % and > s in
// 31.73 % of the 1000 x m coefficients: within 3.2 binomial sd of the counts (m = 6: 60 +- 25 and
// 1904 +- 115). Blocks not weighted by their counts, a direction not normalised, or a
// coefficient that is a mean instead of a sum shift one of the two. The likelihood at a huge dof
// is the Gaussian c^2/var + ln var.
TEST_CASE("the slow coefficients of white noise are N(0, s^2)", "[diagnose][lowfreq]") {
  constexpr std::size_t n = 5000;
  const auto b = d::lowFrequencyBasis(n, {});
  const double sd = 0.3;
  std::mt19937_64 rng(20261125);
  std::normal_distribution<double> normal(0.0, sd);
  int over2576 = 0, over1 = 0, total = 0;
  std::vector<double> y(n);
  for (int seed = 0; seed < 1000; ++seed) {
    for (double& v : y) v = normal(rng);
    for (double c : d::lowFrequencyCoefficients(y, b)) over2576 += std::fabs(c) > 2.576 * sd, over1 += std::fabs(c) > sd, ++total;
  }
  REQUIRE(total == 1000 * int(b.u.size()));
  const double m = double(total);
  CHECK(std::fabs(over2576 - 0.01 * m) <= 3.2 * std::sqrt(m * 0.01 * 0.99));
  CHECK(std::fabs(over1 - 0.3173 * m) <= 3.2 * std::sqrt(m * 0.3173 * 0.6827));
  CHECK(d::lowFrequencyNll({0.3, -0.6}, {0.09, 0.04}, 1e12) ==
        Approx(1.0 + std::log(0.09) + 9.0 + std::log(0.04)).epsilon(1e-6));
}

// lowFrequencyVarianceOf from an Allan term against closed forms, on the plain cosine
// u_t = sqrt(2/N) cos(pi k (t + 1/2) / N): a random walk of increment variance q^2 (AVAR
// q^2 tau / (3 dt)) has u'Sigma u = q^2 sum_j (sum_{t >= j} u_t)^2 = q^2 N^2 / (pi^2 k^2) (1 + O(1/N)),
// summed here exactly; white noise of variance s^2 (AVAR s^2 dt / tau) has s^2, and the
// approximation gives 12/pi^2 s^2 (the stated 1.22x, on the high side). 1 % covers the O(k/N)
// terms at N = 4096.
TEST_CASE("the slow coefficients' variance from an Allan term matches a walk's and bounds white noise's",
          "[diagnose][lowfreq]") {
  constexpr std::size_t N = 4096;
  const double dt = 0.01, T = double(N) * dt, q = 2e-3, s = 0.05;
  const auto [tau, walk, white] = octaveTerms(N, dt, q, s);
  for (int k = 1; k <= 6; ++k) {
    double exact = 0, tail = 0;
    for (std::size_t j = N; j-- > 0;) {
      tail += std::sqrt(2.0 / double(N)) * std::cos(M_PI * k * (double(j) + 0.5) / double(N));
      exact += tail * tail;
    }
    exact *= q * q;
    INFO("k = " << k);
    CHECK(d::lowFrequencyVarianceOf(walk, tau, T, dt, k) == Approx(exact).epsilon(0.01));
    CHECK(d::lowFrequencyVarianceOf(white, tau, T, dt, k) == Approx(12.0 / (M_PI * M_PI) * s * s).epsilon(1e-9));
  }
}

// glsTestOf, the generalised least-squares test of a shape on the cosines, against closed forms. On
// a random walk of increment variance q^2 with a free level, the best linear test of a shape x
// uses the increments: its information is sum_t (x_{t+1} - x_t)^2 / q^2, so with y = x the t is
// the root of that (Parseval on the differenced series: the walk's cosine variance is exact;
// 2 % covers the cosines beyond 512 and the O(k/N) terms). Under H0 (a walk plus white noise,
// std::mt19937_64, 400 records) |t| > 1.96 in 5 % within 3.2 binomial sd, and in more than 2 %
// (a t scaled wrongly by a factor of 1.5 either way fails one of the two; the conversion of the
// white part without powerLawCosineRatio, 1.22x high, gives 3.2 %). The same settling of T/20 on the walk: its mean
// t at least twice the least-squares coefficient's (coefficientVarianceOf, exact for the walk),
// as the closed form says (2.8x at this size). Its dof: infinite for a known noise, R-based for
// an estimated one, 4x when half of it is known (Satterthwaite's (1 + known/estimated)^2).
TEST_CASE("the generalised least-squares test of a settling on a walk", "[diagnose][lowfreq]") {
  constexpr std::size_t N = 8192;
  const double dt = 0.01, T = double(N) * dt, q = 2e-3, s = 0.01;
  const auto [tau, walk, white] = octaveTerms(N, dt, q, s);
  std::vector<double> both = walk;
  for (std::size_t j = 0; j < both.size(); ++j) both[j] += white[j];
  std::vector<double> x(N);
  for (std::size_t k = 0; k < N; ++k) x[k] = std::exp(-double(k) * dt / (T / 20));
  double info = 0;
  for (std::size_t k = 0; k + 1 < N; ++k) info += (x[k + 1] - x[k]) * (x[k + 1] - x[k]) / (q * q);
  const auto cx = d::cosineSpectrum(x);
  CHECK(d::glsTestOf(cx, cx, walk, {}, 16, tau, T, dt).t == Approx(std::sqrt(info)).epsilon(0.02));
  // The dof: a walk known in closed form leaves t exact; estimated by R realisations, the
  // settling's information, all in the first octaves, has Satterthwaite's dof between R (all of
  // it at k = 1) and R times the highest octave's 2^j it reaches; a part known lifts it by
  // (1 / estimated share)^2.
  CHECK(std::isinf(d::glsTestOf(cx, cx, {}, walk, 16, tau, T, dt).dof));
  const double dofAll = d::glsTestOf(cx, cx, walk, {}, 16, tau, T, dt).dof;
  CHECK(dofAll >= 16);
  CHECK(dofAll <= 16 * 256);
  std::vector<double> part = walk, rest = walk;
  for (auto& v : part) v *= 0.5;
  for (auto& v : rest) v *= 0.5;
  const auto split = d::glsTestOf(cx, cx, part, rest, 16, tau, T, dt);
  CHECK(split.dof == Approx(4 * dofAll).epsilon(1e-9));
  CHECK(split.t == Approx(std::sqrt(info)).epsilon(0.02));

  std::mt19937_64 rng(20261201);
  std::normal_distribution<double> normal(0.0, 1.0);
  const double A = 3.0 / std::sqrt(info);  // the GLS t's mean for the walk alone is 3
  const double olsSd = std::sqrt(d::coefficientVarianceOf(cx, both, tau, T, dt));
  double xm = 0, xx = 0;
  for (double v : x) xm += v / double(N);
  for (double v : x) xx += (v - xm) * (v - xm);
  int over = 0;
  double tGls = 0, tOls = 0;
  constexpr int records = 400;
  std::vector<double> y(N);
  for (int r = 0; r < records; ++r) {
    double level = 0;
    for (double& v : y) level += q * normal(rng), v = level + s * normal(rng);
    over += std::fabs(d::glsTestOf(cx, d::cosineSpectrum(y), {}, both, 16, tau, T, dt).t) > 1.96;
    for (std::size_t k = 0; k < N; ++k) y[k] += A * x[k];
    tGls += d::glsTestOf(cx, d::cosineSpectrum(y), {}, both, 16, tau, T, dt).t / records;
    double xy = 0;
    for (std::size_t k = 0; k < N; ++k) xy += (x[k] - xm) * y[k];
    tOls += std::fabs(xy / xx) / olsSd / records;
  }
  const double m = records;
  CHECK(std::fabs(over - 0.05 * m) <= 3.2 * std::sqrt(m * 0.05 * 0.95));
  CHECK(over > 0.02 * m);
  CHECK(tGls > 2.0 * tOls);
}

// powerLawCosineRatio against its three closed forms (white 12/pi^2, flicker 12 ln 2 / pi^2, walk 1)
// and, between them, against the integral it stands for computed here by quadrature: for
// S(f) = f^alpha, (24/pi^2) 4^alpha int_0^inf f^alpha 2 sin^4(pi f) / (pi f)^2 df (Simpson on
// [0, 400] in steps of 1/2000, the tail by sin^4's mean 3/8; 1e-3 covers both).
TEST_CASE("the Allan-to-cosine variance ratio of a power-law noise", "[diagnose][lowfreq]") {
  CHECK(d::powerLawCosineRatio(-1.0) == Approx(12.0 / (M_PI * M_PI)).epsilon(1e-5));
  CHECK(d::powerLawCosineRatio(0.0) == Approx(12.0 * std::log(2.0) / (M_PI * M_PI)).epsilon(1e-5));
  CHECK(d::powerLawCosineRatio(1.0) == Approx(1.0).epsilon(1e-5));
  for (double mu : {-0.7, -0.3, 0.4, 0.8}) {
    const double alpha = -mu - 1, U = 400, h = 1.0 / 2000;
    auto f = [alpha](double u) {
      if (u == 0) return 0.0;
      const double s = std::sin(M_PI * u);
      return std::pow(u, alpha) * 2 * s * s * s * s / (M_PI * M_PI * u * u);
    };
    double I = f(0) + f(U);
    const int n = int(U / h);
    for (int i = 1; i < n; ++i) I += (i % 2 ? 4 : 2) * f(i * h);
    I *= h / 3;
    I += 2 * 0.375 / (M_PI * M_PI) * std::pow(U, alpha - 1) / (1 - alpha);
    INFO("mu = " << mu);
    CHECK(d::powerLawCosineRatio(mu) == Approx(24 / (M_PI * M_PI) * std::pow(4.0, alpha) * I).epsilon(1e-3));
  }
}
