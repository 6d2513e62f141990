// The scenario's segment list: registry, parse and layout (scenario_segments.hpp).
#include "sim/scenario_segments.hpp"

#include <cctype>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>

#include "common/constants.hpp"
#include "common/limits.hpp"
#include "sim/scenario.hpp"

namespace sinsim::sim {
namespace {

using D = Dimension;

// Largest coordinated bank a turn may ask for; tan φ grows without bound towards 90°.
constexpr double kMaxBank = 80.0 * kRadPerDeg;
using limits::kMaxSegments;

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
  std::shared_ptr<const std::vector<SegmentSpec>> body;  // repeat (shared by its aliases)
  explicit SegmentSpec(const ConfigNode& n) : node(n) {}
};

// Segments already parsed, by the position of their YAML node in the text. An alias (*name) is
// the very node it names, so a segment reached through many aliases is parsed, and its problems
// reported, once: a 600-byte file of nested aliases reaches ~100,000 segments within the node
// limit, and parsing every copy anew took 0.6 s of CPU (3 s in the sanitizer build).
using ParsedSegments = std::unordered_map<std::size_t, SegmentSpec>;

struct SegmentType {
  SegmentKind kind;
  std::vector<std::string> keys;  // besides `type`
  std::function<void(const ConfigNode&, SegmentSpec&)> parse;
};

std::vector<SegmentSpec> parseSegmentList(const ConfigNode& list, ParsedSegments& parsed);

double readDuration(const ConfigNode& n) {
  const ConfigNode d = n.require("duration");
  if (!d.exists()) return NAN;
  const auto v = d.asQuantity(D::time());
  if (!v) return NAN;
  if (!d.check(std::isfinite(*v) && *v > 0.0,
               "expected a positive duration, got \"" + limits::echo(d.asString().value_or("")) +
                   "\""))
    return NAN;
  // 1e-12 relative: "10 us" is 10 * 1e-6 = 9.999999999999999e-06 s, below 1e-5 by rounding.
  if (!d.check(*v >= limits::kMinSegmentDuration * (1.0 - 1e-12) && *v <= limits::kMaxDuration,
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

SegmentSpec parseSegment(const ConfigNode& n, ParsedSegments& parsed) {
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
    const ConfigNode countNode = n.require("count");
    if (countNode.exists()) {
      const std::optional<long long> count = countNode.asInteger();  // reports a non-integer
      sp.count = count.value_or(0);
      if (count) countNode.check(*count >= 1, "expected a count ≥ 1");  // once: not after "2.5"
    }
    sp.body = std::make_shared<const std::vector<SegmentSpec>>(
        parseSegmentList(n.require("segments"), parsed));
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

std::vector<SegmentSpec> parseSegmentList(const ConfigNode& list, ParsedSegments& parsed) {
  std::vector<SegmentSpec> out;
  if (!list.exists()) return out;
  const auto items = list.items();
  if (list.isSequence() && items.empty()) list.error("expected at least one segment");
  for (const auto& item : items) {
    const int pos = item.yaml().Mark().pos;  // -1 for a tree built in code (no aliases)
    if (pos < 0) {
      out.push_back(parseSegment(item, parsed));
      continue;
    }
    auto it = parsed.find(static_cast<std::size_t>(pos));
    if (it == parsed.end())
      it = parsed.emplace(static_cast<std::size_t>(pos), parseSegment(item, parsed)).first;
    out.push_back(it->second);
  }
  return out;
}

// Number of segments the specs expand to, saturating at kMaxSegments + 1 (no overflow however
// deep the repeats nest): checked before anything is expanded.
std::size_t expandedCount(const std::vector<SegmentSpec>& specs) {
  std::size_t n = 0;
  for (const SegmentSpec& sp : specs) {
    std::size_t add = 1;
    if (sp.seg.type == "repeat") {
      const std::size_t body = expandedCount(*sp.body);
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

// A segment's peak angular rate and acceleration stay inside limits:: (a 1e6 deg turn in 1 s
// is no vehicle's motion); the message gives a duration that fits.
std::string tooViolent(const Segment& seg) {
  const SegmentPeaks p = segmentPeaks(seg);
  // both peaks scale as 1/T or 1/T² with the duration: the shortest one that fits
  auto longer = [&](double peak, double limit) {
    const double f = peak / limit;
    return seg.duration * (seg.kind == SegmentKind::Climb ? std::sqrt(f) : f);
  };
  if (!(p.angularRate <= limits::kMaxAngularRate))
    return "the " + seg.type + " reaches an angular rate of " +
           limits::fmt(p.angularRate * kDegPerRad, 3) + " deg/s, above " +
           limits::fmt(limits::kMaxAngularRate * kDegPerRad, 3) +
           " deg/s (docs/limits.md); a duration of " +
           limits::fmt(longer(p.angularRate, limits::kMaxAngularRate), 3) + " s fits";
  if (!(p.acceleration <= limits::kMaxAcceleration))
    return "the " + seg.type + " reaches an acceleration of " + limits::fmt(p.acceleration, 3) +
           " m/s^2, above " + limits::fmt(limits::kMaxAcceleration, 3) +
           " m/s^2 (docs/limits.md); a duration of " +
           limits::fmt(longer(p.acceleration, limits::kMaxAcceleration), 3) + " s fits";
  return "";
}

// Lays the specs out in time, resolving targets; returns false after the first problem so that
// one wrong segment does not produce a cascade of follow-up messages.
bool layout(const std::vector<SegmentSpec>& specs, PlanCursor& c, std::vector<Segment>& out,
            const std::string& note) {
  for (const SegmentSpec& sp : specs) {
    if (sp.seg.type == "repeat") {
      for (long long k = 0; k < sp.count; ++k)
        if (!layout(*sp.body, c, out,
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
          sp.node.error("decelerate to " + limits::fmt(sp.value) + " m/s from " + limits::fmt(c.speed) +
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
        } else if (seg.bank == BankMode::Coordinated && std::isfinite(seg.duration) && seg.duration > 0.0) {
          // bank: auto peaks where an explicit bank is refused (88 deg ran in silence).
          const double peak = std::atan(2.0 * c.speed * std::abs(seg.change) / seg.duration / kBankGravity);
          if (peak > kMaxBank * (1.0 + 1e-12)) {
            sp.node.error("bank: auto peaks at " + limits::fmt(peak / kRadPerDeg) + " deg, beyond 80 deg at " +
                          limits::fmt(c.speed) + " m/s; give a duration of at least " +
                          limits::fmt(2.0 * c.speed * std::abs(seg.change) / (kBankGravity * std::tan(kMaxBank))) +
                          " s" + note);
            return false;
          }
        }
        break;
      case SegmentKind::Climb: {
        const double change = sp.target == Target::Absolute ? sp.value - c.h : sp.value;
        const bool climb = sp.seg.type == "climb";
        if (sp.target == Target::Absolute && (climb ? change <= 0.0 : change >= 0.0)) {
          sp.node.error(sp.seg.type + " to " + limits::fmt(sp.value) + " m from " + limits::fmt(c.h) + " m " +
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
    if (problem.empty()) problem = tooViolent(seg);
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
      if (sp.count < 1 || anyInvalid(*sp.body)) return true;
      continue;
    }
    if (sp.seg.type.empty() || registry().count(sp.seg.type) == 0) return true;
    if (!std::isfinite(sp.value)) return true;
    if (!std::isfinite(sp.seg.duration) && !(sp.bankAngle > 0.0)) return true;
  }
  return false;
}

}  // namespace

namespace detail {

std::vector<Segment> readSegments(const ConfigNode& segs, const MotionStart& start,
                                  const ConfigFile& file) {
  std::vector<Segment> out;
  ParsedSegments parsed;
  const std::vector<SegmentSpec> specs = parseSegmentList(segs, parsed);
  // Lay out only what parsed cleanly (and from a valid start): a bad value would otherwise
  // produce follow-up messages about a state that does not exist.
  if (!anyInvalid(specs) && !file.hasErrors() && expandedCount(specs) > kMaxSegments)
    segs.error("the repeats expand to more than " + std::to_string(kMaxSegments) +
               " segments (docs/limits.md)");
  if (!anyInvalid(specs) && !file.hasErrors()) {
    PlanCursor c;
    c.speed = start.speed;
    c.heading = start.heading;
    c.h = start.h;
    layout(specs, c, out, "");
  }
  return out;
}

}  // namespace detail

std::string Scenario::folderName(const std::string& prefix) const {
  std::string s = prefix + name;
  for (char& c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_')) c = '_';
  if (s.empty() || s == "." || s == "..") s = prefix + "scenario";
  return s;
}

std::vector<std::string> segmentTypes() {
  std::vector<std::string> names;
  for (const auto& kv : registry()) names.push_back(kv.first);
  names.push_back("repeat");
  return names;
}

}  // namespace sinsim::sim
