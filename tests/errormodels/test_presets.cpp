// The presets in scenarios/ load, and their derived numbers are what their comments say: the C++
// recomputation here is independent of scripts/derive_adis16355_presets.py (the script documents,
// this test checks).
#include <catch2/catch.hpp>
#include <yaml-cpp/yaml.h>

#include <cmath>

#include "common/units.hpp"
#include "errormodels/ar_model.hpp"
#include "errormodels/imu_model.hpp"
#include "helpers.hpp"

using namespace sinsim;
using namespace sinsim::errormodels;

namespace {

const std::string kDir = std::string(SINSIM_SOURCE_DIR) + "/scenarios/";
const char* const kSensors[2] = {"gyro", "accel"};
const char* const kAxes[3] = {"x", "y", "z"};
// Datasheet total output noise (ADIS16355, unfiltered, 350 Hz bandwidth), SI.
const double kSigmaY[2] = {0.60 * M_PI / 180.0, 4.7e-3 * 9.80665};

std::vector<double> coefficients(const YAML::Node& effect) {
  std::vector<double> a;
  for (const auto& v : effect["a"]) a.push_back(v.as<double>());
  return a;
}

// Least-squares tau of exp(-k h/tau) against rho(1..500), golden section on log tau.
double fitTau(const std::vector<double>& rho, double h) {
  auto cost = [&](double tau) {
    double s = 0;
    for (std::size_t k = 1; k < rho.size(); ++k) {
      double e = rho[k] - std::exp(-double(k) * h / tau);
      s += e * e;
    }
    return s;
  };
  double lo = std::log(1e-4), hi = std::log(1.0);
  const double g = (std::sqrt(5.0) - 1) / 2;
  for (int i = 0; i < 200; ++i) {
    double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
    if (cost(std::exp(x1)) < cost(std::exp(x2))) hi = x2; else lo = x1;
  }
  return std::exp(0.5 * (lo + hi));
}

}  // namespace

TEST_CASE("adis16355-ar5.yaml: sigma_e = datasheet output noise / sqrt(variance gain)") {
  CHECK_NOTHROW(ImuErrorModel::load(kDir + "adis16355-ar5.yaml"));
  YAML::Node root = YAML::LoadFile(kDir + "adis16355-ar5.yaml");
  for (int s = 0; s < 2; ++s)
    for (int ax = 0; ax < 3; ++ax) {
      YAML::Node e = root[kSensors[s]][kAxes[ax]][0];
      auto a = coefficients(e);
      const double sigma = parseQuantity(e["sigma"].as<std::string>()).si;
      const double expected = kSigmaY[s] / std::sqrt(ar::varianceGain(a));
      INFO(kSensors[s] << "." << kAxes[ax]);
      // The file prints 5 significant digits: relative rounding ≤ 5e-5.
      CHECK(sigma == Approx(expected).epsilon(5e-5));
      CHECK(parseQuantity(e["rate"].as<std::string>()).si == 1000.0);
      // The implied output standard deviation, by the impulse response (independent of ar_model).
      const double r0 = test::arAcfImpulse(a, sigma, 0)[0];
      CHECK(std::sqrt(r0) == Approx(kSigmaY[s]).epsilon(5e-5));
    }
}

TEST_CASE("adis16355-gm.yaml: same variance, tau = least-squares fit of the AR(5) ACF") {
  CHECK_NOTHROW(ImuErrorModel::load(kDir + "adis16355-gm.yaml"));
  YAML::Node ar5 = YAML::LoadFile(kDir + "adis16355-ar5.yaml");
  YAML::Node gm = YAML::LoadFile(kDir + "adis16355-gm.yaml");
  for (int s = 0; s < 2; ++s)
    for (int ax = 0; ax < 3; ++ax) {
      INFO(kSensors[s] << "." << kAxes[ax]);
      auto a = coefficients(ar5[kSensors[s]][kAxes[ax]][0]);
      auto r = test::arAcfImpulse(a, 1.0, 500);
      std::vector<double> rho;
      for (double v : r) rho.push_back(v / r[0]);
      YAML::Node e = gm[kSensors[s]][kAxes[ax]][0];
      CHECK(parseQuantity(e["sigma"].as<std::string>()).si == Approx(kSigmaY[s]).epsilon(1e-12));
      // 5 significant digits again; the golden search converges far below that (200 steps).
      CHECK(parseQuantity(e["tau"].as<std::string>()).si == Approx(fitTau(rho, 1e-3)).epsilon(5e-5));
    }
}

TEST_CASE("grade presets load and instantiate at 100 Hz") {
  for (const char* f : {"grade-consumer.yaml", "grade-tactical.yaml", "grade-navigation.yaml"}) {
    INFO(f);
    ImuErrorModel m = ImuErrorModel::load(kDir + f);
    CHECK_FALSE(m.empty());
    CHECK_NOTHROW(m.instantiate(100.0, {1, 0}));
  }
}
