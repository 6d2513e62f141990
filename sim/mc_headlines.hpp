// The answer of a Monte Carlo batch in a few lines, for the terminal and the report: each model's
// CEP and R95 at every report time, and for each pair of models the paired comparison of their
// horizontal drift with a sentence that states it ("GM predicts 10 % more horizontal drift than
// AR at 10 min, p = 1e-12").
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "sim/mc_aided_output.hpp"
#include "sim/mc_output.hpp"
#include "sim/montecarlo.hpp"

namespace sinsim::sim {

/// One model at one report time.
struct McHeadline {
  std::string label;
  double t = 0.0;     // [s]
  double cep = 0.0;   // [m] median horizontal error
  double r95 = 0.0;   // [m] 95th percentile
};

/// Two models at one report time, on the per-run horizontal error (run k of each shares its
/// random streams: a paired comparison).
struct McPairedHeadline {
  std::string a, b;
  double t = 0.0;                  // [s]
  std::size_t runs = 0;
  double meanA = 0.0, meanB = 0.0;  // [m]
  double pT = 1.0;                 // paired t-test, two-sided
  double pWilcoxon = 1.0;          // Wilcoxon signed-rank, two-sided
  /// "GM predicts 10 % more horizontal drift than AR at 10 min (mean 16.8 m vs 15.2 m, 100
  /// paired runs, paired t-test p = 1e-12)"; "no significant difference ..." when p ≥ 0.05.
  std::string sentence() const;
};

struct McHeadlines {
  std::vector<McHeadline> models;       // time-major: every model at the first time, then ...
  /// Every pair of the given models at every time, or each model against the batch's reference
  /// (McOptions::reference) with the reference first.
  std::vector<McPairedHeadline> pairs;
  std::vector<McAidedSummary> aided;    // per model, of a batch whose scenario runs the filter
  /// With a measured record: its horizontal error at the last report time and its mid-rank
  /// percentile among each model's runs, as a sentence; empty otherwise.
  std::string measured;
};

/// The headlines of the given models (the first `models` entries: no budget variants) of a
/// batch at its report epochs.
McHeadlines mcHeadlines(const McBatch& batch, std::size_t models);

/// The same from a complete result (rank 0) and the report times (McOptions::times), with the
/// measured record navigated along the reference where there is one.
McHeadlines mcHeadlines(const Reference& ref, const McResult& result, std::size_t models,
                        const std::vector<double>& times, const McMeasured* measured = nullptr,
                        const std::string& reference = "");

}  // namespace sinsim::sim
