#include "errormodels/identify_lines.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

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

/// The Welch PSD the line test runs on (segments of segmentFor(N)); none below 128 samples per
/// segment.
std::optional<PowerSpectrum> lineTestPsd(const std::vector<double>& x, double rate) {
  WelchOptions wo;
  wo.segment_length = segmentFor(x.size());
  if (wo.segment_length < 128) return std::nullopt;
  return welchPsd(x, rate, wo);
}

}  // namespace

std::vector<RecordLine> recordLines(const std::vector<double>& x, double rate) {
  const auto psd = lineTestPsd(x, rate);
  if (!psd) return {};
  std::vector<RecordLine> out;
  for (const WelchLine& l : welchLineTest(*psd, 4))
    if (l.p < kLineP && l.bin >= kLowestBin)
      out.push_back({l, welchLineAmplitude(psd->psd[l.bin], l.ratio, psd->enbw_hz), {}});
  return out;
}

std::vector<RecordLine> takeOutLines(std::vector<double>& x, double rate) {
  std::vector<RecordLine> taken;
  const double dt = 1.0 / rate;
  while (taken.size() < kMaxLines) {
    const auto psd = lineTestPsd(x, rate);
    if (!psd) break;
    const double bin = rate / double(segmentFor(x.size()));
    std::optional<RecordLine> next;
    for (const WelchLine& l : welchLineTest(*psd, 4 + taken.size())) {
      if (!(l.p < kLineP && l.bin >= kLowestBin)) continue;
      const bool near = std::any_of(taken.begin(), taken.end(), [&](const RecordLine& t) {
        return std::fabs(l.freq - t.fitted.frequency) <= 3 * bin;
      });
      if (near) continue;
      next = RecordLine{l, welchLineAmplitude(psd->psd[l.bin], l.ratio, psd->enbw_hz), {}};
      break;
    }
    if (!next) break;
    // Refined within +-1.5 Welch bins on the whole record, about 6 points per Welch bin's worth
    // of Fourier frequencies (as the diagnosis's sinusoid detector).
    const double fa = std::max(0.25 * bin, next->welch.freq - 1.5 * bin);
    const double fb = std::min(0.5 * rate, next->welch.freq + 1.5 * bin);
    const LinePeriodogram pg(x, 0.0, dt, 0.5 * (fa + fb), 0.5 * (fb - fa));
    const int scan = int(std::min(2000.0, std::max(50.0, 6 * double(x.size()) * bin / rate)));
    next->fitted = fitLineAt(x, 0.0, dt, refineLineFrequency(pg, fa, fb, scan));
    const std::vector<double> s = lineSamples(next->fitted, dt, x.size());
    for (std::size_t k = 0; k < x.size(); ++k) x[k] -= s[k];
    taken.push_back(*next);
  }
  return taken;
}

}  // namespace sinsim::errormodels::detail
