// The base AR refitted when effects are added: the AR fitted to the raw record had absorbed part
// of them (e.g. its low-frequency gain).
#pragma once

#include <vector>

#include "errormodels/diagnose/run.hpp"

namespace sinsim::errormodels::diagnose::detail {

/// A base AR of `order` at the record's rate refitted on the record with the added effects `set`
/// (sizes sol.theta) taken out:
///   - the fitted deterministic signals subtracted, a random walk's level removed by the
///     steady-state RTS smoother of the local-level model (q = K^2 dt, r = the record's variance;
///     fit/composite_fit.hpp);
///   - a lattice quantization: Yule-Walker on the autocovariance with the rounding noise's taken
///     out; the variant (carried or not) that fits the Allan curve better is kept (set updated);
///   - terms with a known autocovariance (bias instability): Yule-Walker on the record's minus
///     theirs;
///   - otherwise, when a signal was taken out: Burg of the same order.
/// The refit is kept only where its Allan chi-square beside the added effects (sizes refitted) is
/// below sol.chi2, the given AR's: a base that was fitted to the record had absorbed the effects
/// and loses to its refit; a true base (or one fitted without them) stays, where subtracting a
/// dominant noise's autocovariance or a coarse lattice's rounding would leave the refit a few % or
/// a factor off.
/// Returns [a1..ap, driving sigma (SI)] and sets sol.s = 1, or returns empty (not refitted; set
/// as given).
std::vector<double> refitBaseAr(const ChannelWork& w, const Record& record, std::size_t order,
                                std::vector<const Candidate*>& set, AllanSolution& sol);

}  // namespace sinsim::errormodels::diagnose::detail
