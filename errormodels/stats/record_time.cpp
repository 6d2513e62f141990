#include "errormodels/stats/record_time.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
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

/// The resolution r [s] a uniform grid's time stamps were rounded to, where they are one: the steps
/// take exactly two values r apart (to 1e-6 of a step, or the doubles' spacing), the mean step lies
/// strictly between them, and no stamp is more than r from the straight line through the first and
/// the last (each is within r / 2 of the grid, whose ends are within r / 2 too), the long steps
/// are spread evenly (not a gap: each eighth of the record holds its share), and r is more than
/// `tolerance` of a step (finer rounding leaves the steps regular). 0 otherwise: steps that agree,
/// jitter (many step values) or a gap (a third value).
double roundedGridResolution(const std::vector<double>& t, double tolerance) {
  const std::size_t n = t.size();
  const double mean = (t[n - 1] - t[0]) / double(n - 1);
  if (!(mean > 0.0) || !std::isfinite(mean)) return 0.0;
  // A step's digits: 1e-6 of it, or the doubles' own spacing where the stamps are large (Unix
  // time in s: 2.4e-7 s apart at 1.7e9).
  const double big = std::max(std::abs(t[0]), std::abs(t[n - 1]));
  const double eps = std::max(1e-6 * mean, 8.0 * std::numeric_limits<double>::epsilon() * big);
  double lo = t[1] - t[0], hi = lo;
  for (std::size_t k = 2; k < n; ++k) {
    const double d = t[k] - t[k - 1];
    if (std::abs(d - lo) <= eps || std::abs(d - hi) <= eps) continue;
    if (hi - lo > eps) return 0.0;  // a third value
    if (d < lo) lo = d; else hi = d;
  }
  const double r = hi - lo;
  if (!(r > tolerance * mean && lo < mean - eps && hi > mean + eps)) return 0.0;
  for (std::size_t k = 0; k < n; ++k)
    if (std::abs(t[k] - (t[0] + double(k) * mean)) > r + eps) return 0.0;
  // Rounding spreads the long steps evenly, a fraction (mean - lo) / r of every stretch (to +-1);
  // a gap or a few put them in one place. Each eighth of the record holds its share to +-2, and
  // there are at least 8 of each step.
  const std::size_t steps = n - 1, block = steps / 8;
  const double p = (mean - lo) / r;
  if (block == 0 || !(p * double(steps) >= 8.0 && (1.0 - p) * double(steps) >= 8.0)) return 0.0;
  for (std::size_t b = 0; b < 8; ++b) {
    std::size_t longSteps = 0;
    for (std::size_t k = b * block + 1; k <= (b + 1) * block; ++k) longSteps += t[k] - t[k - 1] > mean;
    if (std::abs(double(longSteps) - p * double(block)) > 2.0) return 0.0;
  }
  return r;
}

namespace {

/// A rate option and the rate of regular time stamps (their span's, exact to the stamps' digits)
/// must agree this closely: within the 1 % a single step may be off, --rate 100.5 on 100 Hz
/// stamps replaced them silently (every tau and the rate written into a fitted model 0.5 % off).
constexpr double kRateAgreement = 1e-3;

void requireRateAgrees(const Record& rec, double option, double spanRate, const char* what) {
  if (std::abs(option - spanRate) <= kRateAgreement * spanRate) return;
  std::ostringstream os;
  os.precision(10);
  os << "the rate option (--rate) " << option << " Hz disagrees with the time stamps (" << what
     << " " << spanRate << " Hz, " << std::setprecision(2) << 100.0 * std::abs(option / spanRate - 1.0)
     << " % apart; they must agree to " << 100.0 * kRateAgreement
     << " %): leave the rate out to read the stamps' rate, or fix the time column";
  recordError(rec.source, 0, os.str());
}

}  // namespace

