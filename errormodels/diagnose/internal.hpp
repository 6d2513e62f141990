// Internals of the diagnosis shared by its sources (not a public API).
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "errormodels/diagnose/diagnose.hpp"
#include "errormodels/imu_model.hpp"

namespace sinsim::errormodels::diagnose::detail {

extern const std::array<const char*, 6> kChannels;  // gx gy gz ax ay az
int channelIndex(const std::string& name);           // InputError for an unknown name
inline bool isGyro(int c) { return c < 3; }
inline const char* sensorName(int c) { return c < 3 ? "gyro" : "accel"; }
inline const char* axisName(int c) { static const char* n[3] = {"x", "y", "z"}; return n[c % 3]; }
const std::vector<double>& channelData(const Record& r, int c);

/// Display units of the model files and reports (the same as fit/model_writer).
struct Units {
  const char* level;      // signal
  const char* walk;       // signal / sqrt(time)
  const char* increment;  // signal * time
  const char* slope;      // signal / time
  const char* perKelvin;  // signal / degC
  const char* perKelvin2; // signal / degC^2
};
const Units& unitsFor(int channel);
/// "<value in unit> <unit>", 6 significant digits.
std::string quantity(double si, const char* unit);
std::string num(double v, int digits = 4);

/// What the comparison of one channel needs from the statistics of one series.
struct Setup {
  double rate = 0;
  std::size_t n = 0;
  std::vector<std::size_t> factors;  // octave m
  std::size_t psdSegment = 0;
  std::vector<std::vector<std::size_t>> psdBandBins;  // bins of each band
  std::vector<double> psdBandFreq;                   // [Hz]
  std::size_t acfLags = 0;
};
struct SeriesStats {
  std::vector<double> avar;  // per factor
  std::vector<double> psd;   // per band (mean of its bins)
  std::vector<double> acf;   // normalised, lags 0..acfLags
};
Setup makeSetup(double rate, std::size_t n, const DiagnoseOptions& o);
SeriesStats seriesStats(const std::vector<double>& y, const Setup& s);
std::vector<double> allanVariance(const std::vector<double>& y, const Setup& s);

/// Monte Carlo statistics of the model for the channels asked: R realisations.
struct McResult {
  std::vector<std::vector<SeriesStats>> perChannel;  // [channel slot][realisation]
};
McResult monteCarlo(const ImuErrorModel& model, const Record& record,
                    const std::vector<int>& channels, const Setup& setup,
                    const DiagnoseOptions& o);

/// Realisation of the model at the record's rate/length, ideal = record means, record's
/// temperature. out[c] filled for c in channels.
void simulate(const ImuErrorModel& model, double rate, std::size_t n,
              const std::vector<double>& ideal, const std::vector<double>& temperatureK,
              std::uint64_t seed, std::uint64_t run, const std::vector<int>& channels,
              std::array<std::vector<double>, 6>& out);

/// One candidate effect for one channel.
struct Candidate {
  std::string effect;
  bool freeSize = true;        // theta fitted >= 0 (g per unit theta) or fixed (g absolute AVAR)
  std::vector<double> g;       // AVAR contribution at each tau
  double zSpecial = 0.0;       // its own test, Gaussian-equivalent
  /// A test that depends on the current model's AVAR at the tau grid (warm-up), or empty.
  std::function<double(const std::vector<double>& modelAvar)> zConditional;
  std::string evidence;
  /// The fitted deterministic signal [SI] per sample (ramp, warm-up, sinusoid, temperature,
  /// outliers): removed from the record before the base AR is refitted. Empty otherwise.
  std::vector<double> signal;
  /// Quantization from the value lattice: the rate LSB [SI] and whether the remainder is carried
  /// (its autocovariance is subtracted when the base AR is refitted).
  double lsbRate = 0.0;
  bool carry = false;
  /// Autocovariance per unit theta at lags 0..p of the sampled process [SI^2] (bias instability):
  /// subtracted before the base AR is refitted by Yule-Walker. Empty otherwise.
  std::function<std::vector<double>(std::size_t maxLag)> acov;
  /// Fills size/yaml/params of a finding given the fitted theta (ignored when fixed).
  std::function<void(double theta, Finding&)> describe;
};

/// The Allan chi-square problem of one channel.
struct AllanProblem {
  std::vector<double> L;     // ln AVAR of the measurement
  std::vector<double> mu;    // model mean AVAR
  std::vector<double> bias;  // E[ln AVAR_est] - ln mu under the model (Monte Carlo)
  Eigen::MatrixXd W;         // inverse covariance of ln AVAR estimates
};
struct AllanSolution {
  double s = 1.0;
  std::vector<double> theta;  // one per candidate in the set (1 for fixed ones)
  double chi2 = 0.0;
};
/// AVAR of the fitted model s mu + sum theta g at each tau.
std::vector<double> modelAvarOf(const AllanProblem& p, const std::vector<const Candidate*>& set,
                                const AllanSolution& sol);
/// z with P(|Z| > z) = p (two-sided), capped at 40.
double zFromTwoSidedP(double p);
/// Least squares over the level s (unless fixLevel: s = 1) and the free sizes.
AllanSolution solveAllan(const AllanProblem& p, const std::vector<const Candidate*>& set,
                         const std::vector<double>& thetaStart = {}, bool fixLevel = false);
/// Student-t statistic with nu dof -> Gaussian-equivalent z (Wallace 1959):
/// z = sqrt(nu ln(1 + t^2/nu)) (8 nu + 1) / (8 nu + 3).
double zFromStudentT(double t, double nu);

std::vector<Candidate> buildCandidates(const Record& record, int channel,
                                       const std::vector<double>& tau, const Setup& setup,
                                       const std::vector<double>& measAvar,
                                       const std::vector<double>& modelAvar,
                                       const std::string& modelText, double psdLineZ,
                                       double psdLineFreq);

/// Lattice of values: step q [SI] when the record's increments are integer multiples of one
/// step (>= 99 % of non-zero differences within 1 % of a multiple); 0 otherwise.
double latticeStep(const std::vector<double>& y);
/// Mean of y over consecutive windows of m samples.
std::vector<double> windowMeans(const std::vector<double>& y, std::size_t m);

/// Effects of the model file on one channel (types), from its `all` and axis lists.
std::vector<std::string> modelEffectTypes(const std::string& modelText, int channel);

/// Model text with effects appended per channel and the base noise of each channel scaled by
/// sqrt(variance factor).
/// arReplace[c]: when non-empty, the channel's `ar` effect gets these coefficients a1..ap and
/// driving sigma (last element, SI) instead of its own.
std::string editModel(const std::string& modelText,
                      const std::array<std::vector<std::string>, 6>& addYaml,
                      const std::array<double, 6>& varianceScale, const std::string& header,
                      const std::array<std::vector<double>, 6>& arReplace = {});

}  // namespace sinsim::errormodels::diagnose::detail
