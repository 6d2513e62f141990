#include "errormodels/stats/record.hpp"

#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <new>
#include <sstream>

#include "common/constants.hpp"
#include "common/error.hpp"
#include "common/limits.hpp"
#include "common/number_text.hpp"
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
  std::string unit;    // as written in the header's brackets
  double scale = 1.0;   // SI value = scale * file value + offset
  double offset = 0.0;
  /// An auxiliary column with a field that is not a number (a status word, a date, a logger's
  /// empty cell): left out of the record, with why (a Record::notes line); empty while it reads.
  std::string leftOut;
};


[[noreturn]] void fail(const std::string& source, std::size_t line, const std::string& what) {
  detail::recordError(source, line, what);
}

[[noreturn]] void failCrLineEnds(const std::string& source, std::size_t line) {
  fail(source, line,
       "the lines end in a carriage return alone (CR, old Mac line ends), so the file reads as one "
       "line: convert them to LF (tr '\\r' '\\n' < in.csv > out.csv)");
}

/// Calls `line(text, number)` for every line of `path` (gunzipped when it is a gzip stream; zlib
/// reads plain files as they are), without its '\n', while the file is read in chunks: a record
/// of any length needs memory for its values only, not for its text. A line longer than
/// limits::kMaxRecordLineChars fails (a 1 MB gzip can hold a 1 GB line); so do a read error and a
/// truncated gzip stream, with the file's name. Progress: the compressed bytes read of the file.
template <class OnLine>
void forEachLineOfFile(const std::string& path, OnLine&& line) {
  requireRegularFile(path, "record");
  gzFile f = gzopen(path.c_str(), "rb");
  if (f == nullptr) fail(path, 0, std::string("cannot open file: ") + std::strerror(errno));
  struct Closer {
    gzFile f;
    ~Closer() { gzclose(f); }
  } closer{f};
  gzbuffer(f, 1u << 20);
  std::error_code ec;
  const auto fileBytes = std::filesystem::file_size(path, ec);
  constexpr std::size_t kChunk = std::size_t{1} << 22;
  std::vector<char> buf(kChunk + limits::kMaxRecordLineChars + 1);
  std::size_t held = 0, number = 0;
  auto readError = [&] {
    int code = 0;
    fail(path, 0, std::string("read error: ") + gzerror(f, &code));
  };
  for (bool eof = false; !eof;) {
    const int got = gzread(f, buf.data() + held, static_cast<unsigned>(kChunk));
    if (got < 0) readError();
    eof = got == 0;
    held += static_cast<std::size_t>(got);
    const char* p = buf.data();
    const char* const end = p + held;
    for (;;) {
      const char* eol = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
      if (eol == nullptr && !(eof && p < end)) break;
      if (eol == nullptr) eol = end;
      if (static_cast<std::size_t>(eol - p) > limits::kMaxRecordLineChars) break;
      line(std::string_view(p, static_cast<std::size_t>(eol - p)), ++number);
      p = eol < end ? eol + 1 : end;
    }
    held = static_cast<std::size_t>(end - p);
    // CR line ends make the whole file one line: said as such at any size (a file over 1 MiB was
    // "a line longer than 1048576 characters").
    if (held > limits::kMaxRecordLineChars && std::memchr(p, '\r', held) != nullptr)
      failCrLineEnds(path, number + 1);
    if (held > limits::kMaxRecordLineChars)
      fail(path, number + 1, "a line longer than " + std::to_string(limits::kMaxRecordLineChars) +
                                 " characters (docs/limits.md)");
    std::memmove(buf.data(), p, held);
    if (!eof) {
      const auto at = gzoffset(f);
      progress::checkpoint("reading " + path, at > 0 ? std::uint64_t(at) : 0, ec ? 0 : std::uint64_t(fileBytes),
                           progress::Count::bytes);
    }
  }
  // A truncated gzip stream ends with Z_BUF_ERROR ("unexpected end of file").
  int code = Z_OK;
  gzerror(f, &code);
  if (code != Z_OK && code != Z_STREAM_END) readError();
}

struct UnitSpec {
  double scale = 1.0;
  double offset = 0.0;
  Dimension dim;
};

