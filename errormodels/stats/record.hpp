// A measured IMU record read from CSV (plain or gzip): the entry point of the identify path.
//
// File format: optional '#' comment lines, one header line, then one row per sample, fields
// separated by ',', ';' or blanks (detected from the header; record_layout.hpp). Recognised column names (case-insensitive, surrounding blanks ignored):
//   t | time            time stamp            default unit s
//   gx gy gz            angular rate          default unit rad/s  (RecordOptions::gyro_unit)
//   ax ay az            specific force        default unit m/s^2  (RecordOptions::accel_unit)
//   temp | temperature  sensor temperature    default unit degC
// A unit may be written in the header after the name in brackets or parentheses, e.g.
// "gx [deg/s]", "ax (g)", "t[ms]"; it is parsed with sinsim::parseUnit and its dimension checked.
// Every other column is kept, unconverted, as an auxiliary channel (left out, with a Record::notes
// line, when a field of it, or of temp, is no number). Other names are read through
// a column mapping (RecordOptions::columns: "gx=GyroX[deg/s]", or by column number for a file
// without a header). Values are converted to SI once, here; everything downstream is SI.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "errormodels/stats/record_layout.hpp"

namespace sinsim::errormodels {

struct RecordOptions {
  /// Unit of the gx/gy/gz columns ("deg/s", "rad/s", "deg/h", ...). Unset: the header's unit,
  /// else rad/s. Set and different from a unit written in the header: InputError.
  std::optional<std::string> gyro_unit;
  /// Unit of the ax/ay/az columns ("g", "m/s^2", "mg", ...). Unset: the header's unit, else m/s^2.
  std::optional<std::string> accel_unit;
  /// Sample rate [Hz]. Required when the file has no time column; with a time column it must
  /// agree with the time stamps: to 0.1 % with their span's rate when they are regular, to
  /// time_tolerance with their median step otherwise.
  std::optional<double> rate_hz;
  /// A time step is irregular when |dt - dt_nominal| > time_tolerance * dt_nominal. [1]
  double time_tolerance = 0.01;
  /// false: irregular or gapped time stamps are an InputError that says where (default).
  /// true: they are listed in Record::irregularities and the record is returned as read
  /// (never resampled).
  bool allow_irregular_time = false;
  /// Field separator; unset: detected from the header line.
  std::optional<Separator> separator;
  /// Column mapping (parseColumnMapping); empty: the standard names above.
  std::vector<ColumnMap> columns;
  /// [s] Discard this much of the start of the record (e.g. a warm-up). >= 0.
  double skip_s = 0.0;
  /// [s] Keep only this much after the skip; unset: the rest of the record.
  std::optional<double> duration_s;
};

/// One time step that departs from the nominal step (only records with a time column).
struct TimeIrregularity {
  std::size_t line = 0;   ///< 1-based file line of the later sample
  std::size_t row = 0;    ///< 0-based sample index of the later sample
  double t = 0.0;         ///< [s] its time stamp less Record::t_origin_s
  double dt = 0.0;        ///< [s] step from the previous sample
  bool gap = false;       ///< dt > 1.5 nominal steps (missing samples) rather than jitter
};

struct AuxChannel {
  std::string name;            ///< header text as written
  std::vector<double> values;  ///< as in the file, no unit conversion
  std::string unit;            ///< the unit written in the header's brackets; empty when none
};

struct Record {
  std::string source;   ///< file path as given
  double rate_hz = 0;   ///< [Hz] nominal sample rate (option; else from the span of regular time stamps, or 1 / their median step)
  /// [s] time stamps as read, less t_origin_s (empty when the file has no time column: sample k
  /// is at k / rate_hz). Relative, so that Unix time in ns at 100 kHz keeps its steps' digits: as
  /// doubles of ~1.7e9 s the steps of 10 us came out 9.8 or 10.3 us, "irregular".
  std::vector<double> t;
  /// [s] the first time stamp as written (Unix time, say): stamp k is t_origin_s + t[k]
  double t_origin_s = 0.0;
  /// omega_ib_b per axis x, y, z [rad/s]; an axis absent from the file is an empty vector
  std::array<std::vector<double>, 3> gyro;
  /// f_b per axis x, y, z [m/s^2]; an axis absent from the file is an empty vector
  std::array<std::vector<double>, 3> accel;
  /// A gyro column's unit was written in its header or given (--gyro-unit): recordWarnings then
  /// does not ask whether it was forgotten.
  bool gyroUnitStated = false;
  /// [K] sensor temperature; empty when absent
  std::vector<double> temperature;
  std::vector<AuxChannel> aux;
  /// What the reader left out and why (an auxiliary column holding text), as recordWarnings says it.
  std::vector<std::string> notes;
  /// Irregular steps (filled only with RecordOptions::allow_irregular_time; at most 1000 kept)
  std::vector<TimeIrregularity> irregularities;
  std::size_t irregular_count = 0;  ///< total number of irregular steps found
  /// [s] > 0: the time stamps are a uniform grid rounded to this (steps of two values, e.g. 2 and
  /// 3 ms at 400 Hz), read as uniform at the rate of their span
  double time_rounding_s = 0.0;
  std::size_t rows = 0;             ///< number of samples
  /// [s] the file's start dropped by RecordOptions::skip_s (what a message's "--skip" counts from)
  double skipped_s = 0.0;

