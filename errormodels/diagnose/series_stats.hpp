// The statistics the comparison computes alike for the measurement and for every realisation of
// the model: overlapping AVAR on a half-octave tau grid, Welch PSD in log-frequency bands, and
// the normalised ACF.
#pragma once

#include <cstddef>
#include <vector>

#include "errormodels/diagnose/diagnose.hpp"
#include "errormodels/diagnose/low_frequency.hpp"
#include "errormodels/diagnose/noise_level.hpp"

namespace sinsim::errormodels::diagnose::detail {

/// What the comparison of one channel needs from the statistics of one series.
struct Setup {
  double rate = 0;  // [Hz]
  std::size_t n = 0;
  std::vector<std::size_t> factors;  // averaging factors m (half-octave grid)
  std::size_t psdSegment = 0;
  std::vector<std::vector<std::size_t>> psdBandBins;  // bins of each band
  std::vector<double> psdBandFreq;                   // [Hz]
  std::size_t acfLags = 0;
  LowFrequencyBasis lowFreq;  // the slowest cosines beyond slow shapes (low_frequency.hpp)
};
struct SeriesStats {
  std::vector<double> avar;  // per factor [SI^2]
  std::vector<double> psd;   // per band (mean of its bins) [SI^2/Hz]
  std::vector<double> acf;   // normalised, lags 0..acfLags
  double trend = 0;          // least-squares slope [SI/s] (trendSlope)
  std::vector<double> lowFreq;  // coefficients on the slow directions [SI] (lowFrequencyCoefficients)
  /// AVAR per factor of the same series rounded onto the record's value lattice (Lattice), empty
  /// off a lattice: what rounding makes of this model's noise, for the quantization candidate.
  std::vector<double> roundedAvar;
  /// The shortest scale's noise level in blocks of the series and its largest departure
  /// (noise_level.hpp).
  NoiseLevelBlocks levelBlocks;
};
/// Half-octave grid m = round(2^(j/2)) up to maxM: twice the points of the octave grid, so that
/// "the fraction of tau outside a 95 % band" is not decided by one or two points.
std::vector<std::size_t> halfOctaveFactors(std::size_t maxM);
/// The grids for n samples at rate [Hz]; InputError when the PSD segment exceeds the record.
Setup makeSetup(double rate, std::size_t n, const DiagnoseOptions& o);
SeriesStats seriesStats(const std::vector<double>& y, const Setup& s);
/// Overlapping AVAR of y at the factors of s [SI^2].
std::vector<double> allanVariance(const std::vector<double>& y, const Setup& s);

}  // namespace sinsim::errormodels::diagnose::detail
