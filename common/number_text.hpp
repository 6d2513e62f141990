// A number as text for messages, comments and reports: the one "%.*g" formatter.
#pragma once

#include <cstdio>
#include <string>

namespace sinsim {

/// v with `digits` significant digits, printf "%.*g" (e.g. 0.000123, 1.5e+07, nan, inf).
inline std::string significant(double v, int digits = 6) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

}  // namespace sinsim
