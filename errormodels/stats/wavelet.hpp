// Discrete wavelet transform (multilevel, 1-D) and wavelet-shrinkage denoising, numerically
// the same as PyWavelets 1.1.1 `wavedec` / `waverec` / `threshold` (checked to 1e-12 on
// committed fixtures, tests/stats/fixtures/make_wavelet_fixtures.py).
//
// The paper's pre-processing step is Daubechies db5 denoising; the default here is db5, boundary
// mode "symmetric" (PyWavelets' default: half-sample symmetric extension), the largest useful
// level (pywt.dwt_max_level), the universal threshold with soft thresholding.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace sinsim::errormodels {

/// An orthogonal wavelet's four filters, PyWavelets conventions: dec_lo is rec_lo reversed,
/// dec_hi[k] = (-1)^(k+1) rec_lo[k], rec_hi is dec_hi reversed.
struct Wavelet {
  std::string name;
  std::vector<double> dec_lo, dec_hi, rec_lo, rec_hi;
  std::size_t length() const { return rec_lo.size(); }
};

/// The wavelets held here: "db1" (= "haar"), "db2" (closed forms) and "db5" (the paper's).
/// Unknown names are an InputError listing the known ones.
const Wavelet& waveletByName(const std::string& name);

enum class WaveletBoundary {
  Symmetric,      ///< half-sample symmetric extension, x[-1] = x[0] (PyWavelets "symmetric")
  Periodization,  ///< periodic, ceil(n/2) coefficients per level (PyWavelets "periodization";
                  ///< an odd-length level is first extended by repeating its last sample)
};

/// "symmetric" | "periodization" -> enum; InputError otherwise.
WaveletBoundary waveletBoundaryByName(const std::string& name);

/// Coefficients in PyWavelets' order: coeffs[0] = cA_L, coeffs[1] = cD_L, ..., coeffs[L] = cD_1.
struct WaveletCoefficients {
  std::vector<std::vector<double>> coeffs;
  std::size_t level() const { return coeffs.empty() ? 0 : coeffs.size() - 1; }
};

/// pywt.dwt_max_level: floor(log2(n / (filter_length - 1))), 0 when n < filter_length - 1.
int waveletMaxLevel(std::size_t n, std::size_t filter_length);

/// Multilevel decomposition (pywt.wavedec). level < 0: waveletMaxLevel. Throws InputError for
/// an empty signal, a non-finite sample, or level > waveletMaxLevel (PyWavelets only warns;
/// there every coefficient is dominated by the boundary extension).
WaveletCoefficients wavedec(const std::vector<double>& x, const Wavelet& w,
                            WaveletBoundary mode = WaveletBoundary::Symmetric, int level = -1);

/// Multilevel reconstruction (pywt.waverec). The result may be one sample longer than the
/// original (odd lengths); callers trim to their length.
std::vector<double> waverec(const WaveletCoefficients& c, const Wavelet& w,
                            WaveletBoundary mode = WaveletBoundary::Symmetric);

enum class ThresholdRule {
  Universal,  ///< sigma sqrt(2 ln n), n the signal length (Donoho & Johnstone 1994, VisuShrink)
  Sure,       ///< per level, minimum of Stein's unbiased risk estimate (Donoho & Johnstone 1995)
};
enum class ThresholdMode {
  Soft,  ///< sign(c) max(|c| - t, 0)  (pywt.threshold mode="soft")
  Hard,  ///< c where |c| >= t, else 0 (pywt.threshold mode="hard")
};

struct DenoiseOptions {
  std::string wavelet = "db5";
  WaveletBoundary boundary = WaveletBoundary::Symmetric;
  int level = -1;  ///< < 0: waveletMaxLevel(n, filter length)
  ThresholdRule rule = ThresholdRule::Universal;
  ThresholdMode mode = ThresholdMode::Soft;
};

struct DenoiseResult {
  std::vector<double> signal;      ///< denoised, same length and unit as the input
  int level = 0;                   ///< decomposition level used
  double sigma = 0;                ///< noise level: median(|cD_1|) / 0.6744897501960817 [input unit]
  std::vector<double> thresholds;  ///< per detail level, finest first (cD_1, cD_2, ...) [input unit]
};

/// Wavelet shrinkage: decompose, keep the approximation, threshold every detail level, and
/// reconstruct. sigma from the median absolute finest detail (Donoho & Johnstone 1994, not
/// centred), 0.6744897501960817 = Phi^-1(0.75). SURE: per level j, with x = cD_j / sigma and
/// s = sorted x^2, the threshold sigma sqrt(s_k) minimising
/// (n_j - 2(k+1) + sum_{i<=k} s_i + (n_j - k - 1) s_k) / n_j (MATLAB "rigrsure").
/// Throws InputError for fewer than 2 samples, non-finite samples or an unknown wavelet.
DenoiseResult waveletDenoise(const std::vector<double>& x, const DenoiseOptions& options = {});

}  // namespace sinsim::errormodels
