// Order selection and the round trip on the seed paper's AR(5) table: simulate each polynomial at
// 1 kHz for 1 h (3.6e6 samples, seeded), let MDL choose the order, fit by Burg, and check the
// coefficients against the truth with the fit's own asymptotic covariance.
#include <catch2/catch.hpp>

#include <cmath>

#include "common/error.hpp"
#include "errormodels/fit/order_selection.hpp"
#include "fit_test_util.hpp"

using namespace sinsim::errormodels::fit;

TEST_CASE("Order criteria follow their published formulas", "[fit][order]") {
  // E_p path with N = 100: AIC = N ln E + 2p, MDL = N ln E + p ln N, FPE = E (N+p+1)/(N-p-1).
  const std::vector<double> path = {4.0, 2.0, 1.9, 1.89};
  const auto rows = orderCriteria(path, 100, true);
  REQUIRE(rows.size() == 4);
  CHECK(rows[2].aic == Approx(100 * std::log(1.9) + 4).epsilon(1e-15));
  CHECK(rows[2].mdl == Approx(100 * std::log(1.9) + 2 * std::log(100.0)).epsilon(1e-15));
  CHECK(rows[2].fpe == Approx(1.9 * 103.0 / 97.0).epsilon(1e-15));
  // Without mean removal Akaike's FPE is E (N + p)/(N - p).
  CHECK(orderCriteria(path, 100, false)[2].fpe == Approx(1.9 * 102.0 / 98.0).epsilon(1e-15));
  CHECK_THROWS_AS(orderCriteria({1.0, 0.0}, 100), sinsim::InputError);
}

TEST_CASE("The paper's order rule and the correlation time", "[fit][order]") {
  // Smallest p with p * step > T_c: the paper's "20-30 ms correlation, 10-20 ms step -> order 4
  // suffices" is the worst corner (30 ms, 10 ms).
  CHECK(paperRuleOrder(0.030, 0.010) == 4);
  CHECK(paperRuleOrder(0.025, 0.010) == 3);
  CHECK(paperRuleOrder(0.020, 0.020) == 2);
  CHECK(paperRuleOrder(0.030, 0.020) == 2);
  CHECK_THROWS_AS(paperRuleOrder(0.0, 0.01), sinsim::InputError);
  CHECK_THROWS_AS(paperRuleOrder(0.03, std::nan("")), sinsim::InputError);

  // Exact exponential sampled at tau/50: the 1/e crossing by linear interpolation is off by at
  // most (dt/tau)/8 relative (convexity of exp between two lags) = 0.25 %.
  const double tau = 0.025, dt = tau / 50;
  std::vector<double> acf(200);
  for (std::size_t k = 0; k < acf.size(); ++k) acf[k] = 3.0 * std::exp(-double(k) * dt / tau);
  CHECK(correlationTime(acf, dt) == Approx(tau).epsilon(0.0025));
  // AR(1) with phi = exp(-dt/tau) is the sampled GM: the same T_c from its model ACF.
  CHECK(arCorrelationTime({1.0, -std::exp(-dt / tau)}, dt) == Approx(tau).epsilon(0.0025));
  CHECK_THROWS_AS(correlationTime({1.0, 0.9, 0.8}, dt), sinsim::InputError);  // never reaches 1/e

  // The paper's gyro polynomials at dt = 1 ms have T_c in its stated 20-30 ms range (28.6,
  // 30.1, 28.6 ms computed from the model ACF); 5 % margin for the 20/30 ms round numbers.
  for (std::size_t i = 0; i < 3; ++i) {
    const double tc = arCorrelationTime(fit_test::paperTable()[i].a, 1e-3);
    CHECK(tc >= 0.020);
    CHECK(tc <= 0.030 * 1.05);
  }
}

TEST_CASE("Round trip of the paper's AR(5) table: MDL picks 5, Burg recovers the coefficients",
          "[fit][order][roundtrip]") {
  // 1 h at 1 kHz per axis. Per coefficient |a_hat - a| <= 3 sigma_hat (two-sided 0.27 % per
  // coefficient, fixed seeds), and jointly d' C^-1 d <= 20.52, the 0.999 quantile of chi^2 with
  // 5 degrees of freedom, with C the fit's asymptotic covariance sigma^2 Gamma^-1 / N.
  const std::size_t n = 3600000;
  std::uint64_t seed = 1000;
  for (const auto& axis : fit_test::paperTable()) {
    INFO("axis " << axis.name);
    const auto x = fit_test::simulateAr(axis.a, 1.0, n, ++seed);
    OrderSelectionOptions opt;
    opt.maxOrder = 12;
    opt.sampleInterval = 1e-3;
    opt.navigationStep = 0.010;
    const OrderSelection sel = selectArOrder(x, opt);
    CHECK(sel.mdlOrder == 5);
    CHECK(sel.selectedOrder == 5);
    CHECK(sel.selectedBy == OrderCriterion::MDL);
    // AIC's penalty (2 per parameter) is lighter: it may overfit, never underfit here.
    CHECK(sel.aicOrder >= 5);
    REQUIRE(sel.fit.order == 5);
    Eigen::VectorXd d(5);
    for (std::size_t i = 1; i <= 5; ++i) {
      d(static_cast<Eigen::Index>(i - 1)) = sel.fit.a[i] - axis.a[i];
      CHECK(std::abs(sel.fit.a[i] - axis.a[i]) <= 3.0 * sel.fit.stdError[i - 1]);
    }
    const double chi2 = d.dot(sel.fit.covariance.ldlt().solve(d));
    CHECK(chi2 <= 20.52);
    // E of unit driving noise: within 3 sqrt(2/N) relative.
    CHECK(std::abs(sel.fit.drivingVariance - 1.0) <= 3.0 * sel.fit.drivingVarianceStdError);
    REQUIRE(sel.paperOrder.has_value());
    CHECK(*sel.paperOrder == paperRuleOrder(*sel.correlationTime, 0.010));
  }
}

TEST_CASE("Order selection can be forced and refuses impossible requests", "[fit][order]") {
  const auto x = fit_test::simulateAr(fit_test::paperTable()[3].a, 1.0, 20000, 7);
  OrderSelectionOptions opt;
  opt.maxOrder = 8;
  opt.forcedOrder = 3;
  const auto sel = selectArOrder(x, opt);
  CHECK(sel.selectedOrder == 3);
  CHECK(sel.selectedBy == OrderCriterion::Forced);
  CHECK(sel.fit.order == 3);
  CHECK(sel.table.size() == 9);
  OrderSelectionOptions rule;
  rule.criterion = OrderCriterion::PaperRule;  // without a navigation step
  CHECK_THROWS_AS(selectArOrder(x, rule), sinsim::InputError);
  rule.navigationStep = 0.01;  // ... and without a sample interval to get T_c from the model
  CHECK_THROWS_AS(selectArOrder(x, rule), sinsim::InputError);
  rule.correlationTime = 0.030;
  CHECK(selectArOrder(x, rule).selectedOrder == 4);
  CHECK_FALSE(selectArOrder(x, rule).paperCapped);
  // A T_c of 100 s (a denoised record's slow wander) asks for order 10001: capped at maxOrder,
  // said so (Burg at 90466 on 2e5 samples ran for 10+ minutes, deaf to Ctrl-C).
  rule.correlationTime = 100.0;
  rule.maxOrder = 8;
  const auto capped = selectArOrder(x, rule);
  CHECK(*capped.paperOrder == 10001);
  CHECK(capped.paperCapped);
  CHECK(capped.selectedOrder == 8);
  CHECK(capped.fit.order == 8);
}
