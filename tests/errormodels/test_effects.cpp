// Deterministic and signal-dependent effects against closed forms; refusals with their messages.
#include <catch2/catch.hpp>

#include <cmath>

#include "errormodels/effect.hpp"
#include "errormodels/imu_model.hpp"
#include "helpers.hpp"
#include "test_support.hpp"

using namespace sinsim;
using namespace sinsim::errormodels;

using sinsim::test::messageOf;

namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr double kG = 9.80665;

ImuSample sample(double t, double dt, Vec3 dth = Vec3::Zero(),
                      Vec3 dv = Vec3::Zero()) {
  ImuSample s;
  s.t = t;
  s.dt = dt;
  s.dtheta_b = dth;
  s.dv_b = dv;
  return s;
}

}  // namespace

TEST_CASE("every catalogue effect is registered under its YAML name") {
  for (const char* name : {"white", "random_walk", "gauss_markov", "ar", "bias_instability", "bias",
                           "bias_jumps", "quantization", "scale_factor", "misalignment", "g_sensitivity",
                           "temperature", "sinusoid", "ramp", "warmup"})
    CHECK(findEffectType(name) != nullptr);
  CHECK(findEffectType("whyte") == nullptr);
}

TEST_CASE("an unstable AR polynomial is refused, naming its largest pole") {
  // A(z) = 1 - 2.05 z^-1 + 1.05 z^-2 = (1 - z^-1)(1 - 1.05 z^-1): poles 1 and 1.05.
  auto msg = messageOf([] {
    ImuErrorModel::fromString("gyro:\n  x:\n    - {type: ar, a: [-2.05, 1.05], sigma: 1 deg/s, "
                              "rate: 1 kHz}\n", "ar.yaml");
  });
  CHECK(msg.find("ar.yaml:3: gyro.x[0].a: unstable AR polynomial: largest pole magnitude 1.05") !=
        std::string::npos);
  // A pole ON the unit circle (random walk in disguise) is refused too.
  CHECK(messageOf([] {
          ImuErrorModel::fromString("gyro:\n  x: [{type: ar, a: [-1], sigma: 1 deg/s, rate: 1 kHz}]",
                                    "ar.yaml");
        }).find("largest pole magnitude 1 ") != std::string::npos);
  // The paper's six polynomials are accepted (largest poles 0.833 ... 0.982, seed-paper.md).
  CHECK_NOTHROW(ImuErrorModel::load(std::string(SINSIM_SOURCE_DIR) + "/scenarios/adis16355-ar5.yaml"));
}

TEST_CASE("a process defined at a rate slower than the IMU is refused at instantiation") {
  auto m = ImuErrorModel::fromString(
      "accel:\n  all: [{type: gauss_markov, sigma: 1 mg, tau: 1 s, rate: 100 Hz}]\n", "slow.yaml");
  CHECK_NOTHROW(m.instantiate(100.0, {}));
  CHECK_NOTHROW(m.instantiate(50.0, {}));
  auto msg = messageOf([&] { m.instantiate(200.0, {}); });
  CHECK(msg.find("accel.all[0].gauss_markov(x)") != std::string::npos);
  CHECK(msg.find("slower than the IMU rate 200 Hz") != std::string::npos);
  // A record's rate read from its stamps (jitter, Unix time in ns) is 1e-8 off the rate printed
  // in a model fitted on it: the same rate. 1e-5 off is not, and the message shows the digits.
  CHECK_NOTHROW(m.instantiate(100.0000013, {}));
  msg = messageOf([&] { m.instantiate(100.001, {}); });
  CHECK(msg.find("defined at 100 Hz, slower than the IMU rate 100.001 Hz") != std::string::npos);
}