/// Checks that time stamps increase and are uniform; first_line is the file line of row 0.
void checkTime(Record& rec, std::size_t first_line, const RecordOptions& options) {
  const std::vector<double>& t = rec.t;
  const std::size_t n = t.size();
  auto lineOf = [&](std::size_t row) { return first_line + row; };
  for (std::size_t k = 1; k < n; ++k) {
    if (!(t[k] > t[k - 1])) {
      recordError(rec.source, lineOf(k),
           "time stamp " + limits::fmt(rec.t_origin_s + t[k], 12) + " s does not increase (previous " +
               limits::fmt(rec.t_origin_s + t[k - 1], 12) + " s)");
    }
  }
  if (n < 2 && !options.rate_hz) recordError(rec.source, 0, "one sample only and no rate given: the sample rate is unknown");
  // Time stamps printed with fewer digits than the step needs (400 Hz to the millisecond: steps of
  // 2 and 3 ms) are a uniform grid rounded, not irregular: the median step would give 500 Hz.
  const double rounding = n >= 3 ? roundedGridResolution(t, options.time_tolerance) : 0.0;
  if (rounding > 0.0) {
    const double span = (t[n - 1] - t[0]) / double(n - 1);
    if (options.rate_hz) {
      std::ostringstream what;
      what << "rounded to " << rounding << " s; their span gives";
      requireRateAgrees(rec, *options.rate_hz, 1.0 / span, what.str().c_str());
    }
    rec.rate_hz = options.rate_hz ? *options.rate_hz : 1.0 / span;
    rec.time_rounding_s = rounding;
    rec.irregular_count = 0;
    return;
  }
  double dt0 = 0.0;
  if (n >= 2) {
    std::vector<double> dt(n - 1);
    for (std::size_t k = 1; k < n; ++k) dt[k - 1] = t[k] - t[k - 1];
    auto mid = dt.begin() + static_cast<std::ptrdiff_t>(dt.size() / 2);
    std::nth_element(dt.begin(), mid, dt.end());
    dt0 = *mid;  // median step: robust to a few gaps
  }
  // Irregular steps are those off the stamps' own median step: a rate option 1 % off made every
  // regular step "irregular" (--rate 101 on 100 Hz stamps: 15250 irregular steps).
  if (n < 2) dt0 = 1.0 / *options.rate_hz;
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
  if (count == 0 && n >= 2) rec.rate_hz = double(n - 1) / (t[n - 1] - t[0]);
  if (options.rate_hz && n >= 2) {
    // Regular stamps: their span's rate, to 0.1 %. Irregular ones (allowed gaps, jitter): the
    // median step's, to the step tolerance.
    if (count == 0)
      requireRateAgrees(rec, *options.rate_hz, rec.rate_hz, "their span gives");
    else if (std::abs(1.0 / *options.rate_hz - dt0) > options.time_tolerance * dt0)
      requireRateAgrees(rec, *options.rate_hz, 1.0 / dt0, "their median step gives");
  }
  if (options.rate_hz) rec.rate_hz = *options.rate_hz;
  rec.irregular_count = count;
  if (count > 0 && !options.allow_irregular_time) {
    std::ostringstream os;
    os.precision(12);  // Unix time stamps: the fraction of a second shows
    os << count << " irregular time step(s) (nominal " << dt0 << " s, tolerance "
       << options.time_tolerance * 100 << " %); first at:";
    for (std::size_t i = 0; i < std::min<std::size_t>(found.size(), 5); ++i) {
      os << (i ? "," : "") << " line " << found[i].line << " (t = " << rec.t_origin_s + found[i].t << " s, dt = "
         << found[i].dt << " s" << (found[i].gap ? ", gap" : "") << ")";
    }
    os << ". Records are not resampled; fix the file or allow irregular time.";
    recordError(rec.source, 0, os.str());
  }
  rec.irregularities = std::move(found);
}

/// A record's sample rate must be one an IMU record can have (limits::kMinRate..kMaxRate).
void checkRate(double rate, const std::string& source, const std::string& what, const std::string& hint) {
  // A rate read from time stamps at a limit (10 us steps of 100 kHz) is a rounding off it.
  constexpr double slack = 1e-9;
  if (!(rate >= limits::kMinRate * (1 - slack) && rate <= limits::kMaxRate * (1 + slack)))
    recordError(source, 0, what + " " + limits::fmt(rate) + " Hz is outside what an IMU record can be (" +
                        limits::fmt(limits::kMinRate) + " to " + limits::fmt(limits::kMaxRate) +
                        " Hz; docs/limits.md)" + hint);
}

namespace {

/// The index of the first sample at or after `at` seconds into the record: on its time stamps
/// (measured from the first) when it has allowed irregular steps, whose samples no longer sit at
/// k / rate (after a 60-s gap, --skip 200 s counted 200 s of samples and landed at 260 s); k =
/// round(at * rate) otherwise. Half a step early counts as at.
std::size_t sampleAt(const Record& rec, double at) {
  if (rec.irregular_count == 0 || rec.t.empty())
    return static_cast<std::size_t>(std::llround(at * rec.rate_hz));
  const double target = rec.t.front() + at - 0.5 / rec.rate_hz;
  return static_cast<std::size_t>(std::lower_bound(rec.t.begin(), rec.t.end(), target) - rec.t.begin());
}

}  // namespace

/// Keeps the samples [skip, skip + duration) of the record (RecordOptions::skip_s, duration_s).
void applyWindow(Record& rec, const RecordOptions& o) {
  if (o.skip_s == 0.0 && !o.duration_s) return;
  // With gaps the record spans its stamps, not rows / rate.
  const bool stamped = rec.irregular_count > 0 && !rec.t.empty();
  const double total = stamped ? rec.t.back() - rec.t.front() + 1.0 / rec.rate_hz : rec.duration();
  // Compared in floating point first: a skip of 1e300 s must not reach an integer conversion.
  if (!(o.skip_s < total))
    recordError(rec.source, 0, "skip " + limits::fmt(o.skip_s) + " s leaves no samples (the record is " +
                            limits::fmt(total) + " s long)");
  const std::size_t first = std::min(sampleAt(rec, o.skip_s), rec.rows);
  std::size_t count = rec.rows - first;
  if (o.duration_s) {
    if (!(*o.duration_s <= total - o.skip_s + 0.5 / rec.rate_hz))
      recordError(rec.source, 0, "duration " + limits::fmt(*o.duration_s) + " s after a skip of " +
                              limits::fmt(o.skip_s) + " s is longer than the record (" +
                              limits::fmt(total) + " s)");
    count = std::min(count, stamped ? std::min(sampleAt(rec, o.skip_s + *o.duration_s), rec.rows) - first
                                    : static_cast<std::size_t>(std::llround(*o.duration_s * rec.rate_hz)));
  }
  if (count < 2) recordError(rec.source, 0, "skip and duration leave fewer than 2 samples");
  auto cut = [&](std::vector<double>& v) {
    if (v.empty()) return;
    v.erase(v.begin() + static_cast<std::ptrdiff_t>(first + count), v.end());
    v.erase(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(first));
  };
  rec.skipped_s = stamped && first < rec.rows ? rec.t[first] - rec.t.front() : double(first) / rec.rate_hz;
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
