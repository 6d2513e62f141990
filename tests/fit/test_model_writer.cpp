// The model-file writer: the YAML parses, every written quantity reads back (through the same
// unit parser the model loader uses) to the fitted SI value, undetected terms stay comments, and a
// failed write leaves no file.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>

#include <yaml-cpp/yaml.h>

#include "common/error.hpp"
#include "common/units.hpp"
#include "errormodels/fit/model_writer.hpp"
#include "fit_test_util.hpp"

using namespace sinsim::errormodels::fit;
using sinsim::Dimension;

namespace {
constexpr double kDeg = 3.14159265358979323846 / 180.0;
// Values are printed with 9 significant digits: relative rounding <= 5e-9 (plus the unit
// factor round trip, ~1e-16).
constexpr double kPrintTol = 6e-9;
}  // namespace

TEST_CASE("Model writer: AR and Allan terms read back to the fitted values", "[fit][writer]") {
  const auto x = fit_test::simulateAr(fit_test::paperTable()[0].a, 0.02 * kDeg, 200000, 3);
  OrderSelectionOptions os;
  os.maxOrder = 8;
  os.sampleInterval = 1e-3;
  os.navigationStep = 0.01;
  const auto sel = selectArOrder(x, os);

  // Allan terms from a closed-form curve with N and K present, Q/B/R absent.
  // 2 deg/sqrt(h) and 3 deg/h/sqrt(h): the random walk must be resolvable at EDF 1e4 (at
  // 0.5 deg/h/sqrt(h) it is only 0.5 sigma above zero and rightly eliminated).
  const double N = 2.0 * kDeg / 60.0, K = 3.0 * kDeg / 3600.0 / 60.0;
  std::vector<double> tau, edf;
  for (int e = -3; e <= 12; ++e) {
    tau.push_back(std::ldexp(1.0, e));
    edf.push_back(1e4);
  }
  const auto adev = allanModelAdev({0, N * N, 0, K * K, 0}, tau);
  const auto allan = fitAllanTerms(tau, adev, edf);

  AxisFitResult gx;
  gx.sensor = SensorSignal::Gyro;
  gx.axis = "x";
  gx.ar = sel.fit;
  gx.arRate = 1000.0;
  gx.arOrders = sel;
  AxisFitResult gy;
  gy.sensor = SensorSignal::Gyro;
  gy.axis = "y";
  gy.allan = allan;
  AxisFitResult az;
  az.sensor = SensorSignal::Accel;
  az.axis = "z";
  GaussMarkovFit gm;
  gm.sigma = 0.002;  // [m/s^2]
  gm.tau = 0.25;
  az.gaussMarkov = gm;
  ModelProvenance prov;
  prov.description = "test model";
  prov.dataFile = "run1.csv.gz";
  prov.rate = 1000;
  prov.duration = 200;
  prov.method = "Burg AR, MDL";
  const std::string text = modelYaml({gx, gy, az}, prov);
  INFO(text);

  const YAML::Node root = YAML::Load(text);
  CHECK(root["description"].as<std::string>() == "test model");
  CHECK(root["record_duration"].as<std::string>() == "200 s");  // the record's length, for mc's warning
  const YAML::Node ar = root["gyro"]["x"][0];
  CHECK(ar["type"].as<std::string>() == "ar");
  REQUIRE(ar["a"].size() == sel.fit.order);
  for (std::size_t i = 0; i < sel.fit.order; ++i)
    CHECK(ar["a"][i].as<double>() == Approx(sel.fit.a[i + 1]).epsilon(1e-9));  // %.10g
  CHECK(sinsim::parseQuantityAs(ar["sigma"].as<std::string>(), Dimension::angularRate()) ==
        Approx(std::sqrt(sel.fit.drivingVariance)).epsilon(kPrintTol));
  CHECK(sinsim::parseQuantityAs(ar["rate"].as<std::string>(), Dimension::frequency()) == 1000.0);

  // gyro.y: exactly the detected terms, white then random_walk, in SI after parsing.
  const YAML::Node y = root["gyro"]["y"];
  REQUIRE(y.size() == 2);
  CHECK(y[0]["type"].as<std::string>() == "white");
  CHECK(sinsim::parseQuantityAs(y[0]["density"].as<std::string>(),
                                Dimension::angularRate() * Dimension::time().sqrt()) ==
        Approx(N).epsilon(kPrintTol + 1e-8));  // + the fit's own 1e-8 on exact data
  CHECK(y[1]["type"].as<std::string>() == "random_walk");
  CHECK(sinsim::parseQuantityAs(y[1]["K"].as<std::string>(),
                                Dimension::angularRate() / Dimension::time().sqrt()) ==
        Approx(K).epsilon(kPrintTol + 1e-8));
  CHECK(text.find("# bias_instability: not supported by the data, upper bound") != std::string::npos);

  const YAML::Node g = root["accel"]["z"][0];
  CHECK(g["type"].as<std::string>() == "gauss_markov");
  CHECK(sinsim::parseQuantityAs(g["sigma"].as<std::string>(), Dimension::acceleration()) ==
        Approx(0.002).epsilon(kPrintTol));
  CHECK(sinsim::parseQuantityAs(g["tau"].as<std::string>(), Dimension::time()) ==
        Approx(0.25).epsilon(kPrintTol));
  CHECK(text.find("# data: run1.csv.gz") != std::string::npos);
  CHECK(text.find("MDL -> ") != std::string::npos);
}

