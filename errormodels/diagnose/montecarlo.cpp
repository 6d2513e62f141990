// Realisations of a model and their statistics on worker threads (montecarlo.hpp), and
// simulateRecord (diagnose.hpp).
#include "errormodels/diagnose/montecarlo.hpp"
#include "common/parallel.hpp"

#include <algorithm>
#include <cmath>

#include "common/error.hpp"
#include "common/progress.hpp"
#include "common/types.hpp"
#include "errormodels/diagnose/channels.hpp"
#include "errormodels/diagnose/rounding.hpp"
#include "errormodels/effects/quantization.hpp"

namespace sinsim::errormodels::diagnose {

namespace detail {

void simulate(const ImuErrorModel& model, double rate, std::size_t n,
              const std::vector<double>& ideal, const std::vector<double>& temperatureK,
              std::uint64_t seed, std::uint64_t run, const std::vector<int>& channels,
              std::array<std::vector<double>, 6>& out) {
  auto corruptor = model.instantiate(rate, {seed, run});
  const double dt = 1.0 / rate;
  const Vec3 dtheta(ideal[0] * dt, ideal[1] * dt, ideal[2] * dt);
  const Vec3 dv(ideal[3] * dt, ideal[4] * dt, ideal[5] * dt);
  for (int c : channels) out[c].resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    ImuSample s;
    s.t = double(k + 1) * dt;
    s.dt = dt;
    s.dtheta_b = dtheta;
    s.dv_b = dv;
    corruptor->corrupt(s, temperatureK.empty() ? NAN : temperatureK[k]);
    for (int c : channels) out[c][k] = (c < 3 ? s.dtheta_b[c] : s.dv_b[c - 3]) / dt;
  }
}

namespace {

/// The record's mean per channel (0 for a channel it lacks): the ideal signal of the realisations.
std::vector<double> channelMeans(const Record& record) {
  std::vector<double> ideal(6, 0.0);
  for (int c = 0; c < 6; ++c) {
    const auto& y = channelData(record, c);
    if (y.empty()) continue;
    double m = 0;
    for (double v : y) m += v;
    ideal[c] = m / double(y.size());
  }
  return ideal;
}

/// The mean and population sd of x.
struct MeanSd {
  double mean = 0, sd = 0;
};
MeanSd meanSd(const std::vector<double>& x) {
  double m = 0, ss = 0;
  for (double v : x) m += v / double(x.size());
  for (double v : x) ss += (v - m) * (v - m) / double(x.size());
  return {m, std::sqrt(ss)};
}

/// The realisation x moved to the input level at which its rounding onto l averages the record's
/// mean `recordMean` (levelOfRoundedMean at x's own sd), then rounded: on a lattice coarser than
/// the noise, how often the rounded value flips depends on where the level sits in its cell, and
/// the record's mean says where (its own rounded mean, not the input's).
std::vector<double>& roundedAtRecordLevel(std::vector<double>& x, const Lattice& l, double recordMean) {
  const auto [m, sd] = meanSd(x);
  const double mu = sd > 0 ? l.offset + levelOfRoundedMean(recordMean - l.offset, sd, l.q) : recordMean;
  for (double& v : x) v = l.offset + l.q * std::nearbyint((v - m + mu - l.offset) / l.q);
  return x;
}

/// The rate step [SI] on which channel c's model rounds each sample (its enabled quantization
/// that neither carries nor dithers: rate LSB, or increment LSB / dt), 0 when it has none (or
/// more than one rounding: then none is moved).
double sampleRoundingStep(const ErrorModelSpec& spec, int c, double rate) {
  const SensorSpec& s = spec.sensor(isGyro(c) ? Sensor::gyro : Sensor::accel);
  const Dimension signal = isGyro(c) ? Dimension::angularRate() : Dimension::acceleration();
  double step = 0;
  int count = 0;
  for (const auto* list : {&s.all, &s.list(axisList(c % 3))})
    for (const auto& e : *list) {
      if (!e.enabled || e.type != "quantization") continue;
      ++count;
      const QuantizationRule rule = quantizationRule(e, signal);  // the spec passed fromSpec
      if (rule.roundsEachSample()) step = rule.rateStep(rate);
    }
  return count == 1 ? step : 0.0;
}

/// The model without its quantization effects (the other effects draw the same numbers:
/// ImuErrorModel::filtered keeps the streams).
ImuErrorModel withoutQuantization(const ImuErrorModel& model) {
  return model.filtered([](const std::string& n) { return n.find(".quantization") == std::string::npos; });
}

}  // namespace

std::vector<Lattice> modelRoundings(const ErrorModelSpec& spec, const ImuErrorModel& model,
                                   const Record& record, const DiagnoseOptions& o,
                                   const std::vector<int>& channels,
                                   const std::vector<Lattice>& recordLattices) {
  std::vector<Lattice> out(channels.size());
  std::vector<int> rounded;
  for (std::size_t i = 0; i < channels.size(); ++i) {
    const double q = sampleRoundingStep(spec, channels[i], record.rate_hz);
    if (!(std::isfinite(q) && q > 0)) continue;
    // The record's own offset where it sits on the model's lattice; else the model's (0).
    const bool same = i < recordLattices.size() && std::abs(recordLattices[i].q - q) <= 1e-9 * q;
    out[i] = Lattice{q, same ? recordLattices[i].offset : 0.0};
    rounded.push_back(channels[i]);
  }
  if (rounded.empty()) return out;
  std::array<std::vector<double>, 6> buf;
  simulate(withoutQuantization(model), record.rate_hz, record.rows, channelMeans(record),
           record.temperature, o.seed, 0, rounded, buf);
  for (std::size_t i = 0; i < channels.size(); ++i) {
    if (!(out[i].q > 0)) continue;
    const double sd = meanSd(buf[std::size_t(channels[i])]).sd;
    if (!(sd < out[i].q)) out[i] = Lattice{};  // a fine step: the model's own rounding, as given
  }
  return out;
}

McResult monteCarlo(const ImuErrorModel& model, const Record& record,
                    const std::vector<int>& channels, const Setup& setup,
                    const DiagnoseOptions& o, const std::vector<Lattice>& modelRounding,
                    const std::vector<Lattice>& lattices) {
  const std::vector<double> ideal = channelMeans(record);
  const std::size_t R = o.realisations;
  // Channels whose coarse rounding the diagnosis takes over: realised without it (the same
  // streams), each realisation moved to the record's level and rounded there.
  std::vector<int> own, taken;
  for (std::size_t i = 0; i < channels.size(); ++i)
    (i < modelRounding.size() && modelRounding[i].q > 0 ? taken : own).push_back(channels[i]);
  const ImuErrorModel raw = taken.empty() ? model : withoutQuantization(model);
  McResult res;
  res.perChannel.assign(channels.size(), std::vector<SeriesStats>(R));
  parallelFor<std::array<std::vector<double>, 6>>(R, o.threads, [&](std::size_t r, auto& buf) {
    progress::checkpoint("simulating the model", r, R);
    if (!own.empty()) simulate(model, record.rate_hz, record.rows, ideal, record.temperature, o.seed, r, own, buf);
    if (!taken.empty()) simulate(raw, record.rate_hz, record.rows, ideal, record.temperature, o.seed, r, taken, buf);
    for (std::size_t i = 0; i < channels.size(); ++i) {
      auto& x = buf[channels[i]];
      if (i < modelRounding.size() && modelRounding[i].q > 0)
        roundedAtRecordLevel(x, modelRounding[i], ideal[channels[i]]);
      res.perChannel[i][r] = seriesStats(x, setup);
      if (i < lattices.size() && lattices[i].q > 0) {
        res.perChannel[i][r].roundedAvar = allanVariance(roundedAtRecordLevel(x, lattices[i], ideal[channels[i]]), setup);
      }
    }
  });
  return res;
}

}  // namespace detail

Record simulateRecord(const ErrorModelSpec& model, double rate, std::size_t samples, std::uint64_t seed,
                      std::uint64_t run, const std::vector<double>& ideal,
                      const std::vector<double>& temperatureK) {
  if (ideal.size() != 6) throw InputError("simulateRecord: 6 ideal values expected");
  if (!temperatureK.empty() && temperatureK.size() != samples)
    throw InputError("simulateRecord: one temperature per sample expected");
  const auto m = ImuErrorModel::fromSpec(model, model.source);
  std::array<std::vector<double>, 6> out;
  detail::simulate(m, rate, samples, ideal, temperatureK, seed, run, {0, 1, 2, 3, 4, 5}, out);
  Record r;
  r.source = model.source + " (simulated, seed " + std::to_string(seed) + ")";
  r.rate_hz = rate;
  r.rows = samples;
  for (int a = 0; a < 3; ++a) r.gyro[a] = std::move(out[a]), r.accel[a] = std::move(out[3 + a]);
  r.temperature = temperatureK;
  return r;
}

}  // namespace sinsim::errormodels::diagnose
