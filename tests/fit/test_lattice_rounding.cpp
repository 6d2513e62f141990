// Quantization on a value lattice when the true integral moves less than one LSB per sample
// (errormodels/fit/lattice_rounding.hpp), checked against truth from outside its formulas: a
// quadrature of the Gaussian expectation, the classical 3 Q^2 / tau^2 where the motion is large,
// the Allan variance of records made by the simulator's own quantization effect (rounding with
// carry), and its PSD against its Allan variance through the Allan transfer function.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "../identify/identify_test_util.hpp"
#include "common/error.hpp"
#include "errormodels/fit/allan_fit.hpp"
#include "errormodels/fit/lattice_rounding.hpp"
#include "errormodels/fit/latent_model.hpp"
#include "fit_test_util.hpp"

using namespace sinsim::errormodels::fit;

namespace {

/// E[f (1 - f)], f = frac(Z), Z ~ N(mean, sd^2), by the trapezoid rule over +-12 sd (1e6 nodes).
double quadrature(double mean, double sd) {
  const int n = 1000000;
  const double a = mean - 12.0 * sd, h = 24.0 * sd / n;
  double s = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double z = a + i * h, f = z - std::floor(z), u = (z - mean) / sd;
    s += (i == 0 || i == n ? 0.5 : 1.0) * f * (1.0 - f) * std::exp(-0.5 * u * u);
  }
  return s * h / (sd * std::sqrt(2.0 * M_PI));
}

}  // namespace

TEST_CASE("lattice rounding: the Gaussian expectation of frac products equals a quadrature",
          "[fit][latent][lattice]") {
  // Both branches (cells below sd 0.3, the Fourier series from 0.3) against the quadrature.
  for (double mean : {0.0, 0.37, -5.9})
    for (double sd : {0.003, 0.05, 0.2, 0.2999, 0.3, 0.7, 2.0}) {
      INFO("mean " << mean << ", sd " << sd);
      CHECK(expectedFracProduct(mean, sd) == Approx(quadrature(mean, sd)).epsilon(1e-7));
    }
  CHECK(expectedFracProduct(0.25, 0.0) == Approx(0.1875));  // no motion: f (1 - f) itself
  CHECK(expectedFracProduct(0.1, 5.0) == Approx(1.0 / 6.0).epsilon(1e-12));  // uniform phase
  CHECK_THROWS_AS(expectedFracProduct(NAN, 0.1), sinsim::InputError);
  CHECK_THROWS_AS(expectedFracProduct(0.0, -1.0), sinsim::InputError);
}

TEST_CASE("lattice rounding: a motion of several LSB gives the classical 3 Q^2 / tau^2",
          "[fit][latent][lattice]") {
  const double D = 2e-4, dt = 0.01;
  RoundingLattice L{D, 1.5 * D, 0.013 * D};
  REQUIRE_FALSE(L.correlated());
  for (std::size_t m : {1, 2, 8, 1024}) {
    const double tau = double(m) * dt;
    CHECK(latticeQuantizationAllanVariance(L, dt, m) == Approx(3.0 * D * D / 12.0 / (tau * tau)).epsilon(1e-8));
  }
  L.motion = 0.2 * D;
  CHECK(L.correlated());
  // At m = 1 the correlated rounding is a third below the classical form (0.67; with the white
  // noise beside it the record's Allan variance is 0.71 of the classical sum, as bench/fit_blind's
  // generator self-test measured); the simulation test below checks the value.
  const double r = latticeQuantizationAllanVariance(L, dt, 1) / (D * D / 4.0 / (dt * dt));
  CHECK(r > 0.6);
  CHECK(r < 0.75);
  CHECK_THROWS_AS(latticeQuantizationAllanVariance(RoundingLattice{D, 0.0, 0.0}, dt, 1), sinsim::InputError);
  CHECK_THROWS_AS(latticeQuantizationAllanVariance(L, dt, 0), sinsim::InputError);
}

TEST_CASE("lattice rounding: closed form matches the simulated Allan variance of white + quantization",
          "[fit][latent][lattice]") {
  // The simulator's quantization (rounding with carry) of white noise whose integral moves 0.2
  // and 0.05 LSB per sample, with and without a bias (the integral's drift between roundings);
  // 100 Hz, 300 s, 48 seeds, m = 1..256. The classical form is 26 % and 80 % off at m = 1.
  struct Case { double whiteDegSqrtH, biasDegH, motion; };
  const double rate = 100.0, dt = 0.01, D = 0.001 * M_PI / 180.0;  // LSB 0.001 deg
  const double kDegSqrtH = M_PI / 180.0 / 60.0;
  for (const Case c : {Case{0.2 * D / std::sqrt(dt) / kDegSqrtH, 0.0, 0.2}, Case{0.2 * D / std::sqrt(dt) / kDegSqrtH, 10.8, 0.2},
                       Case{0.05 * D / std::sqrt(dt) / kDegSqrtH, 3.6, 0.05}}) {
    const std::string body = "gyro:\n  x:\n    - {type: white, density: " + std::to_string(c.whiteDegSqrtH) +
                             " deg/sqrt(h)}\n    - {type: bias, value: " + std::to_string(c.biasDegH) +
                             " deg/h}\n    - {type: quantization, lsb: 0.001 deg}\n";
    LatentModel model;
    model.white = c.whiteDegSqrtH * kDegSqrtH;
    model.quantization = D / std::sqrt(12.0);
    model.lattice = {D, model.white * std::sqrt(dt), c.biasDegH * M_PI / 180.0 / 3600.0 * dt};
    REQUIRE(model.lattice.motion / D == Approx(c.motion));
    std::vector<std::size_t> m;
    for (std::size_t k = 1; k <= 256; k *= 2) m.push_back(k);
    std::vector<double> s(m.size(), 0.0), s2(m.size(), 0.0);
    const int seeds = 48;
    for (int k = 0; k < seeds; ++k) {
      const auto r = identify_test::staticRecord(body, rate, 300.0, 700 + std::uint64_t(k));
      for (std::size_t i = 0; i < m.size(); ++i) {
        const double v = fit_test::overlappingAvar(r.gyro[0], dt, m[i]);
        s[i] += v, s2[i] += v * v;
      }
    }
    const auto avar = latentAllanVariance(model, dt, m);
    for (std::size_t i = 0; i < m.size(); ++i) {
      const double mean = s[i] / seeds, se = std::sqrt((s2[i] / seeds - mean * mean) / (seeds - 1));
      INFO("motion " << c.motion << " LSB, bias " << c.biasDegH << " deg/h, m " << m[i] << ": simulated " << mean
                     << " +- " << se << ", closed form " << avar[i]);
      CHECK(std::fabs(mean - avar[i]) <= 4.0 * se);  // 27 points at 4 sigma: false alarms < 2e-3
    }
  }
}