UnitSpec parseUnitSpec(std::string_view unit, const std::string& source, std::size_t line,
                       const std::string& column) {
  try {
    const auto [factor, base] = splitUnitFactor(unit);  // raw counts: "0.05 deg/s"
    Quantity q = parseUnit(base);
    UnitSpec spec{factor * q.si, 0.0, q.dim};
    if (q.dim == Dimension::temperature()) {
      // Absolute temperatures carry an offset (degC -> K); parseQuantity applies it to a lone unit.
      spec.offset = parseQuantity("0 " + std::string(base)).si;
    }
    return spec;
  } catch (const InputError& e) {
    fail(source, line, "column \"" + column + "\": " + e.text());
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
      col.unit = limits::echo(unit);
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

/// What a field that is no number may be: several fields of another separator than the one given
/// ("0.1,0.2,0.3" under --delimiter semicolon), a decimal comma ("0,25" in a ';'-separated file),
/// a date or clock time ("12:00:00.010", "2024-05-01T12:00:00").
std::string fieldHint(const std::string& text, const Separator& sep) {
  for (const char c : {',', ';', '\t'})
    if (!sep.at(c) && std::count(text.begin(), text.end(), c) >= 2)
      return std::string(" (fields separated by ") + (c == '\t' ? "tabs" : std::string("'") + c + "'") +
             "? the separator read is " + sep.describe() + ": leave --delimiter out to detect it)";
  auto digits = [&](std::size_t i) { return i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])); };
  for (std::size_t i = 1; i + 1 < text.size(); ++i) {
    if (text[i] == ',' && sep.c != ',' && digits(i - 1) && digits(i + 1))
      return " (a decimal comma? numbers are read with a decimal point: 0.25)";
    if ((text[i] == ':' || text[i] == '-' || text[i] == 'T') && digits(i - 1) && digits(i + 1))
      return " (a date or clock time? time stamps are read as numbers in a unit: convert them to "
             "seconds, or leave the column out and give the rate, --rate)";
  }
  return "";
}

/// One field read as a number: where the next field starts (at a character separator, at the next
/// field after blanks, or at the end), and, when it is no finite number, why, with its text.
struct Field {
  enum class Problem { None, TooLong, OutOfRange, Empty, NotNumber };
  const char* after = nullptr;
  const char* number = nullptr;  // where the number's digits start (past blanks, a quote, a '+')
  double value = 0.0;
  Problem problem = Problem::None;
  std::string text;  // the field as written (echoed safely) when there is a problem

  bool ok() const { return problem == Problem::None; }
  /// "column "gx": expected a finite number, got "OK"" (the hint is the caller's).
  std::string why(const Column& col) const {
    const std::string name = "column \"" + col.header + "\": ";
    switch (problem) {
      case Problem::TooLong: return name + "a field longer than " + std::to_string(limits::kMaxFieldChars) + " characters";
      case Problem::OutOfRange: return name + "number out of range: \"" + text + "\"";
      case Problem::Empty: return name + "empty field";
      case Problem::NotNumber: return name + "expected a finite number, got \"" + text + "\"";
      case Problem::None: break;
    }
    return name;
  }
};

/// Reads one number occupying [p, end) up to the next separator or end of line.
inline Field readField(const char* p, const char* end, const Separator& sep) {
  Field f;
  while (p < end && (*p == ' ' || *p == '\t')) ++p;
  const char* q = p;
  // A quote-everything export writes "0.25": the quotes around a number are not part of it.
  const bool quoted = q < end && *q == '"';
  if (quoted) ++q;
  if (q < end && *q == '+') ++q;  // from_chars does not take a leading '+'
  f.number = q;
  auto res = std::from_chars(q, end, f.value);
  const char* fieldEnd = res.ptr;
  const bool closed = !quoted || (res.ec == std::errc() && fieldEnd < end && *fieldEnd++ == '"');
  f.after = fieldEnd;
  if (f.after - p > static_cast<std::ptrdiff_t>(limits::kMaxFieldChars)) {
    f.problem = Field::Problem::TooLong;
    return f;
  }
  while (f.after < end && (*f.after == ' ' || *f.after == '\t' || *f.after == '\r')) ++f.after;
  const bool separated = f.after == end || (sep.blanks ? f.after > fieldEnd : *f.after == sep.c);
  if (res.ec == std::errc() && closed && separated && std::isfinite(f.value)) return f;
  const char* stop = p;
  while (stop < end && !sep.at(*stop) && *stop != '\r') ++stop;
  f.text = limits::echo(std::string_view(p, static_cast<std::size_t>(stop - p)));
  f.problem = res.ec == std::errc::result_out_of_range ? Field::Problem::OutOfRange
              : f.text.empty()                          ? Field::Problem::Empty
                                                        : Field::Problem::NotNumber;
  return f;
}

