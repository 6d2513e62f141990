// AR(p) + slow latent terms (`sinsim fit --kind ar+slow`): the paper's AR model for the short-tau
// correlation, with a first-order GM, a random walk and/or flicker beside it for the long tau an
// AR model of a few lags cannot carry (issue 11: an AR-based model must not be blind to the
// drift-relevant tau).
//
// Method (every step stated so a reader can redo it):
//  1. Burg AR(p) on the demeaned record, the order by the criterion of `order` (MDL default) or
//     forced: the paper's path (fit/order_selection.hpp). A strong random walk would pull a Burg
//     pole to 1 (and ride inside the AR, hidden from the slow terms), so when the octave ADEV has
//     an interior local minimum (a rise at long tau begins there, at tau_min) Burg sees the record
//     minus its level from the RTS local-level smoother of gain dt / tau_min (composite_fit.hpp),
//     for a rise that lasts (the longest tau's ADEV above the minimum's) and a smoother much
//     slower than the AR it leaves (tau_min >= slowGmMinTc T_c): an oscillating AR's own ADEV
//     minimum a few samples in, or one before an AR's hump, is no such rise (Burg on the record).
//     T_c = the AR model's 1/e time.
//  2. The composite latent GLS fit (fit/latent_fit.hpp) on the octave Allan variance over all tau,
//     with the AR as one of its terms: the AR's Allan variance in closed form at the record's
//     interval (ar::allanVariance) with Burg's polynomial held fixed and its driving variance E
//     refitted jointly with the slow terms, at most Burg's E (the one-step prediction error of AR
//     + slow terms is at least the AR's own E; above it, a fit from a late start read the record's
//     mid-tau excess as AR power: ADIS16405 run 1 gy 1.16x the record at one sample). Candidates: AR alone and AR with every subset of
//     {GM, random walk, flicker} allowed; the same penalised GLS criterion (a GM costs 7.82, a
//     one-parameter term 5.41), the same Omega (now with the AR's PSD E / |A|^2), the same 1-sigma.
//  3. A GM beside the AR is slow by construction: its tau is searched from slowGmMinTc x T_c
//     (default 10) upwards; a faster one is the AR's business.
//  4. While a random walk K is selected (at most 3 rounds, until the set repeats): Burg again on
//     the record minus the walk's level smoothed with the fitted model (q = K^2 dt, r = E / A(1)^2
//     the AR's long-tau white variance per sample; only while that smoother is >= slowGmMinTc T_c
//     slow), then step 2 again. No slow term selected: the AR is Burg's on the record itself.
//  5. Where the joint fit is off the record below a scanned start (offBelowStart) with a slow term
//     selected, once: Burg on the record with the fitted slow terms filtered out (each cosine of
//     its mirrored extension times sqrt(S_rest / (S_rest + S_slow)), stats::zeroPhaseFiltered),
//     then step 2 again; kept with the same terms and no larger worstAdevLogRatio.
//  6. For the comparison the AR alone is kept (Burg's E): its Allan variance at the fitted points
//     (arOnlyAvar) shows what an AR-only model misses at long tau.
// Written by the one model writer (fit/model_writer.hpp) as an `ar` effect (the refitted E) and
// the slow terms' effects on the same channel; the simulator adds them.
#pragma once

#include <vector>

#include "errormodels/fit/latent_fit.hpp"
#include "errormodels/fit/order_selection.hpp"

namespace sinsim::errormodels::fit {

struct ArSlowFitOptions {
  double sampleInterval = 0.0;  ///< dt [s] (required)
  OrderSelectionOptions order;  ///< AR order selection (its sampleInterval is set from dt)
  bool gm = true, randomWalk = true, flicker = true;  ///< slow terms allowed
  double slowGmMinTc = 10.0;    ///< shortest GM tau searched, in AR correlation times T_c
  /// As LatentFitOptions::scanStart (sinsim fit turns it on: a real sensor's short-tau features
  /// that no term carries).
  bool scanStart = false;
  double penaltyPerTerm = LatentFitOptions{}.penaltyPerTerm;
  double penaltyPerParameter = LatentFitOptions{}.penaltyPerParameter;
};

struct ArSlowFit {
  OrderSelection ar;            ///< the Burg AR (criteria table; E is Burg's) of the last round
  double arCorrelationTime = 0.0;  ///< T_c [s] of the Burg AR
  LatentFit joint;              ///< AR (E refitted) + the selected slow terms
  std::vector<double> arOnlyAvar;  ///< [U^2] the Burg AR alone at joint.m
};

/// The candidate sets of step 2 (AR always, white never: the AR's driving noise is the white).
std::vector<LatentTermSet> arSlowCandidateSets(bool gm, bool randomWalk, bool flicker);

/// Fits x [U] (any mean). Throws InputError for bad options, or records too short for the AR
/// order range or for the Allan points.
ArSlowFit fitArPlusSlow(const std::vector<double>& x, const ArSlowFitOptions& options);

}  // namespace sinsim::errormodels::fit