TEST_CASE("triad and axis effects must sit in the right lists, the model file is all-or-nothing") {
  auto msg = messageOf([] {
    ImuErrorModel::fromString(R"(gyro:
  x: [{type: scale_factor, value: 300 ppm}]
  triad: [{type: white, density: 1 deg/sqrt(h)}]
accel:
  triad:
    - {type: g_sensitivity, value: 0.01 deg/s/g}
    - {type: misalignment, matrix: [[1 deg, 0, 0], [0, 0, 0], [0, 0, 0]]}
    - {type: scale_factor, diagonal: [1, 2]}
  y:
    - {type: temperature, T0: 25 degC, coefficients: [0.1 mg/degC, 1 mg]}
    - {type: quantization, lsb: 1 deg}
)", "place.yaml");
  });
  CHECK(msg.find("place.yaml:2: gyro.x[0].type: scale_factor acts on the whole triad") != std::string::npos);
  CHECK(msg.find("place.yaml:3: gyro.triad[0].type: white acts on one axis") != std::string::npos);
  CHECK(msg.find("place.yaml:6: accel.triad[0].type: g_sensitivity is a gyro effect") != std::string::npos);
  CHECK(msg.find("accel.triad[1].matrix: the diagonal must be 0") != std::string::npos);
  CHECK(msg.find("accel.triad[2].diagonal: expected 3 values, got 2") != std::string::npos);
  // The second temperature coefficient must be signal/temperature².
  CHECK(msg.find("place.yaml:10: accel.y[0].coefficients[1]") != std::string::npos);
  CHECK(msg.find("accel.y[1].lsb: expected an LSB of the rate output") != std::string::npos);
}

TEST_CASE("quantization with carry: the summed output stays within one LSB of the true sum") {
  // White noise + a bias, quantized with an increment LSB of 0.001 deg (carry on by default). The
  // same model without the quantization draws the same numbers (filtered() keeps the streams).
  auto m = ImuErrorModel::fromString(R"(
gyro:
  all:
    - {type: white, density: 0.5 deg/sqrt(h)}
    - {type: bias, value: 3.3 deg/h}
    - {type: quantization, lsb: 0.001 deg}
)", "q.yaml");
  auto raw = m.filtered([](const std::string& n) { return n.find("quantization") == std::string::npos; });
  auto cq = m.instantiate(100.0, {3, 0});
  auto cr = raw.instantiate(100.0, {3, 0});
  const double lsb = 0.001 * kDeg;
  Vec3 sq = Vec3::Zero(), sr = Vec3::Zero();
  double worst = 0.0;
  for (int k = 1; k <= 100000; ++k) {
    auto a = sample(k / 100.0, 0.01), b = a;
    cq->corrupt(a, NAN);
    cr->corrupt(b, NAN);
    // every output is an integer number of LSBs (to rounding of the multiplication, 1e-9 LSB)
    CHECK(std::fabs(a.dtheta_b.x() / lsb - std::round(a.dtheta_b.x() / lsb)) < 1e-9);
    sq += a.dtheta_b;
    sr += b.dtheta_b;
    worst = std::max(worst, (sq - sr).cwiseAbs().maxCoeff());
  }
  // |Σq - Σu| = |remainder| ≤ lsb/2, plus the rounding of 1e5 additions (≪ 1e-6 lsb).
  CHECK(worst <= 0.5 * lsb * (1 + 1e-6));
  // Without carry the error accumulates (it is a random walk of ±lsb/2 steps: ≫ 1 LSB after 1e5).
  auto nc = ImuErrorModel::fromString(R"(
gyro:
  all:
    - {type: white, density: 0.5 deg/sqrt(h)}
    - {type: bias, value: 3.3 deg/h}
    - {type: quantization, lsb: 0.001 deg, carry: false}
)", "q.yaml").instantiate(100.0, {3, 0});
  auto cr2 = raw.instantiate(100.0, {3, 0});
  double sum = 0.0;
  for (int k = 1; k <= 100000; ++k) {
    auto a = sample(k / 100.0, 0.01), b = a;
    nc->corrupt(a, NAN);
    cr2->corrupt(b, NAN);
    sum += a.dtheta_b.x() - b.dtheta_b.x();
  }
  CHECK(std::fabs(sum) > 2 * lsb);
}

