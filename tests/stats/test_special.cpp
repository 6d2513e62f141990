// Incomplete gamma and chi-square quantiles against closed forms and published table values.
#include <catch2/catch.hpp>

#include <cmath>

#include "common/error.hpp"
#include "errormodels/stats/special.hpp"

using namespace sinsim::errormodels;

TEST_CASE("chi-square quantiles: closed forms for 1, 2 and 4 degrees of freedom", "[special]") {
  // nu = 2: F(x) = 1 - exp(-x/2)  =>  x_p = -2 ln(1 - p). Exact, so 1e-12 relative is only
  // rounding of a few elementary operations and the Halley stopping rule (1e-15).
  for (double p : {1e-10, 1e-4, 0.01, 0.1585, 0.5, 0.8415, 0.99, 0.999999}) {
    CHECK(chiSquareQuantile(p, 2.0) == Approx(-2.0 * std::log1p(-p)).epsilon(1e-12));
  }
  // nu = 1: F(x) = erf(sqrt(x/2)); nu = 4: F(x) = 1 - exp(-x/2) (1 + x/2).
  for (double x : {1e-6, 0.01, 0.5, 1.0, 3.0, 10.0, 40.0}) {
    CHECK(chiSquareCdf(x, 1.0) == Approx(std::erf(std::sqrt(x / 2))).epsilon(1e-13));
    // 1 - e^-h (1 + h) cancels for small h = x/2: use its series sum_{k>=2} (-1)^k (k-1) h^k / k!.
    const double h = x / 2;
    double f4 = 0;
    if (h < 0.1) {
      double term = h;  // h^k / k!
      for (int k = 2; k < 30; ++k) {
        term *= h / k;
        f4 += (k % 2 ? -1 : 1) * (k - 1) * term;
      }
    } else {
      f4 = 1 - std::exp(-h) * (1 + h);
    }
    CHECK(chiSquareCdf(x, 4.0) == Approx(f4).epsilon(1e-13));
    // Inversion where it is well conditioned (1 - p not rounded away: x <= 10).
    if (x <= 10) CHECK(chiSquareQuantile(chiSquareCdf(x, 1.0), 1.0) == Approx(x).epsilon(1e-10));
  }
}

TEST_CASE("chi-square quantiles: table values", "[special]") {
  // Reference values from mpmath 1.2.1 at 40 digits (fixtures/chi2_reference.py): the textbook
  // table entries (3.841, 20.483, 135.807, ...) to 16 digits. 1e-13 relative is the accuracy
  // the inverse promises (P ~1e-14, Halley stops at 1e-15).
  CHECK(chiSquareQuantile(0.95, 1) == Approx(3.841458820694124).epsilon(1e-13));
  CHECK(chiSquareQuantile(0.05, 1) == Approx(0.003932140000019522).epsilon(1e-11));
  CHECK(chiSquareQuantile(0.975, 10) == Approx(20.48317735080739).epsilon(1e-13));
  CHECK(chiSquareQuantile(0.025, 10) == Approx(3.246972780236841).epsilon(1e-13));
  CHECK(chiSquareQuantile(0.99, 100) == Approx(135.80672317102677).epsilon(1e-13));
  CHECK(chiSquareQuantile(0.01, 100) == Approx(70.064894925399799).epsilon(1e-13));
  CHECK(chiSquareQuantile(0.5, 1) == Approx(0.45493642311957275).epsilon(1e-13));
  // Stable32's 0.683 two-sided interval at a non-integer EDF.
  CHECK(chiSquareQuantile(0.8415, 3.5) == Approx(5.9035995830285427).epsilon(1e-13));
  CHECK(chiSquareQuantile(0.1585, 3.5) == Approx(1.1155656775037786).epsilon(1e-13));
}

TEST_CASE("incomplete gamma round trip over a wide range of shapes", "[special]") {
  // P(a, P^-1(a, p)) = p; the large shapes are the EDFs of long records (1e6 samples).
  for (double a : {0.05, 0.5, 1.0, 2.5, 10.0, 123.4, 5e3, 5e5, 3e6}) {
    for (double p : {1e-8, 0.001, 0.1585, 0.5, 0.8415, 0.999}) {
      const double x = inverseRegularizedGammaP(a, p);
      INFO("a = " << a << ", p = " << p << ", x = " << x);
      // 1e-11 relative: P's own accuracy (~1e-14 times the condition a/x dP/dx ~ sqrt(a)).
      if (p > 0.5) CHECK(regularizedGammaQ(a, x) == Approx(1 - p).epsilon(1e-10));
      else CHECK(regularizedGammaP(a, x) == Approx(p).epsilon(1e-10));
    }
  }
  // Wilson-Hilferty is accurate to ~1e-6 at nu = 1e6: an independent check of the large-a path.
  const double nu = 1e6, z = 1.0;  // p = Phi(1)
  const double wh = nu * std::pow(1 - 2 / (9 * nu) + z * std::sqrt(2 / (9 * nu)), 3);
  CHECK(chiSquareQuantile(0.8413447460685429, nu) == Approx(wh).epsilon(1e-7));
  CHECK_THROWS_AS(chiSquareQuantile(1.5, 3.0), sinsim::NumericalError);
  CHECK_THROWS_AS(regularizedGammaP(-1.0, 1.0), sinsim::NumericalError);
}
