// Second-order statistics of a uniformly sampled record: autocorrelation and Welch power
// spectral density. Inputs are in any unit u; outputs state theirs.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

namespace sinsim::errormodels {

enum class AcfScaling {
  Biased,      ///< r(k) = 1/N sum_{n=0}^{N-1-k} (x_n - xbar)(x_{n+k} - xbar)   [u^2]
  Normalised,  ///< r(k) / r(0)                                                  [1]
};
enum class AcfMethod {
  Auto,    ///< direct sum for up to 64 lags, FFT otherwise
  Direct,  ///< O(N * lags)
  Fft,     ///< FFTW r2c/c2r, zero-padded to >= N + max_lag (no circular wrap), O(N log N)
};

/// Autocorrelation at lags 0..max_lag. The biased estimator (divide by N at every lag) is the
/// one whose sequence is positive semi-definite (Box & Jenkins 2.1.6) and the one Yule-Walker
/// and the GM fit expect; the mean is removed first.
struct Autocorrelation {
  double dt = 0.0;            ///< [s] lag step, 1 / rate
  std::vector<double> lag;    ///< [s] k * dt
  std::vector<double> r;      ///< [u^2] (Biased) or [1] (Normalised)
  AcfScaling scaling = AcfScaling::Normalised;
  double variance = 0.0;      ///< [u^2] r(0) of the biased estimator (mean-removed, / N)
  double mean = 0.0;          ///< [u] the removed mean
  std::size_t samples = 0;    ///< N
};

/// Throws InputError for fewer than 2 samples, non-finite samples, max_lag >= N, rate <= 0.
Autocorrelation autocorrelation(const std::vector<double>& x, double rate_hz, std::size_t max_lag,
                                AcfScaling scaling = AcfScaling::Normalised,
                                AcfMethod method = AcfMethod::Auto);

struct WelchOptions {
  /// Samples per segment; 0: the largest power of two <= N / 8 (about 15 averaged segments at
  /// 50 % overlap), at least 16 and at most N.
  std::size_t segment_length = 0;
  double overlap = 0.5;  ///< fraction of a segment shared with the next, [0, 1)
  bool detrend = true;   ///< remove each segment's mean before windowing
};

/// One-sided power spectral density by Welch's method (Welch 1967) with a periodic Hann window:
/// psd_k = c_k |sum_n w_n x_n e^{-2 pi i k n / L}|^2 / (fs sum_n w_n^2), averaged over segments,
/// c_k = 2 except at DC and (L even) Nyquist where c_k = 1. Same as scipy.signal.welch(x, fs,
/// window="hann", nperseg=L, noverlap=floor(overlap L), detrend="constant"|False,
/// scaling="density"). Units: [u^2/Hz] — e.g. (rad/s)^2/Hz for gyro rates. Parseval: the sum
/// of psd_k * df equals the mean over segments of sum (w x)^2 / sum w^2, the record's variance
/// for a stationary signal.
struct PowerSpectrum {
  std::vector<double> f;    ///< [Hz] k * fs / L, k = 0..L/2
  std::vector<double> psd;  ///< [u^2/Hz] one-sided density
  double rate_hz = 0.0;     ///< [Hz] fs
  double df = 0.0;          ///< [Hz] bin spacing fs / L
  double enbw_hz = 0.0;     ///< [Hz] equivalent noise bandwidth of one bin, fs sum w^2 / (sum w)^2
  std::size_t segment_length = 0;
  std::size_t segments = 0;
};

/// Throws InputError for non-finite samples, a record shorter than the segment, rate <= 0, an
/// overlap outside [0, 1), or a segment shorter than 2.
PowerSpectrum welchPsd(const std::vector<double>& x, double rate_hz, const WelchOptions& options = {});

/// Periodogram of the record (its first n samples, n = the largest 2^a 3^b 5^c 7^d <= N, within
/// ~1 % of N), tapered (Dahlhaus 1988, "Small sample effects in time series analysis: a new
/// asymptotic theory and a new estimate", Ann. Stat. 16): a split-cosine bell h (a cosine ramp over
/// `taperFraction` / 2 of the record at each end, 1 between; Bloomfield 1976, sec. 5.2), the
/// h-weighted least-squares mean (Detrend::Mean) or line (Detrend::Linear) removed, then
///   I_j = |sum_k h_k (x_k - trend_k) e^{-i w_j k}|^2 / sum_k h_k^2,  w_j = 2 pi j / n, j = 0..n/2.
/// For a stationary process of two-sided PSD S(w) in [u^2 per rad/sample] normalised so that
/// (1/pi) int_0^pi S = the variance (white noise of variance s^2: S = s^2), E I_j ~= S(w_j) away
/// from the lowest j, and the ordinates are ~ S(w_j) chi^2_2 / 2, nearly independent. The taper
/// keeps a steep spectrum's power from leaking far, at the cost of a variance inflation
/// n sum h^4 / (sum h^2)^2 (1.06 at taperFraction 0.1).
enum class Detrend { Mean, Linear };
struct Periodogram {
  std::vector<double> w;      ///< [rad/sample] w_j
  std::vector<double> I;      ///< [u^2 per rad/sample] I_j
  std::vector<double> taper;  ///< h_k, k = 0..n-1 (its size is the n used)
  /// The removed line's slope [u per sample] (0 for Detrend::Mean): sum_k g_k x_k with
  /// g_k = h_k (S0 k - S1) / (S0 S2 - S1^2), S_i = sum_k h_k k^i.
  double slope = 0.0;
  double varianceInflation = 1.0;  ///< n sum h^4 / (sum h^2)^2
};
/// Throws InputError for fewer than 16 samples, non-finite samples or taperFraction outside [0, 1].
Periodogram taperedPeriodogram(const std::vector<double>& x, double taperFraction,
                               Detrend detrend = Detrend::Mean);

/// x filtered by the real, zero-phase gain H(w), w in [0, pi) rad/sample, applied to the record's
/// even (mirrored) extension of length 2N: the DCT-II of x, each coefficient k (the cosine of
/// w_k = pi k / N) times H(w_k), and back by the DCT-III (FFTW's REDFT10 / REDFT01). The mirror
/// leaves no step at the ends for the filter to smear, as a circular (periodic) one would; a
/// Wiener smoother of a slow part is this with H = S_slow / (S_slow + S_rest). Throws InputError
/// for fewer than 2 samples, non-finite samples or a non-finite gain.
std::vector<double> zeroPhaseFiltered(const std::vector<double>& x, const std::function<double(double)>& gain);

/// sum_{k=1}^{M-1} |G(w_k)|^2 weight(|w_k|), G(w) = sum_j g_j e^{-i w j}, at w_k = 2 pi k / M
/// wrapped into (-pi, pi], M = pad * g.size() (g zero-padded to M). With weight = S, the PSD of a
/// stationary x (this file's normalisation), Var(sum g_j x_j) = (1/M) (this + S(0) |G(0)|^2) to
/// quadrature accuracy. Computed as interleaved g.size()-point DFTs (k = pad q + r: the DFT of
/// g_j e^{-i 2 pi r j / M}; r and pad - r give the same |w| for a real g), so the only buffer is
/// g.size() complex values, not the M-point transform. Throws InputError for pad < 1 or g.size() < 2.
double paddedPowerSum(const std::vector<double>& g, std::size_t pad, const std::function<double(double)>& weight);

}  // namespace sinsim::errormodels
