// Unit conversion against the definitions (CGPM standard gravity, degree = π/180, hour = 3600 s).
// Conversions are a few floating-point operations, so relative 1e-14 is ~50 ulp: tight enough to
// catch any wrong factor, loose enough for rounding.
#include <catch2/catch.hpp>

#include <cmath>

#include "common/constants.hpp"
#include "common/error.hpp"
#include "common/units.hpp"

using sinsim::Dimension;
using sinsim::parseQuantity;
using sinsim::parseQuantityAs;
using Catch::Matchers::Contains;

namespace {
using sinsim::kPi;
constexpr double kRel = 1e-14;
}

TEST_CASE("plain units convert to SI") {
  CHECK(parseQuantityAs("45 deg", Dimension::angle()) == Approx(kPi / 4).epsilon(kRel));
  CHECK(parseQuantityAs("100 m", Dimension::length()) == 100.0);
  CHECK(parseQuantityAs("20 m/s", Dimension::speed()) == 20.0);
  CHECK(parseQuantityAs("2 ms", Dimension::time()) == Approx(0.002).epsilon(kRel));
  CHECK(parseQuantityAs("1.5 h", Dimension::time()) == 5400.0);
  CHECK(parseQuantityAs("100 Hz", Dimension::frequency()) == 100.0);
  CHECK(parseQuantityAs("300 ppm", Dimension::none()) == Approx(3e-4).epsilon(kRel));
  CHECK(parseQuantityAs("0.5", Dimension::none()) == 0.5);
  CHECK(parseQuantityAs("-3e2 km", Dimension::length()) == -3e5);
  // The micro sign as loggers write it, beside the ASCII u (a t[\xC2\xB5s] column was refused).
  CHECK(parseQuantityAs("250 \xC2\xB5s", Dimension::time()) == Approx(2.5e-4).epsilon(kRel));
  CHECK(parseQuantityAs("3 \xC2\xB5rad", Dimension::angle()) == Approx(3e-6).epsilon(kRel));
  CHECK(parseQuantityAs("7 \xC2\xB5m", Dimension::length()) == Approx(7e-6).epsilon(kRel));
}

TEST_CASE("inertial-sensor units as datasheets write them") {
  const double deg = kPi / 180.0;
  CHECK(parseQuantityAs("10 deg/h", Dimension::angularRate()) ==
        Approx(10 * deg / 3600).epsilon(kRel));
  CHECK(parseQuantityAs("10 dph", Dimension::angularRate()) ==
        Approx(10 * deg / 3600).epsilon(kRel));
  // A MEMS log's header forms (the record reader refused "gx [dps]" and "gx [deg/sec]").
  CHECK(parseQuantityAs("10 dps", Dimension::angularRate()) == Approx(10 * deg).epsilon(kRel));
  CHECK(parseQuantityAs("10 deg/sec", Dimension::angularRate()) == Approx(10 * deg).epsilon(kRel));
  // ARW: 0.2 deg/sqrt(h) = 0.2 deg / 60 sqrt(s) [rad/sqrt(s)]
  const Dimension arw = Dimension::angularRate() * Dimension::time().sqrt();
  CHECK(parseQuantityAs("0.2 deg/sqrt(h)", arw) == Approx(0.2 * deg / 60).epsilon(kRel));
  // the same dimension written as a density
  CHECK(parseQuantityAs("0.005 deg/s/sqrt(Hz)", arw) == Approx(0.005 * deg).epsilon(kRel));
  CHECK(parseQuantityAs("100 ug", Dimension::acceleration()) ==
        Approx(100e-6 * 9.80665).epsilon(kRel));
  const Dimension vrw = Dimension::acceleration() * Dimension::time().sqrt();
  CHECK(parseQuantityAs("0.05 m/s/sqrt(h)", vrw) == Approx(0.05 / 60).epsilon(kRel));
  CHECK(parseQuantityAs("9.81 m/s^2", Dimension::acceleration()) == 9.81);
  CHECK(parseQuantityAs("9.81 m/s2", Dimension::acceleration()) == 9.81);
  CHECK(parseQuantityAs("1 deg/h/sqrt(h)", Dimension::angularRate() / Dimension::time().sqrt()) ==
        Approx(deg / 3600 / 60).epsilon(kRel));
}

