#include "common/units.hpp"
#include "common/text.hpp"

#include "common/limits.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <utility>

#include "common/constants.hpp"
#include "common/error.hpp"

namespace sinsim {
namespace {

struct Atom {
  double factor;
  Dimension dim;
  double offset = 0.0;  // only for absolute temperatures
};

const std::map<std::string, Atom, std::less<>>& atoms() {
  using D = Dimension;
  static const std::map<std::string, Atom, std::less<>> table = {
      // length
      {"m", {1.0, D::length()}},
      {"km", {1e3, D::length()}},
      {"cm", {1e-2, D::length()}},
      {"mm", {1e-3, D::length()}},
      {"um", {1e-6, D::length()}},
      {"\xC2\xB5m", {1e-6, D::length()}},  // µm
      {"ft", {0.3048, D::length()}},
      {"nmi", {1852.0, D::length()}},
      // time
      {"s", {1.0, D::time()}},
      {"sec", {1.0, D::time()}},  // "deg/sec" in vendors' headers
      {"ms", {1e-3, D::time()}},
      {"us", {1e-6, D::time()}},
      {"\xC2\xB5s", {1e-6, D::time()}},  // µs
      {"ns", {1e-9, D::time()}},
      {"min", {60.0, D::time()}},
      {"h", {kSecondsPerHour, D::time()}},
      {"hr", {kSecondsPerHour, D::time()}},
      {"day", {86400.0, D::time()}},
      // frequency
      {"Hz", {1.0, D::frequency()}},
      {"kHz", {1e3, D::frequency()}},
      // angle
      {"rad", {1.0, D::angle()}},
      {"mrad", {1e-3, D::angle()}},
      {"urad", {1e-6, D::angle()}},
      {"\xC2\xB5rad", {1e-6, D::angle()}},  // µrad
      {"deg", {kRadPerDeg, D::angle()}},
      {"\xC2\xB0", {kRadPerDeg, D::angle()}},  // °
      {"arcmin", {kRadPerDeg / 60.0, D::angle()}},
      {"arcsec", {kRadPerDeg / kSecondsPerHour, D::angle()}},
      {"rev", {2.0 * kPi, D::angle()}},
      {"dph", {kRadPerDeg / kSecondsPerHour, D::angularRate()}},  // deg/h, common in INS specs
      {"dps", {kRadPerDeg, D::angularRate()}},                    // deg/s, common in MEMS logs
      // acceleration in units of standard gravity
      {"g", {kStandardGravity, D::acceleration()}},
      {"mg", {1e-3 * kStandardGravity, D::acceleration()}},
      {"ug", {1e-6 * kStandardGravity, D::acceleration()}},
      {"\xC2\xB5g", {1e-6 * kStandardGravity, D::acceleration()}},  // µg
      {"Gal", {1e-2, D::acceleration()}},
      // speed
      {"kn", {1852.0 / kSecondsPerHour, D::speed()}},
      {"kph", {1000.0 / kSecondsPerHour, D::speed()}},
      // dimensionless
      {"ppm", {1e-6, D::none()}},
      {"ppb", {1e-9, D::none()}},
      {"%", {1e-2, D::none()}},
      // temperature (offset applies to a lone absolute value only)
      {"K", {1.0, D::temperature()}},
      {"degC", {1.0, D::temperature(), kZeroCelsius}},
      {"\xC2\xB0" "C", {1.0, D::temperature(), kZeroCelsius}},  // °C
  };
  return table;
}

class UnitParser {
 public:
  explicit UnitParser(std::string_view s) : s_(s) {}

  // expression := factor (('*' | '/' | ' ') factor)*
  Quantity expression() {
    Quantity q = factor();
    for (;;) {
      skipSpaces();
      if (pos_ >= s_.size() || s_[pos_] == ')') return q;
      bool divide = false;
      if (s_[pos_] == '/') {
        divide = true;
        ++pos_;
      } else if (s_[pos_] == '*') {
        ++pos_;
      }
      Quantity f = factor();
      if (divide) {
        q.si /= f.si;
        q.dim = q.dim / f.dim;
      } else {
        q.si *= f.si;
        q.dim = q.dim * f.dim;
      }
      checkExponents(q.dim);
      atomCount_ += 1;
    }
  }

  bool done() {
    skipSpaces();
    return pos_ >= s_.size();
  }
  std::size_t atomCount() const { return atomCount_; }
  double loneOffset() const { return loneOffset_; }

 private:
  // Bounds the recursion of nested parentheses and the integer exponents of a dimension, so
  // that no unit text overflows the stack or an int ("((((s^9)^9)^9)^9)").
  static constexpr int kMaxNesting = 16;
  static constexpr int kMaxExponent = 1000;
  void checkExponents(Dimension d) const {
    if (d.maxAbsExponent() > kMaxExponent) fail("powers too large");
  }

  Quantity nested() {
    if (++depth_ > kMaxNesting) fail("parentheses nested too deep");
    Quantity inner = expression();
    --depth_;
    return inner;
  }

