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

/// A p-value as read in a paper: "0.03", "0.0012", "1e-12", "< 1e-300" (underflow).
inline std::string pValueText(double p) {
  if (!(p > 0)) return p == 0 ? "< 1e-300" : significant(p);
  return significant(p, p >= 1e-3 ? 2 : 1);
}

}  // namespace sinsim
