// Composite fit: AR(p) + random walk, for records whose Allan deviation rises again at long tau
// (a random walk the AR model cannot represent: an AR fit to such data places a pole near 1 and
// distorts the short-lag coefficients).
//
// Method (all steps stated so a reader can redo them):
//  1. Random walk from the long-tau Allan curve: weighted fit of N^2/tau + K^2 tau/3 on
//     tau >= tauMin, with the correlated-points GLS of fitAllanTerms. There the AR part must
//     already look white (density N). Default tauMin: 30 x the tau of the AR hump (the first
//     local maximum of the ADEV, near 1.9 T_c for a GM-like process); the AR's remaining
//     -(3 T_c / 2 tau) relative AVAR correction is then <= ~3 % (GM closed form, IEEE 952 C).
//     K not detected -> no random walk, step 4 on x.
//  2. Random-walk level estimated by the steady-state Rauch-Tung-Striebel smoother of the local
//     level model x = l + v, l[n+1] = l[n] + w, var(w) = K^2 dt, var(v) = N^2 / dt (the AR part's
//     low-frequency level seen as white). Predicted variance P = (q + sqrt(q^2 + 4 q r)) / 2,
//     gain g = P / (P + r); forward l_f[n] = l_f[n-1] + g (x[n] - l_f[n-1]); backward
//     l_s[n] = l_f[n] + (1 - g)(l_s[n+1] - l_f[n]). Smoother time constant T_s = dt / g.
//  3. u = x - l_s is the AR part (plus what the smoother leaves: the random walk above 1/T_s and
//     minus the AR below it — both small when T_s >> T_c).
//  4. AR order selection and Burg fit on u (order forced or by criterion).
//  5. separated = T_s >= 10 T_c (T_c the fitted AR model's 1/e correlation time); when false
//     the two processes overlap in time scale and the split is not reliable — reported, not hidden.
#pragma once

#include <vector>

#include "errormodels/fit/allan_fit.hpp"
#include "errormodels/fit/order_selection.hpp"

namespace sinsim::errormodels::fit {

struct ArRandomWalkFitOptions {
  double sampleInterval = 0.0;     ///< dt of x [s] (required)
  double tauMin = 0.0;             ///< [s] lower end of the Allan points for K; 0: automatic
  OrderSelectionOptions order;     ///< AR order selection on the residual (sampleInterval is set)
};

struct ArRandomWalkFit {
  AllanFit allan;               ///< the N + K fit of the long-tau Allan curve
  AllanTerm randomWalk;         ///< K [U / sqrt(s)] with uncertainty
  AllanTerm whiteEquivalent;    ///< N [U sqrt(s)]: the AR part's long-tau white level
  bool randomWalkDetected = false;
  double smootherGain = 0.0;           ///< g (0 when no random walk)
  double smootherTimeConstant = 0.0;   ///< T_s [s]
  double arCorrelationTime = 0.0;      ///< T_c [s] of the fitted AR
  bool separated = true;               ///< T_s >= 10 T_c
  OrderSelection ar;                   ///< AR fit on x - l_s
};

/// x: the record [U] at sampleInterval; tau/adev/edf: its overlapping Allan curve (tau multiples
/// of dt). Throws InputError on bad input.
ArRandomWalkFit fitArPlusRandomWalk(const std::vector<double>& x, const std::vector<double>& tau,
                                    const std::vector<double>& adev, const std::vector<double>& edf,
                                    const ArRandomWalkFitOptions& options);

/// Step 2 alone: the steady-state RTS smoother of the local-level model (q = var(w), r = var(v)).
std::vector<double> localLevelSmoother(const std::vector<double>& x, double q, double r,
                                       double* gain = nullptr);

}  // namespace sinsim::errormodels::fit
