// The size of a fitted drift from the record's trend, not from its Allan variance.
//
// A drift's Allan variance R^2 tau^2 / 2 is felt only at the last octaves of tau (<= N dt / 10),
// through a few points of few degrees of freedom, and it trades there with a walk or a slow GM:
// on white + ramp records its 2-sigma covered the true R in 191/198 right sets, beside a random
// walk in 121/184 (100 Hz, 20 min; bench/latent_study/generate.py --case white+drift /
// white+rw+drift, docs/fitting.md; 193/198 and 180/184 from the trend).
// The record's trend holds the ramp's information: the generalised least-squares slope of the
// block means under the fitted model's other terms (block_likelihood.hpp, blockLikelihood: the
// level and the slope profiled out of the exact block-mean likelihood; a walk's chance trend is in
// its variance). That slope is the drift's size, its sign the ramp's, its variance the 1-sigma.
// Where the likelihood's slope test chose a drift that the Allan fit of the set put at zero (a ramp
// under a GM's tail: the Allan variance sees it in no octave), the drift is added from the trend
// alone: white + GM + drift at 2 h was right in 66/100 seeds with the Allan fit's veto.
#pragma once

#include <vector>

#include "errormodels/fit/block_likelihood.hpp"
#include "errormodels/fit/latent_fit.hpp"

namespace sinsim::errormodels::fit {

/// Where `fit` holds a drift and no AR: its drift [U/s] (model, parameter "drift", its log-space
/// variance, the selection-aware "drift" but for its weight of inclusion) set from the GLS slope
/// of x's block means (blockSize(N, the first fitted Allan point)) under fit.model without the
/// drift; LatentFit::driftSlope the signed slope, modelAvar recomputed. The Allan fit's chi2 and
/// candidates stand (they chose the set). Left as the Allan fit where the record is too short for
/// kMinBlocks blocks or the blocks' model has no positive variance. Where the likelihood chose the
/// set + drift but its Allan fit held none (LatentFit::trendDrift), the drift is added so (terms,
/// parameters, logCovariance, model); trendDrift stays true only where it was added. The block
/// means are formed again here (one O(N) pass and one filter run over <= 4096 blocks, small beside
/// the fit that chose the set).
///
/// `slopeTest`: where the set was chosen without the block likelihood (the Allan choice on a
/// correlated value lattice, latent_fit.cpp fitRecord) and holds no drift, the slope test that
/// likelihood makes of every set decides it: the drift is added where slope^2 / variance >
/// kDriftSlopeChi2 (the chi^2_1 1 % point; trendDrift set as for the likelihood's own choice).
/// Block means average the lattice rounding's non-Gaussian steps away, which is why the
/// likelihood is not used for the set itself there.
void driftFromTrend(LatentFit& fit, const std::vector<double>& x, bool slopeTest = false);

/// The trend a drift fits, fitted as a random walk instead: the other terms held at `others`
/// (the fit's, drift removed), the walk's K minimised over a log range by golden sections (from
/// the set's own K, or from R sqrt(T) / 1000, to 100 R sqrt(T) and beyond the set's own K), and
/// its -2 log L of the block means compared with the ramp's: `scored` is blockLikelihood(means,
/// others), whose m2LogLikDrift has the slope profiled out and whose m2LogLik is the set's own walk. Returns {gap, K}: the walk's -2 log L minus the ramp's, and the walk's K.
/// A trend over a record is what a walk, or a GM slower than the record, leaves there too, and
/// the two differ in little but a ramp's straightness (a ramp's periodogram falls as 1/f^2, a
/// walk's expected one does too). Where the gap is below the drift's own cost against the set
/// (kDriftSlopeChi2), the record does not tell them apart at the 1 % level.
struct DriftWalkAlternative {
  double gap = 0.0, K = 0.0;
};
DriftWalkAlternative driftWalkAlternative(const BlockMeans& means, const LatentModel& others,
                                          const BlockLikelihood& scored, double R);

}  // namespace sinsim::errormodels::fit
