// A sinusoid fitted to a record: its frequency refined on the whole record's periodogram near a
// line the Welch test proposes (spectral_lines.hpp), then its amplitude and phase by least squares.
// Used by the diagnosis's sinusoid detector and by `fit`, which takes a record's lines out before
// fitting its noise terms.
#pragma once

#include <array>
#include <complex>
#include <cstddef>
#include <vector>

namespace sinsim::errormodels {

/// The periodogram of y - mean near a frequency fc, for |f - fc| <= halfWidth [Hz]: the record
/// demodulated by fc and summed per block of B samples with the block's moments in time, so that
///   X(f) = sum_k v_k e^{-i w (k + 1/2)} = sum_b e^{-i d (bB + 1/2)} sum_m (-i d B)^m / m! U_bm,
///   U_bm = sum_j (j / B)^m v_{bB+j} e^{-i wc (bB + j + 1/2)},  d = w - wc,
/// exact to rounding (|d| B <= 1/2: the Taylor series of e^{-i d j} ends at 16 terms below 1e-19).
/// One pass over the record; each frequency then costs 16 N / B instead of N.
class LinePeriodogram {
 public:
  LinePeriodogram(const std::vector<double>& y, double mean, double dt, double fc, double halfWidth);

  /// a^2 + b^2 of y - mean ~ a cos(w t) + b sin(w t), t = (k + 0.5) dt, at f [Hz].
  double power(double f) const;

 private:
  static constexpr std::size_t kTerms = 16;
  double dt_, wc_;
  std::size_t N_, B_;
  std::vector<std::complex<double>> U_;  // per block, kTerms moments
};

/// Where a line is looked for on the whole record: [fa, fb] [Hz].
struct LineWindow {
  double fa = 0, fb = 0;
};

/// The window of a line the Welch test found at freq [Hz] in bins `bin` [Hz] wide: +-1.5 bins,
/// inside [bin / 4, rate / 2].
LineWindow welchLineWindow(double freq, double bin, double rate);

/// The periodogram's peak in the window: a scan (the periodogram of a whole record has many side
/// lobes inside a few Welch bins) of about 6 points per Welch bin's worth of Fourier frequencies
/// (6 N / L for N samples and Welch segments of L, 50 to 2000), then golden section around the
/// best.
double refineLineFrequency(const LinePeriodogram& pg, const LineWindow& w, std::size_t N, std::size_t L);

/// A sinusoid of the record: y_k - mean ~ sampled sin(2 pi f (k + 1/2) dt + phase), the interval
/// average over sample k of amplitude sin(2 pi f t + phase) (effects/sinusoid.cpp realises that),
/// so sampled = amplitude sinc(pi f dt).
struct FittedLine {
  double frequency = 0;  ///< [Hz]
  double amplitude = 0;  ///< [signal] of the continuous sinusoid
  double sampled = 0;    ///< [signal] of the samples
  double phase = 0;      ///< [rad] at t = 0 (the first sample's start)
};

/// Least-squares amplitude and phase of y - mean at frequency f [Hz] (one pass over the record).
FittedLine fitLineAt(const std::vector<double>& y, double mean, double dt, double f);

/// The fitted line's samples (what fitLineAt explains of the record), N of them.
std::vector<double> lineSamples(const FittedLine& line, double dt, std::size_t N);

/// The Allan variance [signal^2] at averaging time tau [s] of a sinusoid of amplitude A realised as
/// interval averages: A^2 sin^4(pi f tau) / (pi f tau)^2, averaged over its phase (the overlapping
/// estimator on a record of many periods).
double sinusoidAllanVariance(double A, double f, double tau);

}  // namespace sinsim::errormodels
