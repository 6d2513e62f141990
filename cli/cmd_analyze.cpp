// sinsim analyze DATA [--json OUT] [--html OUT]: per-axis statistics of a measured record (ACF,
// Welch PSD, Allan deviation with confidence bounds) as JSON for scripting and as an HTML report.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/record_options.hpp"
#include "common/error.hpp"
#include "common/units.hpp"
#include "errormodels/stats/allan.hpp"
#include "errormodels/stats/record.hpp"
#include "errormodels/stats/spectrum.hpp"
#include "errormodels/stats/wavelet.hpp"
#include "sim/report/report.hpp"

namespace sinsim::cli {
namespace {

using errormodels::AllanCurve;
using json = nlohmann::json;

std::string formatNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

std::string formatPercent(double p) { return formatNumber(100.0 * p) + " %"; }

// Never leave a half-written file: write beside the target, then rename.
void writeAtomically(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream f(tmp);
    if (!f) throw InputError("cannot write " + path);
    f << text;
    if (!f) throw InputError("cannot write " + path);
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw InputError("cannot write " + path);
  }
}

struct AnalyzeArgs {
  std::string data;
  std::string json_out;
  std::string html_out;
  RecordArgs record;
  double max_lag_s = 0;
  std::size_t segment = 0;
  std::string tau = "octave";
  double confidence = 0.683;
  std::string denoise = "none";
};

// The statistics of one channel, computed once and written as JSON and/or HTML.
struct ChannelStats {
  std::string name;
  std::string unit_si;
  double mean = 0.0, sd = 0.0;
  std::optional<errormodels::DenoiseResult> denoised;
  errormodels::Autocorrelation acf;
  errormodels::PowerSpectrum psd;
  AllanCurve allan;
};

ChannelStats channelStats(const std::string& name, const std::vector<double>& y, double rate_hz,
                          const AnalyzeArgs& a, const std::string& unit_si) {
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

  // The paper's pipeline denoises before the ACF; the PSD is of the same (possibly denoised)
  // signal. Allan is always of the raw record: denoising would remove the very white noise
  // whose level it measures.
  const std::vector<double>* z = &y;
  if (a.denoise == "db5") {
    c.denoised = errormodels::waveletDenoise(y, errormodels::DenoiseOptions{});
    z = &c.denoised->signal;
  }
  const std::size_t n = z->size();
  const double duration = static_cast<double>(n) / rate_hz;
  const double max_lag_s = a.max_lag_s > 0 ? a.max_lag_s : std::min(duration / 10.0, 1000.0);
  const std::size_t max_lag =
      std::min<std::size_t>(n - 1, static_cast<std::size_t>(std::llround(
                                       std::min(max_lag_s, duration) * rate_hz)));
  c.acf = errormodels::autocorrelation(*z, rate_hz, max_lag, errormodels::AcfScaling::Biased);

  errormodels::WelchOptions wo;
  wo.segment_length = a.segment;
  c.psd = errormodels::welchPsd(*z, rate_hz, wo);

  errormodels::AllanOptions ao;
  ao.grid = a.tau == "octave" ? errormodels::TauGrid::Octave : errormodels::TauGrid::PerDecade;
  ao.confidence = a.confidence;
  c.allan = errormodels::allanDeviation(y, rate_hz, errormodels::AllanVariant::Overlapping, ao);
  return c;
}

json channelJson(const ChannelStats& c) {
  json j;
  j["mean"] = c.mean;
  j["std"] = c.sd;
  if (c.denoised) {
    const errormodels::DenoiseResult& d = *c.denoised;
    j["denoise"] = {{"wavelet", "db5"}, {"boundary", "symmetric"}, {"level", d.level},
                    {"rule", "universal"}, {"mode", "soft"}, {"sigma", d.sigma},
                    {"threshold", d.thresholds.empty() ? 0.0 : d.thresholds[0]}};
  }
  j["acf"] = {{"lag_s", c.acf.lag}, {"r", c.acf.r},
              {"unit", "(" + c.unit_si + ")^2, biased estimator, mean removed"},
              {"variance", c.acf.variance}};
  const errormodels::PowerSpectrum& p = c.psd;
  j["psd"] = {{"f_hz", p.f}, {"psd", p.psd}, {"unit", "(" + c.unit_si + ")^2/Hz, one-sided"},
              {"segment_length", p.segment_length}, {"segments", p.segments},
              {"window", "hann"}, {"overlap", 0.5}, {"enbw_hz", p.enbw_hz}};
  const AllanCurve& a = c.allan;
  j["allan"] = {{"kind", "oadev"}, {"unit", c.unit_si}, {"tau_s", a.tau}, {"m", a.m},
                {"adev", a.dev}, {"lo", a.lo}, {"hi", a.hi}, {"edf", a.edf}, {"alpha", a.alpha},
                {"alpha_measured", a.alpha_measured}, {"count", a.count},
                {"confidence", a.confidence}};
  return j;
}

// Plots are in display units (gyro deg/s, accel m/s^2); the JSON stays SI.
void addChannelToPage(report::HtmlPage& page, const ChannelStats& c, const AnalyzeArgs& a) {
  constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;
  const bool gyro = c.unit_si == "rad/s";
  const double k = gyro ? kRadToDeg : 1.0;
  const std::string unit = gyro ? "deg/s" : "m/s^2";
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

  report::Plot psd("PSD " + c.name + (c.denoised ? " (db5-denoised)" : ""), "frequency [Hz]",
                   "[(" + unit + ")²/Hz]");
  psd.xLog = psd.yLog = true;
  psd.add(report::Series{"Welch, Hann, 50 % overlap", c.psd.f, scaled(c.psd.psd, k * k),
                         report::paletteColor(1)});

  report::Plot acf("Autocorrelation " + c.name + (c.denoised ? " (db5-denoised)" : ""),
                   "lag [s]", "normalised");
  // Short lags tell the correlation time (the paper's 20-30 ms); show 1 s unless --max-lag asks.
  const double shownLag = a.max_lag_s > 0 ? a.max_lag_s : 1.0;
  std::vector<double> lag, rho;
  for (std::size_t i = 0; i < c.acf.lag.size() && c.acf.lag[i] <= shownLag; ++i) {
    lag.push_back(c.acf.lag[i]);
    rho.push_back(c.acf.variance > 0 ? c.acf.r[i] / c.acf.variance : NAN);
  }
  acf.add(report::Series{"biased estimator", lag, rho, report::paletteColor(2)});

  page.heading(c.name + "  (mean " + formatNumber(c.mean * k) + " " + unit + ", sd " +
               formatNumber(c.sd * k) + " " + unit + ")");
  page.plotRow({adev, psd, acf});
}

int runAnalyze(const AnalyzeArgs& a) {
  const errormodels::RecordOptions ro = recordOptions(a.record);
  if (a.json_out.empty() && a.html_out.empty())
    throw InputError("analyze: give --json OUT and/or --html OUT");
  if (a.denoise != "none" && a.denoise != "db5")
    throw InputError("--denoise: expected db5 or none, got \"" + a.denoise + "\"");
  if (a.tau != "octave" && a.tau != "decade")
    throw InputError("--tau: expected octave or decade, got \"" + a.tau + "\"");
  const errormodels::Record rec = errormodels::loadRecord(a.data, ro);

  json out;
  out["source"] = a.data;
  out["rate_hz"] = rec.rate_hz;
  out["samples"] = rec.size();
  out["duration_s"] = rec.duration();
  out["irregular_time_steps"] = rec.irregular_count;
  out["units"] = {{"gyro", "rad/s"}, {"accel", "m/s^2"}, {"time", "s"}, {"frequency", "Hz"}};
  std::vector<ChannelStats> stats;
  const char* gnames[3] = {"gx", "gy", "gz"};
  const char* anames[3] = {"ax", "ay", "az"};
  // A failure inside the statistics names the file and channel it was computing.
  auto add = [&](const char* name, const std::vector<double>& y, const char* unit) {
    stats.push_back(withContext(a.data + ": channel " + name,
                                [&] { return channelStats(name, y, rec.rate_hz, a, unit); }));
  };
  for (int k = 0; k < 3; ++k)
    if (rec.hasGyro(k)) add(gnames[k], rec.gyro[k], "rad/s");
  for (int k = 0; k < 3; ++k)
    if (rec.hasAccel(k)) add(anames[k], rec.accel[k], "m/s^2");
  if (stats.empty()) throw InputError(a.data + ": no gx/gy/gz/ax/ay/az column to analyse");

  if (!a.json_out.empty()) {
    json channels = json::object();
    for (const ChannelStats& c : stats) channels[c.name] = channelJson(c);
    out["channels"] = channels;
    writeAtomically(a.json_out, out.dump(1) + "\n");
  }
  if (!a.html_out.empty()) {
    report::HtmlPage page("sinsim analyze: " + a.data);
    page.paragraph(a.data + ": " + std::to_string(rec.size()) + " samples at " +
                   formatNumber(rec.rate_hz) + " Hz (" + formatNumber(rec.duration()) +
                   " s). Allan deviation of the raw record with " +
                   formatPercent(a.confidence) +
                   " confidence bounds from Greenhall's equivalent degrees of freedom; PSD and "
                   "autocorrelation of the " + (a.denoise == "db5" ? "db5-denoised" : "raw") +
                   " record, mean removed.");
    for (const ChannelStats& c : stats) addChannelToPage(page, c, a);
    page.write(a.html_out);
  }
  std::cout << "analyze: " << rec.size() << " samples at " << rec.rate_hz << " Hz, "
            << stats.size() << " channel(s) ->"
            << (a.json_out.empty() ? "" : " " + a.json_out)
            << (a.html_out.empty() ? "" : " " + a.html_out) << "\n";
  return 0;
}

}  // namespace

