// A number as text for messages, comments and reports: the one "%.*g" formatter.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace sinsim {

/// v with `digits` significant digits, printf "%.*g" (e.g. 0.000123, 1.5e+07, nan, inf).
inline std::string significant(double v, int digits = 6) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

/// A length [m] in the unit that reads best, `digits` significant digits and no exponent:
/// "350 µm", "4.2 mm", "12.3 m", "49.98 km" (everything from 1 km up in km).
inline std::string lengthText(double m, int digits = 4) {
  if (!std::isfinite(m)) return significant(m);
  const double a = std::fabs(m);
  const char* unit = "m";
  double v = m;
  if (a >= 1000.0) v = m / 1000.0, unit = "km";
  else if (a > 0 && a < 1e-3) v = m * 1e6, unit = "µm";
  else if (a > 0 && a < 1.0) v = m * 1e3, unit = "mm";
  // Digits after the point so that `digits` significant digits show (none beyond the integer).
  const int intDigits = std::fabs(v) >= 1 ? int(std::floor(std::log10(std::fabs(v)))) + 1 : 1;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f %s", std::max(0, digits - intDigits), v, unit);
  return buf;
}

/// A time [s] as people say it: "45 s", "10 min", "1.5 h" (up to 2 decimals, trailing zeros cut).
inline std::string durationText(double s) {
  double v = s;
  const char* unit = "s";
  if (std::fabs(s) >= 3600.0 && std::fmod(s, 360.0) == 0.0) v = s / 3600.0, unit = "h";
  else if (std::fabs(s) >= 60.0 && std::fmod(s, 6.0) == 0.0) v = s / 60.0, unit = "min";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  std::string t = buf;
  while (t.back() == '0') t.pop_back();
  if (t.back() == '.') t.pop_back();
  return t + " " + unit;
}

/// v with `digits` significant digits and never an exponent: "0.00012", "2200", "22345" (more
/// digits rather than "2.2e+04"); "–" when not finite. For text that is read, not parsed.
inline std::string plainSignificant(double v, int digits = 4) {
  if (!std::isfinite(v)) return "–";
  const std::string s = significant(v, digits);
  if (s.find('e') == std::string::npos) return s;
  const int mag = int(std::floor(std::log10(std::fabs(v))));
  char buf[400];  // |v| <= 1.8e308: 309 digits at most
  std::snprintf(buf, sizeof buf, "%.*f", std::clamp(digits - 1 - mag, 0, 12), v);
  std::string t = buf;
  if (t.find('.') != std::string::npos) {  // as %g: no trailing zeros
    while (t.back() == '0') t.pop_back();
    if (t.back() == '.') t.pop_back();
  }
  return t;
}

/// A p-value as read in a paper: "0.03", "0.0012", "1e-12", "< 1e-300" (underflow, denormals).
inline std::string pValueText(double p) {
  if (!(p >= 1e-300)) return p >= 0 ? "< 1e-300" : significant(p);
  return significant(p, p >= 1e-3 ? 2 : 1);
}

/// "p = 0.03", "p < 1e-300", or "p not defined" (NaN: e.g. a test of one pair).
inline std::string pStatement(double p) {
  if (std::isnan(p)) return "p not defined";
  const std::string v = pValueText(p);
  return v[0] == '<' ? "p " + v : "p = " + v;
}

}  // namespace sinsim