  Quantity factor() {
    skipSpaces();
    if (s_.substr(pos_, 5) == "sqrt(") {
      pos_ += 5;
      Quantity inner = nested();
      if (pos_ >= s_.size() || s_[pos_] != ')') fail("missing ')' after sqrt(");
      ++pos_;
      if (!inner.dim.sqrtIsExact()) fail("sqrt of a unit with an odd power");
      atomCount_ += 1;
      return power({std::sqrt(inner.si), inner.dim.sqrt()});
    }
    if (pos_ < s_.size() && s_[pos_] == '(') {
      ++pos_;
      Quantity inner = nested();
      if (pos_ >= s_.size() || s_[pos_] != ')') fail("missing ')'");
      ++pos_;
      atomCount_ += 1;
      return power(inner);
    }
    if (pos_ < s_.size() && s_[pos_] == '1') {  // "1/s"
      ++pos_;
      return {1.0, Dimension::none()};
    }
    std::size_t start = pos_;
    while (pos_ < s_.size()) {
      unsigned char c = static_cast<unsigned char>(s_[pos_]);
      if (std::isalpha(c) || c >= 0x80 || c == '%') {
        ++pos_;
      } else {
        break;
      }
    }
    if (start == pos_) fail("expected a unit");
    std::string_view name = s_.substr(start, pos_ - start);
    const auto& table = atoms();
    auto it = table.find(name);
    if (it == table.end()) {
      throw InputError("unknown unit \"" + limits::echo(name) + "\" (known: " + knownUnits() + ")");
    }
    loneOffset_ = it->second.offset;
    return power({it->second.factor, it->second.dim});
  }

  // optional power: "^2", "^-1", "^(1/2)" is not supported, use sqrt(); "s2" means s^2.
  Quantity power(Quantity q) {
    int p = 1;
    if (pos_ < s_.size() && s_[pos_] == '^') {
      ++pos_;
      p = integer();
    } else if (pos_ < s_.size() && (std::isdigit(static_cast<unsigned char>(s_[pos_])) ||
                                    s_[pos_] == '-')) {
      p = integer();
    }
    if (p != 1) atomCount_ += 1;  // a powered offset unit is not a lone absolute temperature
    const Quantity out{std::pow(q.si, p), q.dim.pow(p)};
    checkExponents(out.dim);
    return out;
  }

  int integer() {
    std::size_t start = pos_;
    if (pos_ < s_.size() && (s_[pos_] == '-' || s_[pos_] == '+')) ++pos_;
    while (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) ++pos_;
    if (pos_ == start || (pos_ == start + 1 && !std::isdigit(static_cast<unsigned char>(s_[start]))))
      fail("expected an integer power");
    if (pos_ - start > std::size_t{2} + (s_[start] == '-' || s_[start] == '+'))
      fail("a power beyond ±99");  // also keeps atoi inside int
    return std::atoi(std::string(s_.substr(start, pos_ - start)).c_str());
  }

  void skipSpaces() {
    while (pos_ < s_.size() && s_[pos_] == ' ') ++pos_;
  }
  [[noreturn]] void fail(const std::string& why) const {
    throw InputError("cannot read unit \"" + limits::echo(s_) + "\": " + why);
  }