void addAnalyzeCommand(CLI::App& app, Action& action) {
  auto args = std::make_shared<AnalyzeArgs>();
  CLI::App* cmd = app.add_subcommand(
      "analyze",
      "Per-axis statistics of a measured record (ACF, Welch PSD, Allan with bounds) as JSON/HTML");
  cmd->add_option("DATA", args->data, "record: CSV or CSV.gz with header (t, gx gy gz, ax ay az, temp)")
      ->required();
  cmd->add_option("--json", args->json_out, "output JSON file (SI units)");
  cmd->add_option("--html", args->html_out,
                  "output HTML report: Allan deviation with bounds, PSD and ACF per axis");
  addRecordOptions(cmd, args->record);
  cmd->add_option("--max-lag", args->max_lag_s, "largest ACF lag [s] (default min(duration/10, 1000 s))");
  cmd->add_option("--segment", args->segment, "Welch segment length [samples] (default: power of 2 <= N/8)");
  cmd->add_option("--tau", args->tau, "Allan tau grid: octave | decade (10 per decade)");
  cmd->add_option("--confidence", args->confidence, "two-sided level of the Allan bounds (default 0.683)");
  cmd->add_option("--denoise", args->denoise, "db5 | none: denoise before ACF and PSD (Allan uses raw data)");
  cmd->callback([args, &action] { action = [args] { return runAnalyze(*args); }; });
}

}  // namespace sinsim::cli
