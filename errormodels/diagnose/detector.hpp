// Diagnosis detectors: one plug-in per effect the diagnosis can find and add.
//
// A detector looks at one channel of the record (DetectorContext: the series, its grids and
// shared statistics, what the model already has) and proposes candidates: the effect's Allan
// signature g(tau), its own significance test, the fitted signal or autocovariance the base refit
// takes out, and how to describe its size. The forward selection (selection.hpp) scores them.
//
// To add a detector: write detectors/<effect>.cpp defining
//   std::vector<Candidate> detect_<effect>(const DetectorContext& ctx)
// and add one line SINSIM_DETECTOR(<effect>, repeatable, "summary") to detectors.def. A candidate's describe
// states the effect as an EffectSpec in SI, each size rounded (stated()) to the digits its
// finding reports, so that the improved model holds what the report says. A detector that is not
// repeatable is not run on a channel whose model already has its effect (enabled).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "errormodels/diagnose/candidate.hpp"
#include "common/units.hpp"
#include "errormodels/diagnose/channels.hpp"
#include "errormodels/diagnose/low_frequency.hpp"
#include "errormodels/diagnose/model_edit.hpp"
#include "errormodels/diagnose/series_stats.hpp"
#include "errormodels/diagnose/series_tools.hpp"

namespace sinsim::errormodels::diagnose::detail {

/// What a detector knows of one channel.
struct DetectorContext {
  const Record& record;
  int channel = 0;
  const std::vector<double>& y;      // the channel's samples [SI]
  std::size_t N = 0;                 // samples
  double dt = 0, T = 0;              // sample interval and record length [s]
  const std::vector<double>& tau;    // the Allan tau grid [s]
  const Setup& setup;                // grids of the comparison (PSD segment, factors)
  const Units& units;                // display units of the channel
  double mean = 0, var = 0;          // of y [SI], [SI^2] (1/N)
  double lattice = 0;                // latticeStep(y) [SI]; 0 off a lattice
  BlockMeans blocks;                 // <= 2000 block means of y
  const std::vector<std::string>& modelEffects;  // enabled effect types of the model here
  Dimension signal;                  // of the channel: angular rate or acceleration
  /// The regressors of the signals already taken out of y (Candidate::basis of the accepted
  /// ones; empty in the first round) and their block means (on `blocks`).
  const std::vector<std::vector<double>>& taken;
  std::vector<std::vector<double>> takenBlocks;
  /// An orthonormal basis (N x rank) of the constant and `taken`, made once (buildCandidates) so
  /// that apart() is two products, not a least-squares solve per shape. Empty without `taken`.
  Eigen::MatrixXd takenBasis;
  /// What rounding onto `lattice` adds to the model's AVAR per factor, from the model's own
  /// realisations rounded (SeriesStats::roundedAvar); empty when not measured.
  std::vector<double> roundingAvar;
  /// The sinusoid lines already taken out of y (Candidate::line of the accepted ones): what is
  /// left near one is that line's own width or distortion, not another line.
  std::vector<Line> linesTaken;
  /// The level steps the selection finds on y (stepSeries, selection.cpp: window-mean jumps, else
  /// level shifts) as a piecewise-constant series; empty when there are none.
  std::vector<double> steps;
  /// cosineSpectrum(y), made once: the record's side of every shape's GLS test (regressorTest).
  CosineSpectrum ySpectrum;

  /// x without its least-squares projection on the constant, `taken` and `beside`: the part of a
  /// shape the record without the taken signals can still show. A coefficient on it is the joint
  /// fit's (Frisch-Waugh-Lovell); judged on the shape itself, a ramp beside a thermal drift of
  /// nearly its form would be credited only with what the drift left of it.
  std::vector<double> apart(const std::vector<double>& x,
                            const std::vector<std::vector<double>>& beside = {}) const;
  /// Whether x lies in the span of the constant and `taken` (its part apart from them below 1e-9
  /// of its spread): an effect of that shape is taken out already, and no candidate of it is
  /// proposed.
  bool spanned(const std::vector<double>& x) const;

  /// g_k = f(tau_k): an Allan signature on the tau grid.
  template <class F>
  std::vector<double> shape(F f) const {
    std::vector<double> g(tau.size());
    for (std::size_t k = 0; k < tau.size(); ++k) g[k] = f(tau[k]);
    return g;
  }
};

/// A deterministic shape x (one value per sample, e.g. the temperature or a settling exponential)
/// tested given the model: the record's least-squares coefficient on x against the scatter the
/// current model predicts for it, Var c = V_trend t't / x'x (ModelNow's trend variance; exact for
/// white noise, on the safe side for red noise and slow monotone x: see detector.cpp), the
/// accepted noises' share of it no more than their variance on x's cosines; Student's t with the
/// effective dof (satterthwaiteDof), Bonferroni over `trials` shapes searched. x is taken apart
/// from the signals already taken out and from the shapes `beside` (ctx.apart), which are fitted
/// with it: a coefficient tested beside a shape still in the record (the temperature's second
/// power beside its first). Returns the candidate's zConditional (empty when x is constant).
std::function<double(const ModelNow&)> regressorTestGivenModel(const DetectorContext& ctx,
                                                               const std::vector<double>& x, double trials = 1,
                                                               const std::vector<std::vector<double>>& beside = {});

/// The same test for the least-squares line itself (`line`: t = (k + 0.5) dt, the ramp's shape):
/// where no signal is taken out, the accepted noises whose autocovariance dies out within the
/// Allan grid (Candidate::acovSpan) contribute their exact trend variance
/// (trendVarianceFromAcov) rather than a high-side bound.
std::function<double(const ModelNow&)> trendTestGivenModel(const DetectorContext& ctx, const std::vector<double>& line);

using DetectFn = std::vector<Candidate> (*)(const DetectorContext& ctx);

struct DetectorType {
  const char* effect;   // the catalogue type it proposes
  bool repeatable;      // runs where the model already has its effect (adds to it)
  const char* summary;  // what it looks for
  DetectFn detect;
};

/// Every registered detector, in detectors.def order (the order of their candidates: ties in
/// score keep it).
const std::vector<DetectorType>& detectorTypes();

/// The candidates of every detector that is repeatable or whose effect is not among modelEffects,
/// on the series y of the record's channel (the channel's samples, or them without the signals
/// accepted so far, whose regressors are `taken`) whose value lattice is `lattice` (latticeStep
/// of the channel as recorded) and whose level steps are `steps` (DetectorContext::steps).
std::vector<Candidate> buildCandidates(const Record& record, int channel, const std::vector<double>& y,
                                       double lattice, const std::vector<double>& tau, const Setup& setup,
                                       const std::vector<std::string>& modelEffects,
                                       const std::vector<std::vector<double>>& taken = {},
                                       const std::vector<double>& roundingAvar = {},
                                       const std::vector<Line>& linesTaken = {},
                                       const std::vector<double>& steps = {});

#define SINSIM_DETECTOR(effect, repeatable, summary) std::vector<Candidate> detect_##effect(const DetectorContext& ctx);
#include "errormodels/diagnose/detectors.def"
#undef SINSIM_DETECTOR

}  // namespace sinsim::errormodels::diagnose::detail
