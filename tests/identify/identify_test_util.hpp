// Synthetic static records for the identify tests, made by the simulator's own error plug-ins:
// ImuErrorModel::instantiate + corrupt on zero ideal increments, the loop of `sinsim synth`
// without Earth rate and gravity (the fits remove the mean anyway).
#pragma once

#include <string>

#include "errormodels/imu_model.hpp"
#include "errormodels/stats/record.hpp"
#include "common/types.hpp"

namespace identify_test {

/// A record of `duration` [s] at `rate` [Hz] from the model text `body` (YAML after the
/// description line). Only channels with a non-zero signal are filled (an error-free channel
/// would be constant). Seeded: (seed, run 0).
inline sinsim::errormodels::Record staticRecord(const std::string& body, double rate,
                                                double duration, std::uint64_t seed) {
  using namespace sinsim;
  const auto model =
      errormodels::ImuErrorModel::fromString("description: test\n" + body + "\n", "synthetic.yaml");
  auto c = model.instantiate(rate, {seed, 0});
  const std::size_t n = static_cast<std::size_t>(std::llround(duration * rate));
  const double dt = 1.0 / rate;
  errormodels::Record r;
  r.source = "synthetic";
  r.rate_hz = rate;
  r.rows = n;
  std::array<std::vector<double>, 3> g, a;
  for (int i = 0; i < 3; ++i) g[i].resize(n), a[i].resize(n);
  bool gAny[3] = {false, false, false}, aAny[3] = {false, false, false};
  for (std::size_t k = 0; k < n; ++k) {
    ImuSample s;
    s.t = static_cast<double>(k + 1) * dt;
    s.dt = dt;
    c->corrupt(s, 298.15);
    for (int i = 0; i < 3; ++i) {
      g[i][k] = s.dtheta_b[i] / dt;
      a[i][k] = s.dv_b[i] / dt;
      gAny[i] = gAny[i] || g[i][k] != 0.0;
      aAny[i] = aAny[i] || a[i][k] != 0.0;
    }
  }
  for (int i = 0; i < 3; ++i) {
    if (gAny[i]) r.gyro[i] = std::move(g[i]);
    if (aAny[i]) r.accel[i] = std::move(a[i]);
  }
  return r;
}

}  // namespace identify_test
