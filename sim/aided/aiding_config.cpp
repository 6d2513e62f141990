#include "sim/aided/aiding_config.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "common/error.hpp"
#include "common/limits.hpp"
#include "errormodels/model_io.hpp"
#include "sim/aided/filter_model.hpp"
#include "sim/aided/known_errors.hpp"

namespace sinsim::sim::aided {
namespace {

using D = Dimension;
namespace fs = std::filesystem;

// A scalar (the same on all three axes) or a list of three quantities of dimension dim.
// `axes` names the three components for a message ("north, east, down").
nav::Vec3 vec3(const ConfigNode& n, D dim, bool positive, const char* axes) {
  nav::Vec3 v = nav::Vec3::Constant(NAN);
  if (n.isScalar()) {
    v.setConstant(n.asQuantity(dim).value_or(NAN));
  } else if (n.isSequence()) {
    const auto items = n.items();
    if (items.size() != 3) {
      n.error("expected 3 values (" + std::string(axes) + "), got " + std::to_string(items.size()));
      return v;
    }
    for (int i = 0; i < 3; ++i) v[i] = items[i].asQuantity(dim).value_or(NAN);
  } else {
    n.error("expected a value or a list of 3 values");
    return v;
  }
  if (v.allFinite())
    n.check(!positive || (v.array() > 0.0).all(), "expected positive values");
  return v;
}

ValueOrSigma valueOrSigma(const ConfigNode& n, D dim, const char* axes) {
  ValueOrSigma vs;
  if (!n.exists()) return vs;
  if (n.isMap()) {
    n.allowKeys({"sigma"});
    const ConfigNode s = n.require("sigma");
    if (s.exists()) {
      vs.random = true;
      vs.sigma = vec3(s, dim, false, axes);
      if (vs.sigma.allFinite()) s.check((vs.sigma.array() >= 0.0).all(), "expected sigmas ≥ 0");
    }
  } else {
    vs.value = vec3(n, dim, false, axes);
  }
  return vs;
}

void parseInitialErrors(const ConfigNode& root, InitialErrors& e) {
  const ConfigNode n = root["initial_errors"];
  if (!n.exists()) return;
  n.allowKeys({"position", "velocity", "attitude"});
  e.position = valueOrSigma(n["position"], D::length(), "north, east, down");
  e.velocity = valueOrSigma(n["velocity"], D::speed(), "north, east, down");
  e.attitude = valueOrSigma(n["attitude"], D::angle(), "roll, pitch, yaw");
}

void parseAlignment(const ConfigNode& root, AlignmentConfig& a) {
  const ConfigNode n = root["alignment"];
  if (!n.exists()) return;
  n.allowKeys({"type", "duration"});
  n.choice("type", {"coarse"}, "coarse");
  a.duration = n.quantity("duration", D::time());
  n["duration"].check(std::isfinite(a.duration) && a.duration > 0.0, "expected a positive time");
}

void parseOutages(const ConfigNode& n, double duration, std::vector<TimeWindow>& out) {
  if (!n.exists()) return;
  for (const ConfigNode& w : n.items()) {
    TimeWindow tw;
    if (w.isMap()) {
      w.allowKeys({"start", "duration", "end"});
      tw.start = w.quantity("start", D::time());
      if (w.has("end") == w.has("duration")) {
        w.error("give an outage's end or its duration (one of them)");
        continue;
      }
      tw.end = w.has("end") ? w.quantity("end", D::time())
                            : tw.start + w.quantity("duration", D::time());
    } else if (w.isSequence() && w.items().size() == 2) {
      tw.start = w.items()[0].asQuantity(D::time()).value_or(NAN);
      tw.end = w.items()[1].asQuantity(D::time()).value_or(NAN);
    } else {
      w.error("expected an outage as [start, end] or {start, duration}");
      continue;
    }
    if (!(std::isfinite(tw.start) && std::isfinite(tw.end))) continue;
    if (!w.check(tw.start >= 0.0 && tw.end > tw.start, "expected 0 ≤ start < end")) continue;
    w.check(tw.start < duration || !(duration > 0.0),
            "the outage starts at or after the scenario's end (no epoch inside it)");
    if (duration > 0.0 && tw.end > duration) tw.end = duration, tw.toTheEnd = true;  // "to the end"
    out.push_back(tw);
  }
  std::sort(out.begin(), out.end(),
            [](const TimeWindow& a, const TimeWindow& b) { return a.start < b.start; });
  for (std::size_t i = 1; i < out.size(); ++i)
    n.check(out[i].start >= out[i - 1].end, "outage windows overlap");
}

void parseGnss(const ConfigNode& root, double duration, GnssConfig& g) {
  const ConfigNode n = root["gnss"];
  if (!n.exists()) return;
  n.allowKeys({"rate", "position_sigma", "velocity_sigma", "lever_arm", "outages"});
  g.enabled = true;
  g.rate = n.quantity("rate", D::frequency(), 1.0);
  n["rate"].check(std::isfinite(g.rate) && g.rate > 0.0, "expected a positive rate");
  const auto fixSigma = [&](const char* key, D dim, const char* finest) {
    const nav::Vec3 v = vec3(n[key], dim, true, "north, east, down");
    if (v.allFinite() && (v.array() > 0.0).all())
      n[key].check(v.minCoeff() >= kMinFixSigma, std::string("expected at least ") + finest +
                                                     " (RTK is ~1 cm; finer, the filter's update reaches the "
                                                     "rounding of the navigation solution)");
    return v;
  };
  if (n.has("position_sigma")) g.positionSigma = fixSigma("position_sigma", D::length(), "1 mm");
  if (n.has("velocity_sigma")) g.velocitySigma = fixSigma("velocity_sigma", D::speed(), "1 mm/s");
  n.check(n.has("position_sigma") || n.has("velocity_sigma"),
          "expected position_sigma, velocity_sigma or both (what the fixes measure)");
  if (n.has("lever_arm")) {
    g.leverArm_b = vec3(n["lever_arm"], D::length(), false, "x, y, z in body axes");
    // Beyond any vehicle: a unit slip (mm given as m), and the filter's lever-arm terms would
    // swamp its attitude. (Not finite: a value that did not read, reported where it was read.)
    if (g.leverArm_b.allFinite())
      n["lever_arm"].check(g.leverArm_b.norm() <= kMaxLeverArm, "expected an antenna within 1 km of the IMU");
  }
  parseOutages(n["outages"], duration, g.outages);
  g.runEnd = duration;
}

// A known temperature polynomial is compensated at the scenario's sensor temperature: without
// one, each is a problem at its own line.
void requireNoTemperature(const errormodels::ErrorModelSpec& known, std::vector<Diagnostic>& problems) {
  for (errormodels::Sensor s : {errormodels::Sensor::gyro, errormodels::Sensor::accel})
    for (errormodels::EffectList l : {errormodels::EffectList::all, errormodels::EffectList::x,
                                      errormodels::EffectList::y, errormodels::EffectList::z})
      for (const errormodels::EffectSpec& e : known.sensor(s).list(l))
        if (e.type == "temperature")
          problems.push_back({e.where.file, e.where.line, e.where.key,
                              "temperature: the filter compensates it at the sensor's temperature; "
                              "give the scenario one (e.g. temperature: 25 degC)"});
}

// The filter's model from a file (relative to the scenario) or an inline model map, read into an
// ErrorModelSpec by the one model reader and converted by filterModelFromSpec; the problems of a
// model file are recorded at filter.model with the model file's own line and key. `step`: the
// filter step [s] (the GNSS interval, at most kMaxPropagationStep); `imuRate` [Hz] the scenario's.
void parseFilter(const ConfigNode& root, const std::string& baseDir, double step, double imuRate,
                 bool hasTemperature, FilterConfig& f) {
  const ConfigNode n = root["filter"];
  if (!n.exists()) return;
  n.allowKeys({"model"});
  const ConfigNode m = n.require("model");
  if (!m.exists()) return;
  errormodels::ErrorModelSpec spec;
  if (m.isMap()) {
    spec = errormodels::readErrorModel(m);
    f.model = "inline";
  } else {
    const std::string model = n.string("model");
    if (model.empty()) return;
    // `errors: none` is a perfect IMU; a filter always needs the sensor's noise to weigh the fixes.
    if (!m.check(model != "none", "a filter needs a sensor model (a model file or an inline map; at "
                                  "least white noise): `none` is for `errors`, a perfect IMU"))
      return;
    fs::path p(model);
    if (p.is_relative()) p = fs::path(baseDir) / p;
    f.model = p.lexically_normal().string();
    if (!m.check(fs::exists(f.model), "no such model file: " + f.model)) return;
    try {
      spec = errormodels::loadErrorModel(f.model);
    } catch (const ConfigError& e) {
      for (const Diagnostic& d : e.diagnostics()) m.error(d.str());
      return;
    } catch (const InputError& e) {
      m.error(e.text());
      return;
    }
  }
  std::vector<Diagnostic> problems;
  f.sensors = filterModelFromSpec(spec, step, imuRate, problems);
  if (!hasTemperature) requireNoTemperature(knownPart(spec, false), problems);
  try {
    f.knownAdded = errormodels::ImuErrorModel::fromSpec(knownPart(spec, false), f.model);
    f.knownLinear = errormodels::ImuErrorModel::fromSpec(knownPart(spec, true), f.model);
  } catch (const ConfigError& e) {
    problems.insert(problems.end(), e.diagnostics().begin(), e.diagnostics().end());
  } catch (const InputError& e) {
    m.error(e.text());
  }
  f.knownLabels = knownLabels(spec);
  f.imuRate = imuRate;
  for (const Diagnostic& d : problems) m.error(d.str());
  f.enabled = problems.empty();
}

}  // namespace

bool InitialErrors::any() const {
  for (const ValueOrSigma* v : {&position, &velocity, &attitude})
    if (v->random ? !v->sigma.isZero() : !v->value.isZero()) return true;
  return false;
}

bool GnssConfig::inOutage(double t) const {
  for (const TimeWindow& w : outages)
    if (w.contains(t)) return true;
  return false;
}

AidingConfig parseAiding(const ConfigNode& root, const std::string& baseDir, double duration,
                         double imuRate, bool hasTemperature) {
  AidingConfig c;
  parseInitialErrors(root, c.initialErrors);
  parseAlignment(root, c.alignment);
  parseGnss(root, duration, c.gnss);
  parseFilter(root, baseDir, std::min(1.0 / c.gnss.rate, kMaxPropagationStep), imuRate,
              hasTemperature, c.filter);
  if (root.has("filter") && !c.gnss.enabled)
    root["filter"].error("a filter needs GNSS fixes (a gnss: block) to aid the navigation");
  if (c.gnss.enabled && !root.has("filter"))
    root["gnss"].error("GNSS fixes need a filter to use them (filter: {model: FILE})");
  return c;
}

namespace {

/// Is some GNSS clock epoch k / rate (k >= 1) inside [a, b)?
bool fixEpochIn(double rate, double a, double b) {
  const double k = std::max(1.0, std::ceil(a * rate - 1e-9));
  return k / rate < b;
}

/// Does some GNSS clock epoch up to the scenario's end fall after the alignment and outside every
/// outage (sorted, not overlapping)? Else the filter would never update: its outputs would be the
/// free-inertial drift beside a covariance that never met a fix.
bool anyFixUsed(const GnssConfig& g, double alignEnd, double duration) {
  const double end = duration * (1.0 + 1e-12);  // the last epoch is the end's
  double from = alignEnd;
  for (const TimeWindow& w : g.outages) {
    if (w.start > from && fixEpochIn(g.rate, from, std::min(w.start, end))) return true;
    from = std::max(from, w.end);
    if (w.toTheEnd) return false;
  }
  return from < end && fixEpochIn(g.rate, from, end);
}

}  // namespace

std::string noFixWarning(const GnssConfig& g, double alignEnd) {
  if (!(g.enabled && std::isfinite(g.rate) && g.rate > 0.0 && std::isfinite(g.runEnd) && g.runEnd > 0.0) ||
      anyFixUsed(g, alignEnd, g.runEnd))
    return "";
  return "gnss: no fix is used: fixes every " + limits::fmt(1.0 / g.rate) + " s (rate " + limits::fmt(g.rate) +
         " Hz) all fall after the scenario's end (" + limits::fmt(g.runEnd) +
         " s), inside the alignment or inside an outage; the filter only propagates, the navigation is "
         "the free-inertial one and its sigmas never met a fix";
}

const std::vector<std::string>& aidingKeys() {
  static const std::vector<std::string> keys = {"initial_errors", "alignment", "gnss", "filter"};
  return keys;
}

}  // namespace sinsim::sim::aided
