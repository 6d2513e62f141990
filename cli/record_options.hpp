// The options every command that reads a measured record shares (analyze, fit, diagnose, mc
// --measured): the units of its columns, its rate when it has no time column, whether irregular
// time stamps are accepted, its separator and column mapping, and the window of it to use
// (--skip, --duration). One place, so the commands read records alike.
#pragma once

#include <CLI/CLI.hpp>

#include <cmath>
#include <string>

#include "common/error.hpp"
#include "common/limits.hpp"
#include "common/units.hpp"
#include "errormodels/stats/record.hpp"

namespace sinsim::cli {

struct RecordArgs {
  std::string gyroUnit;   // e.g. "deg/s"; empty: from the header, else rad/s
  std::string accelUnit;  // e.g. "g"; empty: from the header, else m/s^2
  std::string rate;       // "100" or "100 Hz"; empty: from the t column
  bool allowIrregular = false;
  std::string delimiter = "auto";
  std::string columns;   // "t=Time[ms],gx=GyroX[deg/s],..."
  std::string skip;      // "10 min"; empty: none
  std::string duration;  // "1 h"; empty: the rest
};

inline void addRecordOptions(CLI::App* c, RecordArgs& r) {
  c->add_option("--gyro-unit", r.gyroUnit, "unit of gx/gy/gz, e.g. deg/s (default: header or rad/s)");
  c->add_option("--accel-unit", r.accelUnit, "unit of ax/ay/az, e.g. g (default: header or m/s^2)");
  c->add_option("--rate", r.rate, "sample rate [Hz] (required without a t column)");
  c->add_flag("--allow-irregular-time", r.allowIrregular,
              "accept irregular/gapped time stamps (reported, never resampled)");
  c->add_option("--delimiter", r.delimiter,
                "field separator: auto (default: from the header), comma, semicolon, whitespace");
  c->add_option("--columns", r.columns,
                "column mapping, e.g. \"t=Time[ms],gx=GyroX[deg/s],...,az=7\" (by header name or "
                "1-based number; only numbers: the file has no header)");
  c->add_option("--skip", r.skip,
                "discard the start of the record, e.g. \"10 min\" (a warm-up); fit also takes auto "
                "(skip a settling the fit finds)");
  c->add_option("--duration", r.duration, "use only this much of the record after --skip, e.g. \"1 h\"");
}

/// The loader's options; a --rate that is not a positive frequency is refused here (the loader
/// checks its range).
inline errormodels::RecordOptions recordOptions(const RecordArgs& r) {
  errormodels::RecordOptions ro;
  if (!r.rate.empty()) {
    const double rate = parseOptionQuantity(r.rate, Dimension::frequency(), "--rate", true);
    if (!(rate > 0.0))
      throw InputError("--rate: expected a positive sample rate, got \"" + limits::echo(r.rate) +
                       "\"");
    ro.rate_hz = rate;
  }
  if (!r.gyroUnit.empty()) ro.gyro_unit = r.gyroUnit;
  if (!r.accelUnit.empty()) ro.accel_unit = r.accelUnit;
  ro.allow_irregular_time = r.allowIrregular;
  ro.separator = errormodels::parseSeparator(r.delimiter);
  if (!r.columns.empty()) ro.columns = errormodels::parseColumnMapping(r.columns);
  if (r.skip == "auto")
    throw InputError("--skip auto: only `sinsim fit` finds a settling to skip; give a time, e.g. \"10 min\"");
  if (!r.skip.empty()) ro.skip_s = parseDuration(r.skip, "--skip");
  if (!r.duration.empty()) {
    ro.duration_s = parseDuration(r.duration, "--duration");
    if (!(*ro.duration_s > 0.0))
      throw OptionError("--duration: expected a positive time, got \"" + limits::echo(r.duration) + "\"");
  }
  return ro;
}

/// The options as a user would type them again (for the "next command" a report suggests):
/// only those given, values quoted when they hold a blank.
inline std::string recordOptionsText(const RecordArgs& r) {
  auto quoted = [](const std::string& v) {
    return v.find_first_of(" \t") == std::string::npos ? v : "\"" + v + "\"";
  };
  std::string s;
  auto add = [&](const char* name, const std::string& v) {
    if (!v.empty()) s += std::string(" ") + name + " " + quoted(v);
  };
  add("--rate", r.rate);
  add("--gyro-unit", r.gyroUnit);
  add("--accel-unit", r.accelUnit);
  if (r.allowIrregular) s += " --allow-irregular-time";
  if (r.delimiter != "auto") add("--delimiter", r.delimiter);
  add("--columns", r.columns);
  add("--skip", r.skip);
  add("--duration", r.duration);
  return s;
}

}  // namespace sinsim::cli
