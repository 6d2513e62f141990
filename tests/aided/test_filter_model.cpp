// The filter's sensor states from a model file (`filter: {model: FILE}`): the same filter from a
// file (relative to the scenario), from the same model inline, and from the state blocks built by
// hand with the SI values worked out here from the units; an effect the filter cannot carry is
// refused naming the model file, line and key.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "common/constants.hpp"
#include "common/error.hpp"
#include "sim/aided/filter_model.hpp"
#include "sim/scenario.hpp"
#include "test_support.hpp"

using namespace sinsim;
using namespace sinsim::sim::aided;

namespace {

const char* kScenario = R"(
name: fm
start: {latitude: 45 deg, longitude: 7 deg, height: 300 m, heading: 0 deg}
imu_rate: 100 Hz
segments:
  - {type: static, duration: 20 s}
gnss: {rate: 1 Hz, position_sigma: 1 m}
)";

// Every supported effect: white (density and sigma at a rate), bias (value + sigma), random walk,
// Gauss-Markov (continuous, and sampled at a rate: an AR(1)), AR(1) by output sigma; `all` and
// an axis's own list; a disabled unsupported effect; triad scale factors (a diagonal with a
// sigma, a purely random one given in %).
const char* kModel = R"(gyro:
  triad:
    - {type: scale_factor, diagonal: [100 ppm, 0, -50 ppm], sigma: 1000 ppm}
  all:
    - {type: white, density: 0.15 deg/sqrt(h)}
    - {type: gauss_markov, sigma: 20 deg/h, tau: 200 s}
  x:
    - {type: white, sigma: 0.01 deg/s, rate: 100 Hz}
    - {type: ar, a: [-0.9], output_sigma: 0.02 deg/s, rate: 10 Hz}
  y:
    - {type: gauss_markov, sigma: 0.6 deg/s, tau: 20 ms, rate: 1 kHz}
    - {type: bias_instability, B: 10 deg/h, tau_range: [1 s, 100 s], enabled: no}
accel:
  triad:
    - {type: scale_factor, value: 0, sigma: 0.2 %}
  all:
    - {type: bias, value: 1 mg, sigma: 2 mg}
    - {type: random_walk, K: 0.05 m/s/h/sqrt(h)}
)";

// The same model by hand, SI from the units: 1 deg = π/180 rad, 1 h = 3600 s, 1 mg = 9.80665e-3
// m/s² (standard gravity, as the unit table defines g).
FilterSensorModel byHand() {
  const double deg = kPi / 180.0, g0 = 9.80665;
  const double Nall = 0.15 * deg / 60.0;  // deg/sqrt(h) → rad/sqrt(s): / sqrt(3600)
  const double Nx = 0.01 * deg / 10.0;    // sigma / sqrt(rate) = 0.01 deg/s / sqrt(100 Hz)
  FilterSensorModel m;
  for (int i = 0; i < 3; ++i) {
    m.gyro[i].whiteDensity = Nall;
    m.gyro[i].blocks = {gaussMarkovState(20 * deg / 3600, 200)};
    StateBlock b = biasState(2e-3 * g0);
    b.x0(0) = 1e-3 * g0;
    m.accel[i].blocks = {b, randomWalkState(0.05 / 3600 / 60)};
  }
  m.gyro[0].whiteDensity = std::sqrt(Nall * Nall + Nx * Nx);
  // AR(1) y = 0.9 y + e: var y = σe² / (1 − 0.81), so σe = output sigma · sqrt(0.19).
  m.gyro[0].blocks.push_back(arState({-0.9}, 0.02 * deg * std::sqrt(0.19), 10.0));
  // The held GM at 1 kHz: AR(1) y = φ y + e, φ = exp(−1 ms / 20 ms), σe = σ sqrt(1 − φ²).
  const double phi = std::exp(-0.05);
  StateBlock gm = arState({-phi}, 0.6 * deg * std::sqrt(1.0 - phi * phi), 1000.0);
  gm.name = "gauss_markov";
  m.gyro[1].blocks.push_back(gm);
  // Scale factors last on each axis: ppm = 1e-6, % = 1e-2.
  const double sfMean[3] = {100e-6, 0.0, -50e-6};
  for (int i = 0; i < 3; ++i) {
    StateBlock sf = scaleFactorState(1000e-6);
    sf.x0(0) = sfMean[i];
    m.gyro[i].blocks.push_back(sf);
    m.accel[i].blocks.push_back(scaleFactorState(0.2e-2));
  }
  return m;
}

