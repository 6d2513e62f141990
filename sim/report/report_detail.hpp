// Internals shared by the report sources; not part of the public API.
#pragma once

#include <cstddef>
#include <string>

namespace sinsim::report::detail {

/// "⁻¹²" for -12: Unicode superscript digits for exponent labels.
std::string superscript(long long n);
/// Replaces a leading ASCII '-' by the typographic minus U+2212.
std::string typographicMinus(std::string s);
/// Number of Unicode code points in a UTF-8 string (for text width estimates).
std::size_t displayLength(const std::string& utf8);

}  // namespace sinsim::report::detail
