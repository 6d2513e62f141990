// ErrorModelSpec: the one reader and the one writer round-trip every effect type and hundreds of
// random valid specs; edits are functions on values; `enabled: no|false|off` mean the same; errors
// keep file, line and key; a model built from a spec draws the same numbers as from its file.
#include <catch2/catch.hpp>

#include <cmath>
#include <algorithm>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>

#include "errormodels/effect.hpp"
#include "errormodels/imu_model.hpp"
#include "errormodels/model_io.hpp"
#include "errormodels/model_spec.hpp"
#include "test_support.hpp"

using namespace sinsim;
using namespace sinsim::errormodels;

using sinsim::test::messageOf;

namespace {

// Every effect type, in each form its schema allows at least once.
const char* const kEveryEffect = R"(# a header comment
# second line
description: "every effect"
gyro:
  triad:
    # scale factor in ppm
    - {type: scale_factor, value: 300 ppm}
    - {type: misalignment, matrix: [[0, 0.1 deg, -0.05 deg], [0.02 deg, 0, 1 mrad], [0, 0, 0]]}
    - {type: g_sensitivity, diagonal: [0.01 deg/s/g, 0.02 deg/s/g, 0]}
  all:
    - {type: white, density: 0.2 deg/sqrt(h)}
    - {type: bias, value: 3.3 deg/h, sigma: 10 deg/h}
  x:
    - {type: ar, a: [-1.0327, -0.34341, 0.037895, 0.19732, 0.14724], sigma: 0.01 deg/s, rate: 1 kHz}
    - {type: gauss_markov, sigma: 0.01 deg/s, tau: 100 s, rate: 200 Hz}
    - type: bias_instability
      B: 10 deg/h
      tau_range: [1 s, 1000 s]
    # the ramp is disabled
    - {type: ramp, slope: 1 deg/h^2, enabled: no}
    # trailing comment of x
  y:
    - {type: random_walk, K: 1 deg/h/sqrt(h)}
    - {type: sinusoid, amplitude: 0.01 deg/s, frequency: 2 Hz, phase: 30 deg}
    - {type: quantization, lsb: 0.001 deg}
    - {type: white, sigma: 0.01 deg/s, rate: 100 Hz, note: "per-sample form"}
  z:
    - {type: ar, a: [-0.5], output_sigma: 0.1 deg/s, rate: 100 Hz}
    - {type: bias_instability, floor: 6.64 deg/h, tau_range: [1 s, 100 s]}
accel:
  triad:
    - {type: scale_factor, matrix: [[1e-4, 0, 0], [0, 2e-4, 0], [0, 0, 3e-4]]}
  all:
    - {type: temperature, T0: 25 degC, coefficients: [0.1 mg/degC, 0.001 mg/degC^2]}
    - {type: warmup, amplitude: 1 mg, tau: 60 s}
    - {type: outliers, rate: 5 Hz, amplitude: 50 mg}
    - {type: bias_jumps, rate: 0.002 Hz, size: 0.5 mg, telegraph: yes}
    - {type: quantization, lsb: 0.1 mg, carry: true}
  x: []
)";

// Model file text as the writer would print it: read -> write -> read.
ErrorModelSpec roundTrip(const ErrorModelSpec& s) {
  return errorModelFromString(errorModelYaml(s), "rt.yaml");
}

std::vector<double> realisation(const ImuErrorModel& m, std::uint64_t seed) {
  auto c = m.instantiate(100.0, {seed, 3});
  std::vector<double> out;
  for (int k = 1; k <= 300; ++k) {
    ImuSample s;
    s.t = k / 100.0;
    s.dt = 0.01;
    s.dtheta_b = Vec3(1e-4, 0, 0);
    s.dv_b = Vec3(0, 0, -0.098);
    c->corrupt(s, 300.0);  // [K]
    for (int i = 0; i < 3; ++i) out.push_back(s.dtheta_b[i]), out.push_back(s.dv_b[i]);
  }
  return out;
}

bool closeSpecs(const ErrorModelSpec& a, const ErrorModelSpec& b);

}  // namespace