/// readField for a column that must hold a number: throws with line/column context (and a hint
/// for a field of another separator, a decimal comma or a clock time) when it does not.
inline Field numberField(const char* p, const char* end, const Column& col, const Separator& sep,
                         const std::string& source, std::size_t line) {
  Field f = readField(p, end, sep);
  if (!f.ok())
    fail(source, line, f.why(col) + (f.problem == Field::Problem::NotNumber ? fieldHint(f.text, sep) : ""));
  return f;
}

inline const char* parseField(const char* p, const char* end, double& value, const Column& col,
                              const Separator& sep, const std::string& source, std::size_t line) {
  const Field f = numberField(p, end, col, sep, source, line);
  value = f.value;
  return f.after;
}

/// 1 / (the unit in seconds) of ms, us, ns.
double unitFactor(const std::string& unit) { return 1.0 / parseUnit(unit).si; }

/// The unit, of ms, us and ns, in which time stamps whose rate read in seconds is `rate` [Hz] give
/// an IMU's rate (1 Hz to limits::kMaxRate); nullptr when none does.
const char* timeUnitRead(double rate) {
  for (const char* unit : {"ms", "us", "ns"}) {
    const double r = rate * unitFactor(unit);
    if (r >= 1.0 && r <= limits::kMaxRate) return unit;
  }
  return nullptr;
}

/// How to give the time column's unit.
std::string timeUnitAdvice(const std::string& unit) {
  return "in the header (t[" + unit + "]) or in the column mapping (--columns \"t=NAME[" + unit + "]\")";
}

/// For the no-time-column error: a column whose name holds "time" or "stamp" offered as the time
/// column, and the sensor columns' hint when none of them was read either.
std::string noTimeHint(const Record& rec) {
  std::size_t time = rec.aux.size();
  for (std::size_t i = 0; i < rec.aux.size() && time == rec.aux.size(); ++i) {
    const std::string n = lowered(rec.aux[i].name);
    if (n.find("time") != std::string::npos || n.find("stamp") != std::string::npos) time = i;
  }
  bool sensors = false;
  for (int i = 0; i < 3; ++i) sensors = sensors || rec.hasGyro(i) || rec.hasAccel(i);
  if (time == rec.aux.size())
    return sensors ? "" : "; no sensor column was read either: " + sensorColumnsHint(rec);
  const std::string t = "t=" + rec.aux[time].name + "[s]";
  if (!sensors && rec.aux.size() == 7) {  // a time and six others: all mapped in their order
    std::string mapping = t;
    for (std::size_t i = 0, k = 0; i < 7; ++i)
      if (i != time) mapping += std::string(",") + kSensorColumns[k++] + "=" + rec.aux[i].name;
    return "; nor a sensor column: the file's columns are " + rec.aux[0].name + ", ..., " +
           rec.aux[6].name + "; in their order they would read --columns \"" + mapping +
           "\" (check the order; give the units in brackets: [ms], [deg/s], [g])";
  }
  std::string hint = "; the file's column \"" + rec.aux[time].name + "\" may be it: --columns \"" + t +
                     "\" (with its unit: s, ms, us or ns)";
  if (!sensors)  // not sensorColumnsHint: its six-in-order mapping would take the time column too
    hint += "; no sensor column was read either: name them gx gy gz ax ay az in the header or map "
            "them beside it: --columns \"" + t + ",gx=NAME,...,az=NAME\"";
  return hint;
}

/// The record's lines in order: comment and blank lines, the header (or, without one, the first
/// data row), then the rows, each parsed into its columns as it comes -- so that a file is read
/// in chunks and its text never held whole.
class RowReader {
 public:
  RowReader(std::string source, const RecordOptions& options) : source_(std::move(source)), options_(options) {
    if (options.rate_hz) detail::checkRate(*options.rate_hz, source_, "the rate option (--rate)");
    // A unit option is the user's, not the file's: named as the option, before a line is read
    // (`--gyro-unit dps` was "rec.csv:1: column "gx": unknown unit").
    const struct {
      const std::optional<std::string>& unit;
      const char* option;
      Dimension dim;
    } unitOptions[] = {{options.gyro_unit, "the gyro unit option (--gyro-unit)", Dimension::angularRate()},
                       {options.accel_unit, "the accelerometer unit option (--accel-unit)", Dimension::acceleration()}};
    for (const auto& u : unitOptions) {
      if (!u.unit) continue;
      Dimension dim;
      try {
        dim = parseUnit(splitUnitFactor(*u.unit).second).dim;
      } catch (const InputError& e) {
        fail(source_, 0, std::string(u.option) + ": " + e.text());
      }
      if (dim != u.dim)
        fail(source_, 0, std::string(u.option) + " \"" + *u.unit + "\": unit has dimension " + dim.siUnit() +
                             ", expected " + u.dim.siUnit() + " (e.g. " + exampleUnit(u.dim) + ")");
    }
    if (!(std::isfinite(options.time_tolerance) && options.time_tolerance > 0))
      fail(source_, 0, "time tolerance must be positive");
    if (!(std::isfinite(options.skip_s) && options.skip_s >= 0))
      fail(source_, 0, "skip: expected a non-negative time, got " + limits::fmt(options.skip_s));
    if (options.duration_s && !(std::isfinite(*options.duration_s) && *options.duration_s > 0))
      fail(source_, 0, "duration: expected a positive time, got " + limits::fmt(*options.duration_s));
  }

