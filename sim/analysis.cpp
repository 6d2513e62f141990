#include "sim/analysis.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "common/atomic_file.hpp"
#include "common/constants.hpp"
#include "common/error.hpp"
#include "common/limits.hpp"
#include "common/progress.hpp"
#include "sim/output.hpp"
#include "sim/report/report.hpp"
#include "common/json_text.hpp"

namespace sinsim::sim {
namespace {

using errormodels::AllanCurve;
using json = nlohmann::json;

// 4 significant digits, no exponent from 1e4 up ("10000 s", not "1e+04 s").
std::string formatNumber(double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, std::fabs(v) >= 1e4 && std::fabs(v) < 1e15 ? "%.0f" : "%.4g", v);
  return buf;
}

std::string formatPercent(double p) { return formatNumber(100.0 * p) + " %"; }

ChannelStats channelStats(const std::string& name, const std::vector<double>& y, double rate_hz,
                          const AnalysisOptions& a, const std::string& unit_si) {
  ChannelStats c;
  c.name = name;
  c.unit_si = unit_si;
  double mean = 0;
  for (double v : y) mean += v;
  mean /= static_cast<double>(y.size());
  double var = 0;
  for (double v : y) var += (v - mean) * (v - mean);
  var /= static_cast<double>(y.size());
  c.mean = mean;
  c.sd = std::sqrt(var);
  c.constant = errormodels::isConstantChannel(y);

  // The paper's pipeline denoises before the ACF; the PSD is of the same (possibly denoised)
  // signal. Allan is always of the raw record: denoising would remove the very white noise
  // whose level it measures.
  const std::vector<double>* z = &y;
  if (a.denoise) {
    c.denoised = errormodels::waveletDenoise(y, errormodels::DenoiseOptions{});
    z = &c.denoised->signal;
  }
  const std::size_t n = z->size();
  const double duration = static_cast<double>(n) / rate_hz;
  const double max_lag_s = a.max_lag_s > 0 ? a.max_lag_s : std::min(duration / 10.0, 1000.0);
  const std::size_t max_lag =
      std::min<std::size_t>(n - 1, static_cast<std::size_t>(std::llround(max_lag_s * rate_hz)));
  c.acf = errormodels::autocorrelation(*z, rate_hz, max_lag, errormodels::AcfScaling::Biased);

  errormodels::WelchOptions wo;
  wo.segment_length = a.segment;
  c.psd = errormodels::welchPsd(*z, rate_hz, wo);

  errormodels::AllanOptions ao;
  ao.grid = a.tauPerDecade ? errormodels::TauGrid::PerDecade : errormodels::TauGrid::Octave;
  ao.confidence = a.confidence;
  c.allan = errormodels::allanDeviation(y, rate_hz, errormodels::AllanVariant::Overlapping, ao);
  return c;
}

// The indices kept in a compact JSON: every one below 64, then about 32 per decade (log-spaced),
// and the last — the shape of an ACF or PSD on a log axis, in kilobytes instead of megabytes.
std::vector<std::size_t> compactIndices(std::size_t n, bool full) {
  std::vector<std::size_t> idx;
  for (std::size_t i = 0; i < n; ++i) {
    if (full || i < 64 || i + 1 == n) {
      idx.push_back(i);
      continue;
    }
    const double step = std::pow(10.0, 1.0 / 32.0);
    if (double(i) >= double(idx.back()) * step) idx.push_back(i);
  }
  return idx;
}

std::vector<double> pick(const std::vector<double>& v, const std::vector<std::size_t>& idx) {
  std::vector<double> out;
  out.reserve(idx.size());
  for (std::size_t i : idx) out.push_back(v[i]);
  return out;
}

json channelJson(const ChannelStats& c, bool full) {
  json j;
  j["mean"] = c.mean;
  j["std"] = c.sd;
  if (c.constant) j["constant"] = true;
  if (c.denoised) {
    const errormodels::DenoiseResult& d = *c.denoised;
    j["denoise"] = {{"wavelet", "db5"}, {"boundary", "symmetric"}, {"level", d.level},
                    {"rule", "universal"}, {"mode", "soft"}, {"sigma", d.sigma},
                    {"threshold", d.thresholds.empty() ? 0.0 : d.thresholds[0]}};
  }
  const auto ia = compactIndices(c.acf.lag.size(), full);
  const auto ip = compactIndices(c.psd.f.size(), full);
  const char* sampling = full ? "every value" : "every value below index 64, then ~32 per decade";
  j["acf"] = {{"lag_s", pick(c.acf.lag, ia)}, {"r", pick(c.acf.r, ia)}, {"sampling", sampling},
              {"unit", "(" + c.unit_si + ")^2, biased estimator, mean removed"},
              {"variance", c.acf.variance}};
  const errormodels::PowerSpectrum& p = c.psd;
  j["psd"] = {{"f_hz", pick(p.f, ip)}, {"psd", pick(p.psd, ip)}, {"sampling", sampling}, {"unit", "(" + c.unit_si + ")^2/Hz, one-sided"},
              {"segment_length", p.segment_length}, {"segments", p.segments},
              {"window", "hann"}, {"overlap", 0.5}, {"enbw_hz", p.enbw_hz}};
  const AllanCurve& a = c.allan;
  j["allan"] = {{"kind", "oadev"}, {"unit", c.unit_si}, {"tau_s", a.tau}, {"m", a.m},
                {"adev", a.dev}, {"lo", a.lo}, {"hi", a.hi}, {"edf", a.edf}, {"alpha", a.alpha},
                {"alpha_measured", a.alpha_measured}, {"count", a.count},
                {"confidence", a.confidence}};
  return j;
}

// Plots are in datasheet units (gyro deg/h, accel µg: datasheetUnits); the JSON stays SI.
void addChannelToPage(report::HtmlPage& page, const ChannelStats& c, const AnalysisOptions& a) {
  const DatasheetUnits u = datasheetUnits(c.unit_si == "rad/s");
  const double k = u.level;
  const std::string& unit = u.levelUnit;
  auto scaled = [](const std::vector<double>& v, double f) {
    std::vector<double> out(v);
    for (double& x : out) x *= f;
    return out;
  };

  report::Plot adev("Allan deviation " + c.name, "averaging time τ [s]", "σ(τ) [" + unit + "]");
  adev.xLog = adev.yLog = true;
  adev.add(report::Band{formatPercent(c.allan.confidence) + " confidence", c.allan.tau,
                        scaled(c.allan.lo, k), scaled(c.allan.hi, k), report::paletteColor(0)});
  adev.add(report::Series{"overlapping ADEV", c.allan.tau, scaled(c.allan.dev, k),
                          report::paletteColor(0), false, 1.8, true});
  // The noise terms read off (IEEE Std 952 Annex C) as slope guides across the τ range:
  // N/√τ (−½), the flicker floor 0.664·B (0), K·√(τ/3) (+½).
  const NoiseTerms nt = readNoiseTerms(c.allan);
  std::string readout;
  if (c.allan.size() > 1) {
    // Each guide over the τ where its term can dominate (white below the minimum, the floor
    // around it, the random walk above it), leaving the plot's corners to the legend.
    const double t0 = c.allan.tau.front(), t1 = c.allan.tau.back();
    const double tB = nt.tauB, tN = tB > t0 ? tB : std::min(t1, 10 * t0);
    const double tK = tB < t1 ? tB : std::max(t0, t1 / 10);
    adev.add(report::Series{"N = " + formatNumber(nt.N * u.density) + " " + u.densityUnit + " (−½)",
                            {t0, tN}, {k * nt.N / std::sqrt(t0), k * nt.N / std::sqrt(tN)},
                            report::paletteColor(3), true, 1.2});
    adev.add(report::Series{"B = " + formatNumber(nt.B * k) + " " + unit + " (floor 0.664 B)",
                            {std::max(t0, tB / 10), std::min(t1, tB * 10)},
                            {0.664 * nt.B * k, 0.664 * nt.B * k}, report::paletteColor(4), true, 1.2});
    adev.add(report::Series{"K ≤ " + formatNumber(nt.K * u.walk) + " " + u.walkUnit + " (+½)",
                            {tK, t1}, {k * nt.K * std::sqrt(tK / 3), k * nt.K * std::sqrt(t1 / 3)},
                            report::paletteColor(2), true, 1.2});
    // The range of the measured curve and its bounds: guides extend past it, not the axis.
    double lo = INFINITY, hi = 0;
    for (std::size_t i = 0; i < c.allan.size(); ++i) {
      if (c.allan.lo[i] > 0) lo = std::min(lo, c.allan.lo[i] * k);
      if (std::isfinite(c.allan.hi[i])) hi = std::max(hi, c.allan.hi[i] * k);
      if (c.allan.dev[i] > 0) lo = std::min(lo, c.allan.dev[i] * k), hi = std::max(hi, c.allan.dev[i] * k);
    }
    if (lo > 0 && lo < hi) adev.yRange = std::make_pair(lo / 2.0, hi * 2.0);
    readout = "Read off the Allan deviation: white noise N = " + formatNumber(nt.N * u.density) +
              " " + u.densityUnit + " (" + (u.levelUnit == "deg/h" ? "ARW" : "VRW") +
              "), bias instability B " + (nt.bStillFalling ? "≤ " : "= ") + formatNumber(nt.B * k) + " " + unit +
              " at τ = " + formatNumber(nt.tauB) + (nt.bStillFalling ? " s (the curve still falls there)" : " s") + ", rate random walk K ≤ " + formatNumber(nt.K * u.walk) +
              " " + u.walkUnit + " (at the longest τ, " + formatNumber(t1) + " s).";
  }

  report::Plot psd("PSD " + c.name + (c.denoised ? " (db5-denoised)" : ""), "frequency [Hz]",
                   "[(" + unit + ")²/Hz]");
  psd.xLog = psd.yLog = true;
  psd.add(report::Series{"Welch, Hann, 50 % overlap", c.psd.f, scaled(c.psd.psd, k * k),
                         report::paletteColor(1)});

  // Lags on a log axis: the short correlation times (tens of ms) and the slow ones (minutes)
  // both show.
  report::Plot acf("Autocorrelation " + c.name + (c.denoised ? " (db5-denoised)" : ""),
                   "lag [s]", "normalised");
  acf.xLog = true;
  const double shownLag = a.max_lag_s > 0 ? a.max_lag_s : INFINITY;
  std::vector<double> lag, rho;
  for (std::size_t i = 1; i < c.acf.lag.size() && c.acf.lag[i] <= shownLag; ++i) {
    lag.push_back(c.acf.lag[i]);
    rho.push_back(c.acf.variance > 0 ? c.acf.r[i] / c.acf.variance : NAN);
  }
  acf.add(report::Series{"biased estimator", lag, rho, report::paletteColor(2)});

  page.heading(c.name + "  (mean " + formatNumber(c.mean * k) + " " + unit + ", sd " +
               formatNumber(c.sd * k) + " " + unit + ")");
  if (!readout.empty()) page.paragraph(readout);
  page.plotRow({adev, psd, acf});
}

}  // namespace