TEST_CASE("spec: every effect type reads, writes and reads back equal, comments are kept") {
  const ErrorModelSpec a = errorModelFromString(kEveryEffect, "every.yaml");
  // The text covers the whole registry.
  for (const auto& t : effectTypes()) {
    bool found = false;
    for (Sensor s : {Sensor::gyro, Sensor::accel})
      for (int l = 0; l < 5; ++l)
        for (const auto& e : a.sensor(s).list(EffectList(l))) found = found || e.type == t.name;
    CHECK(found);
  }
  // Written in the writer's units, the values come back equal to the printed digits (9); from then
  // on reading and writing is exact: the written spec reads back equal, and its text is a fixed
  // point.
  const ErrorModelSpec b = roundTrip(a);
  CHECK(closeSpecs(a, b));
  const ErrorModelSpec c = roundTrip(b);
  CHECK(b == c);
  CHECK(errorModelYaml(c) == errorModelYaml(b));
  CHECK(a.headerComments == std::vector<std::string>{"a header comment", "second line"});
  CHECK(c.headerComments == a.headerComments);
  CHECK(a.gyro.triad[0].comments == std::vector<std::string>{"scale factor in ppm"});
  CHECK(a.gyro.x[3].comments == std::vector<std::string>{"the ramp is disabled"});
  CHECK(a.gyro.trailing[int(EffectList::x)] == std::vector<std::string>{"trailing comment of x"});
  CHECK(c.gyro.trailing[int(EffectList::x)] == a.gyro.trailing[int(EffectList::x)]);
  CHECK(a.gyro.y[3].note == "per-sample form");
  CHECK(a.accel.keepEmpty[int(EffectList::x)]);
  CHECK(c.accel.keepEmpty[int(EffectList::x)]);
  // SI inside: 0.2 deg/sqrt(h) = 0.2 * (pi/180) / sqrt(3600) rad/sqrt(s); 1e-15 relative: one
  // rounding per factor of the conversion.
  CHECK(a.gyro.all[0].find("density")->si() == Approx(0.2 * M_PI / 180 / 60).epsilon(1e-15));
  CHECK(a.accel.all[0].find("T0")->si() == Approx(298.15).epsilon(1e-15));
  // The same file gives the same realisation, bit for bit, through the spec; and so do two specs
  // that are equal.
  CHECK(realisation(ImuErrorModel::fromString(kEveryEffect, "every.yaml"), 5) ==
        realisation(ImuErrorModel::fromSpec(a, "a"), 5));
  CHECK(realisation(ImuErrorModel::fromSpec(b, "b"), 5) ==
        realisation(ImuErrorModel::fromSpec(c, "c"), 5));
}

TEST_CASE("spec: an effect of the fixed nature draws nothing, a drawn one with a sigma draws") {
  // The registry's nature (effects.def) against what each effect of kEveryEffect does alone:
  // realisations of seeds 5 and 6 are equal for every `fixed` effect and differ for every `drawn`
  // one that has something to draw (a scale factor without a sigma has not).
  const ErrorModelSpec every = errorModelFromString(kEveryEffect, "every.yaml");
  int fixedSeen = 0, drawnSeen = 0;
  for (Sensor s : {Sensor::gyro, Sensor::accel})
    for (int l = 0; l < 5; ++l)
      for (EffectSpec e : every.sensor(s).list(EffectList(l))) {
        e.enabled = true;
        const Nature nature = findEffectType(e.type)->nature;
        const ImuErrorModel m = ImuErrorModel::fromSpec(withEffect({}, s, EffectList(l), e), "one");
        const bool same = realisation(m, 5) == realisation(m, 6);
        INFO(e.type);
        if (nature == Nature::fixed) {
          CHECK(same);
          ++fixedSeen;
        } else if (nature == Nature::drawn && !(e.type == "scale_factor" && !e.find("sigma"))) {
          CHECK_FALSE(same);
          ++drawnSeen;
        }
      }
  CHECK(fixedSeen == 6);  // misalignment, g_sensitivity, ramp, sinusoid, temperature, warmup
  CHECK(drawnSeen == 11);
}