  std::string_view s_;
  std::size_t pos_ = 0;
  std::size_t atomCount_ = 0;
  int depth_ = 0;
  double loneOffset_ = 0.0;
};


}  // namespace

std::string Dimension::siUnit() const {
  static const char* names[4] = {"m", "s", "rad", "K"};
  std::string num, den;
  for (int i = 0; i < 4; ++i) {
    int e = e_[i];
    if (e == 0) continue;
    std::string& part = e > 0 ? num : den;
    int a = std::abs(e);
    std::string term = names[i];
    if (a % 2 == 1) {
      term += a == 1 ? "^(1/2)" : "^(" + std::to_string(a) + "/2)";
    } else if (a != 2) {
      term += "^" + std::to_string(a / 2);
    }
    part += part.empty() ? term : "*" + term;
  }
  if (num.empty()) num = "1";
  // "rad/(s*K)": "rad/s*K" read as rad*K/s.
  if (den.find('*') != std::string::npos) den = "(" + den + ")";
  return den.empty() ? num : num + "/" + den;
}

std::string exampleUnit(Dimension d) {
  using D = Dimension;
  static const std::pair<Dimension, const char*> examples[] = {
      {D::none(), "a plain number, ppm or %"},
      {D::length(), "m"},
      {D::time(), "s"},
      {D::angle(), "deg"},
      {D::temperature(), "degC"},
      {D::frequency(), "Hz"},
      {D::speed(), "m/s"},
      {D::acceleration(), "m/s^2 or mg"},
      {D::angularRate(), "deg/s or deg/h"},
      {D::angularRate() * D::time().sqrt(), "deg/sqrt(h) or deg/s/sqrt(Hz)"},
      {D::acceleration() * D::time().sqrt(), "m/s/sqrt(h) or ug/sqrt(Hz)"},
      {D::angularRate() / D::time().sqrt(), "deg/h/sqrt(h)"},
      {D::acceleration() / D::time().sqrt(), "m/s^2/sqrt(h) or ug/sqrt(s)"},
      {D::angularRate() / D::time(), "deg/s/h"},
      {D::acceleration() / D::time(), "m/s^2/h"},
      {D::angularRate() / D::acceleration(), "deg/s/g"},
      {D::angularRate() / D::temperature(), "deg/s/degC"},
      {D::acceleration() / D::temperature(), "mg/degC"},
  };
  for (const auto& [dim, unit] : examples)
    if (dim == d) return unit;
  return d.siUnit();
}

std::string knownUnits() {
  std::string s;
  for (const auto& [name, atom] : atoms()) {
    if (!s.empty()) s += ", ";
    s += name;
  }
  return s + ", sqrt(...), ^n";
}

Quantity parseUnit(std::string_view unit) {
  UnitParser p(trimmed(unit));
  Quantity q = p.expression();
  if (!p.done()) throw InputError("cannot read unit \"" + limits::echo(unit) + "\"");
  return q;
}

std::pair<double, std::string_view> splitUnitFactor(std::string_view text) {
  const std::string_view t = trimmed(text);
  const auto numeric = [](char c) { return std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+'; };
  if (t.empty() || !numeric(t.front())) return {1.0, t};
  try {
    parseUnit(t);
    return {1.0, t};
  } catch (const InputError&) {
  }
  const std::string buf(t);
  char* end = nullptr;
  const double factor = std::strtod(buf.c_str(), &end);
  const std::string_view rest = trimmed(t.substr(std::size_t(end - buf.c_str())));
  if (end == buf.c_str()) throw InputError("cannot read unit \"" + limits::echo(t) + "\"");
  if (!(std::isfinite(factor) && factor > 0))
    throw InputError("unit \"" + limits::echo(t) + "\": the factor of a count must be positive and finite");
  if (rest.empty())
    throw InputError("unit \"" + limits::echo(t) + "\": a factor needs a unit after it (\"0.05 deg/s\": one count is 0.05 deg/s)");
  return {factor, rest};
}

Quantity parseQuantity(std::string_view text) {
  std::string_view t = trimmed(text);
  if (t.empty()) throw InputError("empty value");
  std::string buf(t);
  char* end = nullptr;
  double value = std::strtod(buf.c_str(), &end);
  if (end == buf.c_str()) throw InputError("expected a number, got \"" + limits::echo(buf) + "\"");
  if (!std::isfinite(value)) throw InputError("value is not finite: \"" + limits::echo(buf) + "\"");
  std::string_view rest = trimmed(std::string_view(end));
  if (rest.empty()) return {value, Dimension::none()};
  UnitParser p(rest);
  Quantity unit = p.expression();
  if (!p.done()) throw InputError("cannot read unit \"" + limits::echo(rest) + "\"");
  // A lone absolute temperature ("25 degC") carries its offset; degC in a compound is a difference.
  double offset = p.atomCount() == 0 ? p.loneOffset() : 0.0;
  const double si = value * unit.si + offset;
  if (!std::isfinite(si))
    throw InputError("value overflows in SI units: \"" + limits::echo(t) + "\"");
  return {si, unit.dim};
}

double parseQuantityAs(std::string_view text, Dimension expected) {
  Quantity q = parseQuantity(text);
  if (q.dim != expected) {
    std::string what = q.dim == Dimension::none() ? "no unit" : "a unit of " + q.dim.siUnit();
    throw InputError("expected a value in " + exampleUnit(expected) + " (SI " + expected.siUnit() +
                     "), got \"" + limits::echo(trimmed(text)) + "\" with " + what);
  }
  return q.si;
}

double parseOptionQuantity(std::string_view text, Dimension expected, const std::string& option,
                           bool plainIsSi) {
  try {
    Quantity q = parseQuantity(text);
    if (plainIsSi && q.dim == Dimension::none()) q.dim = expected;
    if (q.dim != expected) return parseQuantityAs(text, expected);  // its message
    return q.si;
  } catch (const InputError& e) {
    throw OptionError(option + ": " + e.text());
  }
}

double parseDuration(std::string_view text, const std::string& option) {
  try {
    Quantity q = parseQuantity(text);
    if (q.dim == Dimension::none()) q.dim = Dimension::time();  // a plain number is seconds
    if (q.dim != Dimension::time())
      throw InputError("expected a time such as \"90 s\", \"10 min\" or \"2 h\", got \"" +
                       limits::echo(trimmed(text)) + "\"");
    if (!(q.si >= 0.0)) throw InputError("expected a non-negative time, got \"" + limits::echo(trimmed(text)) + "\"");
    return q.si;
  } catch (const InputError& e) {
    throw OptionError(option + ": " + e.text());
  }
}

}  // namespace sinsim
