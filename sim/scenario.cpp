#include "sim/scenario.hpp"

#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <sstream>

#include "common/config.hpp"
#include "common/constants.hpp"
#include "common/limits.hpp"
#include "nav/attitude.hpp"

namespace sinsim::sim {
namespace {

namespace fs = std::filesystem;
using D = Dimension;

// |latitude| limit: lon' = vE/((N+h) cos lat) is singular at the poles.
constexpr double kMaxLatitude = 89.0 * kRadPerDeg;
// Largest coordinated bank a turn may ask for; tan φ grows without bound towards 90°.
constexpr double kMaxBank = 80.0 * kRadPerDeg;
using limits::kMaxSegments;

std::string fmt(double x) {
  std::ostringstream os;
  os.precision(6);
  os << x;
  return os.str();
}

// ---------------------------------------------------------------------------------------------
// Segments are parsed into specs first (targets still symbolic), then laid out in time by
// `layout`, which resolves absolute targets against the running state. Repeats are specs with a
// body; their body is parsed once and laid out `count` times.

enum class Target { None, Change, Absolute };

struct SegmentSpec {
  ConfigNode node;
  Segment seg;                     // kind, type, duration (NaN when derived), change
  Target target = Target::None;    // how `value` is meant
  double value = 0.0;              // a change or an absolute target (SI)
  double bankAngle = 0.0;          // turns with `bank: <angle>`: the duration follows [rad]
  bool decelerate = false;         // `decelerate`: target must not exceed the current speed
  long long count = 0;             // repeat
  std::vector<SegmentSpec> body;   // repeat
  explicit SegmentSpec(const ConfigNode& n) : node(n) {}
};

struct SegmentType {
  SegmentKind kind;
  std::vector<std::string> keys;  // besides `type`
  std::function<void(const ConfigNode&, SegmentSpec&)> parse;
};

std::vector<SegmentSpec> parseSegmentList(const ConfigNode& list);

double readDuration(const ConfigNode& n) {
  const ConfigNode d = n.require("duration");
  if (!d.exists()) return NAN;
  const auto v = d.asQuantity(D::time());
  if (!v) return NAN;
  if (!d.check(std::isfinite(*v) && *v > 0.0,
               "expected a positive duration, got \"" + limits::echo(d.asString().value_or("")) +
                   "\""))
    return NAN;
  if (!d.check(*v >= limits::kMinSegmentDuration && *v <= limits::kMaxDuration,
               "expected a duration from " + limits::fmt(limits::kMinSegmentDuration) + " s to " +
                   limits::fmt(limits::kMaxDuration) + " s (10 days), got \"" +
                   limits::echo(d.asString().value_or("")) + "\" (docs/limits.md)"))
    return NAN;
  return *v;
}

// accelerate / decelerate: a target speed ≥ 0 over the duration (decelerate refuses to speed up).
void readSpeedChange(const ConfigNode& n, SegmentSpec& s, bool decelerate) {
  s.seg.duration = readDuration(n);
  const double v = n.quantity("speed", D::speed());
  if (std::isfinite(v) && !n["speed"].check(v >= 0.0, "expected a speed ≥ 0")) return;
  s.target = Target::Absolute;
  s.value = v;
  s.decelerate = decelerate;
}

// Exactly one of `absKey` (a target) and `changeKey` (a change) must be given.
void readTarget(const ConfigNode& n, SegmentSpec& sp, const std::string& absKey,
                const std::string& changeKey, Dimension dim) {
  const bool hasAbs = n.has(absKey), hasChange = n.has(changeKey);
  if (hasAbs == hasChange) {
    n.error("give either " + absKey + " (the target) or " + changeKey + " (the change), " +
            (hasAbs ? "not both" : "one is missing"));
    return;
  }
  const ConfigNode c = n[hasAbs ? absKey : changeKey];
  sp.target = hasAbs ? Target::Absolute : Target::Change;
  sp.value = c.asQuantity(dim).value_or(NAN);
}

const std::map<std::string, SegmentType>& registry() {
  static const std::map<std::string, SegmentType> types = {
      {"static", {SegmentKind::Static, {"duration"}, [](const ConfigNode& n, SegmentSpec& s) {
                    s.seg.duration = readDuration(n);
                  }}},
      {"cruise", {SegmentKind::Cruise, {"duration"}, [](const ConfigNode& n, SegmentSpec& s) {
                    s.seg.duration = readDuration(n);
                  }}},
      {"accelerate",
       {SegmentKind::Accelerate, {"duration", "speed"},
        [](const ConfigNode& n, SegmentSpec& s) { readSpeedChange(n, s, false); }}},
      {"decelerate",
       {SegmentKind::Accelerate, {"duration", "speed"},
        [](const ConfigNode& n, SegmentSpec& s) { readSpeedChange(n, s, true); }}},
      {"turn",
       {SegmentKind::Turn, {"duration", "heading", "heading_change", "bank"},
        [](const ConfigNode& n, SegmentSpec& s) {
          readTarget(n, s, "heading", "heading_change", D::angle());
          const ConfigNode b = n["bank"];
          std::string mode = b.exists() ? b.asString().value_or("none") : "none";
          if (mode == "none") {
            s.seg.bank = BankMode::None;
          } else if (mode == "auto") {
            s.seg.bank = BankMode::Coordinated;
          } else {
            s.seg.bank = BankMode::Coordinated;
            const auto a = b.asQuantity(D::angle());
            if (a && b.check(*a > 0.0 && *a <= kMaxBank,
                             "expected none, auto or a bank angle in (0, 80] deg"))
              s.bankAngle = *a;
          }
          if (s.bankAngle > 0.0) {
            if (n.has("duration"))
              n["duration"].error(
                  "a turn with a bank angle takes the time that angle needs; give either "
                  "duration (with bank: auto) or the bank angle, not both");
            s.seg.duration = NAN;  // derived in layout
          } else {
            s.seg.duration = readDuration(n);
          }
        }}},
      {"climb",
       {SegmentKind::Climb, {"duration", "height", "height_change"},
        [](const ConfigNode& n, SegmentSpec& s) {
          s.seg.duration = readDuration(n);
          readTarget(n, s, "height", "height_change", D::length());
          if (s.target == Target::Change && std::isfinite(s.value))
            n["height_change"].check(s.value > 0.0,
                                     "expected a positive height change (use descend to go down)");
        }}},
      {"descend",
       {SegmentKind::Climb, {"duration", "height", "height_change"},
        [](const ConfigNode& n, SegmentSpec& s) {
          s.seg.duration = readDuration(n);
          readTarget(n, s, "height", "height_change", D::length());
          if (s.target == Target::Change && std::isfinite(s.value)) {
            n["height_change"].check(s.value > 0.0,
                                     "expected a positive height change (how far down to go)");
            s.value = -s.value;
          }
        }}},
      {"pitch", {SegmentKind::Pitch, {"duration", "angle"}, [](const ConfigNode& n, SegmentSpec& s) {
                   s.seg.duration = readDuration(n);
                   s.seg.change = n.quantity("angle", D::angle());
                   s.target = Target::Change;
                   s.value = s.seg.change;
                 }}},
      {"roll", {SegmentKind::Roll, {"duration", "angle"}, [](const ConfigNode& n, SegmentSpec& s) {
                  s.seg.duration = readDuration(n);
                  s.seg.change = n.quantity("angle", D::angle());
                  s.target = Target::Change;
                  s.value = s.seg.change;
                }}},
  };
  return types;
}

std::string joinNames(const std::vector<std::string>& xs) {
  std::string s;
  for (const auto& x : xs) s += (s.empty() ? "" : ", ") + x;
  return s;
}

SegmentSpec parseSegment(const ConfigNode& n) {
  SegmentSpec sp(n);
  if (!n.isMap()) {
    n.error("expected a segment map such as {type: cruise, duration: 60 s}");
    return sp;
  }
  const ConfigNode typeNode = n.require("type");
  if (!typeNode.exists()) return sp;
  const std::string type = typeNode.asString().value_or("");
  sp.seg.type = type;
  if (type == "repeat") {
    n.allowKeys({"type", "count", "segments"});
    sp.count = n.integer("count");
    if (n.has("count")) n["count"].check(sp.count >= 1, "expected a count ≥ 1");
    sp.body = parseSegmentList(n.require("segments"));
    return sp;
  }
  const auto& reg = registry();
  const auto it = reg.find(type);
  if (it == reg.end()) {
    typeNode.error("unknown segment type \"" + type + "\" (known: " + joinNames(segmentTypes()) +
                   ")");
    return sp;
  }
  std::vector<std::string> keys{"type"};
  keys.insert(keys.end(), it->second.keys.begin(), it->second.keys.end());
  n.allowKeys(keys);
  sp.seg.kind = it->second.kind;
  it->second.parse(n, sp);
  return sp;
}

std::vector<SegmentSpec> parseSegmentList(const ConfigNode& list) {
  std::vector<SegmentSpec> out;
  if (!list.exists()) return out;
  const auto items = list.items();
  if (list.isSequence() && items.empty()) list.error("expected at least one segment");
  for (const auto& item : items) out.push_back(parseSegment(item));
  return out;
}

// Number of segments the specs expand to, saturating at kMaxSegments + 1 (no overflow however
// deep the repeats nest): checked before anything is expanded.
std::size_t expandedCount(const std::vector<SegmentSpec>& specs) {
  std::size_t n = 0;
  for (const SegmentSpec& sp : specs) {
    std::size_t add = 1;
    if (sp.seg.type == "repeat") {
      const std::size_t body = expandedCount(sp.body);
      const std::size_t count = sp.count > 0 ? static_cast<std::size_t>(sp.count) : 0;
      add = body == 0 ? 0 : (count > (kMaxSegments + 1) / body ? kMaxSegments + 1 : count * body);
    }
    n = std::min(n + add, kMaxSegments + 1);
  }
  return n;
}

// Speed and height stay inside limits:: ranges after every segment: beyond them the Earth model
// and the trajectory's products overflow (height 1e308 m gives NaN gravity).
std::string motionOutOfRange(const PlanCursor& c) {
  if (!(c.h >= limits::kMinHeight && c.h <= limits::kMaxHeight))
    return "the height reaches " + limits::fmt(c.h) + " m, outside [" +
           limits::fmt(limits::kMinHeight) + ", " + limits::fmt(limits::kMaxHeight) +
           "] m (docs/limits.md)";
  if (!(c.speed <= limits::kMaxSpeed))
    return "the speed reaches " + limits::fmt(c.speed) + " m/s, above " +
           limits::fmt(limits::kMaxSpeed) + " m/s (docs/limits.md)";
  return "";
}

// Lays the specs out in time, resolving targets; returns false after the first problem so that
// one wrong segment does not produce a cascade of follow-up messages.
bool layout(const std::vector<SegmentSpec>& specs, PlanCursor& c, std::vector<Segment>& out,
            const std::string& note) {
  for (const SegmentSpec& sp : specs) {
    if (sp.seg.type == "repeat") {
      for (long long k = 0; k < sp.count; ++k)
        if (!layout(sp.body, c, out,
                    sp.count > 1 ? " (repetition " + std::to_string(k + 1) + " of " +
                                       std::to_string(sp.count) + ")" + note
                                 : note))
          return false;
      continue;
    }
    if (out.size() >= kMaxSegments) {
      sp.node.error("more than " + std::to_string(kMaxSegments) + " segments after repeats");
      return false;
    }
    Segment seg = sp.seg;
    switch (seg.kind) {
      case SegmentKind::Accelerate:
        seg.change = sp.value - c.speed;
        if (sp.decelerate && sp.value > c.speed) {
          sp.node.error("decelerate to " + fmt(sp.value) + " m/s from " + fmt(c.speed) +
                        " m/s would speed up (use accelerate)" + note);
          return false;
        }
        break;
      case SegmentKind::Turn:
        seg.change = sp.target == Target::Absolute ? nav::wrapAngle(sp.value - c.heading)
                                                   : sp.value;
        if (sp.bankAngle > 0.0) {
          if (!(c.speed > 0.0)) {
            sp.node.error("a turn with a bank angle needs forward speed; give a duration" + note);
            return false;
          }
          // coordinated peak bank: tan φ = s ψ̇_max / g0 with ψ̇_max = 2Δψ/T
          seg.duration = 2.0 * c.speed * std::abs(seg.change) / (kBankGravity * std::tan(sp.bankAngle));
          if (!(seg.duration > 0.0)) {
            sp.node.error("the turn changes the heading by 0 deg" + note);
            return false;
          }
        }
        break;
      case SegmentKind::Climb: {
        const double change = sp.target == Target::Absolute ? sp.value - c.h : sp.value;
        const bool climb = sp.seg.type == "climb";
        if (sp.target == Target::Absolute && (climb ? change <= 0.0 : change >= 0.0)) {
          sp.node.error(sp.seg.type + " to " + fmt(sp.value) + " m from " + fmt(c.h) + " m " +
                        (climb ? "does not go up (use descend)" : "does not go down (use climb)") +
                        note);
          return false;
        }
        seg.change = change;
        break;
      }
      default:
        break;
    }
    std::string problem = planSegment(seg, c);
    if (problem.empty()) problem = motionOutOfRange(c);
    if (!problem.empty()) {
      sp.node.error(problem + note);
      return false;
    }
    out.push_back(seg);
  }
  return true;
}

bool anyInvalid(const std::vector<SegmentSpec>& specs) {
  for (const auto& sp : specs) {
    if (sp.seg.type == "repeat") {
      if (sp.count < 1 || anyInvalid(sp.body)) return true;
      continue;
    }
    if (sp.seg.type.empty() || registry().count(sp.seg.type) == 0) return true;
    if (!std::isfinite(sp.value)) return true;
    if (!std::isfinite(sp.seg.duration) && !(sp.bankAngle > 0.0)) return true;
  }
  return false;
}

// ---------------------------------------------------------------------------------------------

void parseStart(const ConfigNode& root, Scenario& sc) {
  const ConfigNode s = root.require("start");
  if (!s.exists()) return;
  s.allowKeys({"latitude", "longitude", "height", "speed", "heading", "attitude"});
  MotionStart& m = sc.start;
  m.lat = s.quantity("latitude", D::angle());
  if (std::isfinite(m.lat))
    s["latitude"].check(std::abs(m.lat) <= kMaxLatitude,
                        "expected a latitude within ±89 deg (the NED frame is singular at the poles)");
  m.lon = s.quantity("longitude", D::angle());
  if (std::isfinite(m.lon)) m.lon = nav::wrapAngle(m.lon);
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
    att["pitch"].check(std::abs(m.pitch) < 90.0 * kRadPerDeg, "expected a pitch within ±90 deg");
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

void parseTemperature(const ConfigNode& root, Scenario& sc, double duration) {
  const ConfigNode t = root["temperature"];
  if (!t.exists()) return;
  TemperatureProfile& p = sc.temperature;
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
    foreign.insert(foreign.end(), err.diagnostics().begin(), err.diagnostics().end());
  } catch (const InputError& err) {
    e.error(err.what());
  }
  return errormodels::ImuErrorModel::none();
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
                              "the output rate must divide the IMU rate (" + fmt(sc.imuRate) +
                                  " Hz) into a whole number of samples");
  }
  parseVertical(root, sc);