  /// One line (without its '\n'), numbered from 1.
  void line(std::string_view l, std::size_t number) {
    // A UTF-8 byte-order mark (spreadsheet exports) is not part of the first column's name.
    if (number == 1 && l.substr(0, 3) == "\xEF\xBB\xBF") l.remove_prefix(3);
    if (cols_.empty()) return header(l, number);
    // Blank lines are allowed only at the end of the file.
    if (trimmed(l).empty()) {
      if (blankAt_ == 0) blankAt_ = number;
      return;
    }
    if (blankAt_ != 0) fail(source_, blankAt_, "empty row inside the data");
    rows_ == 0 ? firstRow(l, number) : row(l, number);
  }

  Record finish() {
    if (cols_.empty()) fail(source_, 0, "empty file: no header line and no data");
    if (rows_ == 0) fail(source_, headerLine_, "no data rows after the header");
    Record rec;
    rec.source = source_;
    rec.rows = rows_;
    for (std::size_t c = 0; c < cols_.size(); ++c) {
      if (!cols_[c].leftOut.empty()) {
        rec.notes.push_back(cols_[c].leftOut);
        continue;
      }
      store(rec, cols_[c], std::move(data_[c]));
    }
    if (!rec.t.empty()) {
      detail::checkTime(rec, headerLine_ + 1, options_);
      if (const char* unit = timeUnitRead(rec.rate_hz); unit && rec.rate_hz < limits::kMinRate)
        detail::checkRate(rec.rate_hz, source_, "the time stamps' rate",
                          "; read in " + std::string(unit) + " it would be " +
                              limits::fmt(rec.rate_hz * unitFactor(unit)) + " Hz: write the unit " +
                              timeUnitAdvice(unit));
    } else {
      if (!options_.rate_hz)
        fail(source_, 0,
             "the file has no time column (t): give the sample rate (--rate), or name its time column in "
             "the column mapping (--columns \"t=NAME[s]\")" + noTimeHint(rec));
      rec.rate_hz = *options_.rate_hz;
    }
    detail::checkRate(rec.rate_hz, source_, rec.t.empty() ? "the given sample rate" : "the time stamps' rate");
    detail::applyWindow(rec, options_);
    return rec;
  }

 private:
  /// Comment and blank lines before the header are skipped; without a header (a numbered column
  /// mapping) the first data row names the columns "column 1", ... and is read as a row too.
  void header(std::string_view raw, std::size_t number) {
    const std::string_view l = trimmed(raw);
    if (raw.find('\0') != std::string_view::npos || raw.substr(0, 2) == "\xFF\xFE" || raw.substr(0, 2) == "\xFE\xFF")
      fail(source_, number,
           "the file is UTF-16 text (NUL bytes; a spreadsheet's \"Unicode text\" export): save it as "
           "UTF-8 or ASCII CSV (iconv -f UTF-16 -t UTF-8 in.csv > out.csv)");
    if (l.find('\r') != std::string_view::npos) failCrLineEnds(source_, number);
    if (l.empty() || l.front() == '#') return;
    const bool noHeader = headerless(options_.columns);
    headerLine_ = noHeader ? number - 1 : number;
    sep_ = options_.separator ? *options_.separator : detectSeparator(l);
    std::vector<std::string_view> fields = splitHeader(l, sep_);
    // A separator ending the line (a logger's "t,gx,gy,") names no column; quotes around a name
    // ("gx", as spreadsheets write them) are not part of it.
    if (!sep_.blanks && fields.size() > 1 && fields.back().empty()) fields.pop_back();
    for (std::string_view& f : fields)
      if (f.size() >= 2 && f.front() == '"' && f.back() == '"') f = trimmed(f.substr(1, f.size() - 2));
    std::vector<std::string> numbered;
    if (noHeader) {
      for (std::size_t i = 0; i < fields.size(); ++i) numbered.push_back(std::to_string(i + 1));
      fields.assign(numbered.begin(), numbered.end());
    }
    cols_ = parseHeader(fields, source_, number, options_);
    if (noHeader)
      for (Column& c : cols_) c.header = "column " + c.header;
    data_.resize(cols_.size());
    for (const Column& col : cols_) hasSensor_ = hasSensor_ || col.role == Role::Gyro || col.role == Role::Accel;
    if (noHeader) row(raw, number);
  }

