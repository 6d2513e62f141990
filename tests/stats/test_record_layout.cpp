// Records as users have them: other separators, other column names, no header, and a window.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "common/error.hpp"
#include "common/units.hpp"
#include "errormodels/stats/record.hpp"

using namespace sinsim::errormodels;

namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr double kG = 9.80665;

std::string errorOf(const std::string& text, const RecordOptions& opt) {
  try {
    parseRecord(text, "rec.txt", opt);
  } catch (const sinsim::InputError& e) {
    return e.what();
  }
  FAIL("no InputError for:\n" << text);
  return {};
}

/// Ten rows at 10 Hz: gx = row number [deg/s], az = -1 g, separated by `sep`.
std::string tenRows(const std::string& header, const std::string& sep) {
  std::string s = header + "\n";
  for (int k = 0; k < 10; ++k)
    s += std::to_string(0.1 * k) + sep + std::to_string(k) + sep + "0" + sep + "0" + sep + "0" +
         sep + "0" + sep + "-1\n";
  return s;
}

void checkTenRows(const Record& r) {
  REQUIRE(r.size() == 10);
  CHECK(r.rate_hz == Approx(10.0));
  CHECK(r.gyro[0][7] == Approx(7 * kDeg));
  CHECK(r.accel[2][3] == Approx(-kG));
}

}  // namespace

TEST_CASE("record layout: comma, semicolon and blank-separated files read alike", "[record]") {
  RecordOptions opt;
  opt.gyro_unit = "deg/s";
  opt.accel_unit = "g";
  checkTenRows(parseRecord(tenRows("t,gx,gy,gz,ax,ay,az", ","), "a.csv", opt));
  checkTenRows(parseRecord(tenRows("t;gx;gy;gz;ax;ay;az", ";"), "b.csv", opt));
  checkTenRows(parseRecord(tenRows("t gx gy gz ax ay az", "   "), "c.txt", opt));
  checkTenRows(parseRecord(tenRows("t\tgx\tgy\tgz\tax\tay\taz", "\t"), "d.tsv", opt));
  // A unit in brackets keeps its space in a blank-separated header.
  RecordOptions plain;
  const Record r = parseRecord(tenRows("t [s]  gx [deg/s]  gy gz ax ay  az [g]", " "), "e.txt", plain);
  CHECK(r.gyro[0][7] == Approx(7 * kDeg));
  CHECK(r.accel[2][0] == Approx(-kG));
  // Forced separator that the file does not use: the row is one unreadable field.
  RecordOptions semi = opt;
  semi.separator = parseSeparator("semicolon");
  CHECK_THAT(errorOf(tenRows("t,gx,gy,gz,ax,ay,az", ","), semi),
             Catch::Contains("rec.txt:2") && Catch::Contains("expected a finite number"));
  CHECK_THROWS_AS(parseSeparator("pipe"), sinsim::InputError);
}

TEST_CASE("record layout: a column mapping reads other names, with units", "[record]") {
  const std::string text =
      "Time,GyroX,GyroY,GyroZ,AccX,AccY,AccZ,Counter\n"
      "0,1,2,3,0.1,0.2,-1,5\n"
      "5,1,2,3,0.1,0.2,-1,6\n"
      "10,1,2,3,0.1,0.2,-1,7\n";
  RecordOptions opt;
  opt.columns = parseColumnMapping(
      "t=Time[ms],gx=GyroX[deg/s],gy=gyroy[deg/s],gz=GyroZ[deg/h],ax=AccX[g],ay=AccY[g],az=7[g]");
  const Record r = parseRecord(text, "m.csv", opt);
  REQUIRE(r.size() == 3);
  CHECK(r.rate_hz == Approx(200.0));
  CHECK(r.gyro[1][0] == Approx(2 * kDeg));
  CHECK(r.gyro[2][0] == Approx(3 * kDeg / 3600.0));
  CHECK(r.accel[0][0] == Approx(0.1 * kG));
  CHECK(r.accel[2][2] == Approx(-kG));  // by number: column 7
  REQUIRE(r.aux.size() == 1);
  CHECK(r.aux[0].name == "Counter");

  // Without a mapping "Time" is read as seconds and no IMU column is found.
  const Record raw = parseRecord(text, "m.csv", RecordOptions{});
  CHECK(raw.rate_hz == Approx(0.2));
  CHECK_FALSE(raw.hasGyro(0));
  // A mapped column the file does not have, and a unit that disagrees with the header's.
  RecordOptions bad;
  bad.columns = parseColumnMapping("gx=GyroQ");
  CHECK_THAT(errorOf(text, bad), Catch::Contains("gx=gyroq") && Catch::Contains("no column named"));
  bad.columns = parseColumnMapping("gx=gx[deg/s]");
  CHECK_THAT(errorOf("t,gx [rad/s]\n0,1\n1,1\n", bad), Catch::Contains("[rad/s] in the file"));
}

