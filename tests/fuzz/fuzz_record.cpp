// libFuzzer target: the CSV record parser. The first byte picks the options (a given rate or
// not, irregular time allowed or not, unit options), the rest is the file text.
#include "errormodels/stats/record.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  sinsim::errormodels::RecordOptions o;
  const std::uint8_t pick = data[0];
  if (pick & 1) o.rate_hz = (pick & 2) ? 100.0 : 0.5;
  o.allow_irregular_time = (pick & 4) != 0;
  if (pick & 8) o.gyro_unit = "deg/s";
  if (pick & 16) o.accel_unit = "g";
  sinsim::fuzz::expectInputErrorOnly(data + 1, size - 1, [&](const std::string& text) {
    sinsim::errormodels::parseRecord(text, "fuzz.csv", o);
  });
  return 0;
}
