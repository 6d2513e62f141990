// A candidate effect for one channel: what a detector (detector.hpp) proposes and the Allan
// chi-square fit (allan_chi2.hpp) scores.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "errormodels/diagnose/diagnose.hpp"

namespace sinsim::errormodels::diagnose::detail {

/// The scatter a model predicts for a record's least-squares trend [SI^2/s^2]: the realisations'
/// share (their mean square, realisedDof of them) and the accepted noises' share in closed form,
/// with those noises' AVAR on the tau grid [SI^2] (for the scatter of another linear statistic).
/// The variance's effective dof: satterthwaiteDof(realised, realisedDof, known).
struct TrendScatter {
  double realised = 0, realisedDof = 0, known = 0;
  std::vector<double> knownAvar;
  /// The least-squares line's own scatter from the accepted noises: exact for those whose
  /// autocovariance dies out within the Allan grid (Candidate::acovSpan,
  /// trendVarianceFromAcov), and the others' share of `known` and of `knownAvar` (a random walk,
  /// a flicker, a GM near the grid's end).
  double exactLine = 0, restKnown = 0;
  std::vector<double> restAvar;
  /// The base's AVAR at the fitted level on the tau grid [SI^2] (s mu): with knownAvar the whole
  /// model's, whose variance on each slow cosine weighs a shape's generalised least squares.
  std::vector<double> baseAvar;
  /// The part of knownAvar that is the Gaussian noise fitted to the record (ModelNow::trendVarWith):
  /// its size is estimated, like the base's level, not known.
  std::vector<double> fittedAvar;
  double var() const { return realised + known; }
};

/// The current model (the base at its fitted level with the accepted noises) as a conditional
/// test sees it.
struct ModelNow {
  const std::vector<double>& avar;  // AVAR on the tau grid [SI^2]
  /// Variance of a record's least-squares trend (trendSlope) under it [SI^2/s^2], and the
  /// effective degrees of freedom of that estimate (TrendScatter).
  double trendVar = 0, trendDof = 0;
  /// The trend scatter of the current model with the Gaussian noise (a candidate without a
  /// signal, or none) that best fits a series of AVAR `avar` on the tau grid [SI^2]: what a noise
  /// the record shows but the model lacks adds to a realised trend.
  std::function<TrendScatter(const std::vector<double>& avar)> trendVarWith;
};

/// A sinusoid line: frequency [Hz] and amplitude [SI]; `model`: one of the model's own `sinusoid`
/// effects (still in the record), not one taken out of it.
struct Line {
  double frequency = 0, amplitude = 0;
  bool model = false;
};

struct Candidate {
  std::string effect;          // catalogue type
  bool freeSize = true;        // theta fitted >= 0 (g per unit theta) or fixed (g absolute AVAR)
  /// Parameters the effect adds to the model (the criterion's penalty counts them): a GM's
  /// sigma and tau, a sinusoid's amplitude, frequency and phase, ...
  std::size_t parameters = 1;
  std::vector<double> g;       // AVAR contribution at each tau [SI^2]
  double zSpecial = 0.0;       // its own test, Gaussian-equivalent
  /// A test of the candidate given the current model (the ramp's trend against the scatter the
  /// model predicts for it), Gaussian-equivalent (a degree-2 temperature: the root of its two
  /// coefficients' chi-square), or empty.
  std::function<double(const ModelNow& model)> zConditional;
  std::string evidence;
  /// The fitted deterministic signal [SI] per sample (ramp, warm-up, sinusoid, temperature,
  /// outliers): removed from the record before the base AR is refitted. Empty otherwise.
  std::vector<double> signal;
  /// The signal's regressors per sample, without the constant (the ramp's line, the warm-up's
  /// exponential at its time constant, the temperature's powers): once the signal is taken out, a
  /// later signal is fitted beside them (DetectorContext::taken). Empty for noises and for
  /// signals no slow shape overlaps (lines, spikes).
  std::vector<std::vector<double>> basis;
  /// A slow deterministic shape in time (ramp, warm-up, temperature, level steps): a burst of broadband noise
  /// raises the long tau it explains, so on a record whose noise level changes it is credited
  /// only with what it also explains without the loud stretches (selection.cpp, quietRecord). A
  /// line or spikes are not: a burst of broadband noise makes no narrow line, and a vibration
  /// that comes and goes is its line.
  bool slowShape = false;
  /// The signal as `describe` states it, where that differs from `signal`: a signal fitted beside
  /// signals already taken out has its joint size (Frisch-Waugh-Lovell), and `signal` is only its
  /// part apart from them (what the record without them still holds); this is the whole effect
  /// at that size. Empty: the same as `signal`.
  std::vector<double> stated;
  const std::vector<double>& statedSignal() const { return stated.empty() ? signal : stated; }
  /// Quantization from the value lattice: the rate LSB [SI] and whether the remainder is carried
  /// (its autocovariance is subtracted when the base AR is refitted).
  double lsbRate = 0.0;
  bool carry = false;
  /// The white variance the rounding adds per sample [SI^2] (rate LSB, each sample rounded; may
  /// be negative on a coarse lattice: roundingAddedVariance).
  double roundingVar = 0.0;
  /// A rounding that hides noise (a lattice coarser than it): its Allan term `g` holds only for
  /// the base at its own level (the model's realisations rounded), so `--add` keeps the base noise
  /// level beside it, as a base lowered to help the fit is rounded away again (improve.cpp).
  bool keepsBaseLevel = false;
  /// Its Allan term is the model's own realisations rounded onto the record's lattice
  /// (DetectorContext::roundingAvar): once it is accepted, the Allan problem's scatter is theirs
  /// too (ChannelWork::rounded).
  bool roundedRealisations = false;
  /// Autocovariance per unit theta at lags 0..p of the sampled process [SI^2] (bias instability):
  /// subtracted before the base AR is refitted by Yule-Walker. Empty otherwise.
  std::function<std::vector<double>(std::size_t maxLag)> acov;
  /// Where `acov` dies out within the Allan grid (white noise; a GM of correlation time <= tau_max
  /// / 8, whose 1/tau fall the grid's last octaves show), the lags it spans (beyond them it is
  /// below 1e-17 of lag 0); 0 otherwise. Its variance at the record's longest scales is then what
  /// the grid measured, and its trend variance is exact (trendVariance). A slower correlation (a
  /// GM near the grid's end, a flicker) stands for whatever the record holds beyond the grid --
  /// fitted to a walk's Allan excess, a GM of T/50 predicts a realised trend several times too
  /// small -- and keeps the high-side bound from its Allan variance.
  std::size_t acovSpan = 0;
  /// The variance of the record's least-squares trend per unit theta under `acov` [SI^2/s^2]
  /// (trendVariance, selection.cpp), kept once computed (< 0: not yet).
  mutable double trendVarCache = -1.0;
  /// A process whose realisation may be a two-level switching (a telegraph: exponential
  /// autocorrelation, the Gauss-Markov's): on a record whose level steps go back and forth
  /// (selection.cpp, revertingSteps) the steps are its realisation, and it is credited on the
  /// record with them.
  bool switching = false;
  /// How many candidates of this effect a channel may accept: 1, or more for an effect whose
  /// instances are distinct (a sinusoid's lines: each accepted one is taken out of the record and
  /// the next proposed on what is left).
  std::size_t maxAccepted = 1;
  /// A sinusoid's line (frequency 0 for every other effect): once accepted, no later line is
  /// proposed where it is this one's own (DetectorContext::linesTaken).
  Line line;
  /// Fills size/yaml/params of a finding given the fitted theta (ignored when fixed).
  std::function<void(double theta, Finding&)> describe;
};

}  // namespace sinsim::errormodels::diagnose::detail
