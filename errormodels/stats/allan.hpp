// Allan-family deviations of a rate record (gyro rate, specific force, fractional frequency)
// with equivalent degrees of freedom and chi-square confidence intervals.
//
// Definitions follow W. J. Riley, "Handbook of Frequency Stability Analysis", NIST SP 1065
// (2008), written on the phase x (the running integral of the rate y, x_0 = 0,
// x_{i+1} = x_i + tau0 y_i, N_x = N + 1 points), tau = m tau0:
//   overlapping ADEV   (SP1065 eq. 11)  s2 = sum_{i=0}^{N_x-2m-1} (x_{i+2m} - 2x_{i+m} + x_i)^2
//                                            / (2 tau^2 (N_x - 2m))
//   non-overlapping    (SP1065 eq. 10)  the same on every m-th phase point
//   modified ADEV      (SP1065 eq. 14)  inner sum over m consecutive second differences,
//                                            divided by 2 m^2 tau^2 (N_x - 3m + 1)
//   Hadamard (non-ovl) (SP1065 eq. 17)  third differences of every m-th phase point / 6 tau^2
//   overlapping HDEV   (SP1065 eq. 18)  third differences at all i / (6 tau^2 (N_x - 3m))
// The deviation has the unit of y. The record's mean is removed before integration (all these
// variances are invariant to it) so that the phase stays small and no digits are lost.
//
// Confidence intervals: noise type alpha (S_y(f) ~ f^alpha) per tau by the lag-1
// autocorrelation method (Riley & Greenhall 2004, "Power law noise identification using the
// lag 1 autocorrelation", Proc. 18th EFTF), or given by the caller; equivalent degrees of
// freedom by C. A. Greenhall & W. J. Riley (2003), "Uncertainty of stability variances based on
// finite differences", Proc. 35th PTTI (the algorithm IEEE Std 1139-2008 refers to); interval
// dev * sqrt(edf / chi2_{(1 +- c)/2}(edf)) (SP1065 eq. 45).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace sinsim::errormodels {

enum class AllanVariant {
  Overlapping,          ///< overlapping Allan deviation (the default, "OADEV")
  NonOverlapping,       ///< classic Allan deviation ("ADEV")
  Modified,             ///< modified Allan deviation ("MDEV")
  Hadamard,             ///< non-overlapping Hadamard deviation ("HDEV")
  OverlappingHadamard,  ///< overlapping Hadamard deviation ("OHDEV")
};

/// "oadev", "adev", "mdev", "hdev", "ohdev".
std::string toString(AllanVariant variant);

enum class TauGrid {
  Octave,     ///< m = 1, 2, 4, 8, ...
  PerDecade,  ///< about AllanOptions::points_per_decade log-spaced distinct m per decade
  All,        ///< every m = 1, 2, 3, ... (cost ~ N * m_max: for short records only)
};

struct AllanOptions {
  TauGrid grid = TauGrid::Octave;
  int points_per_decade = 10;
  /// Explicit averaging factors (sorted, distinct, each valid for the variant): overrides grid.
  std::vector<std::size_t> factors;
  /// Largest m of a grid; 0 = floor(N / 4) (limited further by what the variant can estimate).
  std::size_t max_factor = 0;
  /// Compute noise type, EDF and bounds (false: only dev and count).
  bool confidence_intervals = true;
  /// Two-sided confidence level of the bounds; 0.683 is Stable32's default "1 sigma".
  double confidence = 0.683;
  /// Noise type for the EDF at every tau (S_y ~ f^alpha, integer in [-4, 2] and alpha + 2d > 1).
  /// Unset: identified per tau from the data.
  std::optional<int> alpha;
};

/// One deviation curve. All vectors have the same length, one entry per tau.
struct AllanCurve {
  AllanVariant variant = AllanVariant::Overlapping;
  double tau0 = 0.0;          ///< [s] sample interval
  std::size_t samples = 0;    ///< N, number of rate samples used
  double confidence = 0.683;  ///< two-sided level of lo/hi
  std::vector<std::size_t> m;       ///< averaging factors
  std::vector<double> tau;          ///< [s] m * tau0
  std::vector<double> dev;          ///< deviation [unit of the input]
  std::vector<std::size_t> count;   ///< number of terms in the estimator's sum (Stable32 "#")
  // Filled when confidence intervals were asked for:
  std::vector<int> alpha;           ///< noise type used for the EDF (S_y ~ f^alpha)
  std::vector<bool> alpha_measured; ///< false: given by the caller, or too few points to
                                    ///< identify (then the nearest identified smaller tau's)
  std::vector<double> edf;          ///< equivalent degrees of freedom
  std::vector<double> lo, hi;       ///< confidence bounds of dev [unit of the input]

  std::size_t size() const { return tau.size(); }
};

/// Deviation curve of the rate samples y taken every 1/rate_hz seconds. Throws InputError for a
/// non-positive rate, non-finite samples, fewer than 3 samples, or invalid explicit factors.
AllanCurve allanDeviation(const std::vector<double>& y, double rate_hz,
                          AllanVariant variant = AllanVariant::Overlapping,
                          const AllanOptions& options = {});

/// Averaging factors of a grid, 1 <= m <= max_factor.
std::vector<std::size_t> tauFactors(TauGrid grid, std::size_t max_factor, int points_per_decade = 10);

/// Result of the lag-1 autocorrelation noise identification at one averaging factor.
struct NoiseId {
  int alpha = 0;        ///< integer power-law exponent of S_y(f), clamped to [alpha_min, 2]
  double alpha_real = 0.0;///< -2 (rho + d) before rounding
  int d = 0;            ///< differences taken
  double rho = 0.0;     ///< r1 / (1 + r1) of the final series
};

/// Riley & Greenhall (2004) on frequency data: average y over blocks of m, remove a linear
/// trend, difference until rho < 0.25 or d = d_max; alpha = -round(2 rho) - 2 d. d_max is
/// (variance order - 1) for rate data: 1 for the Allan family, 2 for Hadamard. Returns nullopt
/// when fewer than 30 block averages are available (the method's stated minimum).
std::optional<NoiseId> identifyNoise(const std::vector<double>& y, std::size_t m, int d_max,
                                     int alpha_min);

/// Greenhall & Riley (2003) EDF. alpha: noise type; d: difference order (2 Allan, 3 Hadamard);
/// m: averaging factor; n_phase: number of phase points (N rate samples + 1); overlapping:
/// stride 1 estimator; modified: modified variance. Throws InputError for alpha + 2d <= 1.
double greenhallEdf(int alpha, int d, double m, double n_phase, bool overlapping, bool modified);

/// Bounds dev * sqrt(edf / chi2_{(1+c)/2}), dev * sqrt(edf / chi2_{(1-c)/2}) (SP1065 eq. 45).
void chiSquareBounds(double dev, double edf, double confidence, double& lo, double& hi);

}  // namespace sinsim::errormodels