namespace {

// A random valid value for item k of a parameter (SI, with its dimension).
double randomValue(const ParamSchema& s, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> mag(-3.0, 3.0);
  double v = std::pow(10.0, mag(rng));
  if (s.bound == Bound::any && (rng() & 1)) v = -v;
  return v;
}

ParamSpec randomParam(const ParamSchema& s, const std::string& type, Sensor sensor,
                      std::mt19937_64& rng) {
  ParamSpec p;
  p.key = s.key;
  p.kind = s.kind;
  auto dimOf = [&](int item) {
    return s.hasAlt && (rng() & 1) ? s.alt.of(sensor, item) : s.dim.of(sensor, item);
  };
  if (s.kind == ParamKind::flag) {
    p.flag = rng() & 1;
    return p;
  }
  int n = s.kind == ParamKind::quantity ? 1 : s.kind == ParamKind::matrix ? 9
                                                                         : (s.count ? s.count : 1 + int(rng() % 4));
  const bool coefficients = type == "ar" && s.key == "a";
  const bool tauRange = s.key == "tau_range";
  if (tauRange) n = 2;
  const Dimension d = dimOf(0);
  for (int i = 0; i < n; ++i) {
    double v = randomValue(s, rng);
    if (coefficients) v = (rng() & 1 ? 0.9 : -0.9) * std::abs(v) / 1000.0 / n;  // sum |a| < 1
    if (type == "misalignment" && i % 4 == 0) v = 0.0;  // zero diagonal
    if (tauRange) v = i == 0 ? std::abs(v) : p.values[0] * 10.0;
    if (type == "temperature" && s.key == "T0") v = 273.15 + 20 * std::abs(v);
    p.values.push_back(v);
    p.dims.push_back(s.kind == ParamKind::list ? dimOf(i) : d);
  }
  if (type == "temperature" && s.kind == ParamKind::list)
    for (int i = 0; i < n; ++i) p.dims[std::size_t(i)] = s.dim.of(sensor, i);
  return p;
}

EffectSpec randomEffect(const EffectType& t, Sensor sensor, std::mt19937_64& rng) {
  EffectSpec e;
  e.type = t.name;
  e.enabled = rng() % 5 != 0;
  if (rng() % 4 == 0) e.note = "note " + std::to_string(rng() % 100);
  if (rng() % 3 == 0) e.comments = {"comment " + std::to_string(rng() % 100)};
  const auto& schema = t.params();
  std::vector<int> groupsDone;
  for (const auto& s : schema) {
    bool take = s.need == Need::required || (s.need == Need::optional && (rng() & 1));
    if (s.need == Need::oneOf) {
      if (std::find(groupsDone.begin(), groupsDone.end(), s.group) != groupsDone.end()) continue;
      // Take this one or, half the time, leave the group to a later member (the last one takes it).
      int left = 0;
      for (const auto& o : schema) left += (o.need == Need::oneOf && o.group == s.group && &o > &s);
      take = left == 0 || (rng() & 1);
      if (take) groupsDone.push_back(s.group);
    }
    if (take) e.parameters.push_back(randomParam(s, t.name, sensor, rng));
  }
  if (t.name == std::string("white") && e.has("sigma") && !e.has("rate"))
    e.parameters.push_back(ParamSpec::quantity("rate", 100.0, Dimension::frequency()));
  if (t.name == std::string("bias") && !e.has("value") && !e.has("sigma"))
    e.parameters.push_back(ParamSpec::quantity("value", 1e-3, signal().of(sensor)));
  return e;
}

ErrorModelSpec randomSpec(std::mt19937_64& rng) {
  ErrorModelSpec spec;
  spec.description = "random " + std::to_string(rng() % 1000);
  if (rng() & 1) spec.headerComments = {"header"};
  const auto& types = effectTypes();
  const int n = 1 + int(rng() % 8);
  for (int i = 0; i < n; ++i) {
    const EffectType& t = types[rng() % types.size()];
    Sensor sensor = rng() & 1 ? Sensor::gyro : Sensor::accel;
    if (t.name == std::string("g_sensitivity")) sensor = Sensor::gyro;
    const EffectList list =
        t.scope == Scope::triad ? EffectList::triad : EffectList(1 + int(rng() % 4));
    spec = withEffect(spec, sensor, list, randomEffect(t, sensor, rng));
  }
  return spec;
}

bool closeSpecs(const ErrorModelSpec& a, const ErrorModelSpec& b) {
  for (Sensor s : {Sensor::gyro, Sensor::accel})
    for (int l = 0; l < 5; ++l) {
      const auto& la = a.sensor(s).list(EffectList(l));
      const auto& lb = b.sensor(s).list(EffectList(l));
      if (la.size() != lb.size()) return false;
      for (std::size_t i = 0; i < la.size(); ++i) {
        if (la[i].type != lb[i].type || la[i].parameters.size() != lb[i].parameters.size() ||
            la[i].enabled != lb[i].enabled || la[i].note != lb[i].note)
          return false;
        for (std::size_t j = 0; j < la[i].parameters.size(); ++j) {
          const auto& pa = la[i].parameters[j];
          const auto& pb = lb[i].parameters[j];
          if (pa.key != pb.key || pa.values.size() != pb.values.size() || pa.flag != pb.flag)
            return false;
          for (std::size_t k = 0; k < pa.values.size(); ++k)
            // 9 significant digits printed (6 for some times): relative 5e-6 covers the coarsest.
            if (!(std::abs(pa.values[k] - pb.values[k]) <= 5e-6 * std::abs(pa.values[k]) + 1e-300))
              return false;
        }
      }
    }
  return true;
}

}  // namespace

