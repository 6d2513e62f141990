// How a record file lays out its columns: the field separator and the user's column mapping.
//
// Separators: ',' or ';' between fields, or runs of blanks (spaces / tabs). Detected from the
// header line (',' first, then ';', else blanks) unless given. In blank-separated files a unit in
// brackets may contain spaces ("gx [deg/s]").
//
// A column mapping names, for each quantity sinsim reads (t, gx gy gz, ax ay az, temp), the file's
// column: by header name (case-insensitive) or by 1-based number, with an optional unit in
// brackets, e.g. "t=Time[ms],gx=GyroX[deg/s],gy=GyroY[deg/s],gz=3". When every column is named
// by number the file has no header line.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sinsim::errormodels {

/// The six sensor columns a record may hold, in channel order (errormodels/channels.hpp's
/// kRecordChannels gives each its sensor and axis).
inline constexpr std::array<const char*, 6> kSensorColumns{"gx", "gy", "gz", "ax", "ay", "az"};

/// The field separator of a record: one character, or runs of blanks.
struct Separator {
  char c = ',';        ///< ',' or ';' (ignored when blanks)
  bool blanks = false; ///< fields separated by one or more spaces / tabs

  bool at(char ch) const { return blanks ? (ch == ' ' || ch == '\t') : ch == c; }
  std::string describe() const;  ///< "','", "';'", "blanks"
};

/// Parses the option text: "," ";" "comma" "semicolon" "space" "tab" "blank"/"whitespace", or
/// "auto" (returns nullopt: detect from the file). InputError naming the option otherwise.
std::optional<Separator> parseSeparator(std::string_view text);

/// The separator a header (or first data) line uses: ',' if it has one, else ';', else blanks.
Separator detectSeparator(std::string_view line);

/// Splits one header line into trimmed fields; with blanks, brackets keep their spaces.
std::vector<std::string_view> splitHeader(std::string_view line, const Separator& sep);

/// One entry of a column mapping: quantity <- file column.
struct ColumnMap {
  std::string quantity;  ///< t, gx, gy, gz, ax, ay, az or temp
  std::string column;    ///< header name (lower case) or 1-based number as text
  std::string unit;      ///< unit written in brackets, or empty
  bool byNumber() const;
};

/// Parses "t=Time[ms],gx=GyroX[deg/s],gz=3"; InputError naming the entry on an unknown quantity,
/// a quantity given twice, an empty column, or an unclosed bracket.
std::vector<ColumnMap> parseColumnMapping(std::string_view text);

/// True when every entry names its column by number (the file then has no header line).
bool headerless(const std::vector<ColumnMap>& mapping);

}  // namespace sinsim::errormodels
