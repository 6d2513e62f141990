// diagnose() (diagnose.hpp): per channel, the comparison with the model's Monte Carlo
// realisations, then the detectors' candidates and their forward selection.
#include "errormodels/diagnose/diagnose.hpp"
#include "errormodels/diagnose/model_drift.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>

#include "common/error.hpp"
#include "common/progress.hpp"
#include "common/units.hpp"
#include "errormodels/diagnose/channels.hpp"
#include "errormodels/diagnose/compare.hpp"
#include "errormodels/diagnose/detector.hpp"
#include "errormodels/diagnose/model_edit.hpp"
#include "errormodels/diagnose/montecarlo.hpp"
#include "errormodels/diagnose/noise_level.hpp"
#include "common/parallel.hpp"
#include "errormodels/diagnose/run.hpp"
#include "errormodels/diagnose/selection.hpp"
#include "errormodels/diagnose/whiteness.hpp"
#include "errormodels/model_io.hpp"
#include "errormodels/stats/lattice.hpp"
#include "errormodels/stats/special.hpp"

namespace sinsim::errormodels::diagnose {

using namespace detail;

const std::vector<std::string>& detectableEffects() {
  static const std::vector<std::string> e = [] {
    std::vector<std::string> names;
    for (const auto& d : detectorTypes()) names.push_back(d.effect);
    return names;
  }();
  return e;
}

AddRequest AddRequest::parse(const std::string& text) {
  AddRequest r;
  const auto colon = text.find(':');
  r.effect = text.substr(0, colon);
  if (colon != std::string::npos) {
    r.channel = text.substr(colon + 1);
    channelIndex(r.channel, "--add " + text);
  }
  const auto& known = detectableEffects();
  if (r.effect != "found" && std::find(known.begin(), known.end(), r.effect) == known.end()) {
    std::string list;
    for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
    throw InputError("--add " + text + ": unknown effect \"" + r.effect + "\" (the diagnosis can add: " +
                     list + "; or \"found\": every reported finding)");
  }
  return r;
}

bool AxisDiagnosis::fits() const {
  if (!unexplainedSteps.empty() || noiseLevelChange) return false;
  for (const auto& f : findings)
    if (f.reported) return false;
  // and the Allan chi-square below its 0.999 quantile
  return chi2Points == 0 || chi2 < chiSquareQuantile(0.999, double(chi2Points));
}

const AxisDiagnosis& Diagnosis::axis(const std::string& channel) const {
  for (const auto& a : axes)
    if (a.channel == channel) return a;
  throw InputError("channel " + channel + " was not diagnosed");
}

std::string effectText(const EffectSpec& effect, const std::string& channel) {
  if (effect.type.empty()) return "";
  return effectYaml(effect, isGyro(channelIndex(channel)) ? Sensor::gyro : Sensor::accel);
}

namespace {

/// The channels asked for (all the record has when none), checked against the record.
std::vector<int> channelsToDiagnose(const Record& record, const DiagnoseOptions& o) {
  std::vector<int> channels;
  if (o.channels.empty()) {
    for (int c = 0; c < 6; ++c)
      if (!channelData(record, c).empty()) channels.push_back(c);
  } else {
    for (const auto& name : o.channels) {
      const int c = channelIndex(name);
      if (channelData(record, c).empty()) throw InputError(record.source + " has no channel " + name);
      channels.push_back(c);
    }
  }
  if (channels.empty())
    throw InputError(record.source + ": no gx/gy/gz/ax/ay/az column to diagnose; " + sensorColumnsHint(record));
  for (int c : channels) {
    if (isConstantChannel(channelData(record, c)))
      throw InputError(record.source + ": channel " + kRecordChannels[c].name +
                       " is constant: nothing to diagnose; leave it out: --channels " + otherChannels(record, c, " "));
  }
  return channels;
}

/// Steps 1-3 of one channel: compare, Ljung-Box of an AR base at the record's rate, candidates
/// and their forward selection.
ChannelWork diagnoseChannel(const Record& record, const ErrorModelSpec& model, int c,
                            const std::vector<SeriesStats>& real, const Setup& setup,
                            const DiagnoseOptions& o, double lattice) {
  const auto& y = channelData(record, c);
  ChannelWork w;
  w.channel = c;
  w.factors = setup.factors;
  w.y = &y;
  w.rate = setup.rate;
  AxisDiagnosis& d = w.d;
  d.channel = kChannels[c];
  d.unit = unitsFor(c).level;
  d.unitFactor = parseUnit(d.unit).si;
  const SeriesStats measured = seriesStats(y, setup);
  compareChannel(measured, real, setup, o.bandLevel, d, w.prob);
  for (const auto& r : real) w.trendVar += r.trend * r.trend / double(real.size());
  w.trendDof = double(real.size());
  w.lowFreq = setup.lowFreq;
  w.lowFreqVar.assign(w.lowFreq.u.size(), 0.0);
  for (const auto& r : real)
    for (std::size_t d = 0; d < r.lowFreq.size() && d < w.lowFreqVar.size(); ++d)
      w.lowFreqVar[d] += r.lowFreq[d] * r.lowFreq[d] / double(real.size());
  const Sensor sensor = isGyro(c) ? Sensor::gyro : Sensor::accel;
  const auto modelEffects = effectTypesOn(model, sensor, c % 3);
  if (auto a = baseAr(model, c, record.rate_hz)) {
    // The AR's residuals are white only where the AR is the channel's whole noise: beside a
    // quantization, a GM, a walk or a line A(q) colours that noise, and the test rejected models
    // that fit (p ~ 1e-175 beside "fits" on a blind probe's AR + quantization channels).
    static const char* const kStatic[] = {"ar", "bias", "scale_factor", "misalignment", "g_sensitivity"};
    const bool alone = std::all_of(modelEffects.begin(), modelEffects.end(), [](const std::string& t) {
      return std::any_of(std::begin(kStatic), std::end(kStatic), [&](const char* k) { return t == k; });
    });
    if (alone && y.size() > o.ljungBoxLags + a->size() + 10) d.ljungBox = ljungBox(y, *a, o.ljungBoxLags);
    w.arOrder = a->size() - 1;
  }
  // Single-LSB steps are what rounding makes of a slow drift only where the noise does not dither
  // the rounding: the mean of a rounded signal follows its input once the noise sd is >= q/2
  // (Widrow & Kollar 2008, ch. 4: the bias falls as exp(-2 pi^2 sd^2 / q^2)); there a window mean
  // resolves sub-LSB level changes, and a step of one LSB is a step. The one-sample noise sd is
  // taken as the sd of the first differences / sqrt(2).
  double dd = 0;
  for (std::size_t k = 1; k < y.size(); ++k) dd += (y[k] - y[k - 1]) * (y[k] - y[k - 1]);
  const double noiseSd = std::sqrt(dd / double(std::max<std::size_t>(y.size() - 1, 1)) / 2.0);
  w.lattice = lattice > 2.0 * noiseSd ? lattice : 0.0;
  // The noise level over the record, where rounding does not set it: on a lattice coarser than
  // the noise how often the value flips follows where the level sits in its cell (a drift of a
  // fraction of an LSB took the flips x0.64..x2.1 on the alt generator's quantized channels).
  // The record's quiet stretches against the model's level: a stationary noise the change alone
  // sizes is not named (selection.cpp, standsInForChange).
  if (w.lattice == 0.0) {
    std::vector<double> spreads, medians;
    for (const auto& r : real) spreads.push_back(r.levelBlocks.spread), medians.push_back(r.levelBlocks.median);
    d.noiseLevelChange = noiseLevelChange(measured.levelBlocks, y.size(), setup.rate, spreads, medians);
  }
  // What rounding onto the record's lattice adds to this model's AVAR: the realisations rounded
  // less the same realisations as they are (paired, so the difference has little scatter).
  std::vector<double> rounding;
  for (const auto& r : real)
    if (r.roundedAvar.size() == r.avar.size()) {
      rounding.resize(r.avar.size(), 0.0);
      for (std::size_t k = 0; k < r.avar.size(); ++k) rounding[k] += (r.roundedAvar[k] - r.avar[k]) / double(real.size());
    }
  w.rounded = roundedScatter(real);
  w.modelJumps = std::find(modelEffects.begin(), modelEffects.end(), "bias_jumps") != modelEffects.end();
  // The model's own lines count as taken: the record shows them, and the model has them.
  w.propose = [&record, c, lattice, &d, &setup, effects = modelEffects, rounding, own = modelLines(model, c)](
                  const std::vector<double>& series, const std::vector<std::vector<double>>& taken,
                  const std::vector<Line>& linesTaken, const std::vector<double>& steps) {
    std::vector<Line> lines = own;
    lines.insert(lines.end(), linesTaken.begin(), linesTaken.end());
    return buildCandidates(record, c, series, lattice, d.adev.x, setup, effects, taken, rounding, lines, steps);
  };
  selectFindings(w, o.threshold, o.furtherThreshold());
  w.propose = nullptr;  // it refers to this call's record and setup
  return w;
}

}  // namespace

namespace detail {

Run diagnoseRun(const Record& record, const ErrorModelSpec& model, const DiagnoseOptions& o) {
  if (o.realisations < 8 || o.realisations > 100000)
    throw OptionError("--realisations: at least 8 and at most 100000 Monte Carlo realisations, got " +
                     std::to_string(o.realisations));
  if (!(std::isfinite(o.threshold) && o.threshold > 0))
    throw OptionError("--threshold: expected a positive score");
  if (!(std::isfinite(o.nextThreshold) && o.nextThreshold > 0))
    throw OptionError("--next-threshold: expected a positive score");
  if (!(o.bandLevel > 0 && o.bandLevel < 1)) throw InputError("band level must be in (0, 1)");
  if (record.rows < 256) throw InputError(record.source + ": at least 256 samples are needed");
  const std::vector<int> channels = channelsToDiagnose(record, o);
  const auto m = ImuErrorModel::fromSpec(model, model.source);
  if (m.needsTemperature() && record.temperature.empty())
    throw InputError("model " + model.source + " needs the sensor temperature, and " + record.source +
                     " has no temp column");
  Setup setup = makeSetup(record.rate_hz, record.rows, o);
  setup.lowFreq = lowFrequencyBasis(record.rows, record.temperature);
  // Each channel's value lattice (latticeStep of it as recorded); the realisations are rounded
  // onto it only where its rounding could be seen at all (detectors/quantization.cpp).
  std::vector<double> steps;
  std::vector<Lattice> seen;
  for (int c : channels) {
    const auto& y = channelData(record, c);
    const double q = latticeStep(y);
    const double offset = q > 0 ? y.front() - q * std::nearbyint(y.front() / q) : 0.0;
    steps.push_back(q);
    const bool visible = latticeVisible(y, q) && std::isfinite(offset);
    seen.push_back(visible ? Lattice{q, offset} : Lattice{});
  }
  const auto mc = monteCarlo(m, record, channels, setup, o,
                             modelRoundings(model, m, record, o, channels, seen), seen);
  Run run;
  run.d.data = record.source;
  run.d.model = model.source;
  run.d.rate = record.rate_hz;
  run.d.samples = record.rows;
  run.d.realisations = o.realisations;
  run.d.threshold = o.threshold;
  run.d.nextThreshold = o.furtherThreshold();
  run.d.bandLevel = o.bandLevel;
  // Channels are independent (each its own series, statistics and candidates): on worker
  // threads, each result in its channel's slot, so the diagnosis is the same for any thread count.
  run.work.resize(channels.size());
  std::atomic<std::size_t> done{0};
  parallelFor<int>(channels.size(), o.threads, [&](std::size_t ci, int&) {
    const auto name = kChannels[std::size_t(channels[ci])];
    progress::checkpoint(std::string("diagnosing channel ") + name, done, channels.size());
    try {
      run.work[ci] = diagnoseChannel(record, model, channels[ci], mc.perChannel[ci], setup, o, steps[ci]);
    } catch (const Error& e) {  // a failure deep in the statistics: say which record and channel
      throw InputError(record.source + ": channel " + name + ": " + e.text());
    }
    ++done;
  });
  for (const auto& w : run.work) run.d.axes.push_back(w.d);
  return run;
}

}  // namespace detail

Diagnosis diagnose(const Record& record, const ErrorModelSpec& model, const DiagnoseOptions& options) {
  const auto net = detail::withoutModelDrift(record, model);
  Diagnosis d = diagnoseRun(net ? net->record : record, net ? net->model : model, options).d;
  if (net) detail::stateModelDrift(d, net->drift);
  d.recordWarnings = recordWarnings(record);
  return d;
}

}  // namespace sinsim::errormodels::diagnose