TEST_CASE("spec: 400 random valid specs round-trip through the writer and the reader") {
  std::mt19937_64 rng(20261123);  // fixed seed: the same 400 specs every run
  for (int k = 0; k < 400; ++k) {
    const ErrorModelSpec spec = randomSpec(rng);
    INFO(errorModelYaml(spec));
    CHECK_NOTHROW(ImuErrorModel::fromSpec(spec, "random"));
    const ErrorModelSpec once = roundTrip(spec);
    CHECK(closeSpecs(spec, once));  // equal to the printed digits
    CHECK(roundTrip(once) == once);  // and exactly equal from then on
    // asWritten is the spec as its file reads back, exactly (no file involved).
    CHECK(asWritten(spec) == once);
    // effectYaml is the effect's line of the file.
    const std::string text = errorModelYaml(spec);
    for (Sensor s : {Sensor::gyro, Sensor::accel})
      for (int l = 0; l < 5; ++l)
        for (const auto& e : spec.sensor(s).list(EffectList(l)))
          CHECK(text.find("    - " + effectYaml(e, s) + "\n") != std::string::npos);
  }
}

TEST_CASE("spec: record_duration, the fitted record's length, reads in any time unit, writes in s and refuses nonsense") {
  const std::string effects = "gyro:\n  x:\n    - {type: white, density: 0.1 deg/sqrt(h)}\n";
  const ErrorModelSpec a = errorModelFromString("record_duration: 40 min\n" + effects, "r.yaml");
  REQUIRE(a.recordDuration);
  CHECK(*a.recordDuration == Approx(2400.0).epsilon(1e-15));
  CHECK(errorModelYaml(a).find("record_duration: 2400 s\n") != std::string::npos);
  CHECK(roundTrip(a) == a);
  CHECK(ImuErrorModel::fromSpec(a, "r.yaml").recordDuration() == a.recordDuration);
  CHECK_FALSE(errorModelFromString(effects, "plain.yaml").recordDuration);
  CHECK_FALSE(ImuErrorModel::fromString(effects, "plain.yaml").recordDuration());
  for (const char* bad : {"-5 min", "0 s", "nan s", "1e999 s"}) {
    INFO(bad);
    const std::string msg =
        messageOf([&] { errorModelFromString(std::string("record_duration: ") + bad + "\n" + effects, "bad.yaml"); });
    CHECK(msg.find("bad.yaml:1: record_duration") != std::string::npos);
  }
  CHECK(messageOf([&] { errorModelFromString("record_duration: 40\n" + effects, "unit.yaml"); })
            .find("unit.yaml:1: record_duration") != std::string::npos);
}