TEST_CASE("dithered quantization: 3Q^2/tau^2 carried, lsb^2/12 white per sample, no lattice") {
  // Remainders independent uniform on +-lsb/2 (IEEE 952's Q = lsb/sqrt(12)): the rate error
  // (r[k-1] - r[k]) / dt has autocovariance 2Q^2/dt^2, -Q^2/dt^2 at lags 0, 1 (then 0), whose Allan
  // variance is 3Q^2/tau^2 at every tau = m dt (helpers.hpp computes it from the autocovariance).
  const double lsb = 0.001 * kDeg, dt = 0.01, Q = lsb / std::sqrt(12.0);
  const auto m = ImuErrorModel::fromString(
      "gyro:\n  x: [{type: quantization, lsb: 0.001 deg, dithered: true}]\n", "q.yaml");
  const std::size_t n = 200000;
  const auto y = sinsim::test::simulateRates(m, 1.0 / dt, n, 5, 0);
  const std::vector<double> r = {2 * Q * Q / (dt * dt), -Q * Q / (dt * dt)};
  for (std::size_t mm : {1, 2, 4, 16, 64}) {
    std::size_t K = 0;
    const double avar = sinsim::test::allanVar({y}, mm, &K);
    const auto th = sinsim::test::allanFromAcf(r, mm, K, K);
    INFO("m = " << mm << ": " << avar << " against " << th.avar << " +- " << th.sd);
    CHECK(th.avar == Approx(3 * Q * Q / (mm * dt * mm * dt)).epsilon(1e-12));
    CHECK(std::fabs(avar - th.avar) < 5 * th.sd);
  }
  // Not on a lattice: a fraction of the outputs far from any multiple of the LSB.
  std::size_t off = 0;
  double sum = 0, worst = 0;
  for (double v : y) {
    const double u = v * dt / lsb;
    off += std::fabs(u - std::round(u)) > 0.1;
    sum += v * dt;
    worst = std::max(worst, std::fabs(sum));
  }
  CHECK(off > n / 2);
  // The remainders telescope: the summed output is the true sum (0) less the last one.
  CHECK(worst <= 0.5 * lsb * (1 + 1e-9));
  // Not carried (a rate LSB): each sample's remainder alone, white noise of variance lsb^2/12.
  const double lsbRate = 0.05 * kDeg;  // deg/s
  const auto w = sinsim::test::simulateRates(
      ImuErrorModel::fromString("gyro:\n  x: [{type: quantization, lsb: 0.05 deg/s, dithered: true}]\n",
                                "w.yaml"),
      1.0 / dt, n, 6, 0);
  for (std::size_t mm : {1, 8}) {
    std::size_t K = 0;
    const double avar = sinsim::test::allanVar({w}, mm, &K);
    const auto th = sinsim::test::allanFromAcf({lsbRate * lsbRate / 12.0}, mm, K, K);
    INFO("rate LSB, m = " << mm << ": " << avar << " against " << th.avar << " +- " << th.sd);
    CHECK(std::fabs(avar - th.avar) < 5 * th.sd);
  }
}

TEST_CASE("a rate LSB rounds each interval's increment to lsb·dt") {
  auto c = ImuErrorModel::fromString(
      "gyro:\n  z: [{type: quantization, lsb: 0.07326 deg/s}]\n", "q.yaml").instantiate(1000, {});
  auto s = sample(0.001, 0.001, Vec3(0, 0, 0.1 * kDeg * 0.001));  // 0.1 deg/s true
  c->corrupt(s, NAN);
  // round(0.1/0.07326) = 1 LSB = 0.07326 deg/s; 1e-12 relative: unit conversion rounding.
  CHECK(s.dtheta_b.z() / 0.001 == Approx(0.07326 * kDeg).epsilon(1e-12));
}

TEST_CASE("linear triad effects: u ← (I+M)(I+S)u in file order, g-sensitivity adds G·dv") {
  auto m = ImuErrorModel::fromString(R"(
gyro:
  triad:
    - {type: scale_factor, diagonal: [1000 ppm, -500 ppm, 0]}
    - {type: misalignment, matrix: [[0, 1 mrad, 0], [0, 0, -2 mrad], [0.001, 0, 0]]}
    - {type: g_sensitivity, matrix: [[0.1 deg/s/g, 0, 0], [0, 0, 0], [0, 0, 0.2 deg/s/g]]}
accel:
  triad:
    - {type: scale_factor, value: 200 ppm}
)", "lin.yaml");
  auto c = m.instantiate(100, {});
  const Vec3 dth(0.01, -0.02, 0.03), dv(0.1, 0.2, -0.098);
  auto s = sample(0.01, 0.01, dth, dv);
  c->corrupt(s, NAN);
  Mat3 S = Vec3(1e-3, -5e-4, 0).asDiagonal();
  Mat3 M;
  M << 0, 1e-3, 0, 0, 0, -2e-3, 1e-3, 0, 0;
  Mat3 G = Vec3(0.1 * kDeg / kG, 0, 0.2 * kDeg / kG).asDiagonal();
  Vec3 expected = (Mat3::Identity() + M) * (Mat3::Identity() + S) * dth + G * dv;
  // 1e-15 absolute on 0.03 rad: a few roundings of 3×3 products.
  CHECK((s.dtheta_b - expected).norm() < 1e-15);
  CHECK((s.dv_b - 1.0002 * dv).norm() < 1e-15);
}

