// The statistics of a measured record, per channel (sinsim analyze): mean and deviation, the
// autocorrelation and Welch PSD of the (optionally db5-denoised) signal, and the overlapping Allan
// deviation of the raw signal with confidence bounds — computed once, written as JSON (SI) and/or
// as an HTML report (display units).
#pragma once

#include <cstddef>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "errormodels/stats/allan.hpp"
#include "errormodels/stats/record.hpp"
#include "errormodels/stats/spectrum.hpp"
#include "errormodels/stats/wavelet.hpp"

namespace sinsim::sim {

struct AnalysisOptions {
  double max_lag_s = 0;       // largest ACF lag [s]; 0: min(duration/10, 1000 s)
  std::size_t segment = 0;    // Welch segment length [samples]; 0: power of 2 <= N/8
  bool tauPerDecade = false;  // Allan τ grid: false octave, true 10 per decade
  double confidence = 0.683;  // two-sided level of the Allan bounds
  bool denoise = false;       // db5 wavelet denoising before ACF and PSD (Allan uses raw data)
  bool fullJson = false;      // JSON with every ACF lag and PSD bin (default: log-spaced subset)
};

/// Throws InputError naming the option (--max-lag, --confidence) when it is out of range: the CLI
/// before reading the record, analyzeRecord for every caller (the Python module took a max lag of
/// 1e300 s that the CLI refused).
void checkAnalysisOptions(const AnalysisOptions& options);

/// The statistics of one channel.
struct ChannelStats {
  std::string name;     // gx, ..., az
  std::string unit_si;  // rad/s or m/s^2
  double mean = 0.0, sd = 0.0;
  /// Every sample has the same value (a dead or unconnected sensor): its statistics are zeros.
  bool constant = false;
  std::optional<errormodels::DenoiseResult> denoised;
  errormodels::Autocorrelation acf;
  errormodels::PowerSpectrum psd;
  errormodels::AllanCurve allan;
};

/// Statistics of every gyro and accelerometer channel the record has (InputError: none).
std::vector<ChannelStats> analyzeRecord(const errormodels::Record& record,
                                        const AnalysisOptions& options);

/// The noise terms read off an Allan deviation curve (IEEE Std 952-1997, Annex C), SI:
/// N from the shortest τ on the −1/2 line σ = N/√τ; B from the curve's minimum, σ_min/0.664
/// (flicker floor); K from the longest τ on the +1/2 line σ = K √(τ/3) (an upper bound when the
/// curve has not reached that slope). NaN when the curve is empty.
struct NoiseTerms {
  double N = NAN;     // white noise density (ARW / VRW) [unit·√s]
  double tauN = NAN;  // τ where N is read [s]: the shortest, or where the slope is nearest −½
  double shortSlope = NAN;  // log-log slope between the two shortest τ (white: −½)
  double B = NAN;     // bias instability [unit]
  double tauB = NAN;  // τ of the minimum [s]
  /// The minimum is the longest τ: the curve still falls there, no floor is in the record, and B
  /// is only an upper bound.
  bool bStillFalling = false;
  double K = NAN;     // rate random walk [unit/√s]
};
/// N is read at the shortest τ unless the curve's slope there is more than 0.1 from white noise's
/// −½ (a sensor's low-pass filter flattens or even raises it and under-reads N by a factor;
/// quantization steepens it): then where the slope between neighbouring points is nearest −½,
/// before the Allan minimum.
NoiseTerms readNoiseTerms(const errormodels::AllanCurve& allan);

/// The datasheet units of a channel: gyros deg/h, deg/√h, deg/h/√h; accelerometers µg, m/s/√h,
/// µg/√h (factors from SI: value·level, N·density, K·walk).
struct DatasheetUnits {
  double level, density, walk;
  std::string levelUnit, densityUnit, walkUnit;
};
DatasheetUnits datasheetUnits(bool gyro);

/// A terminal table: per channel mean and sd, the white-noise density read at the shortest tau
/// and the Allan minimum as a bias-instability B, in datasheet units (deg/h, deg/sqrt(h), ug,
/// m/s/sqrt(h)). A constant channel reads "-" for the noise terms, with a note below the table.
std::string analysisSummary(const std::vector<ChannelStats>& stats);

/// One warning per constant channel ("channel gz is constant (0 rad/s at every sample): a dead
/// or unconnected sensor? ..."); empty when every channel varies.
std::vector<std::string> analysisWarnings(const std::vector<ChannelStats>& stats);

/// Writes the analysis: JSON (SI; ACF and PSD log-spaced unless fullJson) to jsonPath and/or the HTML report to htmlPath
/// (empty: not written), each whole or not at all.
void writeAnalysis(const errormodels::Record& record, const std::vector<ChannelStats>& stats,
                   const AnalysisOptions& options, const std::string& jsonPath,
                   const std::string& htmlPath);

}  // namespace sinsim::sim
