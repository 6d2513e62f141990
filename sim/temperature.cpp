// Sensor temperature profiles (temperature.hpp).
#include "sim/temperature.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "common/constants.hpp"
#include "common/error.hpp"
#include "common/read_file.hpp"
#include "common/limits.hpp"
#include "common/units.hpp"

namespace sinsim::sim {
namespace {

using D = Dimension;

/// Throws unless every temperature of the profile lies in (0 K, limits::kMaxTemperature].
void checkRange(const TemperatureProfile& p, const std::string& where) {
  auto inside = [](double k) { return k > 0.0 && k <= limits::kMaxTemperature; };
  const bool ok = p.kelvins.empty() ? inside(p.start) : std::all_of(p.kelvins.begin(), p.kelvins.end(), inside);
  if (!ok)
    throw InputError(where + ": a temperature outside (-273.15, " +
                     limits::fmt(limits::kMaxTemperature - kZeroCelsius) + "] degC (docs/limits.md)");
}

TemperatureProfile readCsv(const std::string& path) {
  // A regular file of bounded size: a FIFO hung here and /dev/zero filled the memory.
  std::istringstream in(readRegularFile(path, limits::kMaxTemperatureCsvBytes, "temperature CSV"));
  std::string line;
  std::getline(in, line);
  if (line.rfind("t,temp", 0) != 0)
    throw InputError(path + ":1: expected the header \"t,temp\" (s, degC), got \"" + line + "\"");
  TemperatureProfile p;
  p.present = true;
  int row = 1;
  while (std::getline(in, line)) {
    ++row;
    if (line.empty()) continue;
    double t = NAN, c = NAN;
    char comma = 0;
    std::istringstream ss(line);
    if (!(ss >> t >> comma >> c) || comma != ',' || !std::isfinite(t) || !std::isfinite(c))
      throw InputError(path + ":" + std::to_string(row) + ": expected \"t,temp\" numbers, got \"" +
                       line + "\"");
    if (!p.times.empty() && !(t > p.times.back()))
      throw InputError(path + ":" + std::to_string(row) + ": times must increase");
    p.times.push_back(t);
    p.kelvins.push_back(c + kZeroCelsius);
  }
  if (p.times.empty()) throw InputError(path + ": no temperature rows");
  p.start = p.kelvins.front();
  checkRange(p, path);
  return p;
}

}  // namespace

double TemperatureProfile::at(double t) const {
  if (!present) return NAN;
  if (times.empty()) return start + rate * t;
  if (t <= times.front()) return kelvins.front();
  if (t >= times.back()) return kelvins.back();
  // times[i] < t <= times[i + 1]
  const std::size_t i = std::size_t(std::lower_bound(times.begin(), times.end(), t) - times.begin()) - 1;
  const double w = (t - times[i]) / (times[i + 1] - times[i]);
  return kelvins[i] + w * (kelvins[i + 1] - kelvins[i]);
}

TemperatureProfile readTemperature(const ConfigNode& t, double duration) {
  TemperatureProfile p;
  if (!t.exists()) return p;
  if (t.isScalar()) {
    p.start = t.asQuantity(D::temperature()).value_or(NAN);
    p.rate = 0.0;
  } else if (t.isMap()) {
    t.allowKeys({"start", "end", "rate"});
    p.start = t.quantity("start", D::temperature());
    if (t.has("end") && t.has("rate")) {
      t["rate"].error("give end or rate, not both");
    } else if (t.has("end")) {
      const double end = t.quantity("end", D::temperature());
      p.rate = duration > 0.0 ? (end - p.start) / duration : 0.0;
    } else {
      p.rate = t.quantity("rate", D::temperature() / D::time(), 0.0);
    }
  } else {
    t.error("expected a temperature (\"25 degC\") or a map {start, end} or {start, rate}");
  }
  p.present = true;
  if (std::isfinite(p.start)) t.check(p.start > 0.0, "expected an absolute temperature above 0 K");
  const double end = p.start + p.rate * duration;  // linear: the extremes are at the ends
  if (std::isfinite(p.start) && std::isfinite(p.rate) && p.start > 0.0)
    t.check(end > 0.0 && std::max(p.start, end) <= limits::kMaxTemperature,
            "the temperature goes from " + limits::fmt(p.start - kZeroCelsius) + " to " +
                limits::fmt(end - kZeroCelsius) + " degC over the scenario, outside (-273.15, " +
                limits::fmt(limits::kMaxTemperature - kZeroCelsius) + "] degC (docs/limits.md)");
  return p;
}

TemperatureProfile temperatureFromText(const std::string& spec, double duration) {
  TemperatureProfile p;
  p.present = true;
  const auto dots = spec.find("..");
  if (dots != std::string::npos) {
    double t0 = NAN, t1 = NAN;
    try {
      t0 = parseQuantityAs(spec.substr(0, dots), D::temperature());
      t1 = parseQuantityAs(spec.substr(dots + 2), D::temperature());
    } catch (const InputError& e) {
      throw InputError("--temperature \"" + spec + "\": a ramp is \"20 degC..45 degC\": " +
                       e.text());
    }
    p.start = t0;
    // The ramp over [0, duration] as a two-row table: t0 + (t/duration) (t1 - t0).
    if (duration > 0) p.times = {0.0, duration}, p.kelvins = {t0, t1};
    TemperatureProfile ends;
    ends.kelvins = {t0, t1};
    checkRange(ends, "--temperature \"" + spec + "\"");
    return p;
  }
  try {
    p.start = parseQuantityAs(spec, D::temperature());
  } catch (const InputError& e) {
    std::error_code ec;  // not opened to probe it: opening a FIFO waits for a writer
    if (!std::filesystem::exists(spec, ec))
      throw InputError("--temperature \"" + spec + "\": neither a temperature (" + e.text() +
                       "), nor a ramp \"20 degC..45 degC\", nor a readable CSV file");
    return readCsv(spec);
  }
  checkRange(p, "--temperature \"" + spec + "\"");
  return p;
}

}  // namespace sinsim::sim
