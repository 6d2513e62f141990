// The navigation-relevant verdict of a diagnosis (issue 12): what a model's misfit means for the
// drift of a navigation scenario. For the diagnosed model (and the improved one after --add):
//  - its predicted horizontal drift along the scenario (a small Monte Carlo, sim/reference.hpp
//    navigateRealisation, run k keyed StreamKey{seed, k} for every model: paired before/after);
//  - which term drives it: each (sensor, effect type) group of the model alone along the scenario,
//    same seeds, its share of the summed mean-square horizontal error at the end;
//  - which τ band drives the drift at rest, and whether the record's drift from that band is
//    inside the model's: the linearised static INS error kernel on octave bands of the error
//    signals (sim/drift_bands.hpp), the model's runs against the record's own errors;
//  - whether it under- or over-predicts the record's own drift: the record replayed at rest
//    through the same navigation loop as `mc --measured` (sim/measured.hpp), placed among the
//    model's runs along the same static reference (mid-rank percentile);
//  - a warning when the improved model's predicted drift differs from the model's by more than a
//    factor (default 2), naming the added groups that carry it and whether their drift is
//    deterministic (the same in every run: warm-ups, ramps, fixed biases that act from t = 0 and
//    that a navigation start with bias calibration would remove).
// docs/diagnose.md "Navigation-relevant verdict" has the definitions and the thresholds.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "errormodels/diagnose/diagnose.hpp"
#include "errormodels/model_spec.hpp"
#include "errormodels/stats/record.hpp"
#include "sim/scenario.hpp"

namespace sinsim::sim {

struct NavVerdictOptions {
  std::size_t runs = 32;      ///< Monte Carlo runs per model, along the scenario and the replay
  std::size_t termRuns = 16;  ///< runs of each term group alone (its share of the drift)
  std::uint64_t seed = 20240505;
  unsigned threads = 0;  ///< 0: every core
  /// Initial-bias removal [s] for the record and every run alike (NavigateOptions::biasWindow);
  /// unset: `mc --measured`'s default, min(60 s, 10 % of the replay).
  std::optional<double> biasWindow;
  double warnRatio = 2.0;  ///< warn when improved / model median drift leaves [1/r, r]
};

/// Horizontal error across runs at a few epochs (about 10 over the run, and the last) [s], [m].
struct DriftCurve {
  std::vector<double> t, p50, p95;
  double endP50() const { return p50.empty() ? 0.0 : p50.back(); }
  double endP95() const { return p95.empty() ? 0.0 : p95.back(); }
};

/// One (sensor, effect type) group of a model alone along the scenario.
struct TermShare {
  std::string sensor;       ///< "gyro" or "accel"
  std::string effect;       ///< type: "ar", "warmup", ...
  double meanSquare = 0.0;  ///< mean over runs of the horizontal error² at the end [m²]
  double share = 0.0;       ///< meanSquare / the sum over the model's groups
  /// Fraction of meanSquare that is the mean error (the same in every run: deterministic).
  double deterministic = 0.0;
};

/// The drift at rest per octave τ band of the errors (sim/drift_bands.hpp, linearised), at the
/// end of the replay: the model's runs and the record.
struct BandVerdict {
  std::vector<double> tau;         ///< [s] per band (the last: the remainder, the mean level)
  std::vector<double> share;       ///< of the model's summed mean-square band drift
  std::vector<double> modelRms;    ///< √E[h²] of the model's band-alone drift [m]
  std::vector<double> record;      ///< the record's band-alone horizontal drift [m]
  /// The driving band: the fewest adjacent bands holding ≥ half of the model's mean square (of
  /// equal counts, the largest share).
  double from = 0.0, to = 0.0;     ///< [s]
  double shareInBand = 0.0;        ///< of the model's mean square in [from, to]
  double modelP50 = 0.0, modelP95 = 0.0;  ///< the model's drift from [from, to] [m]
  double recordDrift = 0.0;        ///< the record's drift from [from, to] [m]
  double percentile = 50.0;        ///< of recordDrift among the model's runs [%]
  std::string direction;           ///< as ModelDrift::direction
  /// Where the record drifts far beyond the model although the model's own share there is small
  /// (a term the model lacks; the driving band is the model's view and cannot show it): the band
  /// whose record drift is largest among those at ≥ kExcessRatio times the model's rms there,
  /// beyond every run, and at least half the model's whole rms drift; -1: none.
  static constexpr double kExcessRatio = 3.0;
  int excessBand = -1;
  /// The record's drift from all bands together (the linearised model's whole answer) [m], to
  /// compare with the navigated drift (NavVerdict::record): they agree while errors stay small.
  double recordLinear = 0.0;
};

struct ModelDrift {
  std::string label;               ///< the model's name
  DriftCurve scenario, replay;     ///< along the scenario; along the record's static replay
  std::vector<TermShare> terms;    ///< largest share first
  double recordPercentile = 50.0;  ///< of the record's end drift among the replay runs [%]
  double medianPercentile = 50.0;  ///< median over the replay's epochs of the same [%]
  /// "under-predicts" (above every run), "over-predicts" (below every run), or "consistent".
  std::string direction;
  double tail = 0.0;  ///< [%] chance of either for a correct model: 100 / (runs + 1)
  BandVerdict bands;
};

struct NavVerdict {
  std::string scenario;           ///< its name
  double duration = 0.0;          ///< [s] of the scenario
  double replayDuration = 0.0;    ///< [s] of the record used (≤ the scenario's duration)
  double biasWindow = 0.0;        ///< [s]
  std::size_t runs = 0, termRuns = 0;
  std::uint64_t seed = 0;
  DriftCurve record;              ///< the record's own drift (p50 = p95 = its value)
  ModelDrift model;
  std::optional<ModelDrift> improved;
  double ratio = 1.0;             ///< improved / model median drift at the scenario's end
  double warnRatio = 2.0;
  std::string warning;            ///< empty: none
};

/// The verdict for `model` (and `improved`, when given) against `record` along `scenario`.
/// Throws InputError for a record without the six IMU columns, a
/// scenario with aiding keys (the verdict is free-inertial, as `mc --measured`), a model that
/// needs a temperature the scenario lacks; Interrupted on Ctrl-C (progress::interruptFlag).
NavVerdict navigationVerdict(const errormodels::Record& record,
                             const errormodels::ErrorModelSpec& model,
                             const errormodels::ErrorModelSpec* improved, const Scenario& scenario,
                             const NavVerdictOptions& options = {});

/// NavVerdict::warning: empty unless improved / model median drift leaves [1/r, r]; then the
/// groups whose mean square moved most that way, and a hint when their drift is deterministic
/// (more than half of its mean square is the mean over the runs).
std::string navWarningText(const NavVerdict& v);

/// The verdict as lines for the terminal (after the diagnosis table).
std::string navVerdictText(const NavVerdict& v);

/// The diagnosis' JSON (errormodels toJson) with the verdict as its "navigation" member.
std::string diagnoseJsonWithNav(const errormodels::diagnose::Diagnosis& d, const NavVerdict* v);
std::string diagnoseJsonWithNav(const errormodels::diagnose::Improvement& imp, const NavVerdict* v);

}  // namespace sinsim::sim
