// The `auto` kind of the identify pipeline: the rule that chooses between an AR model and the
// Allan terms (stated in identify_auto.cpp above chooseAuto, and in docs/identify.md, "The auto rule"). Internal to
// errormodels/identify*.cpp.
#pragma once

#include <optional>
#include <vector>

#include "errormodels/identify.hpp"
#include "errormodels/identify_terms.hpp"

namespace sinsim::errormodels::detail {

/// Fills out.kind, out.written, out.allanFit / allanLongTau / composite and out.decision for the
/// demeaned record x (sample interval dt [s]) from its usable Allan points, by the auto rule.
/// lattice: the record's (fit::LatentFitOptions::lattice; step 0: none).
void chooseAuto(AxisIdentification& out, const std::vector<double>& x, const CurvePoints& pts,
                double dt, const fit::RoundingLattice& lattice, const fit::OrderSelectionOptions& os,
                const IdentifyOptions& opt);

}  // namespace sinsim::errormodels::detail
