// The working state of one diagnosis, per channel, that improve() continues from: the Allan
// problem, the candidates and the accepted ones (not a public API).
#pragma once

#include <functional>
#include <vector>

#include "errormodels/diagnose/allan_chi2.hpp"
#include "errormodels/diagnose/candidate.hpp"
#include "errormodels/diagnose/compare.hpp"
#include "errormodels/diagnose/low_frequency.hpp"

namespace sinsim::errormodels::diagnose::detail {

struct ChannelWork {
  std::vector<std::size_t> factors;  // averaging factors of the tau grid
  int channel = 0;
  AxisDiagnosis d;
  AllanProblem prob;
  std::vector<Candidate> cands;
  std::vector<std::size_t> accepted;  // indices into cands, in acceptance order
  AllanSolution sol;                  // the joint fit of the accepted ones
  /// The channel's samples and rate [Hz]: an accepted signal is taken out of the record and the
  /// measurement's AVAR recomputed without it (selection.cpp).
  const std::vector<double>* y = nullptr;
  double rate = 0;
  /// The detectors' candidates on a series of this channel and its level steps (during the
  /// diagnosis only): proposed by selectFindings once the record's steps are found, and again on
  /// the record without an accepted signal, so that the next effect is fitted and
  /// tested on what the first leaves (a temperature fit is not bent by spikes), beside the
  /// regressors of the signals taken out (`taken`, DetectorContext::taken).
  std::function<std::vector<Candidate>(const std::vector<double>& series,
                                       const std::vector<std::vector<double>>& taken,
                                       const std::vector<Line>& linesTaken,
                                       const std::vector<double>& steps)>
      propose;
  std::vector<std::vector<double>> taken;
  /// An AR base at the record's rate is re-estimated in each trial of a candidate with a signal
  /// (selection.cpp): the AR order (0: no AR base), the accepted signals' sum and the closed-form
  /// AVAR of the AR refitted on the record without them.
  std::size_t arOrder = 0;
  /// Mean square of the realisations' least-squares trends (the model's trend variance at level
  /// s = 1) [SI^2/s^2] and their number.
  double trendVar = 0, trendDof = 0;
  /// The record's slowest scales (low_frequency.hpp): the slow directions, the mean square of the
  /// realisations' coefficients on them (level s = 1) [SI^2], and the coefficients of the record
  /// without the accepted signals, and without its steps too (empty without steps) [SI].
  LowFrequencyBasis lowFreq;
  std::vector<double> lowFreqVar, lowFreqCoef, jumpFreeCoef;
  std::vector<double> removed, baseAvar;
  /// On a record with level jumps (levelSteps, significance.hpp): ln AVAR of the record without
  /// the accepted signals and without its steps, and per candidate whether its own signal takes
  /// the steps out (a warm-up's first windows). Empty when the record shows none (selection.cpp,
  /// markJumps).
  std::vector<double> jumpFreeL;
  /// Those steps as a piecewise-constant series (empty when there are none).
  std::vector<double> steps;
  /// The record's value lattice step [SI] where the noise (sd < q/2) does not dither the rounding,
  /// else 0: single-LSB steps on it are rounding, not level steps (diagnose.cpp).
  double lattice = 0;
  std::vector<char> explainsJumps;
  /// The channel's model has bias jumps of its own: the record's steps are its realisation, not
  /// unexplained.
  bool modelJumps = false;
  /// Per candidate with a signal that takes most of the steps out but not all: ln AVAR of the
  /// record without the steps left once its signal is taken out (empty otherwise).
  std::vector<std::vector<double>> ownJumpFreeL;
  /// On a record whose noise level changes (AxisDiagnosis::noiseLevelChange): ln AVAR of the
  /// record without the accepted signals and without the stretches whose level departs, the
  /// pieces joined (selection.cpp, quietRecord). Empty otherwise.
  std::vector<double> quietL;
  /// The Allan problem's weight and bias under the realisations rounded onto the record's lattice
  /// (empty when they were not rounded): the problem's once a rounding of them is accepted.
  RoundedScatter rounded;
};

struct Run {
  Diagnosis d;
  std::vector<ChannelWork> work;
};

/// The diagnosis with its working state (diagnose() keeps only run.d).
Run diagnoseRun(const Record& record, const ErrorModelSpec& model, const DiagnoseOptions& o);

}  // namespace sinsim::errormodels::diagnose::detail