  /// The first row after the header, with a clearer message when it holds no number at all: a
  /// second header line (a units row).
  void firstRow(std::string_view l, std::size_t number) {
    try {
      row(l, number);
    } catch (const InputError&) {
      for (std::string_view f : splitHeader(trimmed(l), sep_)) {
        double v;
        const char* b = f.data() + (!f.empty() && f.front() == '+');
        if (std::from_chars(b, f.data() + f.size(), v).ec == std::errc()) throw;
      }
      fail(source_, number,
           "the line after the header holds no number: a second header line (units?); write units "
           "in brackets in the header (gx[deg/s], t[ms]) or give them as options (--gyro-unit, "
           "--accel-unit), and remove the line");
    }
  }

  void row(std::string_view l, std::size_t number) {
    const std::size_t ncol = cols_.size();
    if ((rows_ + 1) > limits::kMaxRecordCells / ncol)
      fail(source_, number, "record too large: more than " + std::to_string(limits::kMaxRecordCells) +
                                " values in rows of " + std::to_string(ncol) + " columns (docs/limits.md)");
    const char* q = l.data();
    const char* const eol = q + l.size();
    for (std::size_t c = 0; c < ncol; ++c) {
      if (q >= eol && c > 0 && !optional(cols_[c]))
        fail(source_, number, "short row: " + std::to_string(c) + " field(s), the header has " + std::to_string(ncol));
      double v;
      if (optional(cols_[c])) {
        q = auxField(q, eol, c, number);
      } else if (cols_[c].role == Role::Time) {
        q = timeField(q, eol, c, number);
      } else {
        q = parseField(q, eol, v, cols_[c], sep_, source_, number);
        push(c, v, number);
      }
      if (c + 1 < ncol) {
        if (q >= eol && !optional(cols_[c + 1]))
          fail(source_, number,
               "short row: " + std::to_string(c + 1) + " field(s), the header has " + std::to_string(ncol));
        if (!sep_.blanks && q < eol) ++q;  // the separator (blanks were skipped by parseField)
      }
    }
    // One separator ending the row (a logger's "0.01,0.02,") holds no field.
    if (!sep_.blanks && q < eol && *q == sep_.c && trimmed(std::string_view(q + 1, std::size_t(eol - q - 1))).empty())
      q = eol;
    if (q < eol) fail(source_, number, "long row: more than the " + std::to_string(ncol) + " fields of the header");
    ++rows_;
  }

  /// A column the record can do without: an auxiliary one (nothing reads it) or the temperature,
  /// in a file whose header names a sensor column. Without one (the wrong separator: "t,gx,gy" read
  /// as one column) the first field that is no number is the error, with its hint.
  bool optional(const Column& col) const {
    return hasSensor_ && (col.role == Role::Aux || col.role == Role::Temperature);
  }

  /// A field of such a column c: read as a number, or, when it is not one (a status word, a date,
  /// an empty or missing cell of a slower sensor, a NaN), the column is left out from then on. It
  /// was fatal: `column "status": expected a finite number, got "OK"` for a column nothing reads.
  const char* auxField(const char* q, const char* eol, std::size_t c, std::size_t number) {
    Column& col = cols_[c];
    if (col.leftOut.empty()) {
      const Field f = readField(q, eol, sep_);
      if (f.ok()) {
        push(c, f.value, number);
        return f.after;
      }
      col.leftOut = "line " + std::to_string(number) + ": " + f.why(col) +
                    (col.role == Role::Temperature
                         ? ": the temperature column is left out (the record has none)"
                         : ": not a column sinsim reads, so it is left out of the record");
      data_[c].clear();
      data_[c].shrink_to_fit();
    }
    // Skip the field: to the separator (or past the blanks that end it), as parseField leaves it.
    while (q < eol && (*q == ' ' || *q == '\t')) ++q;
    while (q < eol && !sep_.at(*q) && *q != '\r') ++q;
    while (q < eol && *q == '\r') ++q;
    if (sep_.blanks)
      while (q < eol && sep_.at(*q)) ++q;
    return q;
  }