  if (root.has("seed")) {
    const long long seed = root.integer("seed");
    if (root["seed"].check(seed >= 0, "expected a seed ≥ 0"))
      sc.seed = static_cast<std::uint64_t>(seed);
  }

  const ConfigNode segs = root.require("segments");
  const std::vector<SegmentSpec> specs = parseSegmentList(segs);
  // Lay out only what parsed cleanly (and from a valid start): a bad value would otherwise
  // produce follow-up messages about a state that does not exist.
  if (!anyInvalid(specs) && !file.hasErrors() && expandedCount(specs) > kMaxSegments)
    segs.error("the repeats expand to more than " + std::to_string(kMaxSegments) +
               " segments (docs/limits.md)");
  if (!anyInvalid(specs) && !file.hasErrors()) {
    PlanCursor c;
    c.speed = sc.start.speed;
    c.heading = sc.start.heading;
    c.h = sc.start.h;
    layout(specs, c, sc.segments, "");
  }

  parseTemperature(root, sc, sc.duration());
  sc.aiding = aided::parseAiding(root, baseDir, sc.duration());

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

std::vector<std::string> segmentTypes() {
  std::vector<std::string> names;
  for (const auto& kv : registry()) names.push_back(kv.first);
  names.push_back("repeat");
  return names;
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
