// The standard normal quantile (the one home: errormodels/stats/special.hpp) against values from
// an independent tool: mpmath at 40 digits for the exact double each test passes
// (fixtures/normal_reference.py; to 7 digits they are the textbook 1.959964, 2.575829, 3.090232).
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <utility>

#include "common/error.hpp"
#include "errormodels/stats/special.hpp"

using namespace sinsim::errormodels;

namespace {

// Tolerance: erfc is accurate to a few ulp, so z has relative error ~1e-16 times the condition
// p phi(z)^-1 / |z| <= ~1 (Mills ratio) in the tails; near z = 0 the error is absolute,
// ~1e-16 / phi(0). 1e-14 relative with a 1e-15 absolute margin leaves a factor >10 over both.
Approx ref(double z) { return Approx(z).epsilon(1e-14).margin(1e-15); }

}  // namespace

TEST_CASE("normal quantile equals mpmath from 1e-300 to 0.999", "[special][normal]") {
  const std::pair<double, double> table[] = {
      {1e-300, -37.047096299361199237}, {1e-100, -21.273453560965324294},
      {1e-20, -9.2623400897984075796},  {1e-10, -6.3613409024040561991},
      {1e-6, -4.7534243088228989573},   {0.001, -3.0902323061678135354},
      {0.025, -1.9599639845400542118},  {0.1585, -1.0006418287624493465},
      {0.3, -0.52440051270804081597},   {0.5, 0.0},
      {0.7, 0.52440051270804065631},    {0.8415, 1.0006418287624494613},
      {0.975, 1.9599639845400538556},   {0.999, 3.0902323061678132778}};
  for (const auto& [p, z] : table) {
    INFO("p = " << p);
    CHECK(normalQuantile(p) == ref(z));
    // The far tail through the two-sided form: P(|Z| > z) = 2 p.
    if (p < 0.5) CHECK(normalTwoSidedCritical(2 * p) == ref(-z));
  }
  CHECK(normalQuantile(0.0) == -std::numeric_limits<double>::infinity());
  CHECK(normalQuantile(1.0) == std::numeric_limits<double>::infinity());
  CHECK(normalTwoSidedCritical(0.0) == std::numeric_limits<double>::infinity());
  CHECK(normalTwoSidedCritical(1.0) == 0.0);
  CHECK_THROWS_AS(normalQuantile(-0.1), sinsim::InputError);
  CHECK_THROWS_AS(normalQuantile(std::nan("")), sinsim::InputError);
  CHECK_THROWS_AS(normalTwoSidedCritical(1.5), sinsim::InputError);
}

TEST_CASE("two-sided normal quantile equals mpmath, cdf inverts it", "[special][normal]") {
  const std::pair<double, double> table[] = {
      {0.5, 0.6744897501960817432},  {0.682689492137085897, 0.99999999999999990574},
      {0.683, 1.0006418287624494613}, {0.9, 1.6448536269514728225},
      {0.95, 1.9599639845400538556},  {0.99, 2.5758293035489004539},
      {0.999999, 4.8916384756929317718}};
  for (const auto& [c, z] : table) {
    INFO("confidence = " << c);
    CHECK(normalQuantileTwoSided(c) == ref(z));
    // Round trip through the distribution function: P(|Z| <= z) = 1 - 2 Phi(-z) = c.
    CHECK(1 - 2 * normalCdf(-normalQuantileTwoSided(c)) == Approx(c).epsilon(1e-14));
  }
  CHECK_THROWS_AS(normalQuantileTwoSided(1.0), sinsim::InputError);
  CHECK_THROWS_AS(normalQuantileTwoSided(0.0), sinsim::InputError);
}