  /// A time stamp, kept less the first one in the column's unit, read with a 64-bit mantissa: Unix
  /// time in ns (1.7e18) is exact, and its steps keep every digit as doubles.
  const char* timeField(const char* q, const char* eol, std::size_t c, std::size_t number) {
    const Field f = numberField(q, eol, cols_[c], sep_, source_, number);
    long double exact = f.value;
    std::from_chars(f.number, eol, exact);
    if (!tOrigin_) tOrigin_ = exact;
    push(c, static_cast<double>(exact - *tOrigin_), number);
    return f.after;
  }

  /// Appends v to column c. A record within the value limit may still not fit in the memory the
  /// process has (an address-space limit, a small machine): that is said with the file, the line
  /// and what was read, not as std::bad_alloc.
  void push(std::size_t c, double v, std::size_t number) {
    try {
      data_[c].push_back(v);
    } catch (const std::bad_alloc&) {
      data_.clear();
      data_.shrink_to_fit();
      fail(source_, number,
           "the record does not fit in the memory left: " + std::to_string(rows_) + " rows of " +
               std::to_string(cols_.size()) + " columns were read (8 bytes a value) when it ran out");
    }
  }

  /// One column in SI units into its place in the record.
  void store(Record& rec, const Column& col, std::vector<double> v) const {
    v.shrink_to_fit();
    if (col.role == Role::Time) {  // stamps less the first (timeField): the unit's offset is the origin's
      rec.t_origin_s = col.scale * static_cast<double>(tOrigin_.value_or(0.0L)) + col.offset;
      if (col.scale != 1.0)
        for (double& x : v) x = col.scale * x;
    } else if (col.role != Role::Aux && (col.scale != 1.0 || col.offset != 0.0)) {
      for (double& x : v) x = col.scale * x + col.offset;
    }
    // Beyond kMaxQuantity (SI) sums of squares in the statistics overflow to inf and NaN. Time
    // stamps only give steps and a rate, checked by checkTime, whose message names the unit Unix
    // time in ms or ns under a plain `t` needs (1.7e12 "s" was "beyond any sensor").
    if (col.role != Role::Aux && col.role != Role::Time)
      for (std::size_t r = 0; r < v.size(); ++r)
        if (!(std::abs(v[r]) <= limits::kMaxQuantity))
          fail(source_, headerLine_ + 1 + r,
               "column \"" + col.header + "\": value " + limits::fmt(v[r]) +
                   " (SI) is beyond any sensor (|x| <= " + limits::fmt(limits::kMaxQuantity) + "; docs/limits.md)");
    switch (col.role) {
      case Role::Time: rec.t = std::move(v); break;
      case Role::Gyro:
        rec.gyro[col.axis] = std::move(v);
        rec.gyroUnitStated = rec.gyroUnitStated || !col.unit.empty() || options_.gyro_unit.has_value();
        break;
      case Role::Accel: rec.accel[col.axis] = std::move(v); break;
      case Role::Temperature: rec.temperature = std::move(v); break;
      case Role::Aux: rec.aux.push_back({col.header, std::move(v), col.unit}); break;
    }
  }

  std::string source_;
  const RecordOptions& options_;
  std::vector<Column> cols_;
  bool hasSensor_ = false;  // a gyro or accelerometer column among cols_
  Separator sep_;
  std::vector<std::vector<double>> data_;
  std::size_t rows_ = 0, headerLine_ = 0, blankAt_ = 0;
  std::optional<long double> tOrigin_;  // the first time stamp, in the column's unit
};

}  // namespace

Record parseRecord(std::string_view text, const std::string& source, const RecordOptions& options) {
  RowReader reader(source, options);
  std::size_t number = 0;
  for (std::size_t at = 0; at < text.size();) {
    std::size_t eol = text.find('\n', at);
    if (eol == std::string_view::npos) eol = text.size();
    reader.line(text.substr(at, eol - at), ++number);
    at = eol + 1;
    if ((number & 0xffff) == 0) progress::checkpoint("reading " + source, at, text.size(), progress::Count::bytes);
  }
  return reader.finish();
}

