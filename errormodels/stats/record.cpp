#include "errormodels/stats/record.hpp"

#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <sstream>

#include "common/error.hpp"
#include "common/limits.hpp"
#include "common/progress.hpp"
#include "common/read_file.hpp"
#include "common/text.hpp"
#include "common/units.hpp"
#include "errormodels/stats/record_time.hpp"

namespace sinsim::errormodels {
namespace {

enum class Role { Time, Gyro, Accel, Temperature, Aux };

struct Column {
  Role role = Role::Aux;
  int axis = 0;
  std::string header;  // as written
  double scale = 1.0;   // SI value = scale * file value + offset
  double offset = 0.0;
};


[[noreturn]] void fail(const std::string& source, std::size_t line, const std::string& what) {
  detail::recordError(source, line, what);
}

/// Reads (and gunzips) `path` into `out`, at most `limit` bytes; with `out` nullptr only counts,
/// up to `limit` + 1 (more than the limit). The number of bytes read. A read error or a truncated
/// gzip stream fails with the file's name.
std::size_t readGz(const std::string& path, char* out, std::size_t limit) {
  gzFile f = gzopen(path.c_str(), "rb");
  if (f == nullptr) fail(path, 0, std::string("cannot open file: ") + std::strerror(errno));
  gzbuffer(f, 1u << 20);
  std::vector<char> scratch(out ? 0 : std::size_t{1} << 20);
  std::size_t used = 0;
  const std::size_t stop = out ? limit : limit + 1;
  while (used < stop) {
    const std::size_t room = out ? limit - used : scratch.size();
    const unsigned want = static_cast<unsigned>(std::min<std::size_t>(room, 1u << 30));
    const int got = gzread(f, out ? out + used : scratch.data(), want);
    if (got < 0) {
      int code = 0;
      std::string msg = gzerror(f, &code);
      gzclose(f);
      fail(path, 0, "read error: " + msg);
    }
    if (got == 0) break;
    used += static_cast<std::size_t>(got);
  }
  // A truncated gzip stream ends with Z_BUF_ERROR ("unexpected end of file").
  int code = Z_OK;
  const char* msg = gzerror(f, &code);
  if (used <= limit && code != Z_OK && code != Z_STREAM_END) {
    std::string m = msg;
    gzclose(f);
    fail(path, 0, "read error: " + m);
  }
  gzclose(f);
  return used;
}

/// Reads a whole file, gunzipping when it is a gzip stream (zlib reads plain files as they are).
/// Two passes: the size first, without keeping the text (a 1 MB gzip can hold 1 GB, and nothing
/// is allocated for it), then one buffer of exactly that size. A buffer grown by doubling held the
/// old and the new copy at once: 1 GB of memory for a 512 MB record.
std::string readWholeFile(const std::string& path) {
  requireRegularFile(path, "record");
  const std::size_t size = readGz(path, nullptr, limits::kMaxRecordBytes);
  if (size > limits::kMaxRecordBytes)
    fail(path, 0, "record larger than " + std::to_string(limits::kMaxRecordBytes) +
                      " bytes after decompression (docs/limits.md)");
  std::string text(size, '\0');
  const std::size_t again = readGz(path, text.data(), size);
  if (again != size) fail(path, 0, "the file changed while it was read");
  return text;
}

struct UnitSpec {
  double scale = 1.0;
  double offset = 0.0;
  Dimension dim;
};

UnitSpec parseUnitSpec(std::string_view unit, const std::string& source, std::size_t line,
                       const std::string& column) {
  try {
    Quantity q = parseUnit(unit);
    UnitSpec spec{q.si, 0.0, q.dim};
    if (q.dim == Dimension::temperature()) {
      // Absolute temperatures carry an offset (degC -> K); parseQuantity applies it to a lone unit.
      spec.offset = parseQuantity("0 " + std::string(unit)).si;
    }
    return spec;
  } catch (const InputError& e) {
    fail(source, line, "column \"" + column + "\": " + e.what());
  }
}

/// Resolves the unit of one recognised column from the header text and the user's option.
UnitSpec resolveUnit(std::string_view header_unit, const std::optional<std::string>& option,
                     std::string_view default_unit, Dimension expected, const std::string& source,
                     std::size_t line, const std::string& column) {
  UnitSpec spec;
  if (!header_unit.empty() && option) {
    UnitSpec a = parseUnitSpec(header_unit, source, line, column);
    UnitSpec b = parseUnitSpec(*option, source, line, column);
    if (a.dim != b.dim || std::abs(a.scale - b.scale) > 1e-12 * std::abs(b.scale) ||
        a.offset != b.offset) {
      fail(source, line,
           "column \"" + column + "\" is in " + std::string(header_unit) +
               " by its header but the unit option says " + *option);
    }
    spec = b;
  } else if (!header_unit.empty()) {
    spec = parseUnitSpec(header_unit, source, line, column);
  } else if (option) {
    spec = parseUnitSpec(*option, source, line, column);
  } else {
    spec = parseUnitSpec(default_unit, source, line, column);
  }
  if (spec.dim != expected) {
    fail(source, line,
         "column \"" + column + "\": unit has dimension " + spec.dim.siUnit() + ", expected " +
             expected.siUnit() + " (e.g. " + exampleUnit(expected) + ")");
  }
  return spec;
}

/// The mapping entry for the header field `name` (lower case) at 1-based position `pos`.
const ColumnMap* mappedAs(const std::vector<ColumnMap>& mapping, const std::string& name,
                          std::size_t pos) {
  for (const ColumnMap& m : mapping)
    if (m.byNumber() ? m.column == std::to_string(pos) : m.column == name) return &m;
  return nullptr;
}

std::vector<Column> parseHeader(const std::vector<std::string_view>& fields,
                                const std::string& source, std::size_t line,
                                const RecordOptions& options) {
  std::vector<Column> cols;
  for (std::string_view field : fields) {
    if (cols.size() >= limits::kMaxRecordColumns)
      fail(source, line, "header: more than " + std::to_string(limits::kMaxRecordColumns) +
                             " columns (docs/limits.md)");
    Column col;
    col.header = limits::echo(field);
    if (field.empty()) fail(source, line, "header: column " + std::to_string(cols.size() + 1) + " has no name");
    std::string_view name = field;
    std::string_view unit;
    const std::size_t open = field.find_first_of("[(");
    if (open != std::string_view::npos) {
      const char close_char = field[open] == '[' ? ']' : ')';
      const std::size_t close = field.find(close_char, open);
      if (close == std::string_view::npos)
        fail(source, line, "header: column \"" + col.header + "\": unclosed unit bracket");
      name = trimmed(field.substr(0, open));
      unit = trimmed(field.substr(open + 1, close - open - 1));
    }
    std::string key = lowered(name);
    if (const ColumnMap* m = mappedAs(options.columns, key, cols.size() + 1)) {
      if (!m->unit.empty() && !unit.empty() && lowered(m->unit) != lowered(unit))
        fail(source, line, "column \"" + col.header + "\": unit [" + std::string(unit) +
                               "] in the file and [" + m->unit + "] in the column mapping");
      if (!m->unit.empty()) unit = m->unit;
      key = m->quantity;
    } else {
      const std::string q = key == "time" ? "t" : key == "temperature" ? "temp" : key;
      for (const ColumnMap& m : options.columns)
        if (m.quantity == q) key.clear();  // the mapping reads this quantity from another column
    }
    if (key == "t" || key == "time") {
      col.role = Role::Time;
      UnitSpec u = resolveUnit(unit, std::nullopt, "s", Dimension::time(), source, line, col.header);
      col.scale = u.scale;
    } else if (key.size() == 2 && (key[0] == 'g' || key[0] == 'a') &&
               (key[1] == 'x' || key[1] == 'y' || key[1] == 'z')) {
      const bool gyro = key[0] == 'g';
      col.role = gyro ? Role::Gyro : Role::Accel;
      col.axis = key[1] - 'x';
      UnitSpec u = gyro ? resolveUnit(unit, options.gyro_unit, "rad/s", Dimension::angularRate(),
                                      source, line, col.header)
                        : resolveUnit(unit, options.accel_unit, "m/s^2",
                                      Dimension::acceleration(), source, line, col.header);
      col.scale = u.scale;
    } else if (key == "temp" || key == "temperature") {
      col.role = Role::Temperature;
      UnitSpec u = resolveUnit(unit, std::nullopt, "degC", Dimension::temperature(), source, line,
                               col.header);
      col.scale = u.scale;
      col.offset = u.offset;
    }
    for (const Column& other : cols) {
      if (col.role != Role::Aux && other.role == col.role && other.axis == col.axis)
        fail(source, line, "header: columns \"" + other.header + "\" and \"" + col.header +
                               "\" hold the same quantity");
    }
    cols.push_back(col);
  }
  for (const ColumnMap& m : options.columns) {
    bool found = false;
    for (std::size_t i = 0; i < fields.size() && !found; ++i) {
      std::string_view f = fields[i];
      const std::size_t open = f.find_first_of("[(");
      found = m.byNumber() ? m.column == std::to_string(i + 1)
                           : lowered(trimmed(f.substr(0, open))) == m.column;
    }
    if (!found)
      fail(source, line, "column mapping " + m.quantity + "=" + m.column + ": the file has no " +
                             (m.byNumber() ? "column " + m.column + " (it has " +
                                                 std::to_string(fields.size()) + ")"
                                           : "column named \"" + m.column + "\""));
  }
  return cols;
}

/// Parses one number occupying [p, end) up to the next separator or end of line; returns the
/// position after the field (at a character separator, at the next field after blanks, or at the
/// end). Throws with line/column context on anything that is not a finite number.
inline const char* parseField(const char* p, const char* end, double& value, const Column& col,
                              const Separator& sep, const std::string& source, std::size_t line) {
  while (p < end && (*p == ' ' || *p == '\t')) ++p;
  const char* q = p;
  if (q < end && *q == '+') ++q;  // from_chars does not take a leading '+'
  auto res = std::from_chars(q, end, value);
  const char* after = res.ptr;
  if (after - p > static_cast<std::ptrdiff_t>(limits::kMaxFieldChars))
    fail(source, line, "column \"" + col.header + "\": a field longer than " +
                           std::to_string(limits::kMaxFieldChars) + " characters");
  while (after < end && (*after == ' ' || *after == '\t' || *after == '\r')) ++after;
  const bool separated = after == end || (sep.blanks ? after > res.ptr : *after == sep.c);
  if (res.ec != std::errc() || !separated || !std::isfinite(value)) {
    const char* stop = p;
    while (stop < end && !sep.at(*stop) && *stop != '\r') ++stop;
    const std::string text = limits::echo(std::string_view(p, static_cast<std::size_t>(stop - p)));
    if (res.ec == std::errc::result_out_of_range)
      fail(source, line, "column \"" + col.header + "\": number out of range: \"" + text + "\"");
    if (text.empty()) fail(source, line, "column \"" + col.header + "\": empty field");
    fail(source, line, "column \"" + col.header + "\": expected a finite number, got \"" + text + "\"");
  }
  return after;
}

}  // namespace

Record parseRecord(std::string_view text, const std::string& source, const RecordOptions& options) {
  if (options.rate_hz) detail::checkRate(*options.rate_hz, source, "the rate option (--rate)");
  if (!(std::isfinite(options.time_tolerance) && options.time_tolerance > 0))
    fail(source, 0, "time tolerance must be positive");
  if (!(std::isfinite(options.skip_s) && options.skip_s >= 0))
    fail(source, 0, "skip: expected a non-negative time, got " + limits::fmt(options.skip_s));
  if (options.duration_s && !(std::isfinite(*options.duration_s) && *options.duration_s > 0))
    fail(source, 0, "duration: expected a positive time, got " + limits::fmt(*options.duration_s));

  // A UTF-8 byte-order mark (spreadsheet exports) is not part of the first column's name.
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  const char* p = text.data();
  const char* const end = p + text.size();
  std::size_t line = 0;
  // Comment lines and blank lines before the header.
  const bool noHeader = headerless(options.columns);
  std::string_view header;
  while (p < end) {
    const char* eol = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
    if (eol == nullptr) eol = end;
    ++line;
    std::string_view l = trimmed(std::string_view(p, static_cast<std::size_t>(eol - p)));
    const char* const lineStart = p;
    p = eol < end ? eol + 1 : end;
    if (l.empty() || l.front() == '#') continue;
    header = l;
    if (noHeader) {  // the first data row: read again below
      p = lineStart;
      --line;
    }
    break;
  }
  if (header.empty()) fail(source, 0, "empty file: no header line and no data");
  const std::size_t header_line = line;
  const Separator sep = options.separator ? *options.separator : detectSeparator(header);
  std::vector<std::string_view> fields = splitHeader(header, sep);
  std::vector<std::string> numbered;  // a file without a header: "column 1", "column 2", ...
  if (noHeader) {
    for (std::size_t i = 0; i < fields.size(); ++i) numbered.push_back(std::to_string(i + 1));
    fields.assign(numbered.begin(), numbered.end());
  }
  std::vector<Column> cols = parseHeader(fields, source, line, options);
  if (noHeader)
    for (Column& c : cols) c.header = "column " + c.header;
  const std::size_t ncol = cols.size();

  // Upper bound of the row count, so that columns are written in place.
  const std::size_t max_rows =
      static_cast<std::size_t>(std::count(p, end, '\n')) + 1;
  if (max_rows > limits::kMaxRecordCells / ncol)
    fail(source, 0, "record too large: up to " + std::to_string(max_rows) + " rows of " +
                        std::to_string(ncol) + " columns, more than " +
                        std::to_string(limits::kMaxRecordCells) + " values (docs/limits.md)");
  std::vector<std::vector<double>> data(ncol);
  for (auto& c : data) c.resize(max_rows);

  std::size_t rows = 0;
  while (p < end) {
    const char* eol = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
    if (eol == nullptr) eol = end;
    ++line;
    const char* q = p;
    const char* next = eol < end ? eol + 1 : end;
    // Blank lines are allowed only at the end of the file.
    if (trimmed(std::string_view(p, static_cast<std::size_t>(eol - p))).empty()) {
      const char* r = next;
      while (r < end && (*r == '\n' || *r == '\r' || *r == ' ' || *r == '\t')) ++r;
      if (r == end) break;
      fail(source, line, "empty row inside the data");
    }
    for (std::size_t c = 0; c < ncol; ++c) {
      if (q >= eol && c > 0) {
        fail(source, line, "short row: " + std::to_string(c) + " field(s), the header has " +
                               std::to_string(ncol));
      }
      double v;
      q = parseField(q, eol, v, cols[c], sep, source, line);
      data[c][rows] = v;
      if (c + 1 < ncol) {
        if (q >= eol)
          fail(source, line, "short row: " + std::to_string(c + 1) + " field(s), the header has " +
                                 std::to_string(ncol));
        if (!sep.blanks) ++q;  // the separator (blanks were skipped by parseField)
      }
    }
    if (q < eol) {
      fail(source, line, "long row: more than the " + std::to_string(ncol) + " fields of the header");
    }
    ++rows;
    p = next;
    if ((rows & 0xffff) == 0) progress::checkpoint("reading " + source, rows, max_rows);
  }
  if (rows == 0) fail(source, header_line, "no data rows after the header");

  Record rec;
  rec.source = source;
  rec.rows = rows;
  for (std::size_t c = 0; c < ncol; ++c) {
    std::vector<double>& v = data[c];
    v.resize(rows);
    v.shrink_to_fit();
    const Column& col = cols[c];
    if (col.role != Role::Aux && (col.scale != 1.0 || col.offset != 0.0)) {
      for (double& x : v) x = col.scale * x + col.offset;
    }
    // Beyond kMaxQuantity (SI) sums of squares in the statistics overflow to inf and NaN.
    if (col.role != Role::Aux)
      for (std::size_t r = 0; r < rows; ++r)
        if (!(std::abs(v[r]) <= limits::kMaxQuantity))
          fail(source, header_line + 1 + r,
               "column \"" + col.header + "\": value " + limits::fmt(v[r]) +
                   " (SI) is beyond any sensor (|x| <= " + limits::fmt(limits::kMaxQuantity) +
                   "; docs/limits.md)");
    switch (col.role) {
      case Role::Time: rec.t = std::move(v); break;
      case Role::Gyro: rec.gyro[col.axis] = std::move(v); break;
      case Role::Accel: rec.accel[col.axis] = std::move(v); break;
      case Role::Temperature: rec.temperature = std::move(v); break;
      case Role::Aux: rec.aux.push_back({col.header, std::move(v)}); break;
    }
  }
  if (!rec.t.empty()) {
    detail::checkTime(rec, header_line + 1, options);
  } else {
    if (!options.rate_hz)
      fail(source, 0, "the file has no time column (t): give the sample rate, or name its time column in the column mapping (t=NAME)");
    rec.rate_hz = *options.rate_hz;
  }
  detail::checkRate(rec.rate_hz, source, rec.t.empty() ? "the given sample rate" : "the time stamps' rate");
  detail::applyWindow(rec, options);
  return rec;
}

Record loadRecord(const std::string& path, const RecordOptions& options) {
  progress::checkpoint("reading " + path);
  const std::string text = readWholeFile(path);
  return parseRecord(text, path, options);
}

}  // namespace sinsim::errormodels
