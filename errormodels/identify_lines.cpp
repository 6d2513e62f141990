#include "errormodels/identify_lines.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "errormodels/stats/spectrum.hpp"

namespace sinsim::errormodels::detail {

namespace {

constexpr double kLineP = 1e-3;
constexpr std::size_t kLowestBin = 12;
/// Below the Welch test's lowest bin, the whole record's periodogram (lowLineTest) and a stricter
/// look-elsewhere p: its continuum is predicted from 44 neighbouring ordinates, and a red
/// continuum's curvature (a Gauss-Markov's corner in the band) is not a straight line in log-log.
/// The diagnosis reports such a line from z 5.5 (p 4e-8); here p < 1e-6 (z 4.9). The smallest p
/// on 400 red-noise records made for it (white; a GM with its corner in the band; a walk; 1/f)
/// was 0.008, and no line was written on 1080 null channel fits of the diagnosis challenge's
/// generators (test_identify [lines]; docs/fitting.md, the lines bullet).
constexpr double kLowLineP = 1e-6;
constexpr std::size_t kMaxLines = 8;

/// The Welch segment of the fit's line test on n samples: the diagnosis's (lineTestSegment, at
/// most 4096), or the largest power of two <= n / 16 where that is longer (31 segments averaged,
/// 58 EDF). The test starts at its 12th bin, 12 rate / L: with 4096 samples that is 2.9 Hz at
/// 1 kHz, and a record's lines below it (a third of them, on a log-uniform spread from 0.3 Hz)
/// stayed in; at 1.2 M samples the 65536-sample segment starts at 0.18 Hz. A steady line stands
/// higher over the noise as the bins narrow (a line whose frequency wanders by more than a bin
/// does not).
std::size_t segmentFor(std::size_t n) {
  std::size_t L = 16;
  while (L * 2 <= n / 16) L *= 2;
  return std::max(L, lineTestSegment(n));
}

/// The lines the Welch test finds in x (segments of L samples), most significant first, that the
/// fit takes: p below kLineP, from kLowestBin up; each with its Welch amplitude. None when a
/// segment would be shorter than 128 samples.
std::vector<RecordLine> welchLines(const std::vector<double>& x, double rate, std::size_t L, std::size_t count) {
  if (L < 128) return {};
  WelchOptions wo;
  wo.segment_length = L;
  const PowerSpectrum psd = welchPsd(x, rate, wo);
  std::vector<RecordLine> out;
  for (const WelchLine& l : welchLineTest(psd, count))
    if (l.p < kLineP && l.bin >= kLowestBin)
      out.push_back({l, welchLineAmplitude(psd.psd[l.bin], l.ratio, psd.enbw_hz), {}});
  return out;
}

/// A low line proposed within this many Fourier spacings 1 / T of a low line taken is what is left
/// of that one (as the diagnosis's kResolved); the whole record's periodogram resolves lines closer
/// than the Welch test's 3 bins (3 N / L spacings: two slow lines 0.05 Hz apart in 20 min at 100 Hz
/// were one before).
constexpr double kLowResolved = 5.0;

/// The line below the Welch test's reach (below its bin kLowestBin: fewer than 12 N / L cycles
/// per record) that lowLineTest finds at p < kLowLineP, its frequency refined within one Fourier
/// spacing either side and its amplitude fitted on the whole record; none when it lies within
/// 3 Welch bins of a Welch line taken or within kLowResolved / T of a low one.
std::optional<RecordLine> lowLine(const std::vector<double>& x, double rate, std::size_t L,
                                  const std::vector<RecordLine>& taken) {
  const double dt = 1.0 / rate, T = double(x.size()) * dt, bin = rate / double(L);
  std::vector<double> lowTaken;  // what is left of a low line taken is not proposed again
  for (const RecordLine& t : taken)
    if (t.welch.bin == 0) lowTaken.push_back(t.fitted.frequency);
  const LowLine low = lowLineTest(x, rate, L, kLowestBin, lowTaken, kLowResolved / T);
  if (low.ordinate == 0 || !(low.p < kLowLineP)) return std::nullopt;
  const LinePeriodogram pg(x, 0.0, dt, low.freq, 1.0 / T);
  const double f = refineLineFrequency(pg, {low.freq - 1.0 / T, low.freq + 1.0 / T}, x.size(), L);
  if (std::any_of(taken.begin(), taken.end(), [&](const RecordLine& t) {
        return std::fabs(f - t.fitted.frequency) <= (t.welch.bin > 0 ? 3 * bin : kLowResolved / T);
      }))
    return std::nullopt;
  RecordLine line{{low.p, low.ratio, low.freq, 0}, 0.0, fitLineAt(x, 0.0, dt, f)};
  line.welchAmplitude = line.fitted.amplitude;
  return line;
}

/// The Welch line at `freq` refined within its window and sized on the whole record (as the
/// diagnosis's sinusoid detector does): its coherent part.
FittedLine refinedLine(const std::vector<double>& x, double rate, std::size_t L, double freq) {
  const double dt = 1.0 / rate;
  const LineWindow w = welchLineWindow(freq, rate / double(L), rate);
  const LinePeriodogram pg(x, 0.0, dt, 0.5 * (w.fa + w.fb), 0.5 * (w.fb - w.fa));
  return fitLineAt(x, 0.0, dt, refineLineFrequency(pg, w, x.size(), L));
}

}  // namespace

std::vector<RecordLine> recordLines(const std::vector<double>& x, double rate) {
  const std::size_t L = segmentFor(x.size());
  std::vector<RecordLine> out = welchLines(x, rate, L, 4);
  for (RecordLine& l : out) l.fitted = refinedLine(x, rate, L, l.welch.freq);
  if (L >= 128)
    if (auto low = lowLine(x, rate, L, {})) out.push_back(*low);
  return out;
}

std::vector<RecordLine> takeOutLines(std::vector<double>& x, double rate) {
  std::vector<RecordLine> taken;
  const double dt = 1.0 / rate;
  const std::size_t L = segmentFor(x.size());
  const double bin = rate / double(L);
  while (taken.size() < kMaxLines) {
    const auto found = welchLines(x, rate, L, 4 + taken.size());
    const auto next = std::find_if(found.begin(), found.end(), [&](const RecordLine& l) {
      return std::none_of(taken.begin(), taken.end(), [&](const RecordLine& t) {
        return std::fabs(l.welch.freq - t.fitted.frequency) <= 3 * bin;
      });
    });
    RecordLine line;
    if (next != found.end()) {
      line = *next;
      line.fitted = refinedLine(x, rate, L, line.welch.freq);
    } else if (auto low = L >= 128 ? lowLine(x, rate, L, taken) : std::nullopt) {
      line = *low;
    } else {
      break;
    }
    const std::vector<double> s = lineSamples(line.fitted, dt, x.size());
    for (std::size_t k = 0; k < x.size(); ++k) x[k] -= s[k];
    taken.push_back(line);
  }
  return taken;
}

}  // namespace sinsim::errormodels::detail