// Entry by entry to 1e-12 relative: the unit conversions round differently from the hand-written
// products (a few ulp), a wrong conversion or placement is off by orders of magnitude.
bool close(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols()) return false;
  for (Eigen::Index i = 0; i < a.size(); ++i)
    if (std::abs(a.data()[i] - b.data()[i]) > 1e-12 * std::max(std::abs(b.data()[i]), 1e-300))
      return false;
  return true;
}

void requireClose(const FilterSensorModel& a, const FilterSensorModel& b) {
  for (int i = 0; i < 6; ++i) {
    const SensorAxisModel& x = i < 3 ? a.gyro[i] : a.accel[i - 3];
    const SensorAxisModel& y = i < 3 ? b.gyro[i] : b.accel[i - 3];
    INFO("axis " << i);
    CHECK(std::abs(x.whiteDensity - y.whiteDensity) <= 1e-12 * y.whiteDensity);
    REQUIRE(x.blocks.size() == y.blocks.size());
    for (std::size_t k = 0; k < x.blocks.size(); ++k) {
      const StateBlock &p = x.blocks[k], &q = y.blocks[k];
      INFO("block " << k << " " << q.name);
      CHECK(p.name == q.name);
      CHECK(p.discrete == q.discrete);
      CHECK(p.scale == q.scale);
      CHECK(p.period == q.period);
      for (auto [u, v] : {std::pair(&p.F, &q.F), {&p.Qc, &q.Qc}, {&p.A, &q.A}, {&p.Qs, &q.Qs},
                          {&p.P0, &q.P0}})
        CHECK(close(*u, *v));
      CHECK(close(p.x0, q.x0));
      CHECK(close(p.c, q.c));
    }
  }
}

}  // namespace

TEST_CASE("filter model file: equal to the same model inline and to the states built by hand") {
  const auto dir = test::freshTempDir("sinsim-filter-model");
  test::writeText(dir / "filt.yaml", kModel);
  const sim::Scenario fromFile = sim::parseScenario(
      std::string(kScenario) + "filter: {model: filt.yaml}\n", "fm.yaml", dir.string());
  REQUIRE(fromFile.aiding.filter.enabled);
  CHECK(fromFile.aiding.filter.model == (dir / "filt.yaml").string());

  // The same model inline, indented under filter.model.
  std::string inlineModel = "filter:\n  model:\n";
  for (std::size_t a = 0, b; a < std::string(kModel).size(); a = b + 1) {
    b = std::string(kModel).find('\n', a);
    inlineModel += "    " + std::string(kModel).substr(a, b - a) + "\n";
  }
  const sim::Scenario inl = sim::parseScenario(std::string(kScenario) + inlineModel, "fm.yaml");
  CHECK(inl.aiding.filter.model == "inline");
  CHECK(fromFile.aiding.filter.sensors == inl.aiding.filter.sensors);  // bit for bit

  const FilterSensorModel& m = fromFile.aiding.filter.sensors;
  // GM per gyro axis, AR(1) on x, the sampled GM on y, bias + RW per accel, a scale factor per axis
  CHECK(m.stateCount() == 3 * 1 + 1 + 1 + 3 * 2 + 6);
  requireClose(m, byHand());
}

