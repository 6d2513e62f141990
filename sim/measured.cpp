#include "sim/measured.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "common/constants.hpp"
#include "common/error.hpp"
#include "common/limits.hpp"
#include "nav/attitude.hpp"

namespace sinsim::sim {

nav::Vec3 levelAttitude(const errormodels::Record& record, std::size_t n, double yaw) {
  n = std::min(n, record.size());
  if (n == 0) throw InputError(record.source + ": no samples to level from");
  double f[3] = {0, 0, 0};  // mean specific force [m/s^2]
  for (int a = 0; a < 3; ++a) {
    for (std::size_t k = 0; k < n; ++k) f[a] += record.accel[a][k];
    f[a] /= double(n);
  }
  return nav::Vec3(std::atan2(-f[1], -f[2]), std::atan2(f[0], std::hypot(f[1], f[2])), yaw);
}

Scenario staticScenario(const std::string& name, const MotionStart& start, double imuRate,
                        double outputRate, const nav::StrapdownOptions& strapdown,
                        double duration) {
  if (!(std::isfinite(start.lat) && std::abs(start.lat) <= limits::kMaxLatitude))
    throw InputError(name + ": expected a latitude within ±89 deg (the NED frame is singular at "
                     "the poles)");
  if (!(std::isfinite(start.lon) && std::isfinite(start.h) && std::isfinite(start.roll) &&
        std::isfinite(start.pitch) && std::isfinite(start.heading)))
    throw InputError(name + ": the start position and attitude must be finite");
  if (!(std::abs(start.pitch) < kPi / 2))
    throw InputError(name + ": expected a pitch within ±90 deg");
  if (!(std::isfinite(imuRate) && imuRate > 0 && std::isfinite(outputRate) && outputRate > 0))
    throw InputError(name + ": expected positive IMU and output rates");
  const double ratio = imuRate / outputRate;
  if (!(ratio >= 1.0 - 1e-9 && std::abs(ratio - std::round(ratio)) < 1e-6))
    throw InputError(name + ": the output rate must divide the IMU rate into a whole number of "
                     "samples");
  Scenario sc;
  sc.name = name;
  sc.start = start;
  sc.start.lon = nav::wrapAngle(start.lon);
  sc.start.speed = 0.0;
  sc.imuRate = imuRate;
  sc.outputRate = outputRate;
  sc.strapdown = strapdown;
  Segment seg;
  seg.kind = SegmentKind::Static;
  seg.type = "static";
  seg.duration = duration;
  PlanCursor c;
  c.heading = sc.start.heading;
  c.h = sc.start.h;
  const std::string problem = planSegment(seg, c);
  if (!problem.empty()) throw InputError(name + ": " + problem);
  sc.segments.push_back(seg);
  return sc;
}

namespace {

void dropHead(errormodels::Record& r, std::size_t k) {
  auto drop = [k](std::vector<double>& v) {
    if (!v.empty()) v.erase(v.begin(), v.begin() + long(k));
  };
  for (int ax = 0; ax < 3; ++ax) {
    drop(r.gyro[ax]);
    drop(r.accel[ax]);
  }
  drop(r.t);
  drop(r.temperature);
  r.rows -= k;
}

// Every value the static scenario is built from, exactly (hexadecimal floats), for resume checks.
std::string identityText(const Scenario& sc) {
  char buf[512];
  const MotionStart& s = sc.start;
  std::snprintf(buf, sizeof buf,
                "static %s lat %a lon %a h %a roll %a pitch %a yaw %a imu %a out %a vertical %d "
                "tau %a duration %a",
                sc.name.c_str(), s.lat, s.lon, s.h, s.roll, s.pitch, s.heading, sc.imuRate,
                sc.outputRate, int(sc.strapdown.vertical), sc.strapdown.dampingTimeConstant,
                sc.duration());
  return buf;
}

}  // namespace

MeasuredSetup prepareMeasured(const MeasuredOptions& o) {
  return measuredSetup(errormodels::loadRecord(o.path, o.record), o);
}

MeasuredSetup measuredSetup(errormodels::Record record, const MeasuredOptions& o) {
  MeasuredSetup m;
  m.record = std::move(record);
  errormodels::Record& rec = m.record;
  for (int ax = 0; ax < 3; ++ax)
    if (!rec.hasGyro(ax) || !rec.hasAccel(ax))
      throw InputError(rec.source + ": the record needs the columns gx, gy, gz, ax, ay, az; " +
                       errormodels::sensorColumnsHint(rec));
  const double rate = rec.rate_hz;
  if (o.skip != 0.0) {  // drop a warm-up: the navigation starts after it
    const auto k = std::size_t(std::llround(std::max(0.0, o.skip) * rate));
    if (k >= rec.size())
      throw InputError("--skip " + std::to_string(o.skip) + " s leaves nothing of " + rec.source);
    dropHead(rec, k);
  }
  std::size_t n = rec.size();
  if (o.duration) {
    if (!(*o.duration > 0)) throw InputError("--duration must be positive");
    n = std::min(n, std::size_t(std::llround(*o.duration * rate)));
  }
  if (!(std::isfinite(o.outputRate) && o.outputRate > 0))
    throw InputError("--output-rate must be positive");
  const auto perOut = std::llround(rate / o.outputRate);
  if (perOut < 1) throw InputError(rec.source + ": the output rate exceeds the record's rate");
  n -= n % std::size_t(perOut);  // whole output epochs
  if (n == 0) throw InputError(rec.source + ": the record is shorter than one output epoch");
  m.biasWindow = o.biasWindow ? *o.biasWindow : std::min(60.0, 0.1 * double(n) / rate);
  // Here, with the record's name (the loop's own check named neither it nor diagnose's option).
  if (!(m.biasWindow <= double(n) / rate + 0.5 / rate))
    throw InputError(rec.source + ": the bias window (" + o.biasWindowOption + ") of " + limits::fmt(m.biasWindow) +
                     " s is longer than the record used (" + limits::fmt(double(n) / rate) + " s" +
                     (o.duration ? ", the shorter of the record and " + limits::fmt(*o.duration) + " s" : "") + ")");

  MotionStart start;
  start.lat = o.lat;
  start.lon = o.lon;
  start.h = o.h;
  const nav::Vec3 rpy =
      o.attitude ? *o.attitude
                 : levelAttitude(rec, std::size_t(std::llround(std::max(m.biasWindow, 1.0) * rate)),
                                 o.heading);
  start.roll = rpy.x();
  start.pitch = rpy.y();
  start.heading = rpy.z();
  const std::string name = "measured-" + std::filesystem::path(rec.source).stem().stem().string();
  m.scenario = staticScenario(name, start, rate, o.outputRate, o.strapdown, double(n) / rate);
  m.identity = identityText(m.scenario);
  return m;
}

McMeasured navigateMeasured(const MeasuredSetup& setup, const Reference& ref,
                            const NavigateOptions& options) {
  if (!ref.aiding.inert())
    throw InputError("mc --measured: the scenario " + ref.name + " has aiding keys (initial_errors, "
                     "alignment, gnss, filter); a measured record is replayed free-inertially "
                     "only, so its drift would not compare with the aided runs");
  McMeasured measured;
  measured.source = setup.record.source;
  measured.errors.resize(ref.epochs() * kErrorFields);
  RecordSource source(ref, setup.record);
  navigateErrors(source, ref, options, measured.errors.data());
  return measured;
}

}  // namespace sinsim::sim