void checkAnalysisOptions(const AnalysisOptions& a) {
  // NaN or negative was read as the default before (the Python module).
  if (!(std::isfinite(a.max_lag_s) && a.max_lag_s >= 0 && a.max_lag_s <= limits::kMaxDuration))
    throw InputError("--max-lag: expected a lag from 0 to " + limits::fmt(limits::kMaxDuration) +
                     " s (the largest ACF lag, max lag; 0: the default), got " + limits::fmt(a.max_lag_s));
  if (!(a.confidence > 0 && a.confidence < 1))
    throw InputError("--confidence: expected a level in (0, 1), got " + limits::fmt(a.confidence));
}

std::vector<ChannelStats> analyzeRecord(const errormodels::Record& rec, const AnalysisOptions& a) {
  checkAnalysisOptions(a);
  std::vector<ChannelStats> stats;
  const char* gnames[3] = {"gx", "gy", "gz"};
  const char* anames[3] = {"ax", "ay", "az"};
  // A failure inside the statistics names the file and channel it was computing.
  std::uint64_t channels = 0;
  for (int k = 0; k < 3; ++k) channels += rec.hasGyro(k) + rec.hasAccel(k);
  auto add = [&](const char* name, const std::vector<double>& y, const char* unit) {
    progress::checkpoint(std::string("channel ") + name, stats.size(), channels);
    stats.push_back(withContext(rec.source + ": channel " + name,
                                [&] { return channelStats(name, y, rec.rate_hz, a, unit); }));
  };
  for (int k = 0; k < 3; ++k)
    if (rec.hasGyro(k)) add(gnames[k], rec.gyro[k], "rad/s");
  for (int k = 0; k < 3; ++k)
    if (rec.hasAccel(k)) add(anames[k], rec.accel[k], "m/s^2");
  if (stats.empty())
    throw InputError(rec.source + ": no gx/gy/gz/ax/ay/az column to analyse; " + errormodels::sensorColumnsHint(rec));
  return stats;
}

