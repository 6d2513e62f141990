// CSV / gzip record loading: conversions, every kind of bad input, and the real ADIS16405 file.
#include <catch2/catch.hpp>

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "common/constants.hpp"
#include "common/error.hpp"
#include "errormodels/stats/record.hpp"

using namespace sinsim::errormodels;
namespace fs = std::filesystem;

namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr double kG = 9.80665;

/// Catches the InputError of parsing `text` and returns its message.
std::string errorOf(const std::string& text, const RecordOptions& opt = {}) {
  try {
    parseRecord(text, "rec.csv", opt);
  } catch (const sinsim::InputError& e) {
    return e.what();
  }
  FAIL("no InputError for:\n" << text);
  return {};
}

fs::path tempPath(const std::string& name) {
  return fs::temp_directory_path() / ("sinsim_test_stats_" + std::to_string(::getpid()) + "_" + name);
}

}  // namespace

TEST_CASE("record: columns, header units, options and conversion to SI", "[record]") {
  const std::string text =
      "# a comment line before the header\n"
      "t [ms], gx, gy, gz, ax (g), ay (g), az (g), temp, counter\n"
      "0, 1, 2, 3, 0, 0, -1, 25, 7\n"
      "10, 1.5, -2e-1, +3, 0.5, 0, -1.0, 26.5, 8\r\n"
      "20, 0, 0, 0, 0, 0, -1, 27, 9\n"
      "\n";
  RecordOptions opt;
  opt.gyro_unit = "deg/s";
  const Record r = parseRecord(text, "rec.csv", opt);
  REQUIRE(r.size() == 3);
  CHECK(r.rate_hz == Approx(100.0));  // 10 ms steps
  CHECK(r.t[1] == Approx(0.010));
  CHECK(r.gyro[0][1] == Approx(1.5 * kDeg));
  CHECK(r.gyro[1][1] == Approx(-0.2 * kDeg));
  CHECK(r.gyro[2][1] == Approx(3 * kDeg));  // leading '+'
  CHECK(r.accel[0][1] == Approx(0.5 * kG));
  CHECK(r.accel[2][0] == Approx(-kG));
  CHECK(r.temperature[0] == Approx(298.15));  // degC -> K
  REQUIRE(r.aux.size() == 1);
  CHECK(r.aux[0].name == "counter");
  CHECK(r.aux[0].values[2] == 9.0);
  CHECK(r.irregular_count == 0);
}

TEST_CASE("record: the rate of regular time stamps comes from their span, not from one step's digits",
          "[record]") {
  // 104 Hz for 20 min with the time printed to the microsecond (%.6f) and to 12 significant
  // digits (%.12g): one step read from the text is 1e-7..1e-4 off the true 1/104 s (the median
  // step read 104.000004 Hz with %.12g), and a model's AR defined at 104 Hz was refused as slower
  // than the record (an independent generator's records). The span (n - 1) / (t_last - t_first)
  // has the digits' error divided by the record's length.
  for (const char* fmt : {"%.6f", "%.12g"}) {
    std::string text = "t,gx,gy,gz,ax,ay,az\n";
    char buf[64];
    for (int k = 1; k <= 124800; ++k) {
      std::snprintf(buf, sizeof buf, fmt, k / 104.0);
      text += std::string(buf) + ",0,0,0,0,0,-9.8\n";
    }
    const Record r = parseRecord(text, "rec.csv", {});
    INFO(fmt);
    CHECK(std::abs(r.rate_hz / 104.0 - 1.0) < 1e-9);
  }
}

TEST_CASE("record: no time column needs a rate, defaults are SI", "[record]") {
  const std::string text = "gx,gy,gz\n0.1,0.2,0.3\n0.1,0.2,0.3\n";
  CHECK_THAT(errorOf(text), Catch::Contains("no time column") && Catch::Contains("rec.csv"));
  RecordOptions opt;
  opt.rate_hz = 200.0;
  const Record r = parseRecord(text, "rec.csv", opt);
  CHECK(r.rate_hz == 200.0);
  CHECK(r.gyro[1][0] == 0.2);  // rad/s by default: untouched
  CHECK(r.t.empty());
  CHECK_FALSE(r.hasAccel(0));
  CHECK(r.duration() == Approx(0.01));
}

TEST_CASE("record: bad rows name the file and the line", "[record]") {
  RecordOptions opt;
  opt.rate_hz = 1.0;
  const std::string head = "gx,gy,gz\n1,2,3\n";
  CHECK_THAT(errorOf(head + "1,nan,3\n", opt), Catch::Contains("rec.csv:3") && Catch::Contains("\"gy\"") && Catch::Contains("nan"));
  CHECK_THAT(errorOf(head + "1,abc,3\n", opt), Catch::Contains("rec.csv:3") && Catch::Contains("abc"));
  CHECK_THAT(errorOf(head + "1,2\n", opt), Catch::Contains("rec.csv:3") && Catch::Contains("short row"));
  CHECK_THAT(errorOf(head + "1,2,3,4\n", opt), Catch::Contains("rec.csv:3") && Catch::Contains("long row"));
  CHECK_THAT(errorOf(head + "1,,3\n", opt), Catch::Contains("rec.csv:3") && Catch::Contains("empty field"));
  CHECK_THAT(errorOf(head + "1,2,inf\n", opt), Catch::Contains("rec.csv:3"));
  CHECK_THAT(errorOf(head + "1,2,3 4\n", opt), Catch::Contains("rec.csv:3"));
  CHECK_THAT(errorOf(head + "\n1,2,3\n", opt), Catch::Contains("rec.csv:3") && Catch::Contains("empty row"));
  CHECK_THAT(errorOf(head + "1,2,1e999\n", opt), Catch::Contains("rec.csv:3") && Catch::Contains("range"));
  CHECK_THAT(errorOf("", opt), Catch::Contains("empty file"));
  CHECK_THAT(errorOf("# only a comment\n\n", opt), Catch::Contains("empty file"));
  CHECK_THAT(errorOf("gx,gy,gz\n", opt), Catch::Contains("rec.csv:1") && Catch::Contains("no data rows"));
}

