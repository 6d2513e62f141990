// Step 3 of the diagnosis: selection of the candidates by trial (diagnose.hpp, "score" and
// "findings"; docs/diagnose.md, "Selection by trial").
#pragma once

#include <cstddef>

#include "errormodels/diagnose/run.hpp"

namespace sinsim::errormodels::diagnose::detail {

/// Penalty per fitted parameter of the criterion: ln(points), BIC's (Schwarz 1978) for the Allan
/// points of the channel.
double criterionPenalty(std::size_t points);

/// The candidates w.propose makes on the record and its level steps (w.cands as given when there
/// is no w.propose); then, greedily: every candidate not yet accepted is added in trial to the
/// accepted set, the level and all free sizes refitted (solveAllan), and its drop of the criterion
///   chi2 (Allan GLS) + penalty x parameters - sum of z^2 of the members' own tests
/// computed; the largest drop is accepted while drop >= threshold^2 (w.accepted, w.sol), the
/// threshold `first` for the channel's first finding and `next` for every later one. Then fills
/// w.d.findings (the accepted ones with sizes from the final joint fit, then one per other effect,
/// its best variant, by drop), w.d.noiseScale, w.d.chi2Selected and w.d.unexplained.
void selectFindings(ChannelWork& w, double first, double next);

}  // namespace sinsim::errormodels::diagnose::detail