TEST_CASE("Model writer: quantization is written as an increment LSB = sqrt(12) Q",
          "[fit][writer]") {
  // ADIS16355 gyro LSB 0.07326 deg/s at 1 kHz is an angle step of 7.326e-5 deg per sample;
  // its Allan Q = lsb / sqrt(12) (IEEE 952 Annex C).
  const double lsb = 7.326e-5 * kDeg, Q = lsb / std::sqrt(12.0), N = 1e-4;
  std::vector<double> tau, edf;
  for (int e = -8; e <= 4; ++e) {
    tau.push_back(std::ldexp(1.0, e));
    edf.push_back(1e5);
  }
  const auto fit = fitAllanTerms(tau, allanModelAdev({Q * Q, N * N, 0, 0, 0}, tau), edf);
  AxisFitResult ax;
  ax.axis = "z";
  ax.allan = fit;
  const YAML::Node root = YAML::Load(modelYaml({ax}, {}));
  const YAML::Node qn = root["gyro"]["z"][0];
  REQUIRE(qn["type"].as<std::string>() == "quantization");
  CHECK(sinsim::parseQuantityAs(qn["lsb"].as<std::string>(), Dimension::angle()) ==
        Approx(lsb).epsilon(kPrintTol + 1e-8));
}

TEST_CASE("Model writer refuses bad entries and never leaves a half-written file",
          "[fit][writer][input]") {
  AxisFitResult bad;
  bad.axis = "w";
  CHECK_THROWS_AS(modelYaml({bad}, {}), sinsim::InputError);
  AxisFitResult noRate;
  noRate.ar = sinsim::errormodels::fit::burg(fit_test::simulateAr({1.0, -0.5}, 1.0, 100, 1), 1);
  CHECK_THROWS_AS(modelYaml({noRate}, {}), sinsim::InputError);
  AxisFitResult twice;
  CHECK_THROWS_AS(modelYaml({twice, twice}, {}), sinsim::InputError);

  const std::string dir = std::string(SINSIM_BINARY_DIR) + "/no-such-dir/model.yaml";
  CHECK_THROWS_AS(writeModelFile(dir, {twice}, {}), sinsim::Error);
  std::ifstream probe(dir);
  CHECK_FALSE(probe.good());
  const std::string ok = std::string(SINSIM_BINARY_DIR) + "/test_fit_model.yaml";
  writeModelFile(ok, {twice}, {});
  CHECK(YAML::LoadFile(ok)["gyro"]["x"].IsSequence());
  std::remove(ok.c_str());
}

TEST_CASE("Model writer: an ln interval the record does not bound is said so, not printed as 0..inf",
          "[fit][writer]") {
  // A latent fit of white noise (the fitted set: white), with two selection-aware entries added
  // by hand: a rarely included GM's sigma whose Wald interval in ln has half-width 1e5 (as a
  // second GM's had on a white + weak GM + walk record) and a tau bounded to 2..8 s.
  std::mt19937_64 rng(41);
  std::normal_distribution<double> g;
  std::vector<double> x(20000);
  for (auto& v : x) v = 1e-3 * g(rng);
  LatentFitOptions o;
  o.sampleInterval = 0.01;
  AxisFitResult r;
  r.axis = "x";
  r.latent = fitLatentModel(x, o);
  LatentAveragedParameter wide{"gm2.sigma", 0.005, 1e-4, 1e-3, true, std::log(1e-4), 1e5, 1e5};
  LatentAveragedParameter tau{"gm2.tau", 0.005, 4.0, 2.0, true, std::log(4.0), std::log(2.0), std::log(2.0)};
  r.latent->averaged.push_back(wide);
  r.latent->averaged.push_back(tau);
  const std::string text = modelYaml({r}, {});
  INFO(text);
  CHECK(text.find("gm2.sigma") != std::string::npos);
  CHECK(text.find("(ln-space 1-sigma not bounded by the record)") != std::string::npos);
  CHECK(text.find("(profile 1-sigma 2 s..8 s)") != std::string::npos);
  CHECK(text.find("inf") == std::string::npos);
}