TEST_CASE("lattice rounding: the PSD gives the closed-form Allan variance through the Allan filter",
          "[fit][latent][lattice]") {
  // AVAR(m) = (1/pi) int_0^pi S(w) 2 sin^4(m w / 2) / (m^2 sin^2(w / 2)) dw (midpoint, 2^18 nodes):
  // the PSD's line sum and the Allan form's cells / series are two derivations of one process.
  const double D = 1e-4, dt = 0.005;
  for (double motion : {0.2, 0.1})
    for (double drift : {0.0, 0.031}) {
      const RoundingLattice L{D, motion * D, drift * D};
      for (std::size_t m : {1, 3, 16}) {
        const int n = 1 << 18;
        const double h = M_PI / n, md = double(m);
        double sum = 0.0;
        for (int i = 0; i < n; ++i) {
          const double w = (i + 0.5) * h, a = std::sin(0.5 * md * w), b = std::sin(0.5 * w);
          sum += latticeQuantizationPsd(L, dt, w) * 2.0 * a * a * a * a / (md * md * b * b);
        }
        INFO("motion " << motion << " LSB, drift " << drift << " LSB/sample, m " << m);
        CHECK(sum * h / M_PI == Approx(latticeQuantizationAllanVariance(L, dt, m)).epsilon(1e-6));
      }
    }
}

TEST_CASE("lattice rounding: the Allan estimates' covariance is the simulated records' spread, not the Gaussian one",
          "[fit][latent][lattice]") {
  // White noise moving 0.13 LSB per sample behind the simulator's carried rounding (LSB 0.002 deg,
  // 100 Hz, 300 s), 64 seeds: the variance over seeds of the Allan estimate at m = 1, 2, 4 against
  // latticeAllanCovariance (48 Monte Carlo records; both spreads are sampled, each ~20 %: bounds
  // 0.5-2), and against the Gaussian covariance of the same PSD, which it exceeds ~7x at m = 1.
  const double rate = 100.0, dt = 0.01, D = 0.002 * M_PI / 180.0, kDegSqrtH = M_PI / 180.0 / 60.0;
  const double N = 0.13 * D / std::sqrt(dt);
  const std::string body = "gyro:\n  x:\n    - {type: white, density: " + std::to_string(N / kDegSqrtH) +
                           " deg/sqrt(h)}\n    - {type: quantization, lsb: 0.002 deg}\n";
  const std::vector<std::size_t> m{1, 2, 4};
  const int seeds = 64;
  std::vector<double> s(m.size(), 0.0), s2(m.size(), 0.0);
  std::size_t n = 0;
  for (int k = 0; k < seeds; ++k) {
    const auto r = identify_test::staticRecord(body, rate, 300.0, 900 + std::uint64_t(k));
    n = r.gyro[0].size();
    for (std::size_t i = 0; i < m.size(); ++i) {
      const double v = fit_test::overlappingAvar(r.gyro[0], dt, m[i]);
      s[i] += v, s2[i] += v * v;
    }
  }
  const RoundingLattice L{D, N * std::sqrt(dt), 0.0};
  const Eigen::MatrixXd mc = latticeAllanCovariance(L, dt, n, m, 48, 7);
  LatentModel model;
  model.white = N, model.quantization = D / std::sqrt(12.0), model.lattice = L;
  const Eigen::MatrixXd gauss = allanEstimateCovariance([&](double w) { return latentPsd(model, dt, w); }, m, n);
  for (std::size_t i = 0; i < m.size(); ++i) {
    const double mean = s[i] / seeds, var = (s2[i] - seeds * mean * mean) / (seeds - 1);
    const auto j = Eigen::Index(i);
    INFO("m " << m[i] << ": simulated variance " << var << ", Monte Carlo " << mc(j, j) << ", Gaussian " << gauss(j, j));
    CHECK(mc(j, j) / var > 0.5);
    CHECK(mc(j, j) / var < 2.0);
    if (m[i] == 1) CHECK(var / gauss(j, j) > 3.0);
  }
  CHECK_THROWS_AS(latticeAllanCovariance(L, dt, n, {1, 4000}, 48, 7), sinsim::InputError);
}