TEST_CASE("filter model: a bias_instability becomes its Gauss-Markov components, the fast ones "
          "white noise") {
  // B = 10 deg/h over [1 s, 100 s]: components of variance B² ln 10 / (π d) each (d = 2 a
  // decade) at τ_j = 10^-1.5 s · 10^((j + 0.5)/2), j = 0..9 (the range widened 1.5 decades each
  // side; effects/bias_instability.cpp). GNSS at 2 Hz: a 0.5 s step, so τ_0 = 0.056 s and
  // τ_1 = 0.18 s become white noise of density² 2 σ² τ, the other eight a state each.
  const auto dir = test::freshTempDir("sinsim-filter-model-flicker");
  test::writeText(dir / "bi.yaml",
                  "gyro:\n  x: [{type: bias_instability, B: 10 deg/h, tau_range: [1 s, 100 s]}]\n");
  std::string scenario = kScenario;
  scenario.replace(scenario.find("rate: 1 Hz"), 10, "rate: 2 Hz");
  const sim::Scenario sc = sim::parseScenario(scenario + "filter: {model: bi.yaml}\n", "fm.yaml",
                                              dir.string());
  const SensorAxisModel& x = sc.aiding.filter.sensors.gyro[0];
  const double B = 10.0 * kPi / 180.0 / 3600.0, s2 = B * B * std::log(10.0) / (2.0 * kPi);
  auto tau = [](int j) { return std::pow(10.0, -1.5 + (j + 0.5) / 2.0); };
  REQUIRE(x.blocks.size() == 8);
  for (int j = 2; j < 10; ++j) {
    const StateBlock& b = x.blocks[std::size_t(j - 2)];
    INFO("component " << j);
    CHECK(b.name == "bias_instability");
    CHECK(b.F(0, 0) == Approx(-1.0 / tau(j)).epsilon(1e-12));
    CHECK(b.P0(0, 0) == Approx(s2).epsilon(1e-12));
    CHECK(b.Qc(0, 0) == Approx(2.0 * s2 / tau(j)).epsilon(1e-12));
  }
  CHECK(x.whiteDensity * x.whiteDensity == Approx(2.0 * s2 * (tau(0) + tau(1))).epsilon(1e-12));
  CHECK(sc.aiding.filter.sensors.gyro[1].blocks.empty());  // x's own list only
}

TEST_CASE("filter model file: a temperature without the scenario's temperature is refused with "
          "file, line, key, the rest of the catalogue is carried") {
  const auto dir = test::freshTempDir("sinsim-filter-model-bad");
  test::writeText(dir / "bad.yaml", R"(gyro:
  triad:
    - {type: scale_factor, matrix: [[100 ppm, 10 ppm, 0], [0, 100 ppm, 0], [0, 0, 100 ppm]]}
  all:
    - {type: temperature, T0: 25 degC, coefficients: [0.01 deg/s/degC]}
    - {type: sinusoid, amplitude: 0.01 deg/s, frequency: 2 Hz, phase: 0 deg}
accel:
  y:
    - {type: outliers, rate: 0.1 Hz, amplitude: 1 m/s^2}
    - {type: ramp, slope: 1 mg/h}
    - {type: white, density: 0.1 m/s/sqrt(h)}
)");
  try {
    sim::parseScenario(std::string(kScenario) + "filter: {model: bad.yaml}\n", "fm.yaml",
                       dir.string());
    FAIL("expected a ConfigError");
  } catch (const ConfigError& e) {
    const std::string m = e.what();
    INFO(m);
    // The scenario's key and, inside the message, the model file's line and key of each effect.
    CHECK(m.find("fm.yaml:") != std::string::npos);
    CHECK(m.find("filter.model") != std::string::npos);
    CHECK(m.find("bad.yaml:5: gyro.all[0]: temperature: the filter compensates it at the "
                 "sensor's temperature") != std::string::npos);
    // known errors are compensated (test_known_errors.cpp), outliers are white noise of their
    // variance, the white is supported: none of them is refused
    for (const char* fine : {"gyro.triad[0]", "gyro.all[1]", "accel.y[0]", "accel.y[1]", "accel.y[2]"})
      CHECK(m.find(fine) == std::string::npos);
    // the temperature sits in `all`: reported once, not once per axis.
    CHECK(m.find("all[0]: temperature:") == m.rfind("all[0]: temperature:"));
  }
}

