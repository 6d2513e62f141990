// Sinusoid: a narrow line in the Welch PSD, its frequency refined on the whole record (golden
// section on the periodogram within +-1.5 Welch bins), then least-squares amplitude and phase
// (stats/line_fit.hpp).
#include "errormodels/diagnose/detector.hpp"
#include "errormodels/diagnose/significance.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "errormodels/stats/line_fit.hpp"
#include "errormodels/stats/special.hpp"
#include "errormodels/stats/spectral_lines.hpp"
#include "errormodels/stats/spectrum.hpp"

namespace sinsim::errormodels::diagnose::detail {

namespace {

/// A Welch bin that stands out: its Gaussian-equivalent z (look-elsewhere corrected) and frequency.
struct WelchLine {
  double z = 0, freq = 0;  // [-], [Hz]
};

/// The shared Welch line test (stats/spectral_lines.hpp), each line's p as a z.
std::vector<WelchLine> psdLineTest(const PowerSpectrum& p, std::size_t count) {
  std::vector<WelchLine> out;
  for (const errormodels::WelchLine& l : welchLineTest(p, count))
    out.push_back({l.p > 0 ? zFromTwoSidedP(l.p) : 40.0, l.freq});
  return out;
}

/// The line confirmed on the whole record's periodogram: its ordinate at the refined frequency f0
/// against the median of the record's Fourier ordinates j / T in the window (those within 2 / T
/// of f0, the line's own main lobe, left out). A continuum's ordinate is S(f) times an Exp(1)
/// variate (chi^2_2 / 2; Priestley 1981 sec. 6.1.3), whose median is ln 2, so
/// x = I(f0) ln 2 / median and P(max over the window > x) <= 2 M e^-x for M ordinates (Bonferroni;
/// the factor 2 for the continuous search between them). Returns the Gaussian-equivalent z.
/// Why: the Welch test's neighbourhood is one-sided in its lowest bins (k - 12 .. k - 3 does not
/// exist there), so a red continuum (a Gauss-Markov or telegraph bias beyond its corner, a walk)
/// stands out against the lower, higher-frequency bins; its "line" then refines to the window's low
/// edge and has no peak in the fine ordinates (S(edge) / S(centre) <= 4 for f^-2 at bin 3). A line
/// concentrates its power in one of the T / L fine ordinates per Welch bin: a line just at the Welch
/// test's limit stands ~T / L times above the fine median.
double fineLineZ(const DetectorContext& ctx, const LinePeriodogram& pg, const LineWindow& w, double f0) {
  const double T = double(ctx.N) * ctx.dt;
  std::vector<double> ords;
  for (double j = std::ceil(w.fa * T); j / T <= w.fb; j += 1)
    if (std::fabs(j / T - f0) > 2 / T) ords.push_back(pg.power(j / T));
  if (ords.size() < 8) return 40.0;  // too few ordinates to judge: the Welch test stands alone
  std::nth_element(ords.begin(), ords.begin() + std::ptrdiff_t(ords.size() / 2), ords.end());
  const double median = ords[ords.size() / 2];
  if (!(median > 0)) return 40.0;
  const double x = pg.power(f0) * std::log(2.0) / median;
  const double lnP = std::log(2.0 * double(ords.size())) - x;
  if (lnP >= 0) return 0.0;
  return lnP < -700 ? 40.0 : std::min(40.0, zFromTwoSidedP(std::exp(lnP)));
}

/// A line below the Welch test's reach (its bins k >= 3, f >= 3 rate / L: on a record of n
/// samples the lowest 3 n / L Fourier frequencies, up to ~730 cycles per record at 1e6 samples):
/// the shared test on the whole record's periodogram (stats/spectral_lines.hpp, lowLineTest).
/// Returns its z and frequency (z 0: none scanned).
WelchLine lowLineZ(const DetectorContext& ctx) {
  const LowLine low = errormodels::lowLineTest(ctx.y, ctx.record.rate_hz, ctx.setup.psdSegment, 3);
  if (low.ordinate == 0) return {};
  return {low.p > 0 ? zFromTwoSidedP(low.p) : 40.0, low.freq};
}

/// A line proposed at f within the Welch test's separation of a line taken out at `taken` [Hz] is
/// another line only where the whole record resolves it: f is more than kResolved Fourier spacings
/// (kResolved / T) from the taken line, and the ordinates j / T within +-2 / T of f (its main lobe
/// and first side lobes: >= 95 % of a line's power) hold at least half of what stands out within
/// the separation of the taken line (ordinates above 10 times their median: 0.1 % of a
/// continuum's, Exp(1) law; each counted above the continuum, median / ln 2). What is left of a line
/// whose frequency wanders lies close to it or is spread: the ADIS16405 stand's 0.564 Hz line,
/// taken out of a whole run's accelerometer, leaves 65-100 of the ~1465 ordinates above that
/// level, the largest peak's +-2 / T holding 19-32 % of them; out of a 1000-s window, 4-9 of 147,
/// the largest within 1.1-3.1 / T of the line (holding 33-59 %). 3 Welch bins are 3 N / L
/// ordinates: two lines 17.7 / T apart on a 75-s record (1.2 Welch bins) were one line before.
/// The ordinates come from one FFT of the record (untapered, its first n ~ N samples), computed
/// once per proposal and only when a line lands that close: N log N, where evaluating each ordinate
/// by demodulation would cost (N / L)^2.
constexpr double kResolved = 5.0;
bool resolvedBeside(const Periodogram& pg, double rate, double taken, double f, double separation) {
  const double T = double(pg.taper.size()) / rate;  // of the n samples transformed
  if (std::fabs(f - taken) <= kResolved / T) return false;
  const auto j0 = std::size_t(std::max(1.0, std::ceil((taken - separation) * T)));
  const auto j1 = std::size_t(std::max(0.0, std::floor((taken + separation) * T)));
  if (j1 >= pg.I.size() || j1 < j0 + 8) return false;
  const double med = median({pg.I.begin() + std::ptrdiff_t(j0), pg.I.begin() + std::ptrdiff_t(j1) + 1});
  if (!(med > 0)) return false;
  const double continuum = med / std::log(2.0);
  double all = 0, own = 0;
  for (std::size_t j = j0; j <= j1; ++j) {
    if (!(pg.I[j] > 10 * med)) continue;
    all += pg.I[j] - continuum;
    if (std::fabs(double(j) / T - f) <= 2 / T) own += pg.I[j] - continuum;
  }
  return all > 0 && own >= 0.5 * all;
}

/// Lines a channel may be found to have: each accepted one is taken out of the record and the next
/// proposed on what is left (a test stand's line and a vibration's, harmonics).
constexpr std::size_t kMaxLines = 8;
/// A later line at a harmonic k = 2..kHarmonics of a line taken, below kHarmonicShare of its
/// amplitude, is that line's distortion.
constexpr int kHarmonics = 50;
constexpr double kHarmonicShare = 0.25;
/// A record's line near one of the model's own lines is another line when it is more than this
/// times the model's amplitude.
constexpr double kModelLineExcess = 2.0;

}  // namespace

std::vector<Candidate> detect_sinusoid(const DetectorContext& ctx) {
  WelchOptions wo;
  wo.segment_length = ctx.setup.psdSegment;
  // The most significant Welch bins, each confirmed on the whole record's periodogram; the line
  // is the one whose smaller z is largest. A red continuum's lowest bins can be the most
  // significant by the Welch test and then fail the confirmation: the real line behind them (a
  // test stand's 0.564 Hz beside a 10x Gauss-Markov in the ADIS16405 injections) must not be lost.
  // Near a line taken out already (within the Welch test's separation of 3 bins) what is left is
  // that line's own width (a test stand's line wanders by tens of 1/T over hours), not another
  // line, unless the whole record resolves it as one (resolvedBeside);
  // so is a much weaker line at one of its harmonics (folded at Nyquist): the distortion of a
  // strong line rounded onto a lattice (odd harmonics at 3-8 % of it) or of a nonlinear source.
  const double separation = 3.0 * ctx.record.rate_hz / double(ctx.setup.psdSegment);
  std::optional<Periodogram> ordinates;  // the whole record's, for resolvedBeside
  auto nearTaken = [&](double f, double amplitude) {
    const double fs = ctx.record.rate_hz;
    for (const Line& t : ctx.linesTaken) {
      // A model's own line explains the record's near it unless that is more than kModelLineExcess
      // times as large (its power 4x): a line the model under-states is proposed, whole, beside it.
      if (t.model && std::fabs(f - t.frequency) <= separation && amplitude > kModelLineExcess * t.amplitude) continue;
      if (std::fabs(f - t.frequency) <= separation) {
        if (!ordinates) ordinates = taperedPeriodogram(ctx.y, 0.0, Detrend::Mean);
        if (!resolvedBeside(*ordinates, fs, t.frequency, f, separation)) return true;
      }
      if (!(amplitude < kHarmonicShare * t.amplitude)) continue;
      for (int k = 2; k <= kHarmonics; ++k) {
        const double h = std::fmod(k * t.frequency, fs), folded = std::min(h, fs - h);
        if (std::fabs(f - folded) <= separation) return true;
      }
    }
    return false;
  };
  double lineZ = 0, f0 = 0;
  for (const auto& line : psdLineTest(welchPsd(ctx.y, ctx.record.rate_hz, wo), 4 + ctx.linesTaken.size())) {
    if (line.z <= lineZ) break;  // sorted: no later one can beat the best confirmed z
    const LineWindow win = welchLineWindow(line.freq, ctx.record.rate_hz / double(ctx.setup.psdSegment), ctx.record.rate_hz);
    const LinePeriodogram pg(ctx.y, ctx.mean, ctx.dt, 0.5 * (win.fa + win.fb), 0.5 * (win.fb - win.fa));
    const double f = refineLineFrequency(pg, win, ctx.N, ctx.setup.psdSegment);
    if (!ctx.linesTaken.empty() && nearTaken(f, std::sqrt(pg.power(f)))) continue;
    const double z = std::min(line.z, fineLineZ(ctx, pg, win, f));
    if (z > lineZ || f0 == 0) lineZ = z, f0 = f;
  }
  // Below the Welch bins: the whole record's periodogram (lowLineZ), refined within one
  // Fourier spacing either side.
  if (const WelchLine low = lowLineZ(ctx); low.z > lineZ) {
    const double T = double(ctx.N) * ctx.dt;
    const LineWindow win{low.freq - 1.0 / T, low.freq + 1.0 / T};
    const LinePeriodogram pg(ctx.y, ctx.mean, ctx.dt, low.freq, 1.0 / T);
    const double f = refineLineFrequency(pg, win, ctx.N, ctx.setup.psdSegment);
    if (ctx.linesTaken.empty() || !nearTaken(f, std::sqrt(pg.power(f)))) lineZ = low.z, f0 = f;
  }
  if (!(f0 > 0)) return {};
  const Units& u = ctx.units;
  const FittedLine fitted = fitLineAt(ctx.y, ctx.mean, ctx.dt, f0);
  const double At = fitted.sampled, A = fitted.amplitude, phase = fitted.phase;
  std::vector<double> sig = lineSamples(fitted, ctx.dt, ctx.N);
  Candidate c;
  c.effect = "sinusoid";
  c.freeSize = false;
  c.parameters = 3;  // amplitude, frequency, phase
  c.maxAccepted = kMaxLines;
  c.line = {f0, At};
  c.g = allanVariance(sig, ctx.setup);
  c.signal = sig;
  c.zSpecial = lineZ;
  c.evidence = "a narrow line in the PSD at " + num(f0, 6) + " Hz (" + num(lineZ, 3) +
               " sigma above its neighbourhood, look-elsewhere corrected)";
  const Dimension signalDim = ctx.signal;
  c.describe = [A, f0, phase, u, signalDim](double, Finding& f) {
    f.size = "A = " + quantity(A, u.level) + " at " + num(f0, 6) + " Hz";
    f.spec = EffectSpec::make("sinusoid",
                              {ParamSpec::quantity("amplitude", stated(A, u.level), signalDim),
                               ParamSpec::quantity("frequency", stated(f0, "Hz", 9), Dimension::frequency()),
                               ParamSpec::quantity("phase", stated(phase, "deg"), Dimension::angle())});
    f.params["amplitude"] = A;
    f.params["frequency"] = f0;
    f.params["phase"] = phase;
  };
  return {c};
}

}  // namespace sinsim::errormodels::diagnose::detail