TEST_CASE("spec: enabled no, false and off all switch an effect off, in simulation and queries") {
  for (const char* off : {"no", "false", "off", "No", "FALSE"}) {
    const std::string text = std::string("gyro:\n  x:\n    - {type: white, density: 1 deg/sqrt(h), enabled: ") +
                             off + "}\n    - {type: bias, value: 1 deg/h}\n";
    INFO(off);
    // yaml-cpp's scalar is read as written; the reader accepts the YAML 1.1 spellings it knows.
    ErrorModelSpec s;
    try {
      s = errorModelFromString(text, "off.yaml");
    } catch (const ConfigError&) {
      continue;  // a capitalised spelling that ConfigNode::asBool refuses is refused everywhere
    }
    CHECK_FALSE(s.gyro.x[0].enabled);
    CHECK(effectTypesOn(s, Sensor::gyro, 0) == std::vector<std::string>{"bias"});
    CHECK_FALSE(findEffect(s, Sensor::gyro, 0, "white").has_value());
    CHECK(ImuErrorModel::fromSpec(s, "off").effectNames() == std::vector<std::string>{"gyro.x[1].bias"});
    CHECK(ImuErrorModel::fromString(text, "off.yaml").effectNames() ==
          std::vector<std::string>{"gyro.x[1].bias"});
  }
  for (const char* on : {"yes", "true", "on"}) {
    const std::string text =
        std::string("gyro:\n  all: [{type: white, density: 1 deg/sqrt(h), enabled: ") + on + "}]\n";
    CHECK(effectTypesOn(errorModelFromString(text, "on.yaml"), Sensor::gyro, 2) ==
          std::vector<std::string>{"white"});
  }
}

TEST_CASE("spec: edits are functions on values") {
  const ErrorModelSpec a = errorModelFromString(kEveryEffect, "every.yaml");
  const ErrorModelSpec before = a;
  auto ramp = EffectSpec::make("ramp", {ParamSpec::quantity("slope", 1e-6, Dimension::angularRate() / Dimension::time())});
  ErrorModelSpec b = withEffect(a, Sensor::gyro, EffectList::z, ramp);
  CHECK(a == before);  // the argument is unchanged
  CHECK(b.gyro.z.back() == ramp);
  CHECK(effectTypesOn(b, Sensor::gyro, 2) ==
        std::vector<std::string>{"white", "bias", "ar", "bias_instability", "ramp"});
  // Removing from axis 0 removes the `all` white from every axis.
  ErrorModelSpec c = withoutEffects(b, Sensor::gyro, 0, "white");
  CHECK(effectTypesOn(c, Sensor::gyro, 1) ==
        std::vector<std::string>{"bias", "random_walk", "sinusoid", "quantization", "white"});
  auto ref = findEffect(a, Sensor::gyro, 0, "gauss_markov");
  REQUIRE(ref);
  CHECK(ref->list == EffectList::x);
  CHECK(ref->index == 1);
  ErrorModelSpec d = scaleParameter(a, *ref, "sigma", 2.0);
  CHECK(effectAt(d, *ref).find("sigma")->si() == 2.0 * effectAt(a, *ref).find("sigma")->si());
  CHECK_THROWS_AS(scaleParameter(a, *ref, "nope", 2.0), InputError);
  // Replace keeps the comments of what it replaces when the new one has none.
  auto bi = EffectSpec::make("bias_instability",
                             {ParamSpec::quantity("B", 1e-5, Dimension::angularRate()),
                              ParamSpec::quantities("tau_range", {1.0, 10.0}, Dimension::time())});
  ErrorModelSpec e = withReplacedEffect(a, Sensor::gyro, 2, bi);
  CHECK(e.gyro.z.back().find("B")->si() == 1e-5);
  CHECK(std::count_if(e.gyro.z.begin(), e.gyro.z.end(),
                      [](const EffectSpec& x) { return x.type == "bias_instability"; }) == 1);
  CHECK_NOTHROW(ImuErrorModel::fromSpec(e, "edited"));
}