TEST_CASE("record: header problems", "[record]") {
  RecordOptions opt;
  opt.rate_hz = 1.0;
  CHECK_THAT(errorOf("gx,GX\n1,2\n", opt), Catch::Contains("same quantity"));
  CHECK_THAT(errorOf("gx [m/s],gy\n1,2\n", opt), Catch::Contains("dimension"));
  CHECK_THAT(errorOf("gx [furlong],gy\n1,2\n", opt), Catch::Contains("gx [furlong]"));
  CHECK_THAT(errorOf("gx,,gz\n1,2,3\n", opt), Catch::Contains("no name"));
  opt.gyro_unit = "rad/s";
  CHECK_THAT(errorOf("gx [deg/s]\n1\n", opt), Catch::Contains("unit option"));
  opt.gyro_unit = "m/s^2";
  CHECK_THAT(errorOf("gx\n1\n", opt), Catch::Contains("dimension"));
}

TEST_CASE("record: irregular and gapped time stamps are reported, not resampled", "[record]") {
  const std::string text = "t,gx\n0,0\n0.01,0\n0.02,0\n0.05,0\n0.06,0\n0.0705,0\n0.08,0\n";
  const std::string msg = errorOf(text);
  // One gap (line 5) and one late sample (line 7), which makes two off-nominal steps.
  CHECK_THAT(msg, Catch::Contains("3 irregular") && Catch::Contains("line 5") &&
                      Catch::Contains("gap") && Catch::Contains("line 7") && Catch::Contains("line 8"));
  RecordOptions opt;
  opt.allow_irregular_time = true;
  const Record r = parseRecord(text, "rec.csv", opt);
  CHECK(r.size() == 7);  // nothing inserted or dropped
  CHECK(r.rate_hz == Approx(100.0));
  REQUIRE(r.irregularities.size() == 3);
  CHECK(r.irregularities[0].line == 5);
  CHECK(r.irregularities[0].gap);
  CHECK(r.irregularities[0].dt == Approx(0.03));
  CHECK_FALSE(r.irregularities[1].gap);
  CHECK_THAT(errorOf("t,gx\n0,0\n0.01,0\n0.01,0\n"), Catch::Contains("rec.csv:4") && Catch::Contains("does not increase"));
  // Stamps finer than a microsecond are printed as given, not as "-0.000000".
  CHECK_THAT(errorOf("t,gx\n-0.0000001,0\n-0.0000002,0\n"),
             Catch::Contains("time stamp -2e-07 s does not increase (previous -1e-07 s)"));
  RecordOptions wrong_rate;
  wrong_rate.rate_hz = 50.0;
  CHECK_THAT(errorOf("t,gx\n0,0\n0.01,0\n0.02,0\n", wrong_rate), Catch::Contains("disagrees"));
}

TEST_CASE("record: a rate option must agree with regular stamps to 0.1 %, and never makes them irregular",
          "[record]") {
  // 1000 stamps exactly 10 ms apart. Before: --rate 100.5 replaced them silently (every tau and a
  // fitted model's rate 0.5 % off); --rate 101 was refused as "999 irregular time step(s)".
  std::string text = "t,gx\n";
  for (int k = 0; k < 1000; ++k) text += std::to_string(k) + "e-2,0\n";
  for (const double rate : {100.5, 101.0, 99.0, 99.85}) {
    RecordOptions o;
    o.rate_hz = rate;
    const std::string msg = errorOf(text, o);
    INFO(rate << ": " << msg);
    CHECK_THAT(msg, Catch::Contains("disagrees with the time stamps (their span gives 100 Hz") &&
                        Catch::Contains("must agree to 0.1 %"));
    CHECK(msg.find("irregular") == std::string::npos);
  }
  for (const double rate : {100.0, 100.05, 99.95}) {  // a nominal rate beside a clock 0.05 % off
    RecordOptions o;
    o.rate_hz = rate;
    CHECK(parseRecord(text, "rec.csv", o).rate_hz == rate);
  }
  CHECK(parseRecord(text, "rec.csv", {}).rate_hz == Approx(100.0).epsilon(1e-12));
}

TEST_CASE("record: after an allowed gap, --skip and --duration cut on the time stamps", "[record]") {
  // 100 Hz, 0..99.99 s with the stamps 20..39.99 s missing (a 20-s gap); gx is the stamp itself.
  // Before: --skip 50 counted 50 s of samples and started at t = 70 s.
  std::string text = "t,gx\n";
  for (int k = 0; k < 10000; ++k)
    if (k < 2000 || k >= 4000) text += std::to_string(k) + "e-2," + std::to_string(k) + "e-2\n";
  RecordOptions o;
  o.allow_irregular_time = true;
  o.skip_s = 50.0;
  o.duration_s = 30.0;
  const Record r = parseRecord(text, "rec.csv", o);
  REQUIRE(r.size() == 3000);
  CHECK(r.gyro[0].front() == Approx(50.0));
  CHECK(r.gyro[0].back() == Approx(79.99));
  CHECK(r.skipped_s == Approx(50.0));
  // A window across the gap keeps the stamps in it; the record spans 100 s, not 80 s of rows.
  o.skip_s = 10.0;
  o.duration_s = 85.0;
  const Record across = parseRecord(text, "rec.csv", o);
  CHECK(across.size() == 6500);  // 10..19.99 s and 40..94.99 s
  CHECK(across.gyro[0].back() == Approx(94.99));
  o.skip_s = 0.0;
  o.duration_s = 101.0;
  CHECK_THAT(errorOf(text, o), Catch::Contains("is longer than the record (100 s)"));
  // Regular stamps: the same windows as counting samples.
  std::string regular = "t,gx\n";
  for (int k = 0; k < 1000; ++k) regular += std::to_string(k) + "e-2," + std::to_string(k) + "\n";
  RecordOptions w;
  w.skip_s = 2.004;
  w.duration_s = 3.0;
  const Record rr = parseRecord(regular, "rec.csv", w);
  CHECK(rr.gyro[0].front() == 200.0);
  CHECK(rr.size() == 300);
}

