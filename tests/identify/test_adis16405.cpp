// The real ADIS16405 records (../shared/data/adis16405, 100 Hz, 10 000 s each; data: SMAC-Group
// imudata, University of Calgary, CC BY-NC-SA 4.0): the model fitted on run 1 predicts run 2's
// Allan curve.
//
// Band: z = ln(model(tau) / adev_2(tau)) / sqrt(1 / (2 nu_1) + 1 / (2 nu_2)), with nu_1, nu_2 the
// Greenhall EDF of the run-1 and run-2 points (sd of ln ADEV ~ 1 / sqrt(2 nu)): the model carries
// run 1's estimation noise, the comparison run 2's. |z| <= 3.29 is the two-sided 99.9 % band.
// It holds for the gyros from 10 s to 82 s (tested below); where and why it does not hold
// elsewhere is in the README (run 2's long-tau floor is ~25 % above run 1's, the accelerometers'
// short-tau noise differs by 2-9 % between runs, the bias-instability asymptote overshoots in its
// transition region).
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <string>

#include "errormodels/identify.hpp"

using namespace sinsim::errormodels;

TEST_CASE("ADIS16405: run-1 model predicts run-2 gyro Allan curve, 10-82 s", "[identify][adis16405]") {
  const std::string dir = std::string(SINSIM_SHARED_DIR) + "/data/adis16405/";
  if (!std::ifstream(dir + "run1.csv.gz") || !std::ifstream(dir + "run2.csv.gz")) {
    WARN("ADIS16405 data not found in " << dir << ": skipped");
    return;
  }
  RecordOptions ro;
  ro.rate_hz = 100.0;
  ro.gyro_unit = "deg/s";
  ro.accel_unit = "g";
  IdentifyOptions o;
  o.axes = {"gx", "gy", "gz"};
  o.skipStart = 600.0;  // the warm-up drift of the first 5-10 min (data README)
  const Identification id1 = identify(loadRecord(dir + "run1.csv.gz", ro), o);
  const Identification id2 = identify(loadRecord(dir + "run2.csv.gz", ro), o);
  for (const auto& a : id1.axes) {
    const auto& b = id2.axis(a.channel);
    REQUIRE(a.allan.tau == b.allan.tau);
    const auto pred = a.modelAdev(b.allan.tau);
    std::size_t tested = 0;
    for (std::size_t i = 0; i < b.allan.size(); ++i) {
      if (b.allan.tau[i] < 10.0 || b.allan.tau[i] > 82.0) continue;
      const double z = std::log(pred[i] / b.allan.dev[i]) /
                       std::sqrt(1.0 / (2.0 * a.allan.edf[i]) + 1.0 / (2.0 * b.allan.edf[i]));
      INFO(a.channel << " tau " << b.allan.tau[i] << " model " << pred[i] << " run 2 "
                     << b.allan.dev[i] << " z " << z);
      CHECK(std::fabs(z) <= 3.29);
      ++tested;
    }
    CHECK(tested == 4);  // 10.24, 20.48, 40.96, 81.92 s
    // White noise vs the datasheet: ARW 2.0 deg/sqrt(h) typical. The AR's long-tau white level
    // sqrt(E dt) / |A(1)| is the model's ARW; the data README measured ~2.4 deg/sqrt(h). Checked
    // loosely (1.5-3.5): a datasheet "typical" is not a bound.
    REQUIRE(a.written.ar);
    double A1 = 0.0;
    for (double c : a.written.ar->a) A1 += c;
    const double arw = std::sqrt(a.written.ar->drivingVariance * 0.01) / std::fabs(A1) * 180.0 / M_PI * 60.0;
    INFO(a.channel << " ARW " << arw << " deg/sqrt(h)");
    CHECK(arw > 1.5);
    CHECK(arw < 3.5);
  }
}