TEST_CASE("spec: problems name file, line and key, from the reader and from fromSpec") {
  const std::string text = "gyro:\n  x:\n    - {type: ar, a: [-0.5], sigma: 1 deg/s, rate: 1 kHz}\n"
                           "    - {type: gauss_markov, sigma: -1 deg/s, tau: 1 s}\n";
  const ErrorModelSpec s = errorModelFromString(
      "gyro:\n  x:\n    - {type: ar, a: [-0.5], sigma: 1 deg/s, rate: 1 kHz}\n", "m.yaml");
  CHECK(s.gyro.x[0].find("a")->where.line == 3);
  CHECK(s.gyro.x[0].find("a")->where.key == "gyro.x[0].a");
  // An edit that makes the AR unstable is refused by fromSpec at the key, in the file named as
  // edited: line 3 holds the old value, not the one refused.
  auto bad = withParameter(s, {Sensor::gyro, EffectList::x, 0}, ParamSpec::numbers("a", {-1.0}));
  const std::string msg = messageOf([&] { ImuErrorModel::fromSpec(bad, "m.yaml"); });
  CHECK(msg.find("m.yaml (edited): gyro.x[0].a: unstable AR polynomial") != std::string::npos);
  CHECK(msg.find("m.yaml:3") == std::string::npos);
  // A value the file holds is still refused at its line (the effect built in code from it).
  auto sameFile = errorModelFromString("gyro:\n  x:\n    - {type: ar, a: [-0.5], sigma: 1 deg/s, rate: 1 kHz}\n", "m.yaml");
  sameFile.gyro.x[0].find("sigma")->values = {-1.0};  // a value changed without withParameter keeps its line
  CHECK(messageOf([&] { ImuErrorModel::fromSpec(sameFile, "m.yaml"); }).find("m.yaml:3: gyro.x[0].sigma") != std::string::npos);
  // The reader reports every problem at once: the value refused by its bound, with its text.
  const std::string msg2 = messageOf([&] { errorModelFromString(text, "two.yaml"); });
  CHECK(msg2.find("two.yaml:4: gyro.x[1].sigma: must be positive, got \"-1 deg/s\"") !=
        std::string::npos);
  // A reference temperature below absolute zero (0 K = -273.15 degC) is refused as such.
  const std::string msg4 = messageOf([&] {
    errorModelFromString("accel:\n  x:\n    - {type: temperature, T0: -300 degC, coefficients: [1e-4 m/s^2/K]}\n",
                         "cold.yaml");
  });
  CHECK(msg4.find("cold.yaml:3: accel.x[0].T0: must be above absolute zero (0 K = -273.15 degC), got \"-300 degC\"") !=
        std::string::npos);
  CHECK_NOTHROW(errorModelFromString(
      "accel:\n  x:\n    - {type: temperature, T0: -40 degC, coefficients: [1e-4 m/s^2/K]}\n", "cold.yaml"));
  // A spec built in code with a wrong dimension is refused with its key.
  ErrorModelSpec code = withEffect({}, Sensor::accel, EffectList::y,
                                   EffectSpec::make("white", {ParamSpec::quantity("density", 1.0, Dimension::time())}));
  const std::string msg3 = messageOf([&] { ImuErrorModel::fromSpec(code, "code"); });
  CHECK(msg3.find("accel.y[0].density: expected a value in") != std::string::npos);
}

TEST_CASE("spec: the documented format names every effect and parameter of the registry") {
  std::ifstream in(std::string(SINSIM_SOURCE_DIR) + "/docs/model-format.md");
  REQUIRE(in);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string doc = ss.str();
  for (const auto& t : effectTypes()) {
    const auto at = doc.find("### `" + std::string(t.name) + "`");
    INFO(t.name);
    REQUIRE(at != std::string::npos);
    const auto end = doc.find("\n### ", at + 1);
    const std::string section = doc.substr(at, end == std::string::npos ? std::string::npos : end - at);
    for (const auto& p : t.params()) {
      INFO(p.key);
      CHECK(section.find("| `" + p.key + "` |") != std::string::npos);
    }
  }
}