TEST_CASE("scale_factor with a sigma: a per-axis turn-on scale error, N(value, sigma²) per run") {
  // Over R runs each axis's drawn scale error has mean `value` and variance sigma²: the sample
  // mean within 4 sigma/sqrt(R) (failure ~6e-5 per axis for a right draw), the sample variance
  // within 4 sqrt(2/R) relative (normal approximation of χ²(R−1)/(R−1)); the axes uncorrelated
  // (|r| < 4/sqrt(R)). The same run twice: the same numbers, bit for bit.
  const auto m = ImuErrorModel::fromString(R"(
accel:
  triad:
    - {type: scale_factor, diagonal: [100 ppm, 0, -300 ppm], sigma: 2000 ppm}
)", "sf.yaml");
  const int R = 4000;
  const Vec3 mean(100e-6, 0, -300e-6);
  const double sigma = 2000e-6;
  Vec3 sum = Vec3::Zero(), sum2 = Vec3::Zero();
  double sumXY = 0.0;
  for (int r = 0; r < R; ++r) {
    const StreamKey key{3, std::uint64_t(r)};
    auto s = sample(0.01, 0.01, Vec3::Zero(), Vec3::Ones());
    m.instantiate(100, key)->corrupt(s, NAN);
    const Vec3 e = s.dv_b - Vec3::Ones() - mean;
    auto again = sample(0.01, 0.01, Vec3::Zero(), Vec3::Ones());
    m.instantiate(100, key)->corrupt(again, NAN);
    REQUIRE(again.dv_b == s.dv_b);
    sum += e;
    sum2 += e.cwiseProduct(e);
    sumXY += e.x() * e.y();
  }
  for (int i = 0; i < 3; ++i) {
    CHECK(std::abs(sum[i] / R) < 4.0 * sigma / std::sqrt(double(R)));
    CHECK(std::abs(sum2[i] / R / (sigma * sigma) - 1.0) < 4.0 * std::sqrt(2.0 / R));
  }
  CHECK(std::abs(sumXY / R) / (sigma * sigma) < 4.0 / std::sqrt(double(R)));
}

TEST_CASE("sinusoid, ramp, warmup: increments are the exact integrals, temperature needs T") {
  auto m = ImuErrorModel::fromString(R"(
gyro:
  x: [{type: sinusoid, amplitude: 0.05 deg/s, frequency: 12.34 Hz, phase: 30 deg}]
  y: [{type: ramp, slope: 36 deg/h/h}]
  z: [{type: warmup, amplitude: 0.1 deg/s, tau: 2 s}]
accel:
  x: [{type: temperature, T0: 25 degC, coefficients: [0.1 mg/degC, 0.01 mg/degC^2]}]
)", "det.yaml");
  CHECK(m.needsTemperature());
  auto c = m.instantiate(100, {});
  auto s0 = sample(0.01, 0.01);
  CHECK(messageOf([&] { c->corrupt(s0, NAN); }).find("no sensor temperature") != std::string::npos);
  const double A = 0.05 * kDeg, w = 2 * M_PI * 12.34, ph = 30 * kDeg;
  const double R = 36 * kDeg / 3600 / 3600, Aw = 0.1 * kDeg, tw = 2.0;
  Vec3 sum = Vec3::Zero();
  const double T = 273.15 + 35;  // 10 K above T0
  for (int k = 1; k <= 1000; ++k) {
    auto s = sample(k * 0.01, 0.01);
    c->corrupt(s, T);
    sum += s.dtheta_b;
    CHECK(s.dv_b.x() == Approx((0.1e-3 * kG * 10 + 0.01e-3 * kG * 100) * 0.01).epsilon(1e-12));
  }
  // ∫_0^10 s of each error, closed form (12.34 Hz: 123.4 periods, so the integral is not 0);
  // 1e-10 / 1e-12 relative: 1000 roundings of terms of comparable size.
  CHECK(sum.x() == Approx(A / w * (std::cos(ph) - std::cos(w * 10 + ph))).epsilon(1e-10));
  CHECK(sum.y() == Approx(R * 100 / 2).epsilon(1e-12));
  CHECK(sum.z() == Approx(Aw * tw * (1 - std::exp(-10 / tw))).epsilon(1e-12));
}