  std::size_t size() const { return rows; }
  double duration() const { return rows / rate_hz; }  ///< [s] rows times the nominal step
  bool hasGyro(int axis) const { return !gyro[axis].empty(); }
  bool hasAccel(int axis) const { return !accel[axis].empty(); }
};

/// Reads a CSV record; a path ending in ".gz" (or any gzip stream) is decompressed on the fly
/// with zlib. Throws sinsim::InputError naming the file and line for: a missing/unreadable
/// file, no header or no data rows, duplicate or unknown-unit columns, a row with too few or too
/// many fields, a field that is not a finite number (text, NaN, inf, empty), time stamps that do
/// not increase, and (unless allowed) irregular or gapped time stamps.
Record loadRecord(const std::string& path, const RecordOptions& options = {});

/// What to do when `record` lacks sensor columns a command needs, to end its error message: the
/// file's unrecognised columns and a column mapping of them to try, e.g. "the file's other
/// columns: gyro_x, gyro_y, gyro_z; name the sensor columns gx gy gz ax ay az in the header (a unit
/// in brackets: gx[deg/s]) or map them: --columns \"gx=gyro_x,gy=gyro_y,gz=gyro_z\"".
std::string sensorColumnsHint(const Record& record);

/// True when every sample of a channel has the same value (a dead or unconnected sensor): compared
/// exactly, not through a variance, whose mean removal leaves ~1e-34 for a constant 0.1 deg/s.
bool isConstantChannel(const std::vector<double>& x);

/// Warnings on how a static record was read, empty when nothing looks wrong:
///  - time: stamps that read as slower than 1 Hz in seconds (ms or us written as s?); stamps
///    rounded coarser than the step, read as uniform at their span's rate; irregular steps or
///    gaps read as uniform (RecordOptions::allow_irregular_time).
///  - units: a static accelerometer reads |f| = g whatever its attitude, so a mean norm more than
///    20 % off 9.8 "m/s^2" (above 0.5: below, the logger may have removed gravity) names the unit
///    (g, mg, ug, ft/s^2, Gal) whose reading is gravity, or asks for it; a static gyro reads Earth
///    rate (7.3e-5 rad/s) plus a bias of degrees per second at most, with a sample sd well below
///    1 deg/s, so means of norm above 0.5 "rad/s" or a median sample sd above 0.05 "rad/s" are
///    another unit read as rad/s (deg/s the likeliest; the values cannot tell mrad/s or deg/h).
///  - columns: a column whose name is not read (kept as auxiliary) but whose header unit is an
///    angular rate, an acceleration, a temperature or a time, while the record lacks that quantity
///    (an axis of it): "gyro_x [deg/s]" beside no gx; it is named with the mapping that reads it.
/// Over the channels present.
std::vector<std::string> recordWarnings(const Record& record);

/// The same parser on text already in memory; `source` names it in messages.
Record parseRecord(std::string_view text, const std::string& source,
                   const RecordOptions& options = {});

}  // namespace sinsim::errormodels
