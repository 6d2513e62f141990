#include "sim/mc_per_run.hpp"

#include <algorithm>

#include "sim/output.hpp"

namespace sinsim::sim {

std::vector<std::size_t> perRunEpochs(const McBatch& batch) {
  std::vector<std::size_t> epochs = batch.timeEpochs;
  const std::size_t last = batch.ref.epochs() - 1;
  if (std::find(epochs.begin(), epochs.end(), last) == epochs.end()) epochs.push_back(last);
  return epochs;
}

void writePerRunCsv(const McBatch& batch, std::FILE* f) {
  std::fputs("model,run,t [s],north [m],east [m],down [m],horizontal [m],vertical [m],"
             "vn [m/s],ve [m/s],vd [m/s],roll [rad],pitch [rad],yaw [rad]\n",
             f);
  const std::vector<std::size_t> epochs = perRunEpochs(batch);
  const std::size_t perRun = batch.ref.runFloats();
  for (std::size_t m = 0; m < batch.entries.size(); ++m) {
    const std::string label = csvField(batch.entries[m].label);
    for (std::uint64_t k = 0; k < batch.runs; ++k)
      for (std::size_t e : epochs) {
        const float* row = batch.errors[m].data() + k * perRun + e * kErrorFields;
        std::fprintf(f, "%s,%llu,%.6f,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n",
                     label.c_str(), static_cast<unsigned long long>(k), batch.ref.epochTime(e),
                     double(row[kNorth]), double(row[kEast]), double(row[kDown]),
                     metricValue(row, kHorizontal), metricValue(row, kVertical), double(row[kVn]),
                     double(row[kVe]), double(row[kVd]), double(row[kRoll]), double(row[kPitch]),
                     double(row[kYaw]));
      }
  }
}

}  // namespace sinsim::sim