TEST_CASE("record: a column nothing reads that holds text, a blank or a NaN is left out and said", "[record]") {
  // Before: `column "status": expected a finite number, got "OK"`, the whole record refused for a
  // column no statistic reads; the same for a slower magnetometer's empty cells and a NaN in temp.
  const std::string text =
      "t,gx,status,date,mx,temp\n"
      "0,0.5,OK,2026-12-07T06:00:00,1.5,25\n"
      "0.01,0.25,OK,2026-12-07T06:00:00.01,,25.1\n"
      "0.02,0.75,LOW,2026-12-07T06:00:00.02,1.6,nan\n"
      "0.03,0.5,OK,2026-12-07T06:00:00.03\n";
  const Record r = parseRecord(text, "rec.csv", {});
  REQUIRE(r.size() == 4);
  CHECK(r.gyro[0] == std::vector<double>{0.5, 0.25, 0.75, 0.5});
  CHECK(r.aux.empty());
  CHECK(r.temperature.empty());
  REQUIRE(r.notes.size() == 4);
  CHECK(r.notes[0] == "line 2: column \"status\": expected a finite number, got \"OK\": not a column sinsim reads, "
                      "so it is left out of the record");
  CHECK_THAT(r.notes[1], Catch::Contains("line 2: column \"date\": expected a finite number, got \"2026-12-07T06:00:00\""));
  CHECK_THAT(r.notes[2], Catch::Contains("line 3: column \"mx\": empty field"));
  CHECK_THAT(r.notes[3], Catch::Contains("line 4: column \"temp\"") && Catch::Contains("the temperature column is left out"));
  const auto warnings = recordWarnings(r);
  CHECK(std::count_if(warnings.begin(), warnings.end(),
                      [](const std::string& w) { return w.rfind("rec.csv: line ", 0) == 0; }) == 4);
  // A sensor column is never left out, and a numeric extra column is kept.
  CHECK_THAT(errorOf("t,gx,status\n0,OK,1\n0.01,0.5,1\n"), Catch::Contains("rec.csv:2: column \"gx\""));
  CHECK(parseRecord("t,gx,counter\n0,1,7\n0.01,1,8\n", "rec.csv", {}).aux.at(0).values == std::vector<double>{7, 8});
}

