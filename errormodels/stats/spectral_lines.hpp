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

/// A line below a Welch test's reach: the whole record's periodogram ordinate that stands out most.
struct LowLine {
  double p = 1.0;              ///< probability of so large an ordinate among those scanned (Bonferroni)
  double ratio = 0.0;          ///< the ordinate over the continuum predicted from its neighbours
  double freq = 0.0;           ///< [Hz] its frequency, j / T
  std::size_t ordinate = 0;    ///< j, cycles per record (0: nothing scanned)
};

/// The line test below a Welch test's lowest bin `lowestBin` (segments of `segment` samples): on
/// the whole record's tapered periodogram (taperedPeriodogram, 10 % split-cosine bell, line
/// removed: a steep continuum's power stays local), each ordinate I_j, j = 12 .. lowestBin n /
/// segment + 2 (n the periodogram's length), against the continuum there: a least-squares line in
/// log I over log j fitted to its neighbours j +- 3..24 from j = 3 up (the line's own main lobe
/// left out; a red continuum's slope followed, not taken for a peak), predicting ln S_j - gamma
/// (E ln of an Exp(1) ordinate is -gamma, its variance pi^2 / 6). Then r = I_j / S_j-hat is Exp(1)
/// times exp(-e), e the prediction's error (~ N(0, s^2), s from the fit), so P(r > x) = E exp(-x
/// e^e), integrated numerically, and Bonferroni over the ordinates scanned. Returns the largest r.
/// The diagnosis's sinusoid detector scans below its Welch bin 3, the fit below its bin 12.
/// Ordinates within `skip` [Hz] of a frequency in `taken` [Hz] (lines already taken out: what
/// is left of them) are not proposed; they stay among the neighbours, and the Bonferroni count
/// stays that of every ordinate scanned.
LowLine lowLineTest(const std::vector<double>& y, double rate, std::size_t segment, std::size_t lowestBin,
                    const std::vector<double>& taken = {}, double skip = 0.0);

/// The amplitude [signal] of a sinusoid whose line stands `ratio` times above the continuum in a
/// bin of density `psd` [signal²/Hz]: its power A²/2 is (psd − psd / ratio) times the bin's
/// equivalent noise bandwidth, exact for a line at a bin's centre (Hann: up to 16 % low between
/// two bins, the scalloping loss of 1.42 dB).
double welchLineAmplitude(double psd, double ratio, double enbw_hz);

}  // namespace sinsim::errormodels
