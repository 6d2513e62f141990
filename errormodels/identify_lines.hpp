// Narrow lines in a static record, for the identify pipeline: found by the Welch line test, each
// fitted as a sinusoid on the whole record and taken out before the noise terms are fitted (no
// noise term is a line: a vibration line would become a Gauss-Markov at its period, more white
// noise, or a quantization near Nyquist). Internal to errormodels/identify*.cpp.
#pragma once

#include <vector>

#include "errormodels/stats/line_fit.hpp"
#include "errormodels/stats/spectral_lines.hpp"

namespace sinsim::errormodels::detail {

/// A line the Welch test finds in a record (spectral_lines.hpp; segments of lineTestSegment(N), or
/// of the largest power of two <= N / 16 where that is longer: identify_lines.cpp): from the 12th
/// bin up, where its neighbourhood is two-sided (below it a red continuum can stand
/// out), at a look-elsewhere p below 1e-3; below that bin (fewer than 12 N / L cycles per record)
/// by the whole record's periodogram (lowLineTest) at p below 1e-6. For a low line `welch` holds
/// that test's p, ratio and ordinate frequency (bin 0) and welchAmplitude the fitted amplitude.
struct RecordLine {
  WelchLine welch;           ///< the Welch bin and its ratio
  double welchAmplitude = 0; ///< [signal] welchLineAmplitude of that bin
  FittedLine fitted;         ///< refined and sized on the whole record: the coherent part
};

/// The lines of x (mean removed) without taking them out: the Welch test once, and the strongest
/// line below its reach; each sized on the whole record as takeOutLines does.
std::vector<RecordLine> recordLines(const std::vector<double>& x, double rate);

/// Finds lines in x (mean removed) one at a time, each refined and sized on the whole record
/// (stats/line_fit.hpp) and subtracted before the next is looked for, up to 8; a proposal within
/// 3 Welch bins of a line taken is what is left of that line (a frequency that wanders), not
/// another. Returns the lines taken; x is left without them.
std::vector<RecordLine> takeOutLines(std::vector<double>& x, double rate);

}  // namespace sinsim::errormodels::detail
