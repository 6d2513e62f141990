// Narrow lines in a Welch power spectrum: bins that stand out of the continuum around them (a
// vibration, a test stand's oscillation, a sinusoidal error). Used by the diagnosis's sinusoid
// detector (which confirms and sizes a line on the whole record) and by the fit's line warning.
#pragma once

#include <cstddef>
#include <vector>

#include "errormodels/stats/spectrum.hpp"

namespace sinsim::errormodels {

/// A Welch bin that stands out of its neighbourhood.
struct WelchLine {
  double p = 1.0;      ///< probability of so large a bin anywhere in the spectrum under the continuum (Bonferroni)
  double ratio = 0.0;  ///< the bin's density over its neighbourhood's continuum estimate
  double freq = 0.0;   ///< [Hz] the bin's frequency
  std::size_t bin = 0; ///< the bin's index
};

/// The Welch segment the line test is run with on n samples: the largest power of two <= n / 8
/// (about 15 averaged segments) up to 4096, at least 16.
std::size_t lineTestSegment(std::size_t n);

/// Narrow-line test on a raw Welch PSD: each bin against the median of its neighbourhood
/// (bins k-12..k-3 and k+3..k+12; the Hann main lobe is +-2 bins), chi-square with the Welch EDF
/// nu = 2 K / 1.056 (K segments, 50 % overlap Hann: Welch 1967, Percival & Walden 1993 eq. 292b),
/// Bonferroni over the bins tested. Returns up to `count` bins with p < 1, most significant first
/// (equal p, as where they underflow to 0 on a strong line's main lobe: the larger ratio first,
/// the lobe's peak before its flanks), each more than 3 bins from the ones before (a line's main
/// lobe, or one red stretch). In its lowest 12 bins the neighbourhood is one-sided, so a red
/// continuum (a Gauss-Markov beyond its corner, a walk) may stand out there: confirm a line there
/// on the whole record before calling it one. Empty below 40 bins.
std::vector<WelchLine> welchLineTest(const PowerSpectrum& p, std::size_t count);

/// The amplitude [signal] of a sinusoid whose line stands `ratio` times above the continuum in a
/// bin of density `psd` [signal²/Hz]: its power A²/2 is (psd − psd / ratio) times the bin's
/// equivalent noise bandwidth, exact for a line at a bin's centre (Hann: up to 16 % low between
/// two bins, the scalloping loss of 1.42 dB).
double welchLineAmplitude(double psd, double ratio, double enbw_hz);

}  // namespace sinsim::errormodels