TEST_CASE("filter model: a missing model key and a model file that does not parse") {
  const auto dir = test::freshTempDir("sinsim-filter-model-missing");
  test::writeText(dir / "broken.yaml", "gyro:\n  x: [{type: white, density: -1 deg/sqrt(h)}]\n");
  for (const char* filter : {"filter: {}\n", "filter: {model: broken.yaml}\n"}) {
    try {
      sim::parseScenario(std::string(kScenario) + filter, "fm.yaml", dir.string());
      FAIL("expected a ConfigError");
    } catch (const ConfigError& e) {
      const std::string m = e.what();
      INFO(m);
      CHECK(m.find("filter") != std::string::npos);
      if (std::string(filter).find("broken") != std::string::npos)
        CHECK(m.find("broken.yaml:2: gyro.x[0].density") != std::string::npos);
      // A present but broken filter is not also reported as a missing one.
      CHECK(m.find("GNSS fixes need a filter") == std::string::npos);
    }
  }
}

TEST_CASE("filter model: a sampled process slower than the filter's step is refused with its line") {
  // The filter propagates an AR or rated GM in whole periods within each step (the GNSS interval,
  // at most 1 s): at 0.5 Hz against 1 Hz fixes a period is longer than a step. At 1 Hz it fits.
  const auto dir = test::freshTempDir("sinsim-filter-model-slow");
  for (const char* rate : {"1 Hz", "0.5 Hz"}) {
    test::writeText(dir / "slow.yaml", std::string("gyro:\n  all:\n    - {type: ar, a: [-0.9], "
                                                   "sigma: 0.01 deg/s, rate: ") + rate + "}\n");
    const std::string text = std::string(kScenario) + "filter: {model: slow.yaml}\n";
    if (std::string(rate) == "1 Hz") {
      CHECK_NOTHROW(sim::parseScenario(text, "fm.yaml", dir.string()));
      continue;
    }
    try {
      sim::parseScenario(text, "fm.yaml", dir.string());
      FAIL("expected a ConfigError");
    } catch (const ConfigError& e) {
      const std::string m = e.what();
      INFO(m);
      CHECK(m.find("slow.yaml:3: gyro.all[0]: ar: a process sampled every 2 s is slower than "
                   "the filter's step of 1 s") != std::string::npos);
    }
  }
}

TEST_CASE("filter model: a quantization adds white noise where each sample is rounded, nothing "
          "where the remainder is carried") {
  // A fitted model (`fit --kind latent`) can hold a quantization; the filter takes it as the
  // effect reads its spec. At 100 Hz: a rate LSB of 0.05 deg/s, each sample rounded, is white
  // noise of variance LSB²/12 per sample, density² = LSB² / (12 · 100 Hz), in quadrature with the
  // axis's white (0.2 deg/sqrt(h)); the same LSB carried, and an increment LSB (carried by
  // default, dithered or not), leave the axis as without it.
  const auto dir = test::freshTempDir("sinsim-filter-model-quantization");
  test::writeText(dir / "q.yaml", R"(gyro:
  all: [{type: white, density: 0.2 deg/sqrt(h)}]
  x: [{type: quantization, lsb: 0.05 deg/s}]
  y: [{type: quantization, lsb: 0.05 deg/s, carry: yes}]
  z: [{type: quantization, lsb: 0.0005 deg, dithered: yes}]
accel:
  x: [{type: quantization, lsb: 0.5 mg, dithered: yes}]
  y: [{type: quantization, lsb: 0.00125 m/s}]
)");
  const sim::Scenario sc = sim::parseScenario(std::string(kScenario) + "filter: {model: q.yaml}\n",
                                              "fm.yaml", dir.string());
  const FilterSensorModel& m = sc.aiding.filter.sensors;
  CHECK(m.stateCount() == 0);
  const double d = kPi / 180.0, white = 0.2 * d / 60.0, lsb = 0.05 * d;
  CHECK(m.gyro[0].whiteDensity * m.gyro[0].whiteDensity ==
        Approx(white * white + lsb * lsb / (12.0 * 100.0)).epsilon(1e-12));
  CHECK(m.gyro[1].whiteDensity == Approx(white).epsilon(1e-15));
  CHECK(m.gyro[2].whiteDensity == Approx(white).epsilon(1e-15));
  const double g = kStandardGravity * 0.5e-3;  // 0.5 mg, dithered, not carried: uniform on ±LSB/2 each sample
  CHECK(m.accel[0].whiteDensity == Approx(g / std::sqrt(12.0 * 100.0)).epsilon(1e-12));
  CHECK(m.accel[1].whiteDensity == 0.0);
}

