#include "errormodels/stats/record_time.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "common/error.hpp"
#include "common/limits.hpp"

namespace sinsim::errormodels::detail {

void recordError(const std::string& source, std::size_t line, const std::string& what) {
  std::ostringstream os;
  os << source;
  if (line > 0) os << ":" << line;
  os << ": " << what;
  throw InputError(os.str());
}

/// Checks that time stamps increase and are uniform; first_line is the file line of row 0.
void checkTime(Record& rec, std::size_t first_line, const RecordOptions& options) {
  const std::vector<double>& t = rec.t;
  const std::size_t n = t.size();
  auto lineOf = [&](std::size_t row) { return first_line + row; };
  for (std::size_t k = 1; k < n; ++k) {
    if (!(t[k] > t[k - 1])) {
      recordError(rec.source, lineOf(k),
           "time stamp " + std::to_string(t[k]) + " s does not increase (previous " +
               std::to_string(t[k - 1]) + " s)");
    }
  }
  double dt0 = 0.0;
  if (n >= 2) {
    std::vector<double> dt(n - 1);
    for (std::size_t k = 1; k < n; ++k) dt[k - 1] = t[k] - t[k - 1];
    auto mid = dt.begin() + static_cast<std::ptrdiff_t>(dt.size() / 2);
    std::nth_element(dt.begin(), mid, dt.end());
    dt0 = *mid;  // median step: robust to a few gaps
  }
  if (options.rate_hz) {
    const double dt_opt = 1.0 / *options.rate_hz;
    if (n >= 2 && std::abs(dt_opt - dt0) > options.time_tolerance * dt_opt) {
      std::ostringstream os;
      os << "the rate option (--rate) " << *options.rate_hz << " Hz disagrees with the time stamps (median step "
         << dt0 << " s, i.e. " << 1.0 / dt0 << " Hz)";
      recordError(rec.source, 0, os.str());
    }
    dt0 = dt_opt;
  }
  if (n < 2 && !options.rate_hz) recordError(rec.source, 0, "one sample only and no rate given: the sample rate is unknown");
  rec.rate_hz = 1.0 / dt0;
  std::size_t count = 0;
  std::vector<TimeIrregularity> found;
  for (std::size_t k = 1; k < n; ++k) {
    const double dt = t[k] - t[k - 1];
    if (std::abs(dt - dt0) > options.time_tolerance * dt0) {
      ++count;
      if (found.size() < 1000) found.push_back({lineOf(k), k, t[k], dt, dt > 1.5 * dt0});
    }
  }
  // Regular steps: the rate from the whole span, not from one step, whose printed digits (a time
  // column written with %.12g or %.6f) leave it 1e-7..1e-4 off -- enough for a model's process
  // defined at the record's own rate to read as slower than it.
  if (count == 0 && n >= 2 && !options.rate_hz) rec.rate_hz = double(n - 1) / (t[n - 1] - t[0]);
  rec.irregular_count = count;
  if (count > 0 && !options.allow_irregular_time) {
    std::ostringstream os;
    os << count << " irregular time step(s) (nominal " << dt0 << " s, tolerance "
       << options.time_tolerance * 100 << " %); first at:";
    for (std::size_t i = 0; i < std::min<std::size_t>(found.size(), 5); ++i) {
      os << (i ? "," : "") << " line " << found[i].line << " (t = " << found[i].t << " s, dt = "
         << found[i].dt << " s" << (found[i].gap ? ", gap" : "") << ")";
    }
    os << ". Records are not resampled; fix the file or allow irregular time.";
    recordError(rec.source, 0, os.str());
  }
  rec.irregularities = std::move(found);
}

/// A record's sample rate must be one an IMU record can have (limits::kMinRate..kMaxRate).
void checkRate(double rate, const std::string& source, const std::string& what, const std::string& hint) {
  if (!(rate >= limits::kMinRate && rate <= limits::kMaxRate))
    recordError(source, 0, what + " " + limits::fmt(rate) + " Hz is outside what an IMU record can be (" +
                        limits::fmt(limits::kMinRate) + " to " + limits::fmt(limits::kMaxRate) +
                        " Hz; docs/limits.md)" + hint);
}

/// Keeps the samples [skip, skip + duration) of the record (RecordOptions::skip_s, duration_s).
void applyWindow(Record& rec, const RecordOptions& o) {
  if (o.skip_s == 0.0 && !o.duration_s) return;
  const double total = rec.duration();
  // Compared in floating point first: a skip of 1e300 s must not reach an integer conversion.
  if (!(o.skip_s < total))
    recordError(rec.source, 0, "skip " + limits::fmt(o.skip_s) + " s leaves no samples (the record is " +
                            limits::fmt(total) + " s long)");
  const std::size_t first = static_cast<std::size_t>(std::llround(o.skip_s * rec.rate_hz));
  std::size_t count = rec.rows - std::min(first, rec.rows);
  if (o.duration_s) {
    if (!(*o.duration_s <= total - o.skip_s + 0.5 / rec.rate_hz))
      recordError(rec.source, 0, "duration " + limits::fmt(*o.duration_s) + " s after a skip of " +
                              limits::fmt(o.skip_s) + " s is longer than the record (" +
                              limits::fmt(total) + " s)");
    count = std::min(count, static_cast<std::size_t>(std::llround(*o.duration_s * rec.rate_hz)));
  }
  if (count < 2) recordError(rec.source, 0, "skip and duration leave fewer than 2 samples");
  auto cut = [&](std::vector<double>& v) {
    if (v.empty()) return;
    v.erase(v.begin() + static_cast<std::ptrdiff_t>(first + count), v.end());
    v.erase(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(first));
  };
  rec.skipped_s = double(first) / rec.rate_hz;
  cut(rec.t);
  for (auto& v : rec.gyro) cut(v);
  for (auto& v : rec.accel) cut(v);
  cut(rec.temperature);
  for (auto& a : rec.aux) cut(a.values);
  std::vector<TimeIrregularity> kept;
  for (TimeIrregularity ti : rec.irregularities)
    if (ti.row > first && ti.row < first + count) {
      ti.row -= first;
      kept.push_back(ti);
    }
  rec.irregularities = std::move(kept);
  rec.irregular_count = rec.irregularities.size();
  rec.rows = count;
}

}  // namespace sinsim::errormodels::detail
