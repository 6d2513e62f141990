// Numbers as engineers read them in terminals and reports (common/number_text.hpp): lengths in
// µm/mm/m/km without exponents ("49.98 km", never "4.998e+04"), durations in s/min/h, p-values.
#include <catch2/catch.hpp>

#include <cmath>

#include "common/json_text.hpp"
#include "common/number_text.hpp"

using sinsim::durationText;
using sinsim::lengthText;
using sinsim::pValueText;

TEST_CASE("lengthText: the unit that reads best, 4 significant digits, no exponent", "[text]") {
  CHECK(lengthText(49980.0) == "49.98 km");   // the "4.998e+04"
  CHECK(lengthText(1000.0) == "1.000 km");    // from 1 km up in km
  CHECK(lengthText(999.4) == "999.4 m");
  CHECK(lengthText(12.34) == "12.34 m");
  CHECK(lengthText(1.0) == "1.000 m");
  CHECK(lengthText(0.0042) == "4.200 mm");
  CHECK(lengthText(0.000188) == "188.0 µm");  // README's 188 µm final error
  CHECK(lengthText(0.0) == "0.000 m");
  CHECK(lengthText(-12.34) == "-12.34 m");
  CHECK(lengthText(123456789.0) == "123457 km");  // beyond 4 digits: integer km, no exponent
  CHECK(lengthText(15.24, 3) == "15.2 m");
  CHECK(lengthText(NAN) == "nan");
}

TEST_CASE("durationText: s, min, h as said", "[text]") {
  CHECK(durationText(45.0) == "45 s");
  CHECK(durationText(600.0) == "10 min");
  CHECK(durationText(90.0) == "1.5 min");
  CHECK(durationText(3600.0) == "1 h");
  CHECK(durationText(5400.0) == "1.5 h");
  CHECK(durationText(61.0) == "61 s");    // not a round number of tenths of a minute
  CHECK(durationText(2078.0) == "2078 s");
  CHECK(durationText(0.5) == "0.5 s");
}

TEST_CASE("pValueText: two digits down to 0.001, then one", "[text]") {
  CHECK(pValueText(0.5) == "0.5");
  CHECK(pValueText(0.034) == "0.034");
  CHECK(pValueText(0.0012) == "0.0012");
  CHECK(pValueText(1.2e-12) == "1e-12");
  CHECK(pValueText(0.0) == "< 1e-300");
  CHECK(pValueText(2.5e-320) == "< 1e-300");  // a denormal
  CHECK(sinsim::pStatement(0.034) == "p = 0.034");
  CHECK(sinsim::pStatement(0.0) == "p < 1e-300");
  CHECK(sinsim::pStatement(NAN) == "p not defined");
}

TEST_CASE("plainSignificant: significant digits, never an exponent") {
  CHECK(sinsim::plainSignificant(2.5e-5) == "0.000025");
  CHECK(sinsim::plainSignificant(2234.0, 2) == "2234");
  CHECK(sinsim::plainSignificant(1.25, 2) == "1.2");
  CHECK(sinsim::plainSignificant(NAN) == "–");
}

TEST_CASE("JSON text: bytes that are not UTF-8 are replaced, not thrown at the end of a run") {
  // A Latin-1 scenario name (caf\xe9) or file name: nlohmann's dump threw type_error 316 and the
  // finished run ended in "internal error".
  const nlohmann::json j{{"name", std::string("caf\xe9")}, {"x", 1}};
  const std::string text = sinsim::jsonText(j, 1);
  CHECK(text.find("caf\xEF\xBF\xBD") != std::string::npos);  // U+FFFD
  CHECK(text.back() == '\n');
  CHECK(nlohmann::json::parse(text)["x"] == 1);
}