void writeAnalysis(const errormodels::Record& rec, const std::vector<ChannelStats>& stats,
                   const AnalysisOptions& a, const std::string& jsonPath,
                   const std::string& htmlPath) {
  // Both before either is written (an output file's folder is not created, docs/limits.md).
  requireWritableTargets({jsonPath, htmlPath});
  if (!jsonPath.empty()) {
    json out;
    out["source"] = rec.source;
    out["rate_hz"] = rec.rate_hz;
    out["samples"] = rec.size();
    out["duration_s"] = rec.duration();
    out["irregular_time_steps"] = rec.irregular_count;
    out["record_warnings"] = errormodels::recordWarnings(rec);
    out["units"] = {{"gyro", "rad/s"}, {"accel", "m/s^2"}, {"time", "s"}, {"frequency", "Hz"}};
    json channels = json::object();
    for (const ChannelStats& c : stats) channels[c.name] = channelJson(c, a.fullJson);
    out["channels"] = channels;
    const std::filesystem::path target(jsonPath);
    OutputFiles files(target.has_parent_path() ? target.parent_path().string() : ".");
    std::fputs(jsonText(out, 1).c_str(), files.open(target.filename().string()));
    files.commit();
  }
  if (!htmlPath.empty()) {
    report::HtmlPage page("sinsim analyze: " + rec.source);
    page.paragraph(rec.source + ": " + std::to_string(rec.size()) + " samples at " +
                   formatNumber(rec.rate_hz) + " Hz (" + formatNumber(rec.duration()) +
                   " s). Allan deviation of the raw record with " +
                   formatPercent(a.confidence) +
                   " confidence bounds from Greenhall's equivalent degrees of freedom; PSD and "
                   "autocorrelation of the " + (a.denoise ? "db5-denoised" : "raw") +
                   " record, mean removed.");
    // The reader's warnings (irregular steps, gaps, columns left out) stand on the page too: the
    // JSON had irregular_time_steps, the page nothing.
    for (const std::string& w : errormodels::recordWarnings(rec)) page.paragraph("Record warning: " + w);
    for (const ChannelStats& c : stats) addChannelToPage(page, c, a);
    page.write(htmlPath);
  }
}

}  // namespace sinsim::sim