TEST_CASE("record layout: mapping by number means a file without a header", "[record]") {
  const std::string text = "# logger v2\n0.00 1 -1\n0.01 2 -1\n0.02 3 -1\n";
  RecordOptions opt;
  opt.columns = parseColumnMapping("t=1,gz=2[deg/s],az=3[g]");
  const Record r = parseRecord(text, "raw.txt", opt);
  REQUIRE(r.size() == 3);  // the first line is data, not a header
  CHECK(r.rate_hz == Approx(100.0));
  CHECK(r.gyro[2][2] == Approx(3 * kDeg));
  CHECK(r.accel[2][1] == Approx(-kG));
  opt.columns = parseColumnMapping("t=1,gz=4");
  CHECK_THAT(errorOf(text, opt), Catch::Contains("no column 4 (it has 3)"));
}

TEST_CASE("record layout: mapping text errors name the entry", "[record]") {
  CHECK_THROWS_WITH(parseColumnMapping("gq=GyroX"), Catch::Contains("unknown quantity \"gq\""));
  CHECK_THROWS_WITH(parseColumnMapping("gx=A,gx=B"), Catch::Contains("gx is mapped twice"));
  CHECK_THROWS_WITH(parseColumnMapping("gx=A,gy=A"), Catch::Contains("mapped to gx and gy"));
  CHECK_THROWS_WITH(parseColumnMapping("gx"), Catch::Contains("QUANTITY=COLUMN"));
  CHECK_THROWS_WITH(parseColumnMapping("gx=0"), Catch::Contains("start at 1"));
  CHECK_THROWS_WITH(parseColumnMapping("gx=A[deg/s"), Catch::Contains("brackets"));
}

TEST_CASE("record window: --skip and --duration keep the samples from skip to skip + duration", "[record]") {
  RecordOptions opt;
  opt.gyro_unit = "deg/s";
  opt.accel_unit = "g";
  opt.skip_s = 0.3;
  opt.duration_s = 0.5;
  const Record r = parseRecord(tenRows("t,gx,gy,gz,ax,ay,az", ","), "w.csv", opt);
  REQUIRE(r.size() == 5);
  CHECK(r.gyro[0].front() == Approx(3 * kDeg));
  CHECK(r.gyro[0].back() == Approx(7 * kDeg));
  CHECK(r.t.front() == Approx(0.3));
  CHECK(r.accel[2].size() == 5);
  CHECK(r.skipped_s == Approx(0.3));  // what a message's suggested --skip counts from

  opt.duration_s.reset();
  CHECK(parseRecord(tenRows("t,gx,gy,gz,ax,ay,az", ","), "w.csv", opt).size() == 7);
  opt.skip_s = 1.0;  // the whole record
  CHECK_THAT(errorOf(tenRows("t,gx,gy,gz,ax,ay,az", ","), opt), Catch::Contains("leaves no samples"));
  opt.skip_s = 0.5;
  opt.duration_s = 2.0;
  CHECK_THAT(errorOf(tenRows("t,gx,gy,gz,ax,ay,az", ","), opt), Catch::Contains("longer than the record"));
  opt.skip_s = 1e300;
  opt.duration_s.reset();
  CHECK_THAT(errorOf(tenRows("t,gx,gy,gz,ax,ay,az", ","), opt), Catch::Contains("leaves no samples"));
}

TEST_CASE("durations on options: plain seconds or any time unit", "[units]") {
  CHECK(sinsim::parseDuration("90", "--skip") == 90.0);
  CHECK(sinsim::parseDuration("10 min", "--skip") == 600.0);
  CHECK(sinsim::parseDuration("2 h", "--duration") == 7200.0);
  CHECK(sinsim::parseDuration("250 ms", "--duration") == Approx(0.25));
  CHECK_THROWS_WITH(sinsim::parseDuration("3 m", "--duration"), Catch::StartsWith("--duration:"));
  CHECK_THROWS_WITH(sinsim::parseDuration("-1 s", "--skip"), Catch::Contains("non-negative"));
  CHECK_THROWS_AS(sinsim::parseDuration("soon", "--skip"), sinsim::InputError);
}
