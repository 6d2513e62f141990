// The change improve() makes to a model, on ErrorModelSpec (errormodels/diagnose/model_edit.hpp):
// expected values by hand from the model below (a variance factor 4 doubles every noise size;
// an AR refit replaces a and sigma; added effects come last; noise of `all` moves ahead of each
// axis's own effects so the axes can differ).
#include <catch2/catch.hpp>

#include <cmath>

#include "errormodels/diagnose/model_edit.hpp"
#include "errormodels/model_io.hpp"

using namespace sinsim::errormodels;
using sinsim::Dimension;
namespace dd = sinsim::errormodels::diagnose::detail;

namespace {

const char* const kModel =
    "gyro:\n"
    "  all:\n"
    "    - {type: white, density: 1 deg/sqrt(h)}\n"
    "    - {type: ramp, slope: 10 deg/h^2}\n"
    "  x:\n"
    "    - {type: ar, a: [-0.5], sigma: 0.1 deg/s, rate: 100 Hz}\n"
    "  y:\n"
    "    - {type: ar, a: [-0.5], output_sigma: 0.2 deg/s, rate: 100 Hz}\n"
    "accel:\n"
    "  all: [{type: white, density: 0.1 m/s/sqrt(h)}]\n";

const double kDeg = M_PI / 180;  // [rad/deg]

double param(const ErrorModelSpec& m, EffectList l, std::size_t i, const char* key) {
  return m.gyro.list(l).at(i).find(key)->values.at(0);
}

}  // namespace

TEST_CASE("editedModel scales, refits the AR, adds, and keeps list order", "[diagnose][model_edit]") {
  const auto model = errorModelFromString(kModel, "m.yaml");
  dd::ModelEdits e;
  e.varianceScale[0] = 4.0;                // gx: every noise size x 2
  e.arReplace[1] = {-0.3, 0.01 * kDeg};    // gy: a = [-0.3], driving sigma 0.01 deg/s
  const auto rw = EffectSpec::make(
      "random_walk", {ParamSpec::quantity("K", 1e-5, Dimension::angularRate() / Dimension::time().sqrt())});
  e.add[2] = {rw};
  const auto m = dd::editedModel(model, e);

  // The white noise left `all` for the three axes (ahead of their own effects); the ramp stayed.
  REQUIRE(m.gyro.all.size() == 1);
  CHECK(m.gyro.all[0].type == "ramp");
  REQUIRE(m.gyro.x.size() == 2);
  REQUIRE(m.gyro.y.size() == 2);
  REQUIRE(m.gyro.z.size() == 2);
  for (const auto* l : {&m.gyro.x, &m.gyro.y, &m.gyro.z}) CHECK((*l)[0].type == "white");
  // gx: density 2 deg/sqrt(h), AR sigma 0.2 deg/s, a unchanged (exact: factor 2 on doubles).
  const double N = kDeg / 60;  // 1 deg/sqrt(h) [rad/sqrt(s)]
  CHECK(param(m, EffectList::x, 0, "density") == Approx(2 * N).epsilon(1e-15));
  CHECK(param(m, EffectList::x, 1, "sigma") == Approx(0.2 * kDeg).epsilon(1e-15));
  CHECK(m.gyro.x[1].find("a")->values == std::vector<double>{-0.5});
  // gy: its own level; the AR has the new a and sigma and no output_sigma.
  CHECK(param(m, EffectList::y, 0, "density") == Approx(N).epsilon(1e-15));
  CHECK(m.gyro.y[1].find("a")->values == std::vector<double>{-0.3});
  CHECK(param(m, EffectList::y, 1, "sigma") == Approx(0.01 * kDeg).epsilon(1e-15));
  CHECK_FALSE(m.gyro.y[1].has("output_sigma"));
  // gz: the random walk appended after its white noise.
  CHECK(m.gyro.z[1] == rw);
  // The accelerometer had no edit: untouched (its white noise stays in `all`).
  CHECK(m.accel == model.accel);
  // A new model: it points into no file.
  CHECK(m.gyro.x[1].find("sigma")->where.line == 0);
  CHECK(m.gyro.all[0].where.line == 0);
}

TEST_CASE("editedModel refuses a variance factor that is not positive", "[diagnose][model_edit]") {
  const auto model = errorModelFromString(kModel, "m.yaml");
  for (double bad : {0.0, -1.0, double(NAN)}) {
    dd::ModelEdits e;
    e.varianceScale[3] = bad;
    CHECK_THROWS_AS(dd::editedModel(model, e), sinsim::InputError);
  }
}

TEST_CASE("baseAr: the one enabled AR of a channel at the record's rate", "[diagnose][model_edit]") {
  const auto model = errorModelFromString(kModel, "m.yaml");
  CHECK(dd::baseAr(model, 0, 100.0) == std::vector<double>{1.0, -0.5});
  CHECK_FALSE(dd::baseAr(model, 0, 200.0));  // another rate
  CHECK_FALSE(dd::baseAr(model, 2, 100.0));  // gz has none
  // Two ARs acting on one axis (all + own): no single base.
  const auto two = errorModelFromString(
      "gyro:\n  all: [{type: ar, a: [-0.2], sigma: 0.1 deg/s, rate: 100 Hz}]\n"
      "  x: [{type: ar, a: [-0.5], sigma: 0.1 deg/s, rate: 100 Hz}]\n", "two.yaml");
  CHECK_FALSE(dd::baseAr(two, 0, 100.0));
  CHECK(dd::baseAr(two, 1, 100.0) == std::vector<double>{1.0, -0.2});
  // A disabled one does not count (enabled: no is absent, as for the simulator).
  const auto off = errorModelFromString(
      "gyro:\n  all: [{type: ar, a: [-0.2], sigma: 0.1 deg/s, rate: 100 Hz, enabled: no}]\n"
      "  x: [{type: ar, a: [-0.5], sigma: 0.1 deg/s, rate: 100 Hz}]\n", "off.yaml");
  CHECK(dd::baseAr(off, 0, 100.0) == std::vector<double>{1.0, -0.5});
}

TEST_CASE("asWritten is what the written file reads back as", "[diagnose][model_edit]") {
  // A value with more digits than the writer prints (9 significant; AR a 10).
  auto model = errorModelFromString(kModel, "m.yaml");
  model.gyro.x[0].find("sigma")->values[0] = 0.1234567890123 * kDeg;
  model.gyro.x[0].find("a")->values[0] = -0.123456789012345;
  const auto w = asWritten(model);
  CHECK(w == errorModelFromString(errorModelYaml(model), "again.yaml"));
  CHECK(w.gyro.x[0].find("a")->values[0] == -0.123456789);  // %.10g
  CHECK_FALSE(w == model);
}