namespace {

/// The mean and the sample sd of x (two passes).
std::pair<double, double> meanAndSd(const std::vector<double>& x) {
  double m = 0.0, v = 0.0;
  for (double a : x) m += a;
  m /= double(x.size());
  for (double a : x) v += (a - m) * (a - m);
  return {m, std::sqrt(v / double(x.size()))};
}

}  // namespace

namespace {

/// The accelerometer unit whose reading of a static record's mean |f| (as m/s^2) is gravity within
/// 20 %, the closest first; empty when none is.
std::string accelUnitFor(double f) {
  static const std::pair<const char*, double> kUnits[] = {
      {"g", kStandardGravity}, {"mg", 1e-3 * kStandardGravity}, {"ug", 1e-6 * kStandardGravity},
      {"ft/s^2", 0.3048}, {"Gal", 1e-2}};  // Gal = cm/s^2
  std::string best;
  double closest = std::log(1.2);
  for (const auto& [name, si] : kUnits) {
    const double off = std::fabs(std::log(f * si / kStandardGravity));
    if (off < closest) closest = off, best = name;
  }
  return best;
}

std::string accelWarning(double f) {
  const std::string lead = "accelerometer mean |f| = " + significant(f, 4) +
                           " m/s^2 in a static record (gravity is 9.8 m/s^2): ";
  const std::string unit = accelUnitFor(f);
  if (!unit.empty()) return lead + "did you forget --accel-unit " + unit + "?";
  // Raw counts: gravity is f counts, so one count is about 1000 / f mg (the datasheet's LSB says exactly).
  return lead + "give the file's accelerometer unit (--accel-unit, or in the header: ax[mg]); raw counts " +
         "take their size, about --accel-unit \"" + significant(1e3 / f, 3) +
         " mg\" here (the datasheet's LSB), unless the logger removed gravity";
}

std::string timeWarning(const Record& record) {
  if (record.time_rounding_s > 0.0)
    return "the time stamps are rounded to " + significant(record.time_rounding_s, 3) +
           " s, coarser than the step: read as uniform at " + limits::fmt(record.rate_hz) +
           " Hz, the rate of their span";
  if (record.irregular_count == 0) return "";
  std::size_t gaps = 0;
  for (const TimeIrregularity& i : record.irregularities) gaps += i.gap;
  const TimeIrregularity& first = record.irregularities.front();
  // Gaps counted among the first 1000 listed; jitter alone joins nothing ("(0+ gap(s)) ... the
  // samples either side of a gap joined" on a record without one).
  const bool more = record.irregularities.size() < record.irregular_count;
  const std::string gapText = gaps > 0 ? std::to_string(gaps) + (more ? "+" : "") + " gap(s)"
                              : more  ? "no gap among the first " + std::to_string(record.irregularities.size())
                                      : "no gap";
  return std::to_string(record.irregular_count) + " irregular time step(s) (" + gapText + "), the first at line " +
         std::to_string(first.line) + " (t = " + significant(record.t_origin_s + first.t, 13) + " s, dt = " + significant(first.dt, 4) +
         " s): read as uniform at " + limits::fmt(record.rate_hz) + " Hz (--allow-irregular-time)" +
         (gaps > 0 ? ", the samples either side of a gap joined" : "");
}

/// Auxiliary columns whose header unit says they hold a quantity the record lacks (see
/// recordWarnings), each with the mapping that reads it.
std::vector<std::string> unreadColumnWarnings(const Record& record) {
  std::vector<std::string> out;
  std::size_t gyroAxes = 0, accelAxes = 0;
  for (int i = 0; i < 3; ++i) gyroAxes += record.hasGyro(i), accelAxes += record.hasAccel(i);
  for (const AuxChannel& a : record.aux) {
    if (a.unit.empty()) continue;
    Dimension dim;
    try {
      dim = parseUnit(a.unit).dim;
    } catch (const InputError&) {
      continue;  // a unit of another kind (uT, hPa, ...): a column the record keeps for the user
    }
    struct Kind {
      const char* what;   // the quantity its unit is
      const char* names;  // the header names sinsim reads it under
      const char* key;    // the mapping's quantity
    };
    const std::optional<Kind> kind =
        dim == Dimension::angularRate() && gyroAxes < 3                ? Kind{"an angular rate", "gx (gy, gz)", "gx"}
        : dim == Dimension::acceleration() && accelAxes < 3            ? Kind{"an acceleration", "ax (ay, az)", "ax"}
        : dim == Dimension::temperature() && record.temperature.empty() ? Kind{"a temperature", "temp", "temp"}
        : dim == Dimension::time() && record.t.empty()                 ? Kind{"a time", "t", "t"}
                                                                       : std::optional<Kind>{};
    if (!kind) continue;
    const std::string name(trimmed(std::string_view(a.name).substr(0, a.name.find_first_of("[("))));
    out.push_back("column \"" + a.name + "\" is in " + kind->what + " unit but its name is not one sinsim reads, "
                  "so it is not used; name it " + kind->names + " in the header or map it: --columns \"" +
                  kind->key + "=" + name + "\"");
  }
  return out;
}

}  // namespace

