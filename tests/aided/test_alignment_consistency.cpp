// The filter's start after a coarse alignment (ErrorStateFilter::startAfterAlignment) against the
// alignment's actual errors: with the filter's model = the truth's (white + bias + Gauss-Markov +
// random walk on every axis, a grade at which gyrocompassing works: heading 1-sigma ≈ 1°), the
// run-averaged NEES of the 9 navigation states over R runs is χ²(9R)/R (Bar-Shalom, Li &
// Kirubarajan 2001, §5.4.2) at the first filter epochs after the alignment (still static, the
// attitude known only from the alignment), at the end of the aiding stretch and of the outage.
// Two-sided 99 % bands (normal approximation, 9R = 1800 degrees of freedom).
// Before the alignment's own uncertainty was used, the filter kept the user's initial attitude
// sigma (here 0.3°, 0.3°, 2°): twice the true heading error, a NEES far below its band.
#include <catch2/catch.hpp>

#include <cmath>

#include "common/constants.hpp"
#include "consistency_support.hpp"
#include "errormodels/imu_model.hpp"
#include "sim/aided/aided_navigation.hpp"

using namespace sinsim;
using namespace sinsim::sim::aided;

namespace {

const char* kModel = R"(
gyro:
  all:
    - {type: white, density: 0.01 deg/sqrt(h)}
    - {type: bias, sigma: 0.1 deg/h}
    - {type: gauss_markov, sigma: 0.05 deg/h, tau: 100 s}
    - {type: random_walk, K: 0.02 deg/h/sqrt(h)}
accel:
  all:
    - {type: white, density: 0.05 m/s/sqrt(h)}
    - {type: bias, sigma: 0.5 mg}
    - {type: gauss_markov, sigma: 0.2 mg, tau: 60 s}
    - {type: random_walk, K: 0.05 m/s/h/sqrt(h)}
)";

FilterSensorModel filterModel() {
  FilterSensorModel m;
  const double dph = kRadPerDeg / 3600.0, mg = 1e-3 * kStandardGravity;
  for (int i = 0; i < 3; ++i) {
    m.gyro[i].whiteDensity = 0.01 * kRadPerDeg / 60.0;
    m.gyro[i].blocks = {biasState(0.1 * dph), gaussMarkovState(0.05 * dph, 100.0),
                        randomWalkState(0.02 * dph / 60.0)};
    m.accel[i].whiteDensity = 0.05 / 60.0;
    m.accel[i].blocks = {biasState(0.5 * mg), gaussMarkovState(0.2 * mg, 60.0),
                         randomWalkState(0.05 / 3600.0 / 60.0)};
  }
  return m;
}


}  // namespace

TEST_CASE("coarse alignment: the filter starts as uncertain as the alignment made it (NEES bands)") {
  const sim::Scenario sc = sim::parseScenario(test::kConsistencyDrive, "consistency.yaml");
  const nav::Earth earth;
  const test::IdealDrive ideal = test::idealDrive(sc, earth);
  const auto model = errormodels::ImuErrorModel::fromString(kModel, "truth.yaml");
  AidingConfig cfg = test::consistencyAiding(100.0, 130.0);
  cfg.alignment.duration = 15.0;
  const int runs = 200;
  // Epochs: the first two filter epochs after the alignment, the last aided one, the outage's end.
  const double epochs[] = {16.0, 19.0, 99.0, 129.0};
  double nees[4] = {0, 0, 0, 0}, headingError2 = 0.0, headingVar = 0.0;
  test::aidedRuns(sc, ideal, earth, model, cfg, filterModel(), runs, 11,
                  [&](int, const FilterEpoch& fe) {
                    for (int e = 0; e < 4; ++e)
                      if (std::abs(fe.t - epochs[e]) < 1e-6) nees[e] += fe.nees / runs;
                    if (std::abs(fe.t - 16.0) < 1e-6) {
                      headingError2 += fe.error[8] * fe.error[8] / runs;
                      headingVar += fe.sigma[8] * fe.sigma[8] / runs;
                    }
                  });
  INFO("NEES at 16 s " << nees[0] << ", 19 s " << nees[1] << ", 99 s " << nees[2] << ", 129 s "
                       << nees[3] << "; heading rms " << std::sqrt(headingError2) / kRadPerDeg
                       << " deg against the filter's " << std::sqrt(headingVar) / kRadPerDeg);
  for (double v : nees) CHECK(test::inChiSquareBand(v, 9, runs));
  // The heading alone (one degree of freedom): its mean square against the filter's variance,
  // inside the 99 % band of χ²(R)/R.
  CHECK(test::inChiSquareBand(headingError2 / headingVar, 1, runs));
}