TEST_CASE("enabled: false removes an effect without moving the other effects' streams") {
  auto on = ImuErrorModel::fromString(
      "gyro:\n  x: [{type: bias, sigma: 1 deg/s}, {type: white, density: 1 deg/sqrt(h)}]\n", "e.yaml");
  auto off = ImuErrorModel::fromString(
      "gyro:\n  x: [{type: bias, sigma: 1 deg/s, enabled: false}, {type: white, density: 1 deg/sqrt(h)}]\n",
      "e.yaml");
  auto white = on.filtered([](const std::string& n) { return n.find("white") != std::string::npos; });
  CHECK(off.effectNames() == white.effectNames());
  auto a = test::simulateRates(off, 100, 100, 9, 0), b = test::simulateRates(white, 100, 100, 9, 0);
  CHECK(a == b);
}

TEST_CASE("corruptBlock gives corrupt()'s numbers bit for bit, whatever the block sizes") {
  // Every effect type, the stateful ones (AR at its own rate, quantization's carried remainder,
  // the processes' streams) among them: the block path must be the sample-by-sample path.
  const auto m = ImuErrorModel::fromString(R"(
gyro:
  triad:
    - {type: scale_factor, diagonal: [300 ppm, -200 ppm, 150 ppm]}
    - {type: misalignment, matrix: [[0, 0.1 deg, 0], [-0.05 deg, 0, 0.2 mrad], [0, 0, 0]]}
    - {type: g_sensitivity, value: 0.01 deg/s/g}
  all:
    - {type: white, density: 0.5 deg/sqrt(h)}
    - {type: bias, sigma: 10 deg/h}
    - {type: gauss_markov, sigma: 20 deg/h, tau: 200 s}
    - {type: random_walk, K: 3 deg/h/sqrt(h)}
    - {type: bias_instability, floor: 10 deg/h, tau_range: [1 s, 1000 s]}
    - {type: ar, a: [-1.0604, -0.30249, 0.043657, 0.18006, 0.14555], sigma: 0.021 deg/s, rate: 1 kHz}
    - {type: outliers, rate: 0.5 Hz, amplitude: 1 deg/s}
    - {type: bias_jumps, rate: 0.2 Hz, size: 0.05 deg/s}
    - {type: ramp, slope: 1 deg/h^2}
    - {type: temperature, T0: 25 degC, coefficients: [0.01 deg/s/degC]}
    - {type: quantization, lsb: 0.001 deg}
  x: [{type: sinusoid, amplitude: 0.05 deg/s, frequency: 12.34 Hz, phase: 30 deg},
      {type: bias_jumps, rate: 1 Hz, size: 0.02 deg/s, telegraph: yes}]
  z: [{type: warmup, amplitude: 0.1 deg/s, tau: 2 s}]
accel:
  all:
    - {type: white, density: 0.1 m/s/sqrt(h)}
    - {type: gauss_markov, sigma: 2 mg, tau: 300 s}
    - {type: quantization, lsb: 2.522 mg}
)", "every.yaml");
  auto one = m.instantiate(100.0, {7, 3});
  auto block = m.instantiate(100.0, {7, 3});
  std::vector<ImuSample> a, b;
  std::vector<double> temperature;
  for (int k = 1; k <= 3000; ++k) {
    const double t = k / 100.0;
    a.push_back(sample(t, t - (k - 1) / 100.0, Vec3(0.01 * std::sin(t), 0.002, -0.003 * t / 30),
                       Vec3(0.001, -0.002 * std::cos(t), -kG / 100.0)));
    temperature.push_back(298.15 + 0.1 * t);
  }
  b = a;
  for (std::size_t k = 0; k < a.size(); ++k) one->corrupt(a[k], temperature[k]);
  const std::size_t sizes[4] = {1, 7, 128, 300};
  for (std::size_t at = 0, i = 0; at < b.size(); ++i) {
    const std::size_t n = std::min(sizes[i % 4], b.size() - at);
    block->corruptBlock(&b[at], &temperature[at], n);
    at += n;
  }
  int differ = 0;
  for (std::size_t k = 0; k < a.size(); ++k)
    differ += (a[k].dtheta_b != b[k].dtheta_b || a[k].dv_b != b[k].dv_b) ? 1 : 0;
  CHECK(differ == 0);
  CHECK(a.back().dtheta_b != sample(30.0, 0.01).dtheta_b);  // the model did corrupt
}