std::vector<std::string> recordWarnings(const Record& record) {
  std::vector<std::string> out;
  if (!record.t.empty() && record.rate_hz < 1.0)
    if (const char* unit = timeUnitRead(record.rate_hz))
      out.push_back("the time stamps give a rate of " + limits::fmt(record.rate_hz) +
                    " Hz read in seconds, slower than an IMU records; if they are in " + unit + " (" +
                    limits::fmt(record.rate_hz * unitFactor(unit)) + " Hz), write the unit " +
                    timeUnitAdvice(unit));
  if (const std::string w = timeWarning(record); !w.empty()) out.push_back(w);
  for (const std::string& n : record.notes) out.push_back(record.source + ": " + n);
  double g2 = 0.0, f2 = 0.0;
  std::vector<double> gyroSd;
  int accelAxes = 0;
  for (int i = 0; i < 3; ++i) {
    if (!record.gyro[i].empty()) {
      const auto [m, sd] = meanAndSd(record.gyro[i]);
      g2 += m * m, gyroSd.push_back(sd);
    }
    if (!record.accel[i].empty()) f2 += std::pow(meanAndSd(record.accel[i]).first, 2), ++accelAxes;
  }
  // |f| of a static record is gravity whatever its attitude; well below it (under 0.5 m/s^2) it is
  // a record whose logger removed gravity, or g read as m/s^2 beside a large bias: unit unknown.
  const double f = std::sqrt(f2);
  if (accelAxes > 0 && f > 0.5 && std::fabs(std::log(f / kStandardGravity)) > std::log(1.2))
    out.push_back(accelWarning(f));
  if (!gyroSd.empty()) {
    std::sort(gyroSd.begin(), gyroSd.end());
    const double w = std::sqrt(g2), sd = gyroSd[gyroSd.size() / 2];
    // The sd alone (a noisy gyro at a high rate reaches 3 deg/s) asks only where no unit was
    // stated: `--gyro-unit deg/s` on a deg/s record was asked whether it was forgotten.
    if (w > 0.5 || (sd > 0.05 && !record.gyroUnitStated))
      out.push_back("gyro mean |w| = " + significant(w, 3) + " rad/s, sample sd " + significant(sd, 3) +
                    " rad/s in a static record (Earth rate is 7.3e-5 rad/s, a gyro's bias and noise "
                    "are degrees per second at most): did you forget --gyro-unit deg/s? (or the file's unit, "
                    "e.g. mrad/s or deg/h: the values alone cannot tell which)");
  }
  for (std::string& w : unreadColumnWarnings(record)) out.push_back(std::move(w));
  return out;
}

bool isConstantChannel(const std::vector<double>& x) {
  return std::adjacent_find(x.begin(), x.end(), std::not_equal_to<>()) == x.end();
}

std::string sensorColumnsHint(const Record& record) {
  const std::size_t n = record.aux.size();
  std::string listed, mapping;
  for (std::size_t i = 0; i < n && i < 8; ++i) listed += (i ? ", " : "") + record.aux[i].name;
  if (n > 8) listed += ", ... (" + std::to_string(n) + " in all)";
  // Six unrecognised columns are mapped in their order; any other count gets a template.
  for (std::size_t i = 0; i < 6; ++i)
    mapping += std::string(i ? "," : "") + kSensorColumns[i] + "=" + (n == 6 ? record.aux[i].name : std::string("NAME"));
  std::string hint = "name the sensor columns gx gy gz ax ay az in the header (a unit in brackets: gx[deg/s])";
  if (listed.empty()) return hint;
  return "the file's other columns: " + listed + "; " + hint + " or map them: --columns \"" + mapping + "\"" +
         (n == 6 ? "" : " (NAME: a header name or a 1-based column number)");
}

Record loadRecord(const std::string& path, const RecordOptions& options) {
  progress::checkpoint("reading " + path);
  RowReader reader(path, options);
  forEachLineOfFile(path, [&](std::string_view l, std::size_t number) { reader.line(l, number); });
  return reader.finish();
}

}  // namespace sinsim::errormodels
