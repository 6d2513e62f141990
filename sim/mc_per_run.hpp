// Per-run Monte Carlo results as CSV (per_run.csv): each run's errors at the report times and at
// the end, per model, in long format — one row per (model, run, time), ready for a histogram in
// pandas or MATLAB. Units in the header.
#pragma once

#include <cstdio>
#include <vector>

#include "sim/mc_output.hpp"

namespace sinsim::sim {

/// The epochs of per_run.csv: the report epochs in order, then the last epoch if not among them.
std::vector<std::size_t> perRunEpochs(const McBatch& batch);

/// Writes per_run.csv to f: every entry (models, then budget variants), run and perRunEpochs().
void writePerRunCsv(const McBatch& batch, std::FILE* f);

}  // namespace sinsim::sim
