#include "errormodels/stats/record_layout.hpp"

#include <algorithm>
#include <cctype>

#include "common/error.hpp"
#include "common/text.hpp"
#include "common/limits.hpp"

namespace sinsim::errormodels {
namespace {

bool knownQuantity(const std::string& q) {
  return q == "t" || q == "temp" ||
         std::any_of(kSensorColumns.begin(), kSensorColumns.end(), [&](const char* n) { return q == n; });
}

}  // namespace

std::string Separator::describe() const {
  if (blanks) return "blanks";
  return std::string("'") + c + "'";
}

std::optional<Separator> parseSeparator(std::string_view text) {
  const std::string t = lowered(trimmed(text));
  if (t.empty() || t == "auto") return std::nullopt;
  if (t == "," || t == "comma") return Separator{',', false};
  if (t == ";" || t == "semicolon") return Separator{';', false};
  if (t == "space" || t == "tab" || t == "blank" || t == "blanks" || t == "whitespace")
    return Separator{' ', true};
  throw InputError("--delimiter: expected auto, comma, semicolon or whitespace, got \"" +
                   limits::echo(text) + "\"");
}

Separator detectSeparator(std::string_view line) {
  if (line.find(',') != std::string_view::npos) return {',', false};
  if (line.find(';') != std::string_view::npos) return {';', false};
  return {' ', true};
}

std::vector<std::string_view> splitHeader(std::string_view line, const Separator& sep) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  const std::size_t n = line.size();
  while (i <= n) {
    if (sep.blanks)
      while (i < n && sep.at(line[i])) ++i;
    if (sep.blanks && i == n) break;
    const std::size_t start = i;
    char close = 0;
    for (;;) {
      while (i < n && (close != 0 || !sep.at(line[i]))) {
        if (close == 0 && (line[i] == '[' || line[i] == '(')) close = line[i] == '[' ? ']' : ')';
        else if (line[i] == close) close = 0;
        ++i;
      }
      // "gx [deg/s]": with blanks between fields, a unit in brackets belongs to the name before it
      std::size_t j = i;
      while (sep.blanks && j < n && sep.at(line[j])) ++j;
      if (!sep.blanks || j == n || (line[j] != '[' && line[j] != '(')) break;
      i = j;
    }
    out.push_back(trimmed(line.substr(start, i - start)));
    if (out.size() > limits::kMaxRecordColumns) break;  // the caller reports the limit
    ++i;  // past the separator (or one past the end)
  }
  return out;
}

bool ColumnMap::byNumber() const {
  return !column.empty() &&
         std::all_of(column.begin(), column.end(), [](char c) { return c >= '0' && c <= '9'; });
}

std::vector<ColumnMap> parseColumnMapping(std::string_view text) {
  std::vector<ColumnMap> out;
  for (std::string_view entry : splitHeader(text, Separator{',', false})) {
    if (entry.empty()) continue;
    const std::string where = "--columns: \"" + limits::echo(entry) + "\": ";
    const std::size_t eq = entry.find('=');
    if (eq == std::string_view::npos)
      throw InputError(where + "expected QUANTITY=COLUMN, e.g. gx=GyroX[deg/s]");
    ColumnMap m;
    m.quantity = lowered(trimmed(entry.substr(0, eq)));
    if (m.quantity == "time") m.quantity = "t";
    if (m.quantity == "temperature") m.quantity = "temp";
    if (!knownQuantity(m.quantity))
      throw InputError(where + "unknown quantity \"" + limits::echo(m.quantity) +
                       "\" (t, gx, gy, gz, ax, ay, az, temp)");
    std::string_view col = trimmed(entry.substr(eq + 1));
    const std::size_t open = col.find('[');
    if (open != std::string_view::npos) {
      const std::size_t close = col.find(']', open);
      if (close == std::string_view::npos || !trimmed(col.substr(close + 1)).empty())
        throw InputError(where + "a unit goes in brackets at the end, e.g. GyroX[deg/s]");
      m.unit = std::string(trimmed(col.substr(open + 1, close - open - 1)));
      col = trimmed(col.substr(0, open));
    }
    m.column = lowered(col);
    if (m.column.empty()) throw InputError(where + "no column after '='");
    if (m.byNumber() && (m.column.size() > 9 || std::stoul(m.column) == 0))
      throw InputError(where + "column numbers start at 1");
    for (const ColumnMap& o : out) {
      if (o.quantity == m.quantity) throw InputError(where + m.quantity + " is mapped twice");
      if (o.column == m.column)
        throw InputError(where + "column \"" + m.column + "\" is mapped to " + o.quantity +
                         " and " + m.quantity);
    }
    out.push_back(std::move(m));
  }
  return out;
}

bool headerless(const std::vector<ColumnMap>& mapping) {
  return !mapping.empty() &&
         std::all_of(mapping.begin(), mapping.end(), [](const ColumnMap& m) { return m.byNumber(); });
}

}  // namespace sinsim::errormodels
