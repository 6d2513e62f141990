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
/// The ideal (input) signal of the realisations per channel [rad/s x3, m/s^2 x3]: the record's
/// mean, except on a channel whose model rounds each sample (an enabled quantization that neither
/// carries nor dithers) on a step coarser than the model's unrounded one-sample sd: there the level
/// whose rounded mean is the record's (levelOfRoundedMean). The record's mean is a rounded mean;
/// input at it, the model's rounding would sit elsewhere in its cell than the sensor's did and flip
/// between levels at another rate. The sd is that of realisation 0 of the model without its
/// quantization (the same streams: ImuErrorModel::filtered), on o.seed.
std::vector<double> inputLevels(const ErrorModelSpec& spec, const ImuErrorModel& model,
                                const Record& record, const DiagnoseOptions& o);

/// R = o.realisations realisations on o.threads worker threads at the input levels `input`
/// (inputLevels). Where a channel slot's lattice has q > 0, each realisation is also rounded onto
/// it at the record's mean (SeriesStats::roundedAvar).
McResult monteCarlo(const ImuErrorModel& model, const Record& record,
                    const std::vector<int>& channels, const Setup& setup,
                    const DiagnoseOptions& o, const std::vector<double>& input,
                    const std::vector<Lattice>& lattices = {});

/// Realisation of the model at rate [Hz] and length n, ideal [rad/s x3, m/s^2 x3] held constant,
/// temperature [K] per sample (or empty). out[c] filled for c in channels.
void simulate(const ImuErrorModel& model, double rate, std::size_t n,
              const std::vector<double>& ideal, const std::vector<double>& temperatureK,
              std::uint64_t seed, std::uint64_t run, const std::vector<int>& channels,
              std::array<std::vector<double>, 6>& out);

}  // namespace sinsim::errormodels::diagnose::detail
