// Realisations of the model at the record's length and rate, and their statistics (the Monte
// Carlo bands of the comparison). Realisation r is StreamKey (seed, r) whatever thread runs it.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "errormodels/diagnose/series_stats.hpp"
#include "errormodels/imu_model.hpp"
#include "errormodels/model_spec.hpp"

namespace sinsim::errormodels::diagnose::detail {

/// Monte Carlo statistics of the model for the channels asked: R realisations.
struct McResult {
  std::vector<std::vector<SeriesStats>> perChannel;  // [channel slot][realisation]
};
/// A channel's value lattice: step q and offset (the values are offset + integers x q); q = 0 off
/// a lattice.
struct Lattice {
  double q = 0, offset = 0;
};
/// Per channel slot, the coarse rounding of the model that the diagnosis takes over (q = 0:
/// none): an enabled quantization that neither carries nor dithers, the channel's only one, whose
/// step q exceeds the model's unrounded one-sample sd (realisation 0 of the model without its
/// quantization, on o.seed); the offset is the record's lattice's (recordLattices, per slot) where
/// the record sits on that step, else 0. On such a lattice where the level sits in its cell sets
/// how often the value flips, and the record's mean — a rounded mean — says where the sensor's sat;
/// a realisation's own level (the ideal plus its turn-on bias, scale factor, ...) does not.
std::vector<Lattice> modelRoundings(const ErrorModelSpec& spec, const ImuErrorModel& model,
                                   const Record& record, const DiagnoseOptions& o,
                                   const std::vector<int>& channels,
                                   const std::vector<Lattice>& recordLattices);

/// R = o.realisations realisations on o.threads worker threads; ideal = the record's means. A
/// channel slot with modelRounding[i].q > 0 is realised without its quantization, moved to the
/// level whose rounded mean is the record's (levelOfRoundedMean at the realisation's own sd) and
/// rounded there. Where a channel slot's lattice has q > 0, each realisation is also rounded onto
/// it at the record's mean (SeriesStats::roundedAvar).
McResult monteCarlo(const ImuErrorModel& model, const Record& record,
                    const std::vector<int>& channels, const Setup& setup,
                    const DiagnoseOptions& o, const std::vector<Lattice>& modelRounding,
                    const std::vector<Lattice>& lattices = {});

/// Realisation of the model at rate [Hz] and length n, ideal [rad/s x3, m/s^2 x3] held constant,
/// temperature [K] per sample (or empty). out[c] filled for c in channels.
void simulate(const ImuErrorModel& model, double rate, std::size_t n,
              const std::vector<double>& ideal, const std::vector<double>& temperatureK,
              std::uint64_t seed, std::uint64_t run, const std::vector<int>& channels,
              std::array<std::vector<double>, 6>& out);

}  // namespace sinsim::errormodels::diagnose::detail
