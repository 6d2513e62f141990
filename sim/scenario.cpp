#include "sim/scenario.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "common/config.hpp"
#include "common/constants.hpp"
#include "common/limits.hpp"
#include "nav/attitude.hpp"
#include "sim/scenario_segments.hpp"

namespace sinsim::sim {
namespace {

namespace fs = std::filesystem;
using D = Dimension;

void parseStart(const ConfigNode& root, Scenario& sc) {
  const ConfigNode s = root.require("start");
  if (!s.exists()) return;
  s.allowKeys({"latitude", "longitude", "height", "speed", "heading", "attitude"});
  MotionStart& m = sc.start;
  m.lat = s.quantity("latitude", D::angle());
  if (std::isfinite(m.lat))
    s["latitude"].check(std::abs(m.lat) <= limits::kMaxLatitude,
                        "expected a latitude within ±89 deg (the NED frame is singular at the poles)");
  m.lon = s.quantity("longitude", D::angle());
  if (std::isfinite(m.lon) &&
      s["longitude"].check(std::abs(m.lon) <= 2.0 * kPi, "expected a longitude within ±360 deg"))
    m.lon = nav::wrapAngle(m.lon);  // the outputs' (−180°, 180°]
  m.h = s.quantity("height", D::length(), 0.0);
  if (std::isfinite(m.h))
    s["height"].check(m.h >= limits::kMinHeight && m.h <= limits::kMaxHeight,
                      "expected a height from " + limits::fmt(limits::kMinHeight) + " m to " +
                          limits::fmt(limits::kMaxHeight) + " m (docs/limits.md)");
  m.speed = s.quantity("speed", D::speed(), 0.0);
  if (std::isfinite(m.speed) && s["speed"].check(m.speed >= 0.0, "expected a speed ≥ 0"))
    s["speed"].check(m.speed <= limits::kMaxSpeed, "expected a speed of at most " +
                                                       limits::fmt(limits::kMaxSpeed) +
                                                       " m/s (docs/limits.md)");
  const ConfigNode att = s["attitude"];
  att.allowKeys({"roll", "pitch", "yaw"});
  m.roll = att.quantity("roll", D::angle(), 0.0);
  m.pitch = att.quantity("pitch", D::angle(), 0.0);
  if (std::isfinite(m.pitch))
    att["pitch"].check(std::abs(m.pitch) < 90.0 * kRadPerDeg, "expected a pitch strictly between -90 and 90 deg (the Euler angles are singular at ±90)");
  if (att.has("yaw") && s.has("heading")) {
    att["yaw"].error("give the heading or attitude.yaw, not both");
  }
  m.heading = att.has("yaw") ? att.quantity("yaw", D::angle(), 0.0)
                             : s.quantity("heading", D::angle(), 0.0);
}

void parseVertical(const ConfigNode& root, Scenario& sc) {
  const ConfigNode v = root["vertical"];
  if (!v.exists()) return;
  std::string mode;
  double tau = sc.strapdown.dampingTimeConstant;
  ConfigNode modeNode = v;
  if (v.isMap()) {
    v.allowKeys({"channel", "time_constant"});
    modeNode = v.require("channel");
    if (!modeNode.exists()) return;
    tau = v.quantity("time_constant", D::time(), tau);
    if (v.has("time_constant"))
      v["time_constant"].check(std::isfinite(tau) && tau > 0.0,
                               "expected a positive time constant");
  }
  mode = modeNode.asString().value_or("");
  if (mode == "free") {
    sc.strapdown.vertical = nav::VerticalChannel::Free;
  } else if (mode == "held") {
    sc.strapdown.vertical = nav::VerticalChannel::Held;
  } else if (mode == "damped") {
    sc.strapdown.vertical = nav::VerticalChannel::Damped;
  } else {
    modeNode.error("\"" + mode + "\" is not one of: free, held, damped");
    return;
  }
  if (v.isMap() && v.has("time_constant") && mode != "damped")
    v["time_constant"].error("a time constant applies to the damped channel only");
  sc.strapdown.dampingTimeConstant = tau;
}

errormodels::ImuErrorModel parseErrors(const ConfigNode& root, const std::string& baseDir,
                                       std::vector<Diagnostic>& foreign) {
  const ConfigNode e = root["errors"];
  if (!e.exists()) return errormodels::ImuErrorModel::none();
  if (e.isMap()) return errormodels::ImuErrorModel::parse(e);
  const auto text = e.asString();
  if (!text) return errormodels::ImuErrorModel::none();
  if (*text == "none") return errormodels::ImuErrorModel::none();
  fs::path path(*text);
  if (path.is_relative()) path = fs::path(baseDir) / path;
  try {
    return errormodels::ImuErrorModel::load(path.lexically_normal().string());
  } catch (const ConfigError& err) {
    // A problem of the whole file (a folder, a device, empty, too large) is reported at the
    // scenario's `errors:` line too; problems inside the model name its own lines.
    for (const Diagnostic& d : err.diagnostics()) {
      if (d.line == 0 && d.key.empty()) e.error(d.file + ": " + d.message);
      else foreign.push_back(d);
    }
  } catch (const InputError& err) {
    e.error(err.what());
  }
  return errormodels::ImuErrorModel::none();
}

/// Coarse alignment averages the IMU over the first `duration` seconds as if the vehicle stood
/// still (docs/aided.md): a moving start, or a window longer than the static start, would level
/// and gyrocompass on the motion and start the filter kilometres off, silently.
void checkAlignmentAtRest(const ConfigNode& root, const Scenario& sc) {
  const double T = sc.aiding.alignment.duration;
  if (!(T > 0.0) || sc.segments.empty()) return;
  const ConfigNode n = root["alignment"]["duration"];
  for (const Segment& g : sc.segments) {
    if (g.t0 >= T * (1.0 - 1e-12)) return;
    const bool atRest = g.kind == SegmentKind::Static || (g.kind == SegmentKind::Cruise && g.speed0 == 0.0);
    if (atRest) continue;
    std::string how = g.type + " segment";
    if (g.speed0 != 0.0) how += ", at " + limits::fmt(g.speed0) + " m/s";
    n.error("coarse alignment needs the vehicle at rest for its " + limits::fmt(T) +
            " s, but it moves from t = " + limits::fmt(g.t0) + " s (" + how +
            "): start with a static segment at least that long, or shorten the alignment");
    return;
  }
  n.check(sc.duration() >= T * (1.0 - 1e-12), "the alignment is longer than the scenario (" +
                                                 limits::fmt(sc.duration()) + " s)");
}

Scenario parse(ConfigFile& file, const std::string& baseDir) {
  ConfigNode root = file.root();
  Scenario sc;
  sc.file = file.name();
  if (!root.isMap()) {
    root.error("expected a scenario map with keys start, segments, ...");
    file.throwIfErrors();
  }
  std::vector<std::string> keys = {"name",   "description", "start", "imu_rate", "output_rate",
                                   "vertical", "errors", "temperature", "seed", "segments"};
  keys.insert(keys.end(), aided::aidingKeys().begin(), aided::aidingKeys().end());
  root.allowKeys(keys);
  sc.name = root.string("name", fs::path(file.name()).stem().string());
  sc.description = root.string("description", "");
  parseStart(root, sc);

  sc.imuRate = root.quantity("imu_rate", D::frequency(), 100.0);
  root["imu_rate"].check(std::isfinite(sc.imuRate) && sc.imuRate >= limits::kMinRate,
                         "expected a rate of at least " + limits::fmt(limits::kMinRate) + " Hz");
  sc.outputRate = root.quantity("output_rate", D::frequency(), 1.0);
  if (root["output_rate"].check(std::isfinite(sc.outputRate) && sc.outputRate > 0.0,
                                "expected a positive rate") &&
      std::isfinite(sc.imuRate) && sc.imuRate > 0.0) {
    const double ratio = sc.imuRate / sc.outputRate;
    root["output_rate"].check(ratio >= 1.0 - 1e-9 && std::abs(ratio - std::round(ratio)) < 1e-6,
                              "the output rate must divide the IMU rate (" + limits::fmt(sc.imuRate) +
                                  " Hz) into a whole number of samples");
  }
  parseVertical(root, sc);

  if (root.has("seed")) {
    const long long seed = root.integer("seed");
    if (root["seed"].check(seed >= 0, "expected a seed ≥ 0"))
      sc.seed = static_cast<std::uint64_t>(seed);
  }

  const ConfigNode segs = root.require("segments");
  const std::size_t problemsBefore = file.diagnostics().size();
  sc.segments = detail::readSegments(segs, sc.start, file);
  // A refused segment leaves the scenario's length unknown: no follow-on "after the end" errors.
  const double knownDuration = file.diagnostics().size() == problemsBefore ? sc.duration() : NAN;

  sc.temperature = readTemperature(root["temperature"], sc.duration());
  sc.aiding = aided::parseAiding(root, baseDir, knownDuration, sc.imuRate, sc.temperature.present);
  checkAlignmentAtRest(root, sc);
  // A fix is applied at an IMU epoch: GNSS at 100 kHz with a 100 Hz IMU ran as if it were 100 Hz.
  if (sc.aiding.gnss.enabled && std::isfinite(sc.imuRate) && sc.imuRate > 0.0 && sc.aiding.gnss.rate > sc.imuRate)
    root["gnss"]["rate"].error("GNSS at " + limits::fmt(sc.aiding.gnss.rate) +
                               " Hz is faster than the IMU (" + limits::fmt(sc.imuRate) +
                               " Hz): fixes are applied at IMU epochs");

  std::vector<Diagnostic> foreign;
  sc.errors = parseErrors(root, baseDir, foreign);
  if (!sc.errors.empty() && sc.errors.needsTemperature() && !sc.temperature.present)
    root["errors"].error("the error model has temperature-dependent effects: give the scenario "
                         "a temperature (e.g. temperature: 25 degC)");

  if (!file.hasErrors() && foreign.empty()) {
    const double T = sc.duration();
    if (!(T > 0.0)) {
      segs.error("the segments add up to no time at all");
    } else if (!(T <= limits::kMaxDuration)) {
      segs.error("the segments add up to " + limits::fmt(T) + " s, more than " +
                 limits::fmt(limits::kMaxDuration) + " s (10 days; docs/limits.md)");
    } else if (limits::tooManySamples(T, sc.imuRate)) {
      segs.error(limits::fmt(T) + " s at " + limits::fmt(sc.imuRate) + " Hz is " +
                 limits::fmt(T * sc.imuRate) + " IMU samples, more than " +
                 limits::fmt(limits::kMaxSamples) + " (docs/limits.md)");
    } else if (T * sc.imuRate < 1.0 - 1e-9) {
      segs.error("the segments add up to " + limits::fmt(T) + " s, less than one IMU sample at " +
                 limits::fmt(sc.imuRate) + " Hz");
    }
  }

  if (file.hasErrors() || !foreign.empty()) {
    std::vector<Diagnostic> all = file.diagnostics();
    all.insert(all.end(), foreign.begin(), foreign.end());
    throw ConfigError(all);
  }
  return sc;
}

}  // namespace

double Scenario::duration() const {
  return segments.empty() ? 0.0 : segments.back().t1();
}

long long Scenario::decimation() const {
  return std::max(1LL, std::llround(imuRate / outputRate));
}

std::string Scenario::durationWarning() const {
  const double T = duration(), n = T * imuRate;
  if (segments.empty() || !std::isfinite(n)) return {};
  const double end = double(std::llround(n)) / imuRate;
  // Warned where the end moves by more than 0.1 % of the last segment (a 1.005-s acceleration at
  // 100 Hz ended 5 ms early, short of its speed); a turn whose bank sets its duration leaves a
  // fraction of a sample on any long scenario, which is no news.
  if (!(std::abs(end - T) > 1e-3 * segments.back().duration)) return {};
  return "the segments add up to " + limits::fmt(T, 9) + " s, not a whole number of IMU intervals (" +
         limits::fmt(1.0 / imuRate) + " s): the run ends at the nearest sample, " + limits::fmt(end, 9) +
         " s (" + (end < T ? "before the last segment ends" : "the last segment's end state held after it") + ")";
}

void requireTemperatureFor(const Scenario& sc, const errormodels::ImuErrorModel& model,
                           const std::string& label) {
  if (model.empty() || !model.needsTemperature() || sc.temperature.present) return;
  throw InputError((sc.file.empty() ? "scenario " + sc.name : sc.file) + ": no temperature: key, while the error model " +
                   label + " has temperature-dependent effects; add one to the scenario (e.g. "
                   "temperature: 25 degC, or {start: 20 degC, end: 45 degC})");
}

Scenario loadScenario(const std::string& path) {
  ConfigFile file = ConfigFile::load(path);
  const fs::path dir = fs::path(path).parent_path();
  return parse(file, dir.empty() ? "." : dir.string());
}

Scenario parseScenario(ConfigFile& file, const std::string& baseDir) {
  return parse(file, baseDir);
}

Scenario parseScenario(const std::string& text, const std::string& name,
                       const std::string& baseDir) {
  ConfigFile file = ConfigFile::fromString(text, name);
  return parse(file, baseDir);
}

}  // namespace sinsim::sim
