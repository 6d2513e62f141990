#include "errormodels/identify_lines.hpp"

#include <algorithm>
#include <cmath>

#include "errormodels/stats/spectrum.hpp"

namespace sinsim::errormodels::detail {

namespace {

constexpr double kLineP = 1e-3;
constexpr std::size_t kLowestBin = 12;
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

}  // namespace

std::vector<RecordLine> recordLines(const std::vector<double>& x, double rate) {
  return welchLines(x, rate, segmentFor(x.size()), 4);
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
    if (next == found.end()) break;
    // Refined on the whole record, as the diagnosis's sinusoid detector does.
    RecordLine line = *next;
    const LineWindow w = welchLineWindow(line.welch.freq, bin, rate);
    const LinePeriodogram pg(x, 0.0, dt, 0.5 * (w.fa + w.fb), 0.5 * (w.fb - w.fa));
    line.fitted = fitLineAt(x, 0.0, dt, refineLineFrequency(pg, w, x.size(), L));
    const std::vector<double> s = lineSamples(line.fitted, dt, x.size());
    for (std::size_t k = 0; k < x.size(); ++k) x[k] -= s[k];
    taken.push_back(line);
  }
  return taken;
}

}  // namespace sinsim::errormodels::detail
