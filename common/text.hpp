// Small text helpers shared by the readers: trimming blanks and ASCII lower case.
#pragma once

#include <cctype>
#include <string>
#include <string_view>

namespace sinsim {

/// s without leading and trailing white space (blanks, tabs, CR, ...).
inline std::string_view trimmed(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

/// s in ASCII lower case.
inline std::string lowered(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace sinsim