TEST_CASE("filter model: bias jumps and outliers by the processes with their second moments") {
  // At 100 Hz and rates far below it, the closed forms of the Poisson limit (effects/bias_jumps.cpp,
  // outliers.cpp; the effects' own statistics against simulation: test_errormodels): steps a
  // random walk of K² = rate size², a telegraph a Gauss-Markov of sigma size/2 and tau
  // 1/(2 rate), outliers a white density² of rate amplitude² / imu_rate² beside the axis's white.
  const auto dir = test::freshTempDir("sinsim-filter-model-jumps");
  test::writeText(dir / "j.yaml", R"(gyro:
  all: [{type: white, density: 0.2 deg/sqrt(h)}]
  x: [{type: bias_jumps, rate: 0.01 Hz, size: 20 deg/h}]
  y: [{type: bias_jumps, rate: 0.02 Hz, size: 40 deg/h, telegraph: yes}]
accel:
  z: [{type: outliers, rate: 0.5 Hz, amplitude: 0.3 m/s^2}]
)");
  const sim::Scenario sc = sim::parseScenario(std::string(kScenario) + "filter: {model: j.yaml}\n",
                                              "fm.yaml", dir.string());
  const FilterSensorModel& m = sc.aiding.filter.sensors;
  const double dph = kPi / 180.0 / 3600.0;
  REQUIRE(m.gyro[0].blocks.size() == 1);
  REQUIRE(m.gyro[1].blocks.size() == 1);
  CHECK(m.gyro[2].blocks.empty());
  const StateBlock& steps = m.gyro[0].blocks[0];
  const StateBlock walk = randomWalkState(std::sqrt(0.01) * 20 * dph);
  CHECK(steps.name == "bias_jumps");
  CHECK(steps.Qc(0, 0) == Approx(walk.Qc(0, 0)).epsilon(1e-4));  // 1 − p/2 of the Poisson limit
  CHECK(steps.F(0, 0) == 0.0);
  const StateBlock& tele = m.gyro[1].blocks[0];
  const StateBlock gm = gaussMarkovState(20 * dph, 25.0);
  CHECK(tele.name == "bias_jumps");
  CHECK(tele.P0(0, 0) == Approx(gm.P0(0, 0)).epsilon(1e-12));
  CHECK(tele.F(0, 0) == Approx(gm.F(0, 0)).epsilon(1e-3));
  CHECK(tele.Qc(0, 0) == Approx(gm.Qc(0, 0)).epsilon(1e-3));
  const double white = 0.2 * kPi / 180.0 / 60.0;
  CHECK(m.gyro[0].whiteDensity == Approx(white).epsilon(1e-15));
  CHECK(m.accel[2].whiteDensity * m.accel[2].whiteDensity ==
        Approx(0.5 * 0.3 * 0.3 / (100.0 * 100.0)).epsilon(1e-12));
  CHECK(m.accel[2].blocks.empty());
}
