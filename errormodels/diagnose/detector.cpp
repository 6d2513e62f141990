// The detector registry and the candidates of one channel (detector.hpp).
#include "errormodels/diagnose/detector.hpp"

#include <algorithm>

namespace sinsim::errormodels::diagnose::detail {

const std::vector<DetectorType>& detectorTypes() {
  static const std::vector<DetectorType> types = {
#define SINSIM_DETECTOR(effect, repeatable, summary) {#effect, repeatable, summary, &detect_##effect},
#include "errormodels/diagnose/detectors.def"
#undef SINSIM_DETECTOR
  };
  return types;
}

std::vector<Candidate> buildCandidates(const Record& record, int channel, const std::vector<double>& y,
                                       double lattice, const std::vector<double>& tau, const Setup& setup,
                                       const std::vector<std::string>& modelEffects) {
  const std::size_t N = y.size();
  const double dt = 1.0 / record.rate_hz;
  double mean = 0;
  for (double v : y) mean += v;
  mean /= double(N);
  double var = 0;
  for (double v : y) var += (v - mean) * (v - mean);
  var /= double(N);
  const DetectorContext ctx{record, channel, y, N, dt, double(N) * dt, tau, setup, unitsFor(channel),
                            mean, var, lattice, blockMeans(y, dt, 2000), modelEffects,
                            isGyro(channel) ? Dimension::angularRate() : Dimension::acceleration()};
  std::vector<Candidate> out;
  for (const auto& d : detectorTypes()) {
    if (!d.repeatable && std::find(modelEffects.begin(), modelEffects.end(), d.effect) != modelEffects.end())
      continue;
    for (auto& c : d.detect(ctx)) out.push_back(std::move(c));
  }
  return out;
}

}  // namespace sinsim::errormodels::diagnose::detail
