// The one table of constants (common/constants.hpp) against outside definitions, and the unit
// parser against it: a degree typed in a file and a degree written in code are the same double.
#include <catch2/catch.hpp>

#include <cmath>

#include "common/constants.hpp"
#include "common/units.hpp"

TEST_CASE("constants equal their definitions", "[constants]") {
  // π from the C library (acos(-1) is correctly rounded in glibc): the literal is the same double.
  CHECK(sinsim::kPi == std::acos(-1.0));
  // Published values: 1 rad = 57.295779513082320876... deg (OEIS A072097), 1 deg =
  // 0.017453292519943295769... rad (OEIS A019685). Both are one rounding of the exact value, so
  // they must agree to 1 ulp (2.3e-16 relative).
  CHECK(sinsim::kDegPerRad == Approx(57.295779513082320876).epsilon(2.3e-16));
  CHECK(sinsim::kRadPerDeg == Approx(0.017453292519943295769).epsilon(2.3e-16));
  // The two directions are inverses (the old `kDeg` meant one in one file and the other in
  // another): their product is 1 within the two roundings.
  CHECK(std::fabs(sinsim::kRadPerDeg * sinsim::kDegPerRad - 1.0) <= 2.3e-16);
  CHECK(sinsim::degToRad(180.0) == sinsim::kPi);
  CHECK(sinsim::radToDeg(sinsim::kPi) == Approx(180.0).epsilon(2.3e-16));
  CHECK(sinsim::kStandardGravity == 9.80665);  // 3rd CGPM (1901), exact by definition
  CHECK(sinsim::kSecondsPerHour == 60.0 * 60.0);
  CHECK(sinsim::kZeroCelsius == 273.15);  // ITS-90: 0 degC = 273.15 K exactly
}

TEST_CASE("the unit parser uses the same constants", "[constants]") {
  using sinsim::parseQuantity;
  // Bit-for-bit: a value typed as "1 deg" is the constant code uses, not a neighbouring double.
  CHECK(parseQuantity("1 deg").si == sinsim::kRadPerDeg);
  CHECK(parseQuantity("1 g").si == sinsim::kStandardGravity);
  CHECK(parseQuantity("1 h").si == sinsim::kSecondsPerHour);
  CHECK(parseQuantity("0 degC").si == sinsim::kZeroCelsius);
  CHECK(parseQuantity("1 dph").si == sinsim::kRadPerDeg / sinsim::kSecondsPerHour);
}
