// The ADIS16405 numbers of the README "Identify" section: fits run 1 and run 2 (after skipping
// the first SKIP seconds), prints the run-1 model file, and per channel and octave tau the
// run-1 model's Allan deviation against run 2's: z = ln(model / adev_2) / sqrt(1/(2 nu_1) +
// 1/(2 nu_2)) and the relative difference. SELF=1 compares with run 1 itself.
// Built and run by scripts/adis16405_fit.sh.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

#include "errormodels/identify.hpp"

using namespace sinsim::errormodels;

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: adis16405_predict DATA_DIR SKIP_SECONDS\n");
    return 2;
  }
  const std::string dir = argv[1];
  RecordOptions ro;
  ro.rate_hz = 100;
  ro.gyro_unit = "deg/s";
  ro.accel_unit = "g";
  IdentifyOptions o;
  o.skipStart = std::atof(argv[2]);
  const auto id1 = identify(loadRecord(dir + "/run1.csv.gz", ro), o);
  const auto id2 = identify(loadRecord(dir + "/run2.csv.gz", ro), o);
  std::cout << id1.modelYaml();
  std::printf("# tau:z/relative difference of the run-1 model vs run %s\n", std::getenv("SELF") ? "1" : "2");
  for (const auto& a : id1.axes) {
    const auto& b = std::getenv("SELF") ? a : id2.axis(a.channel);
    const auto pred = a.modelAdev(b.allan.tau);
    std::printf("%s:", a.channel.c_str());
    for (std::size_t i = 0; i < b.allan.size(); ++i) {
      const double z = std::log(pred[i] / b.allan.dev[i]) /
                       std::sqrt(1 / (2 * a.allan.edf[i]) + 1 / (2 * b.allan.edf[i]));
      std::printf(" %.3g:%.1f/%+.0f%%", b.allan.tau[i], z, 100 * (pred[i] / b.allan.dev[i] - 1));
    }
    std::printf("\n");
  }
  return 0;
}