TEST_CASE("temperatures: offset for an absolute value, none inside a compound unit") {
  CHECK(parseQuantityAs("25 degC", Dimension::temperature()) == Approx(298.15).epsilon(kRel));
  CHECK(parseQuantityAs("300 K", Dimension::temperature()) == 300.0);
  CHECK(parseQuantityAs("0.01 deg/s/degC", Dimension::angularRate() / Dimension::temperature()) ==
        Approx(0.01 * kPi / 180).epsilon(kRel));
}

TEST_CASE("a unit of the wrong dimension is refused with the expected unit named") {
  REQUIRE_THROWS_AS(parseQuantityAs("5 m", Dimension::time()), sinsim::InputError);
  REQUIRE_THROWS_WITH(parseQuantityAs("5 m", Dimension::time()), Contains("expected a value in s"));
  // the classic confusion: a velocity random walk where a rate random walk belongs
  REQUIRE_THROWS_WITH(parseQuantityAs("0.05 m/s/sqrt(h)", Dimension::acceleration()),
                      Contains("m/s^2"));
  REQUIRE_THROWS_WITH(parseQuantityAs("30", Dimension::time()), Contains("no unit"));
}

TEST_CASE("malformed values are refused") {
  REQUIRE_THROWS_WITH(parseQuantity("fast"), Contains("expected a number"));
  REQUIRE_THROWS_WITH(parseQuantity("3 parsecs"), Contains("unknown unit \"parsecs\""));
  REQUIRE_THROWS_WITH(parseQuantity("3 sqrt(m"), Contains("missing ')'"));
  REQUIRE_THROWS_WITH(parseQuantity("3 sqrt(sqrt(m))"), Contains("odd power"));
  REQUIRE_THROWS_AS(parseQuantity(""), sinsim::InputError);
  REQUIRE_THROWS_AS(parseQuantity("nan m"), sinsim::InputError);
  REQUIRE_THROWS_AS(parseQuantity("inf s"), sinsim::InputError);
}

TEST_CASE("dimensions print in SI") {
  CHECK(Dimension::acceleration().siUnit() == "m/s^2");
  CHECK((Dimension::angularRate() * Dimension::time().sqrt()).siUnit() == "rad/s^(1/2)");
  CHECK(Dimension::none().siUnit() == "1");
  // A compound denominator in parentheses: rad/s*K read as rad*K/s (helper-19).
  CHECK((Dimension::angularRate() / Dimension::temperature()).siUnit() == "rad/(s*K)");
}

TEST_CASE("a count size in front of a unit is split off, and a unit read whole keeps factor 1") {
  const auto [f, u] = sinsim::splitUnitFactor(" 0.05 deg/s ");
  CHECK(f == 0.05);
  CHECK(u == "deg/s");
  CHECK(sinsim::splitUnitFactor("2.5e-4g").first == 2.5e-4);
  CHECK(sinsim::splitUnitFactor("2.5e-4g").second == "g");
  CHECK(sinsim::splitUnitFactor("1/s").first == 1.0);  // the grammar's own "1/s"
  CHECK(sinsim::splitUnitFactor("1/s").second == "1/s");
  CHECK(sinsim::splitUnitFactor("deg/s").first == 1.0);
  CHECK_THROWS_WITH(sinsim::splitUnitFactor("0 mg"), Catch::Contains("positive and finite"));
  CHECK_THROWS_WITH(sinsim::splitUnitFactor("-1 mg"), Catch::Contains("positive and finite"));
  CHECK_THROWS_WITH(sinsim::splitUnitFactor("3"), Catch::Contains("a factor needs a unit"));
}
