// Unit-bearing values as engineers write them ("45 deg", "0.2 deg/sqrt(h)", "100 ug",
// "0.005 deg/s/sqrt(Hz)", "300 ppm") converted once, at the edge, to SI with a checked dimension.
//
// Base dimensions: length [m], time [s], angle [rad], temperature [K]. Angle is kept as a
// dimension of its own so that "deg/h" can never be mistaken for "m/s". Exponents are stored in
// halves so that sqrt(h) and sqrt(Hz) are exact.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <utility>

namespace sinsim {

class Dimension {
 public:
  constexpr Dimension() = default;
  /// Exponents in halves: Dimension(2, -2, 0, 0) is m/s.
  constexpr Dimension(int length2, int time2, int angle2, int temperature2)
      : e_{length2, time2, angle2, temperature2} {}

  static constexpr Dimension none() { return {}; }
  static constexpr Dimension length() { return {2, 0, 0, 0}; }
  static constexpr Dimension time() { return {0, 2, 0, 0}; }
  static constexpr Dimension angle() { return {0, 0, 2, 0}; }
  static constexpr Dimension temperature() { return {0, 0, 0, 2}; }
  static constexpr Dimension frequency() { return {0, -2, 0, 0}; }
  static constexpr Dimension speed() { return {2, -2, 0, 0}; }
  static constexpr Dimension acceleration() { return {2, -4, 0, 0}; }
  static constexpr Dimension angularRate() { return {0, -2, 2, 0}; }

  constexpr Dimension operator*(Dimension o) const {
    return {e_[0] + o.e_[0], e_[1] + o.e_[1], e_[2] + o.e_[2], e_[3] + o.e_[3]};
  }
  constexpr Dimension operator/(Dimension o) const {
    return {e_[0] - o.e_[0], e_[1] - o.e_[1], e_[2] - o.e_[2], e_[3] - o.e_[3]};
  }
  /// Integer power (p may be negative).
  constexpr Dimension pow(int p) const { return {e_[0] * p, e_[1] * p, e_[2] * p, e_[3] * p}; }
  /// Square root; only valid when every exponent is even in halves (checked by the parser).
  constexpr Dimension sqrt() const { return {e_[0] / 2, e_[1] / 2, e_[2] / 2, e_[3] / 2}; }
  constexpr bool sqrtIsExact() const {
    return e_[0] % 2 == 0 && e_[1] % 2 == 0 && e_[2] % 2 == 0 && e_[3] % 2 == 0;
  }
  constexpr bool operator==(Dimension o) const {
    return e_[0] == o.e_[0] && e_[1] == o.e_[1] && e_[2] == o.e_[2] && e_[3] == o.e_[3];
  }
  constexpr bool operator!=(Dimension o) const { return !(*this == o); }
  /// Largest |exponent| (in halves), for the parser's overflow guard.
  constexpr int maxAbsExponent() const {
    int m = 0;
    for (int e : e_) m = e < 0 ? (-e > m ? -e : m) : (e > m ? e : m);
    return m;
  }

  /// SI spelling, e.g. "m/s^2", "rad/s^(1/2)", "1" for dimensionless.
  std::string siUnit() const;

 private:
  std::array<int, 4> e_{0, 0, 0, 0};
};

/// A parsed value: its SI magnitude and its dimension.
struct Quantity {
  double si = 0.0;
  Dimension dim;
};

/// Parses "<number> <unit expression>". Unit grammar: factors joined by '*', '/' or a space,
/// each factor an atom with an optional power ("s^2", "s^-1", "s2") or "sqrt(<expression>)".
/// A lone absolute temperature ("25 degC") is converted with its offset; inside a compound unit
/// ("deg/s/degC") degC is a temperature difference. Throws InputError with a readable reason.
Quantity parseQuantity(std::string_view text);

/// Parses a unit expression alone ("deg/s", "g") into its SI factor and dimension; the factor of
/// an offset unit (degC) is its scale only. Throws InputError on an unknown unit.
Quantity parseUnit(std::string_view unit);

/// A unit with an optional positive factor in front, as a record states raw counts: "0.05 deg/s"
/// is one count = 0.05 deg/s. Returns the factor (1 without one) and the unit text after it; a
/// text the unit grammar reads whole ("1/s") has no factor. InputError for a factor that is not
/// positive and finite, or one with no unit after it.
std::pair<double, std::string_view> splitUnitFactor(std::string_view text);

/// Parses text and requires the given dimension; the message names the expected dimension and
/// an example unit. A plain number is accepted only for a dimensionless expectation.
double parseQuantityAs(std::string_view text, Dimension expected);

/// A command-line option's quantity (parseQuantityAs; with `plainIsSi` a plain number is taken
/// in SI units: "100" for --rate is 100 Hz). Must be finite; errors are OptionError (exit 2)
/// prefixed with `option`.
double parseOptionQuantity(std::string_view text, Dimension expected, const std::string& option,
                           bool plainIsSi = false);

/// A time option: "90" (seconds), "90 s", "10 min", "2 h"; >= 0. Errors are OptionError
/// prefixed with `option` ("--duration: ...").
double parseDuration(std::string_view text, const std::string& option);

/// A typical unit for messages ("deg/s", "m/s^2", "deg/sqrt(h)"), falling back to the SI form.
std::string exampleUnit(Dimension d);

/// The unit atoms parseQuantity knows, for help texts.
std::string knownUnits();

}  // namespace sinsim
