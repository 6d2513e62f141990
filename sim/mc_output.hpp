// The reduction of a finished Monte Carlo batch to its output files: stats.csv, summary.json,
// report.html and (with a measured record) measured.csv. Pure functions of the per-run values in
// run order: the bytes written do not depend on how the runs were scheduled.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sim/montecarlo.hpp"
#include "sim/reference.hpp"

namespace sinsim::sim {

struct McBatch {
  struct Entry {
    std::string label;
    std::string source;      // model file
    int parent = -1;         // budget variant: index of the full model; -1: a model given
    std::string removed;     // budget variant: the effect switched off
  };
  explicit McBatch(const Reference& r) : ref(r) {}
  const Reference& ref;
  std::uint64_t runs = 0;
  std::uint64_t seed = 0;
  double biasWindow = 0.0;
  std::string reference;                   // McOptions::reference
  std::vector<std::size_t> timeEpochs;     // report epochs
  std::vector<Entry> entries;              // models, then budget variants
  std::vector<std::vector<std::string>> effectNames;  // per entry
  std::vector<std::vector<float>> errors;  // per entry: runs × ref.runFloats()
  const McMeasured* measured = nullptr;
};

/// Percentiles reported everywhere [%].
inline const std::vector<double>& mcPercentiles() {
  static const std::vector<double> p{50, 68, 95, 99};
  return p;
}

/// Magnitudes whose distribution across runs is reported (stats.csv column stems).
enum Metric : int { kHorizontal = 0, kVertical, kVelocity, kRollAbs, kPitchAbs, kYawAbs, kMetrics };
const char* metricName(int metric);  // "horizontal_m", ..., "yaw_abs_rad"
/// The metric of one run at one epoch from its error row.
double metricValue(const float* row, int metric);

/// Distribution of one metric across runs at one epoch.
struct MetricStats {
  double mean = 0, sd = 0, rms = 0;
  double p[4] = {0, 0, 0, 0};  // mcPercentiles()
};

/// Everything derived from a batch that the files show.
struct McStats {
  std::size_t epochs = 0;
  /// [entry][epoch * kMetrics + metric]
  std::vector<std::vector<MetricStats>> metric;
  /// [entry][epoch * kErrorFields + field]: mean and sample sd of the signed errors
  std::vector<std::vector<double>> fieldMean, fieldSd;
  const MetricStats& at(std::size_t entry, std::size_t epoch, int m) const {
    return metric[entry][epoch * kMetrics + m];
  }
};
McStats computeMcStats(const McBatch& batch);

/// Values of one metric across runs (run order) for an entry at an epoch.
std::vector<double> metricAcrossRuns(const McBatch& batch, std::size_t entry, std::size_t epoch,
                                     int metric);

/// Writes the outputs into outDir (each via a temporary + rename); appends their names to files.
void writeMcOutputs(const McBatch& batch, const std::string& outDir,
                    std::vector<std::string>& files);

/// The HTML report (sim/report): drift envelopes side by side, comparison and budget tables,
/// measured record against the envelopes.
std::string mcReportHtml(const McBatch& batch, const McStats& stats);

}  // namespace sinsim::sim
