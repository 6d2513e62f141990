// Step 3 of the diagnosis: forward selection of the candidates (diagnose.hpp, "score" and
// "findings").
#pragma once

#include "errormodels/diagnose/run.hpp"

namespace sinsim::errormodels::diagnose::detail {

/// From w.prob and w.cands: accepts the best-scoring candidate while its score >= threshold
/// (w.accepted, w.sol), then fills w.d.findings (the accepted ones with sizes from the final joint
/// fit, then one per other effect, its best variant, by score) and w.d.noiseScale.
void selectFindings(ChannelWork& w, double threshold);

}  // namespace sinsim::errormodels::diagnose::detail
