// Number formatting and escaping shared by the SVG and HTML writers. std::to_chars is locale
// independent, so a German or French C locale cannot turn "0.5" into "0,5" in the output.
#include <charconv>
#include <cmath>
#include <string>

#include "sim/report/report.hpp"
#include "sim/report/report_detail.hpp"

namespace sinsim::report {

std::string escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

DisplayUnit lengthUnit(double maxAbs) {
  if (maxAbs < 1.0) return {1e3, "mm"};
  if (maxAbs < 1e4) return {1.0, "m"};
  return {1e-3, "km"};
}

std::string formatFixed(double value, int decimals) {
  if (!std::isfinite(value)) return std::isnan(value) ? "nan" : (value > 0 ? "inf" : "-inf");
  if (decimals < 0) decimals = 0;
  if (decimals > 17) decimals = 17;
  char buf[400];  // |value| ≤ 1.8e308 → at most 309 integer digits + sign + point + 17 decimals
  const auto res = std::to_chars(buf, buf + sizeof buf, value, std::chars_format::fixed, decimals);
  std::string s(buf, res.ptr);
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  if (s == "-0") s = "0";
  return s;
}

const std::string& paletteColor(std::size_t i) {
  // Tableau 10 (the matplotlib default cycle): distinguishable, prints well in grey.
  static const std::string palette[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                                        "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};
  return palette[i % (sizeof palette / sizeof palette[0])];
}

namespace detail {

std::string superscript(long long n) {
  static const char* digits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string out;
  if (n < 0) out += "⁻";
  const std::string d = std::to_string(n < 0 ? -n : n);
  for (char c : d) out += digits[c - '0'];
  return out;
}

std::string typographicMinus(std::string s) {
  if (!s.empty() && s[0] == '-') s.replace(0, 1, "−");  // U+2212, the width of a digit
  return s;
}

std::size_t displayLength(const std::string& utf8) {
  std::size_t n = 0;
  for (unsigned char c : utf8)
    if ((c & 0xC0) != 0x80) ++n;  // count code points, not continuation bytes
  return n;
}

}  // namespace detail
}  // namespace sinsim::report
