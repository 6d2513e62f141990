#include "common/limits.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "common/error.hpp"

namespace sinsim::limits {

namespace {

/// Bytes of the well-formed UTF-8 sequence that starts at text[i] (2 to 4), or 0 when none does
/// (a Latin-1 byte, a stray continuation byte, an overlong or cut sequence).
std::size_t utf8Sequence(std::string_view text, std::size_t i) {
  const unsigned char c = static_cast<unsigned char>(text[i]);
  const std::size_t n = c >= 0xC2 && c <= 0xDF ? 2 : c >= 0xE0 && c <= 0xEF ? 3 : c >= 0xF0 && c <= 0xF4 ? 4 : 0;
  if (n == 0 || i + n > text.size()) return 0;
  for (std::size_t k = 1; k < n; ++k)
    if ((static_cast<unsigned char>(text[i + k]) & 0xC0) != 0x80) return 0;
  const unsigned char d = static_cast<unsigned char>(text[i + 1]);
  if ((c == 0xE0 && d < 0xA0) || (c == 0xF0 && d < 0x90) || (c == 0xF4 && d > 0x8F) || (c == 0xED && d > 0x9F))
    return 0;  // overlong, beyond U+10FFFF, or a surrogate
  return n;
}

void appendHex(std::string& out, unsigned char c) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "\\x%02x", c);
  out += buf;
}

/// `text` with every byte that is not UTF-8 shown as \xNN, and control characters too unless
/// `keepLines` keeps '\n' and '\t'; at most `limit` bytes of `text` are looked at.
std::string printable(std::string_view text, std::size_t limit, bool keepLines) {
  std::string out;
  for (std::size_t i = 0; i < std::min(text.size(), limit);) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c < 0x80) {
      if ((c < 0x20 || c == 0x7f) && !(keepLines && (c == '\n' || c == '\t'))) appendHex(out, c);
      else out += static_cast<char>(c);
      ++i;
    } else if (const std::size_t n = utf8Sequence(text, i)) {
      out.append(text.substr(i, n));
      i += n;
    } else {
      appendHex(out, c);
      ++i;
    }
  }
  return out;
}

}  // namespace

std::string echo(std::string_view text) {
  std::string out = printable(text, kMaxEchoChars, false);
  if (kMaxEchoChars < text.size()) out += "... (" + std::to_string(text.size()) + " characters)";
  return out;
}

std::string messageText(std::string_view text) { return printable(text, text.size(), true); }

std::string fmt(double x, int digits) {
  std::ostringstream os;
  os.precision(digits);
  os << x;
  return os.str();
}

void requireThreads(unsigned threads, const std::string& what) {
  if (threads > kMaxThreads)
    throw InputError(what + ": expected 0 (every core) to " + std::to_string(kMaxThreads) + " worker threads, got " +
                     std::to_string(threads));
}

}  // namespace sinsim::limits
