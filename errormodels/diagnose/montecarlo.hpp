// Realisations of the model at the record's length and rate, and their statistics (the Monte
// Carlo bands of the comparison). Realisation r is StreamKey (seed, r) whatever thread runs it.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "errormodels/diagnose/series_stats.hpp"
#include "errormodels/imu_model.hpp"

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
/// R = o.realisations realisations on o.threads worker threads; ideal = the record's means. Where
/// a channel slot's lattice has q > 0, each realisation is also rounded onto it
/// (SeriesStats::roundedAvar).
McResult monteCarlo(const ImuErrorModel& model, const Record& record,
                    const std::vector<int>& channels, const Setup& setup,
                    const DiagnoseOptions& o, const std::vector<Lattice>& lattices = {});

/// Realisation of the model at rate [Hz] and length n, ideal [rad/s x3, m/s^2 x3] held constant,
/// temperature [K] per sample (or empty). out[c] filled for c in channels.
void simulate(const ImuErrorModel& model, double rate, std::size_t n,
              const std::vector<double>& ideal, const std::vector<double>& temperatureK,
              std::uint64_t seed, std::uint64_t run, const std::vector<int>& channels,
              std::array<std::vector<double>, 6>& out);

}  // namespace sinsim::errormodels::diagnose::detail
