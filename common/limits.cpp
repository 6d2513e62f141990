#include "common/limits.hpp"

#include <cstdio>
#include <sstream>

namespace sinsim::limits {

std::string echo(std::string_view text) {
  std::string out;
  const std::size_t shown = std::min(text.size(), kMaxEchoChars);
  for (std::size_t i = 0; i < shown; ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c < 0x20 || c == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
    } else {
      out += static_cast<char>(c);
    }
  }
  if (shown < text.size()) out += "... (" + std::to_string(text.size()) + " characters)";
  return out;
}

std::string fmt(double x, int digits) {
  std::ostringstream os;
  os.precision(digits);
  os << x;
  return os.str();
}

}  // namespace sinsim::limits