TEST_CASE("record: gzip files are read directly, missing or truncated files are errors", "[record]") {
  const std::string text = "gx,gy,gz,ax,ay,az\n0.05,-0.1,0,0.003,0,-1.016\n0.1,0,0,0,0,-1\n";
  const fs::path gz = tempPath("rec.csv.gz");
  {
    gzFile f = gzopen(gz.string().c_str(), "wb");
    REQUIRE(f != nullptr);
    gzwrite(f, text.data(), static_cast<unsigned>(text.size()));
    gzclose(f);
  }
  RecordOptions opt;
  opt.rate_hz = 100;
  opt.gyro_unit = "deg/s";
  opt.accel_unit = "g";
  const Record r = loadRecord(gz.string(), opt);
  const Record p = parseRecord(text, "mem", opt);
  CHECK(r.size() == 2);
  CHECK(r.gyro[0] == p.gyro[0]);
  CHECK(r.accel[2][0] == Approx(-1.016 * kG));
  CHECK(r.source == gz.string());
  // Truncated stream: zlib reports "unexpected end of file".
  const auto size = fs::file_size(gz);
  fs::resize_file(gz, size - 6);
  CHECK_THROWS_AS(loadRecord(gz.string(), opt), sinsim::InputError);
  fs::remove(gz);
  CHECK_THAT([&] {
    try {
      loadRecord("/nonexistent/dir/x.csv", opt);
    } catch (const sinsim::InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  }(), Catch::Contains("/nonexistent/dir/x.csv") && Catch::Contains("cannot open"));
}

// The file is read in chunks of 4 MiB and parsed line by line as it comes (loadRecord); its
// lines straddle the chunks. A record of ~10 MB (plain and gzip, LF and CRLF, a comment and a BOM
// before the header, blank lines at the end) must give exactly what parseRecord gives on the
// whole text, and an empty row inside the data must still fail at its own line.
TEST_CASE("record: a file read in chunks equals the text parsed whole", "[record]") {
  for (const std::string eol : {"\n", "\r\n"}) {
    std::string text = "\xEF\xBB\xBF# a comment\nt [s],gx [deg/s],ax [g],temp [degC]" + eol;
    char row[160];
    for (int k = 0; k < 250000; ++k) {
      std::snprintf(row, sizeof row, "%.3f,%.9f,%.9f,%.4f", k * 0.01, std::sin(0.37 * k) * 1e-3,
                    -1.0 + 1e-4 * std::cos(0.11 * k), 25.0 + 1e-5 * k);
      text += row + eol;
    }
    text += eol + eol;
    REQUIRE(text.size() > 2 * (std::size_t{1} << 22));
    const fs::path plain = tempPath("chunks.csv"), gz = tempPath("chunks.csv.gz");
    {
      std::ofstream(plain, std::ios::binary) << text;
      gzFile f = gzopen(gz.string().c_str(), "wb1");
      REQUIRE(f != nullptr);
      gzwrite(f, text.data(), static_cast<unsigned>(text.size()));
      gzclose(f);
    }
    const Record whole = parseRecord(text, "mem");
    REQUIRE(whole.size() == 250000);
    for (const fs::path& path : {plain, gz}) {
      const Record r = loadRecord(path.string());
      CHECK(r.size() == whole.size());
      CHECK(r.t == whole.t);
      CHECK(r.gyro[0] == whole.gyro[0]);
      CHECK(r.accel[0] == whole.accel[0]);
      CHECK(r.temperature == whole.temperature);
    }
    // an empty row in the middle (line 70002: the comment and the header come first)
    std::string holed = text;
    std::size_t at = 0;
    for (int k = 0; k < 70001; ++k) at = holed.find('\n', at) + 1;
    holed.insert(at, eol);
    std::ofstream(plain, std::ios::binary | std::ios::trunc) << holed;
    const std::string msg = [&] {
      try {
        loadRecord(plain.string());
      } catch (const sinsim::InputError& e) {
        return std::string(e.what());
      }
      return std::string();
    }();
    CHECK_THAT(msg, Catch::Contains("chunks.csv:70002") && Catch::Contains("empty row inside the data"));
    fs::remove(plain);
    fs::remove(gz);
  }
}

TEST_CASE("record: the ADIS16405 run 1 file", "[record][real]") {
  // Data README: 1,000,000 rows, 100 Hz, deg/s and g; gyro means ~ +0.40 / -0.42 / -0.29 deg/s,
  // z accel ~ -1.016 g. The means are quoted to 2 digits, hence +-0.01 deg/s and +-0.002 g.
  RecordOptions opt;
  opt.rate_hz = 100;
  opt.gyro_unit = "deg/s";
  opt.accel_unit = "g";
  const Record r = loadRecord(std::string(SINSIM_SHARED_DIR) + "/data/adis16405/run1.csv.gz", opt);
  REQUIRE(r.size() == 1000000);
  CHECK(r.duration() == Approx(10000.0));
  auto mean = [](const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return s / v.size();
  };
  CHECK(mean(r.gyro[0]) / kDeg == Approx(0.40).margin(0.01));
  CHECK(mean(r.gyro[1]) / kDeg == Approx(-0.42).margin(0.01));
  CHECK(mean(r.gyro[2]) / kDeg == Approx(-0.29).margin(0.01));
  CHECK(mean(r.accel[2]) / kG == Approx(-1.016).margin(0.002));
  CHECK(r.aux.empty());
}

TEST_CASE("a record without sensor columns: the hint lists its columns and a mapping that reads them",
          "[record]") {
  const std::string text = "gyro_x,gyro_y,gyro_z,acc_x,acc_y,acc_z\n1,2,3,4,5,6\n1,2,3,4,5,6\n";
  RecordOptions o;
  o.rate_hz = 100.0;
  const Record r = parseRecord(text, "imu.csv", o);
  CHECK_FALSE(r.hasGyro(0));
  const std::string hint = sensorColumnsHint(r);
  CHECK(hint.find("other columns: gyro_x, gyro_y, gyro_z, acc_x, acc_y, acc_z") != std::string::npos);
  // The suggested mapping, given back as --columns, reads the six channels in the file's order.
  const std::size_t at = hint.find("--columns \"");
  REQUIRE(at != std::string::npos);
  const std::size_t from = at + 11, to = hint.find('"', from);
  o.columns = parseColumnMapping(hint.substr(from, to - from));
  const Record mapped = parseRecord(text, "imu.csv", o);
  for (int k = 0; k < 3; ++k) {
    REQUIRE(mapped.hasGyro(k));
    REQUIRE(mapped.hasAccel(k));
    CHECK(mapped.gyro[k][0] == Approx(1.0 + k));
    CHECK(mapped.accel[k][0] == Approx(4.0 + k));
  }
  // Seven columns (a time stamp first): a template, not a guess.
  RecordOptions plain;
  plain.rate_hz = 100.0;
  const std::string seven = sensorColumnsHint(parseRecord("stamp,wx,wy,wz,fx,fy,fz\n0,1,2,3,4,5,6\n", "imu.csv", plain));
  CHECK(seven.find("other columns: stamp, wx, wy, wz, fx, fy, fz") != std::string::npos);
  CHECK(seven.find("--columns \"gx=NAME,gy=NAME,gz=NAME,ax=NAME,ay=NAME,az=NAME\"") != std::string::npos);
  CHECK(seven.find("gx=stamp") == std::string::npos);
}

TEST_CASE("record: a static record's units that look forgotten are named", "[record][units]") {
  // 200 rows of a static IMU as an ADIS16405 writes it: gyro in deg/s (offsets 0.43, -0.40, -0.26,
  // alternating +-0.35 about them), accelerometer in g (az = -1.0).
  std::string text = "gx,gy,gz,ax,ay,az\n";
  for (int k = 0; k < 200; ++k) {
    const double s = k % 2 ? 0.35 : -0.35;
    text += std::to_string(0.43 + s) + "," + std::to_string(-0.40 - s) + "," + std::to_string(-0.26 + s) +
            "," + std::to_string(0.001 * s) + ",0.002,-1.0\n";
  }
  RecordOptions o;
  o.rate_hz = 100.0;
  auto has = [](const std::vector<std::string>& w, const std::string& what) {
    for (const std::string& x : w)
      if (x.find(what) != std::string::npos) return true;
    return false;
  };
  const auto raw = recordWarnings(parseRecord(text, "adis.csv", o));
  CHECK(raw.size() == 2);
  CHECK(has(raw, "accelerometer mean |f| = 1 m/s^2 in a static record (gravity is 9.8 m/s^2): did you forget --accel-unit g?"));
  CHECK(has(raw, "gyro mean |w| = 0.642 rad/s, sample sd 0.35 rad/s"));
  CHECK(has(raw, "did you forget --gyro-unit deg/s?"));
  o.gyro_unit = "deg/s";
  o.accel_unit = "g";
  CHECK(recordWarnings(parseRecord(text, "adis.csv", o)).empty());
  // A gyro-only record in rad/s of a real MEMS (bias 0.01 rad/s, sd 0.005 rad/s): nothing.
  std::string mems = "gx\n";
  for (int k = 0; k < 100; ++k) mems += std::to_string(0.01 + (k % 2 ? 0.005 : -0.005)) + "\n";
  CHECK(recordWarnings(parseRecord(mems, "mems.csv", o)).empty());
  // A noisy gyro (sd 3.4 deg/s = 0.059 rad/s) with its unit stated, by the option or the header:
  // the sd alone asked "did you forget --gyro-unit deg/s?" (helper-17); unstated it still asks.
  std::string noisy = "gx\n";
  for (int k = 0; k < 100; ++k) noisy += std::string(k % 2 ? "3.4" : "-3.4") + "\n";
  CHECK(recordWarnings(parseRecord(noisy, "noisy.csv", o)).empty());
  RecordOptions bare;
  bare.rate_hz = 100.0;
  CHECK(recordWarnings(parseRecord("gx [deg/s]" + noisy.substr(2), "noisy.csv", bare)).empty());
  CHECK(has(recordWarnings(parseRecord(noisy, "noisy.csv", bare)), "did you forget --gyro-unit deg/s?"));
}

TEST_CASE("record: an accelerometer in mg, ft/s^2 or counts read as m/s^2 is named", "[record][units]") {
  // A static accelerometer reads |f| = g in any attitude: (0.3, -0.4, -0.87) g has |f| = 1.003 g.
  // Written in mg (|f| = 1000), ft/s^2 (32.2), Gal (981) or a count of 0.25 mg (4000) under no unit.
  auto record = [](double scale) {
    std::string text = "ax,ay,az\n";
    for (int k = 0; k < 100; ++k)
      text += std::to_string(0.3 * scale) + "," + std::to_string(-0.4 * scale) + "," +
              std::to_string((k % 2 ? -0.871 : -0.869) * scale) + "\n";
    RecordOptions o;
    o.rate_hz = 100.0;
    const auto w = recordWarnings(parseRecord(text, "acc.csv", o));
    return w.size() == 1 ? w[0] : std::string("(" + std::to_string(w.size()) + " warnings)");
  };
  CHECK(record(1000.0).find("mean |f| = 1003 m/s^2") != std::string::npos);  // 1000 sqrt(1.0069)
  CHECK(record(1000.0).find("did you forget --accel-unit mg?") != std::string::npos);
  CHECK(record(sinsim::kStandardGravity / 0.3048).find("did you forget --accel-unit ft/s^2?") != std::string::npos);
  CHECK(record(sinsim::kStandardGravity / 0.01).find("did you forget --accel-unit Gal?") != std::string::npos);
  CHECK(record(4000.0).find("give the file's accelerometer unit") != std::string::npos);
  CHECK(record(4000.0).find("about --accel-unit \"0.249 mg\"") != std::string::npos);  // 1000 / 4012
  CHECK(record(1.0).find("did you forget --accel-unit g?") != std::string::npos);
  CHECK(record(sinsim::kStandardGravity) == "(0 warnings)");  // m/s^2: gravity
  CHECK(record(0.01) == "(0 warnings)");              // gravity removed by the logger: not a unit
}

TEST_CASE("record: time stamps rounded coarser than the step are a uniform grid, a gap is not",
          "[record][time]") {
  // 400 Hz stamped to the millisecond (%.3f): steps of 2 and 3 ms alternate. The median step read
  // 500 Hz; the span gives 400 Hz exactly.
  auto stamped = [](double rate, std::size_t n, const char* fmt, std::size_t drop) {
    std::string text = "t,gx\n";
    char buf[64];
    for (std::size_t k = 0; k < n; ++k) {
      if (k == drop) continue;
      std::snprintf(buf, sizeof buf, fmt, 12.0 + double(k) / rate);
      text += std::string(buf) + ",0.01\n";
    }
    return text;
  };
  const Record r = parseRecord(stamped(400.0, 4001, "%.3f", SIZE_MAX), "r400.csv", {});
  CHECK(r.rate_hz == Approx(400.0).epsilon(1e-9));
  CHECK(r.time_rounding_s == Approx(0.001).epsilon(1e-6));
  CHECK(r.irregular_count == 0);
  const auto w = recordWarnings(r);
  REQUIRE(w.size() == 1);
  CHECK(w[0].find("the time stamps are rounded to 0.001 s") != std::string::npos);
  CHECK(w[0].find("400 Hz") != std::string::npos);
  RecordOptions at400;
  at400.rate_hz = 400.0;
  CHECK(parseRecord(stamped(400.0, 4001, "%.3f", SIZE_MAX), "r400.csv", at400).rate_hz == 400.0);
  RecordOptions at500;
  at500.rate_hz = 500.0;
  CHECK_THROWS_WITH(parseRecord(stamped(400.0, 4001, "%.3f", SIZE_MAX), "r400.csv", at500),
                    Catch::Contains("rounded to 0.001 s; their span gives 400 Hz"));
  // The same in Unix time (doubles 2.4e-7 s apart at 1.7e9 s): still the grid.
  auto unixStamped = [](double rate, std::size_t n) {
    std::string text = "t,gx\n";
    char buf[64];
    for (std::size_t k = 0; k < n; ++k) {
      std::snprintf(buf, sizeof buf, "%.3f", 1700000000.0 + double(k) / rate);
      text += std::string(buf) + ",0.01\n";
    }
    return text;
  };
  const Record u = parseRecord(unixStamped(400.0, 4001), "unix.csv", {});
  CHECK(u.rate_hz == Approx(400.0).epsilon(1e-6));
  CHECK(u.time_rounding_s == Approx(0.001).epsilon(1e-3));
  // 300 Hz to the millisecond: 3 and 4 ms, a third of them long.
  CHECK(parseRecord(stamped(300.0, 3001, "%.3f", SIZE_MAX), "r300.csv", {}).rate_hz == Approx(300.0).epsilon(1e-9));
  // 200 Hz stamped exactly, one sample dropped: steps of 5 and 10 ms are two values too, but one
  // long step is a gap, not rounding: refused, or with allow_irregular_time read and warned.
  const std::string gap = stamped(200.0, 4001, "%.3f", 2000);
  CHECK_THROWS_WITH(parseRecord(gap, "gap.csv", {}), Catch::Contains("1 irregular time step(s)"));
  RecordOptions allow;
  allow.allow_irregular_time = true;
  const Record g = parseRecord(gap, "gap.csv", allow);
  CHECK(g.time_rounding_s == 0.0);
  CHECK(g.irregular_count == 1);
  CHECK(g.rate_hz == Approx(200.0).epsilon(1e-9));
  const auto gw = recordWarnings(g);
  REQUIRE(gw.size() == 1);
  CHECK(gw[0].find("1 irregular time step(s) (1 gap(s)), the first at line 2002") != std::string::npos);
  // Jitter (a third step value): no grid.
  std::string jitter = "t,gx\n";
  for (int k = 0; k < 400; ++k) jitter += std::to_string(0.01 * k + (k % 3 == 0 ? 0.0004 : 0.0)) + ",0.01\n";
  CHECK_THROWS_WITH(parseRecord(jitter, "jitter.csv", {}), Catch::Contains("irregular time step(s)"));
  CHECK(gw[0].find("the samples either side of a gap joined") != std::string::npos);
  // Jitter alone, allowed: no gap is said, and none joined ("(0 gap(s)) ... a gap joined" before).
  const auto jw = recordWarnings(parseRecord(jitter, "jitter.csv", allow));
  REQUIRE(jw.size() == 1);
  CHECK_THAT(jw[0], Catch::Contains("irregular time step(s) (no gap), the first at line ") &&
                        Catch::EndsWith("(--allow-irregular-time)"));
}

TEST_CASE("record: time stamps in ms, us or ns read as seconds are named with the unit to write",
          "[record][units]") {
  // 100 Hz stamps written in ns, us and ms under a plain "t": no IMU records at 1e-7, 1e-4 or
  // 0.1 Hz. ns and us are refused (outside limits::kMinRate..kMaxRate) with the unit to write;
  // ms reads (0.1 Hz is a rate) with a warning naming it.
  auto stamps = [](double perSecond, const std::string& t) {
    std::string text = t + ",gx\n";
    for (int k = 0; k < 50; ++k) text += std::to_string(std::llround(k * perSecond / 100.0)) + ",0.01\n";
    return text;
  };
  const std::string ns = errorOf(stamps(1e9, "t"));
  CHECK(ns.find("the time stamps' rate 1e-07 Hz is outside what an IMU record can be (0.001 to 100000 Hz; "
                "docs/limits.md); read in ns it would be 100 Hz: write the unit in the header (t[ns])") !=
        std::string::npos);
  CHECK(ns.find("t[ns]") != std::string::npos);
  CHECK(errorOf(stamps(1e6, "t")).find("read in us it would be 100 Hz") != std::string::npos);
  // Written as the message says, the same stamps read at 100 Hz.
  CHECK(parseRecord(stamps(1e9, "t[ns]"), "rec.csv", {}).rate_hz == Approx(100.0).epsilon(1e-12));
  CHECK(parseRecord(stamps(1e6, "t[us]"), "rec.csv", {}).rate_hz == Approx(100.0).epsilon(1e-12));
  const Record ms = parseRecord(stamps(1e3, "t"), "rec.csv", {});
  CHECK(ms.rate_hz == Approx(0.1));
  const std::vector<std::string> w = recordWarnings(ms);
  REQUIRE(w.size() == 1);
  CHECK(w[0].find("if they are in ms (100 Hz), write the unit in the header (t[ms])") != std::string::npos);
  CHECK(recordWarnings(parseRecord(stamps(1e3, "t[ms]"), "rec.csv", {})).empty());
  // A 1 Hz log is an IMU's rate: nothing (a slower one is warned: it may be ms read as s).
  CHECK(recordWarnings(parseRecord(stamps(100.0, "t"), "rec.csv", {})).empty());
  // Unix time in ms or ns under a plain "t" gets the same advice (1.7e12 "s" was refused as
  // "beyond any sensor", with no word of the unit).
  auto epoch = [](double perSecond, const std::string& t) {
    std::string text = t + ",gx\n";
    for (int k = 0; k < 50; ++k)
      text += std::to_string(1700000000LL * std::llround(perSecond) + std::llround(k * perSecond / 100.0)) + ",0.01\n";
    return text;
  };
  CHECK_THAT(recordWarnings(parseRecord(epoch(1e3, "t"), "rec.csv", {})).at(0),
             Catch::Contains("if they are in ms (100 Hz), write the unit in the header (t[ms])"));
  CHECK_THAT(errorOf(epoch(1e9, "t")), Catch::Contains("read in ns it would be 100 Hz"));
}

TEST_CASE("record: no time column: a column named like one is offered, with the sensors' mapping",
          "[record]") {
  const std::string text = "time_s,gyro_x,gyro_y,gyro_z,accel_x,accel_y,accel_z\n"
                           "0,1,2,3,4,5,6\n0.01,1,2,3,4,5,6\n0.02,1,2,3,4,5,6\n";
  const std::string msg = errorOf(text);
  CHECK(msg.find("rec.csv: the file has no time column (t)") != std::string::npos);
  // The suggested mapping, given back as --columns, reads the time and the six channels.
  const std::size_t at = msg.find("--columns \"t=time_s");
  REQUIRE(at != std::string::npos);
  const std::size_t from = at + 11, to = msg.find('"', from);
  RecordOptions o;
  o.columns = parseColumnMapping(msg.substr(from, to - from));
  const Record r = parseRecord(text, "rec.csv", o);
  CHECK(r.rate_hz == Approx(100.0));
  for (int k = 0; k < 3; ++k) {
    REQUIRE(r.hasGyro(k));
    REQUIRE(r.hasAccel(k));
    CHECK(r.gyro[k][0] == Approx(1.0 + k));
    CHECK(r.accel[k][0] == Approx(4.0 + k));
  }
  // Sensor columns read, a stamp column not: only the time is offered.
  const std::string some = errorOf("stamp,gx\n0,1\n1,1\n");
  CHECK(some.find("the file's column \"stamp\" may be it: --columns \"t=stamp[s]\"") != std::string::npos);
  CHECK(some.find("sensor") == std::string::npos);
  // A time and five others: no in-order mapping (it would take the time column for gx).
  const std::string six = errorOf("stamp,a,b,c,d,e\n0,1,2,3,4,5\n");
  CHECK(six.find("--columns \"t=stamp[s],gx=NAME,...,az=NAME\"") != std::string::npos);
  CHECK(six.find("gx=stamp") == std::string::npos);
  // Nothing named like a time: the plain message.
  CHECK(errorOf("gx\n1\n1\n").find("may be it") == std::string::npos);
}

TEST_CASE("record: a logger's trailing separators, quoted names and a units row", "[record]") {
  const std::string plain = "t,gx,az\n0,0.5,-9.8\n0.01,0.25,-9.7\n";
  const Record ref = parseRecord(plain, "rec.csv", {});
  auto same = [&](const Record& r) {
    return r.rate_hz == ref.rate_hz && r.t == ref.t && r.gyro == ref.gyro && r.accel == ref.accel &&
           r.aux.empty();
  };
  // A separator ending each line (with CRLF too) names no column and holds no field.
  CHECK(same(parseRecord("t,gx,az,\n0,0.5,-9.8,\n0.01,0.25,-9.7,\n", "rec.csv", {})));
  CHECK(same(parseRecord("t;gx;az;\r\n0;0.5;-9.8;\r\n0.01;0.25;-9.7; \r\n", "rec.csv", {})));
  CHECK(same(parseRecord("t,gx,az\n0,0.5,-9.8,\n0.01,0.25,-9.7\n", "rec.csv", {})));
  // Only one, and only empty: a further field is still a long row, an empty field inside one too.
  CHECK(errorOf("t,gx,az\n0,0.5,-9.8,,\n").find("rec.csv:2: long row") != std::string::npos);
  CHECK(errorOf("t,gx,az\n0,0.5,-9.8,1\n").find("rec.csv:2: long row") != std::string::npos);
  CHECK(errorOf("t,gx,,az\n0,0.5,,-9.8\n").find("column 3 has no name") != std::string::npos);
  // Quoted names are the names; a quoted unit as well.
  CHECK(same(parseRecord("\"t\",\"gx\",\"az\"\n0,0.5,-9.8\n0.01,0.25,-9.7\n", "rec.csv", {})));
  const Record deg = parseRecord("\"t [s]\",\"gx [deg/s]\"\n0,1\n0.01,1\n", "rec.csv", {});
  CHECK(deg.gyro[0][0] == Approx(kDeg));
  // A units row under the header: named as one, at its line.
  CHECK(errorOf("t,gx,az\ns,rad/s,m/s^2\n0,0.5,-9.8\n")
            .find("rec.csv:2: the line after the header holds no number: a second header line (units?)") !=
        std::string::npos);
  // A decimal comma, a clock time: said what they may be.
  CHECK(errorOf("t;gx\n0;0,25\n").find("got \"0,25\" (a decimal comma?") != std::string::npos);
  // A comma file read with --delimiter semicolon: its fields, not a decimal comma.
  RecordOptions semicolon;
  semicolon.separator = parseSeparator("semicolon");
  const std::string wrong = errorOf("t,gx,gy\n0,0.25,0.5\n", semicolon);
  CHECK(wrong.find("(fields separated by ','? the separator read is ';': leave --delimiter out") != std::string::npos);
  CHECK(wrong.find("decimal comma") == std::string::npos);
  CHECK(errorOf("t,gx\n2024-05-01T12:00:00.000,1\n").find("(a date or clock time?") != std::string::npos);
  CHECK(errorOf("t,gx\n12:00:00.010,1\n").find("(a date or clock time?") != std::string::npos);
  CHECK(parseRecord("t,gx\n0,1e-3\n0.01,-2e-3\n", "rec.csv", {}).gyro[0][1] == -2e-3);
  // A first row with a number and a bad field keeps the field's own message.
  CHECK(errorOf("t,gx,az\n0,abc,-9.8\n").find("column \"gx\": expected a finite number, got \"abc\"") !=
        std::string::npos);
}

TEST_CASE("record: UTF-16 text and lines ended by CR alone are named, not read as columns", "[record]") {
  RecordOptions opt;
  opt.rate_hz = 100.0;
  // "gx,gy\n1,2\n" as a spreadsheet's UTF-16 LE export: a byte-order mark and a NUL after each byte.
  std::string utf16 = "\xFF\xFE";
  for (char c : std::string("gx,gy\n1,2\n")) utf16 += std::string(1, c) + '\0';
  CHECK_THAT(errorOf(utf16, opt), Catch::Contains("rec.csv:1: the file is UTF-16 text") &&
                                      Catch::Contains("iconv -f UTF-16 -t UTF-8"));
  CHECK_THAT(errorOf(std::string("gx,gy\n1,2\n").insert(0, "\0", 1), opt), Catch::Contains("UTF-16"));
  // Old Mac line ends: the whole file is one line, which held "more than 64 columns".
  std::string cr = "t,gx,gy,gz,ax,ay,az";
  for (int k = 0; k < 20; ++k) cr += "\r" + std::to_string(0.01 * k) + ",0,0,0,0,0,-9.8";
  CHECK_THAT(errorOf(cr + "\r"), Catch::Contains("rec.csv:1: the lines end in a carriage return alone") &&
                                     Catch::Contains("tr '\\r' '\\n'"));
  // CRLF is read as it always was.
  CHECK(parseRecord("gx,gy\r\n1,2\r\n3,4\r\n", "rec.csv", opt).gyro[1] == std::vector<double>{2.0, 4.0});
  // A quote-everything export ("0.25"), commas and blanks; an unclosed or stray quote stays an error.
  CHECK(parseRecord("\"gx\",\"gy\"\n\"1\",\"2\"\n\"3\", \"-4e-1\"\n", "rec.csv", opt).gyro[1] ==
        std::vector<double>{2.0, -0.4});
  CHECK(parseRecord("gx gy\n\"1\" \"2\"\n3 4\n", "rec.csv", opt).gyro[0] == std::vector<double>{1.0, 3.0});
  CHECK_THAT(errorOf("gx,gy\n1,2\n\"3,4\n", opt), Catch::Contains("rec.csv:3: column \"gx\""));
  CHECK_THAT(errorOf("gx,gy\n1,2\n3\",4\n", opt), Catch::Contains("rec.csv:3: column \"gx\""));
  CHECK_THAT(errorOf("gx gy\n1 2\n\"3\"4 5\n", opt), Catch::Contains("rec.csv:3: column \"gx\""));
  // A CR-only file over the 1 MiB line limit: the same words (was "a line longer than 1048576
  // characters").
  const fs::path big = tempPath("cr_only.csv");
  {
    std::ofstream f(big, std::ios::binary);
    f << "t,gx,gy,gz,ax,ay,az";
    for (int k = 0; k < 60000; ++k) f << "\r" << 0.01 * k << ",0,0,0,0,0,-9.8";
    f << "\r";
  }
  REQUIRE(fs::file_size(big) > 1048576);
  try {
    loadRecord(big.string(), {});
    FAIL("a CR-only file was read");
  } catch (const sinsim::InputError& e) {
    CHECK_THAT(std::string(e.what()), Catch::Contains("the lines end in a carriage return alone"));
  }
  fs::remove(big);
}

TEST_CASE("record: a column in a sensor's unit under a name not read is warned with its mapping", "[record][units]") {
  RecordOptions opt;
  opt.rate_hz = 100.0;
  const std::string rows = "1,2,3,4,5\n1,2,3,4,5\n";
  auto warnings = [&](const std::string& header) {
    std::string all;
    for (const std::string& w : recordWarnings(parseRecord(header + rows, "rec.csv", opt)))
      if (w.find("its name is not one sinsim reads") != std::string::npos) all += w + "\n";
    return all;
  };
  // A gyro on two named axes and one under its logger's name; a die temperature; a pressure.
  const std::string w = warnings("gx,gy,gyro_z [deg/s],die_temp[degC],p [Pa]\n");
  CHECK_THAT(w, Catch::Contains("column \"gyro_z [deg/s]\" is in an angular rate unit") &&
                    Catch::Contains("--columns \"gx=gyro_z\"") && Catch::Contains("name it gx (gy, gz)"));
  CHECK_THAT(w, Catch::Contains("column \"die_temp[degC]\" is in a temperature unit") &&
                    Catch::Contains("--columns \"temp=die_temp\""));
  CHECK(w.find("p [Pa]") == std::string::npos);  // a unit sinsim does not read: kept for the user
  // A second temperature or a third gyro set beside a whole record is no warning.
  CHECK(warnings("gx,gy,gz,temp,t2[degC]\n").empty());
  CHECK(warnings("gx,gy,gz,g2[deg/s],g3[rad/s]\n").empty());
}

TEST_CASE("record: a bad unit option is named as the option, not as the file's column", "[record][units]") {
  RecordOptions o;
  o.gyro_unit = "dpz";
  CHECK_THAT(errorOf("t,gx\n0,1\n0.01,1\n", o),
             Catch::StartsWith("rec.csv: the gyro unit option (--gyro-unit): unknown unit \"dpz\""));
  o.gyro_unit = "g";
  CHECK_THAT(errorOf("t,gx\n0,1\n0.01,1\n", o),
             Catch::Contains("the gyro unit option (--gyro-unit) \"g\": unit has dimension m/s^2, expected rad/s"));
  RecordOptions a;
  a.accel_unit = "deg/s";
  CHECK_THAT(errorOf("t,az\n0,1\n0.01,1\n", a), Catch::Contains("the accelerometer unit option (--accel-unit)"));
  o.gyro_unit = "dps";
  CHECK(parseRecord("t,gx\n0,1\n0.01,1\n", "rec.csv", o).gyro[0][0] == Approx(M_PI / 180.0));
}

TEST_CASE("record: raw counts are read with the count's size as their unit", "[record][units]") {
  // ADIS16405-like counts: 0.05 deg/s and 3.33 mg per count, given as an option or in the header.
  const std::string rows = "2,-1,0,90,-30,-300\n-3,4,1,91,-29,-301\n";
  RecordOptions o;
  o.rate_hz = 100.0;
  o.gyro_unit = "0.05 deg/s";
  o.accel_unit = "3.33 mg";
  const Record a = parseRecord("gx,gy,gz,ax,ay,az\n" + rows, "rec.csv", o);
  CHECK(a.gyro[0][0] == Approx(2 * 0.05 * kDeg));
  CHECK(a.gyro[1][1] == Approx(4 * 0.05 * kDeg));
  CHECK(a.accel[2][1] == Approx(-301 * 3.33e-3 * kG));
  RecordOptions r;
  r.rate_hz = 100.0;
  const Record b = parseRecord("gx [0.05 deg/s],gy [0.05 deg/s],gz [0.05 deg/s],ax [3.33 mg],ay [3.33 mg],az [3.33 mg]\n" + rows, "rec.csv", r);
  CHECK(b.gyro == a.gyro);
  CHECK(b.accel == a.accel);
  // A temperature in tenths of a degree keeps the Celsius offset.
  const Record t = parseRecord("gx,temp [0.1 degC]\n0,250\n0,251\n", "rec.csv", r);
  CHECK(t.temperature[0] == Approx(298.15));
  // A unit the grammar reads whole has no factor; a bad factor is named.
  o.gyro_unit = "-0.05 deg/s";
  CHECK_THAT(errorOf("gx\n1\n2\n", o), Catch::Contains("the factor of a count must be positive and finite"));
  o.gyro_unit = "0.05";
  CHECK_THAT(errorOf("gx\n1\n2\n", o), Catch::Contains("a factor needs a unit after it"));
  o.gyro_unit = "1e999 deg/s";
  CHECK_THAT(errorOf("gx\n1\n2\n", o), Catch::Contains("positive and finite"));
  CHECK_THAT(errorOf("gx [0 deg/s]\n1\n2\n", r), Catch::Contains("rec.csv:1: column \"gx [0 deg/s]\": unit \"0 deg/s\": the factor"));
}

TEST_CASE("record: Unix time stamps in ns up to 100 kHz are regular and messages show them as written",
          "[record]") {
  // As doubles, 1.7e18 ns are 256 ns apart and 1.7e9 s 0.24 us apart: the 10 us steps of 100 kHz
  // came out 9.8 or 10.3 us, thousands of "irregular time steps". The stamps are kept less the
  // first, read with a 64-bit mantissa (exact for integers below 1.8e19).
  auto unixNs = [](long long rate, std::size_t n, std::size_t dropped) {
    std::string text = "t[ns],gx\n";
    const long long t0 = 1733560000123456789LL;
    for (std::size_t k = 0; k < n; ++k)
      if (k != dropped) text += std::to_string(t0 + static_cast<long long>(k) * (1000000000LL / rate)) + ",0.01\n";
    return text;
  };
  for (const long long rate : {1000LL, 20000LL, 50000LL, 100000LL}) {
    INFO(rate);
    const Record r = parseRecord(unixNs(rate, 5001, SIZE_MAX), "ns.csv", {});
    CHECK(r.irregular_count == 0);
    CHECK(r.rate_hz == Approx(double(rate)).epsilon(1e-12));
    CHECK(r.t.front() == 0.0);
    CHECK(r.t_origin_s == Approx(1733560000.123456789).epsilon(1e-15));
    CHECK(r.t.back() == Approx(5000.0 / double(rate)).epsilon(1e-12));
  }
  // Seconds with nine decimals, and ms with six: the same.
  std::string s = "t,gx\n", ms = "t[ms],gx\n";
  char buf[64];
  for (long long k = 0; k <= 5000; ++k) {
    std::snprintf(buf, sizeof buf, "1733560000.%09lld", 123456789LL + 10000LL * k);
    s += std::string(buf) + ",0.01\n";
    std::snprintf(buf, sizeof buf, "1733560000%03lld.%06lld", (123456789LL + 10000LL * k) / 1000000LL,
                  (123456789LL + 10000LL * k) % 1000000LL);
    ms += std::string(buf) + ",0.01\n";
  }
  for (const std::string& text : {s, ms}) {
    const Record r = parseRecord(text, "unix.csv", {});
    CHECK(r.irregular_count == 0);
    CHECK(r.rate_hz == Approx(100000.0).epsilon(1e-8));  // ms to six decimals: 1e-10 s each
  }
  // A dropped sample: the gap is named at its stamp as written.
  RecordOptions allow;
  allow.allow_irregular_time = true;
  const Record g = parseRecord(unixNs(100000, 5001, 2000), "ns.csv", allow);
  CHECK(g.irregular_count == 1);
  const auto w = recordWarnings(g);
  REQUIRE_FALSE(w.empty());
  CHECK_THAT(w[0], Catch::Contains("(t = 1733560000.143 s, dt = 2e-05 s)"));
  CHECK_THAT(errorOf(unixNs(100000, 5001, 2000)), Catch::Contains("(t = 1733560000.14"));
}
