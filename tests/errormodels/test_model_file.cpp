// Model files: format, diagnostics with file/line/key, registry, determinism of streams.
#include <catch2/catch.hpp>

#include <cmath>

#include "errormodels/effect.hpp"
#include "errormodels/imu_model.hpp"
#include "test_support.hpp"

using namespace sinsim;
using namespace sinsim::errormodels;

namespace {

// Collects the diagnostics of a model text that must fail.
std::vector<Diagnostic> diagnosticsOf(const std::string& text) {
  try {
    ImuErrorModel::fromString(text, "bad.yaml");
  } catch (const ConfigError& e) {
    return e.diagnostics();
  }
  return {};
}

bool hasDiagnostic(const std::vector<Diagnostic>& ds, int line, const std::string& key,
                   const std::string& fragment) {
  return test::hasDiagnostic(ds, "bad.yaml", line, key, fragment);
}

ImuSample staticSample(double t, double dt) {
  ImuSample s;
  s.t = t;
  s.dt = dt;
  return s;
}

}  // namespace

TEST_CASE("a constant bias adds value·dt to every increment, in SI") {
  auto m = ImuErrorModel::fromString(R"(
gyro:
  x: [{type: bias, value: 36 deg/h}]
accel:
  all: [{type: bias, value: 1 mg}]
)", "m.yaml");
  auto c = m.instantiate(100.0, {1, 0});
  auto s = staticSample(0.01, 0.01);
  c->corrupt(s, NAN);
  const double deg = M_PI / 180.0;
  // 36 deg/h = 0.01 deg/s; times 0.01 s. Relative 1e-15: one rounding in the unit conversion.
  CHECK(s.dtheta_b.x() == Approx(0.01 * deg * 0.01).epsilon(1e-15));
  CHECK(s.dtheta_b.y() == 0.0);
  CHECK(s.dv_b.z() == Approx(1e-3 * 9.80665 * 0.01).epsilon(1e-15));
  CHECK(m.effectNames().size() == 4);
  CHECK(m.effectNames()[1] == "accel.all[0].bias(x)");
}

TEST_CASE("bad model files are refused with file, line and key path, all at once") {
  auto ds = diagnosticsOf(R"(gyro:
  x:
    - type: white
      density: 0.2 m/sqrt(h)
    - type: whyte
      sigma: 1 deg/s
  all:
    - type: gauss_markov
  w: []
accel:
  all:
    - type: white
      density: 0.05 m/s/sqrt(h)
      sigma: 0.01 furlong
    - type: bias
)");
  // Wrong dimension (a gyro density must be angular rate × sqrt(time)).
  CHECK(hasDiagnostic(ds, 4, "gyro.x[0].density", "deg/sqrt(h) or deg/s/sqrt(Hz)"));
  // Unknown type, listing the known ones.
  CHECK(hasDiagnostic(ds, 5, "gyro.x[1].type", "known: "));
  CHECK(hasDiagnostic(ds, 5, "gyro.x[1].type", "white"));
  // Unknown axis key.
  CHECK(hasDiagnostic(ds, 9, "gyro.w", "unknown key"));
  // Unknown unit.
  CHECK(hasDiagnostic(ds, 14, "accel.all[0].sigma", "unknown unit \"furlong\""));
  // Missing parameter.
  CHECK(hasDiagnostic(ds, 15, "accel.all[1]", "missing parameter"));
}

TEST_CASE("bias_instability: a tau_range that is reversed or too wide is refused, not dropped") {
  // [1e-300 s, 1e12 s]: its ratio overflows a double; the component count once came out of an
  // infinite logarithm and the effect silently drew nothing.
  auto ds = diagnosticsOf(R"(gyro:
  x: [{type: bias_instability, B: 10 deg/h, tau_range: [1e-300 s, 1e12 s]}]
  y: [{type: bias_instability, B: 10 deg/h, tau_range: [100 s, 1 s]}]
  z: [{type: bias_instability, B: 10 deg/h, tau_range: [1e-11 s, 1e12 s]}]
)");
  CHECK(hasDiagnostic(ds, 2, "gyro.x[0].tau_range", "spans more than 24 decades"));
  CHECK(hasDiagnostic(ds, 3, "gyro.y[0].tau_range", "0 < shortest < longest"));
  CHECK(ds.size() == 2);  // 23 decades are accepted
}

TEST_CASE("same seed gives bit-identical output, the stream of run k is regenerated alone") {
  const std::string text = R"(
gyro:
  all: [{type: white, density: 0.2 deg/sqrt(h)}, {type: bias, sigma: 10 deg/h}]
accel:
  all: [{type: white, density: 0.05 m/s/sqrt(h)}]
)";
  auto m = ImuErrorModel::fromString(text, "m.yaml");
  auto run = [&](std::uint64_t seed, std::uint64_t r) {
    auto c = m.instantiate(200.0, {seed, r});
    std::vector<double> out;
    for (int k = 1; k <= 1000; ++k) {
      auto s = staticSample(k / 200.0, 1 / 200.0);
      c->corrupt(s, NAN);
      for (int i = 0; i < 3; ++i) out.push_back(s.dtheta_b[i]), out.push_back(s.dv_b[i]);
    }
    return out;
  };
  auto a = run(42, 7), b = run(42, 7), other = run(42, 8);
  CHECK(a == b);  // bit-identical, not approximately equal
  CHECK(a != other);
}
