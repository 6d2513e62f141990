// Whether the noise at the shortest scale keeps one level over the record: the level of the
// first differences in blocks of the record, against the same statistic on the model's
// realisations. No effect of the catalogue changes the noise's level with time (a vibration that
// comes and goes, a noise that grows with temperature): where the record's does, it is said as
// unexplained, beside whatever the findings are.
#pragma once

#include <optional>
#include <vector>

#include "errormodels/diagnose/diagnose.hpp"

namespace sinsim::errormodels::diagnose::detail {

/// The series' first differences in kNoiseLevelBlocks blocks: each block's mean |difference|
/// (each |difference| capped at 8x the series' median one, so that a few outliers or level steps
/// are no level) over the median of the blocks' (`level`), that median [SI] (`median`), and the
/// largest |ln level| (`spread`). Empty and 0 for fewer than 64 samples a block or a series
/// without differences.
struct NoiseLevelBlocks {
  std::vector<double> level;
  double median = 0;
  double spread = 0;
};
inline constexpr std::size_t kNoiseLevelBlocks = 16;
NoiseLevelBlocks noiseLevelBlocks(const std::vector<double>& y);

/// The record's blocks (noiseLevelBlocks of its n samples) against the realisations' spreads: a
/// change when the record's spread exceeds every realisation's, twice their median, and a 25 %
/// level change (ln 1.25); n at rate [Hz] gives the times of the block that departs most. The
/// record's median block against the realisations' medians (`modelMedians`, as many) gives the
/// level of its quiet stretches against the model's (NoiseLevelChange::quiet, quietZ).
std::optional<NoiseLevelChange> noiseLevelChange(const NoiseLevelBlocks& record, std::size_t n, double rate,
                                                 const std::vector<double>& modelSpreads,
                                                 const std::vector<double>& modelMedians);

}  // namespace sinsim::errormodels::diagnose::detail
