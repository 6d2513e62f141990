// AR(5) + random walk: the composite fit recovers the AR coefficients and K within their stated
// uncertainty, where a plain Burg fit of the same record does not.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "common/error.hpp"
#include "errormodels/fit/composite_fit.hpp"
#include "fit_test_util.hpp"

using namespace sinsim::errormodels::fit;
using fit_test::overlappingAvar;

TEST_CASE("AR(5) + random walk: composite fit recovers both parts", "[fit][composite]") {
  // The paper's Gx AR(5) at 1 kHz, unit driving noise: at long tau it is white with density
  // N_eff = sqrt(E dt) / |A(1)| = 5.33 U sqrt(s). Random walk K = 0.9 U/sqrt(s) puts the ADEV
  // minimum at sqrt(3) N_eff / K ~ 10 s. 20 min record (1.2e6 samples).
  const auto& a = fit_test::paperTable()[0].a;
  const double dt = 1e-3, K = 0.9;
  const std::size_t M = 1200000;
  auto x = fit_test::simulateAr(a, 1.0, M, 31337);
  std::mt19937_64 rng(4242);
  std::normal_distribution<double> w;
  double rw = 0.0;
  for (auto& v : x) {
    rw += K * std::sqrt(dt) * w(rng);
    v += rw;
  }
  double A1 = 0;
  for (double c : a) A1 += c;
  const double Neff = std::sqrt(dt) / std::abs(A1);
  std::vector<double> tau, adev, edf;
  for (std::size_t m = 1; m <= M / 10; m *= 2) {
    const double t = double(m) * dt;
    tau.push_back(t);
    adev.push_back(std::sqrt(overlappingAvar(x, dt, m)));
    edf.push_back(Neff * Neff / t > K * K * t / 3 ? edfOverlappingWhite(M, m)
                                                  : edfOverlappingRandomWalk(M, m));
  }
  ArRandomWalkFitOptions opt;
  opt.sampleInterval = dt;
  opt.order.maxOrder = 10;
  const auto fit = fitArPlusRandomWalk(x, tau, adev, edf, opt);
  INFO("K " << fit.randomWalk.value << " +- " << fit.randomWalk.stdError << "; N "
            << fit.whiteEquivalent.value << " (N_eff " << Neff << "); T_s "
            << fit.smootherTimeConstant << " s, T_c " << fit.arCorrelationTime << " s; order "
            << fit.ar.selectedOrder);
  REQUIRE(fit.randomWalkDetected);
  CHECK(fit.separated);
  // K within 3 stated sigma; the white level within 3 sigma of the AR's analytic N_eff.
  CHECK(std::abs(fit.randomWalk.value - K) <= 3 * fit.randomWalk.stdError);
  CHECK(std::abs(fit.whiteEquivalent.value - Neff) <= 3 * fit.whiteEquivalent.stdError);
  // MDL still picks 5 and the coefficients are within 3 sigma each, chi^2_5 <= 20.52 (0.999).
  CHECK(fit.ar.selectedOrder == 5);
  REQUIRE(fit.ar.fit.order == 5);
  Eigen::VectorXd d(5);
  for (int i = 0; i < 5; ++i) {
    d(i) = fit.ar.fit.a[i + 1] - a[i + 1];
    CHECK(std::abs(d(i)) <= 3 * fit.ar.fit.stdError[i]);
  }
  CHECK(d.dot(fit.ar.fit.covariance.ldlt().solve(d)) <= 20.52);

  // The plain Burg fit of the same record is pulled away by the random walk (fails the same
  // joint test by a wide margin): the reason the composite exists.
  const ArFit plain = burg(x, 5);
  Eigen::VectorXd dp(5);
  for (int i = 0; i < 5; ++i) dp(i) = plain.a[i + 1] - a[i + 1];
  CHECK(dp.dot(plain.covariance.ldlt().solve(dp)) > 100.0);
}

TEST_CASE("Local-level smoother follows a pure random walk and rejects white noise",
          "[fit][composite]") {
  // The steady-state gain for q = r is g = 0.618 (golden-ratio closed form, P = r (1 + sqrt 5)/2);
  // a constant series comes back unchanged (to rounding).
  double g = 0;
  const std::vector<double> c(100, 2.5);
  const auto l = localLevelSmoother(c, 1.0, 1.0, &g);
  CHECK(g == Approx((1 + std::sqrt(5.0)) / 2 / ((1 + std::sqrt(5.0)) / 2 + 1)).epsilon(1e-14));
  for (double v : l) CHECK(v == Approx(2.5).epsilon(1e-14));
  CHECK_THROWS_AS(localLevelSmoother(c, 0.0, 1.0), sinsim::InputError);
}
