// libFuzzer target: the error-model reader, then one realisation of what it accepts driven for a
// few IMU intervals (instantiation checks and the effects' first steps are part of the reader's
// promise: an accepted model runs).
#include "errormodels/imu_model.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  sinsim::fuzz::expectInputErrorOnly(data, size, [](const std::string& text) {
    const auto model = sinsim::errormodels::ImuErrorModel::fromString(text, "fuzz.yaml");
    if (model.empty()) return;
    auto c = model.instantiate(100.0, {1, 0});
    for (int k = 1; k <= 8; ++k) {
      sinsim::ImuSample s;
      s.t = 0.01 * k;
      s.dt = 0.01;
      s.dtheta_b = sinsim::Vec3(1e-4, -2e-4, 3e-4);
      s.dv_b = sinsim::Vec3(0.0, 0.0, -0.098);
      c->corrupt(s, 298.15);
    }
  });
  return 0;
}
