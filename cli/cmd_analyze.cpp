// sinsim analyze DATA --json OUT: per-axis statistics of a measured record (ACF, Welch PSD,
// Allan deviation with confidence bounds) as JSON for plotting and scripting.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "common/error.hpp"
#include "common/units.hpp"
#include "errormodels/stats/allan.hpp"
#include "errormodels/stats/record.hpp"
#include "errormodels/stats/spectrum.hpp"
#include "errormodels/stats/wavelet.hpp"

namespace sinsim::cli {
namespace {

using errormodels::AllanCurve;
using json = nlohmann::json;

struct AnalyzeArgs {
  std::string data;
  std::string json_out;
  std::string gyro_unit;
  std::string accel_unit;
  double rate_hz = 0;
  bool allow_irregular = false;
  double max_lag_s = 0;
  std::size_t segment = 0;
  std::string tau = "octave";
  double confidence = 0.683;
  std::string denoise = "none";
};

json channelJson(const std::vector<double>& y, double rate_hz, const AnalyzeArgs& a,
                 const std::string& unit_si) {
  json j;
  double mean = 0;
  for (double v : y) mean += v;
  mean /= static_cast<double>(y.size());
  double var = 0;
  for (double v : y) var += (v - mean) * (v - mean);
  var /= static_cast<double>(y.size());
  j["mean"] = mean;
  j["std"] = std::sqrt(var);

  // The paper's pipeline denoises before the ACF; the PSD is of the same (possibly denoised)
  // signal. Allan is always of the raw record: denoising would remove the very white noise
  // whose level it measures.
  std::vector<double> z = y;
  if (a.denoise == "db5") {
    errormodels::DenoiseOptions opt;
    const errormodels::DenoiseResult d = errormodels::waveletDenoise(y, opt);
    z = d.signal;
    j["denoise"] = {{"wavelet", "db5"}, {"boundary", "symmetric"}, {"level", d.level},
                    {"rule", "universal"}, {"mode", "soft"}, {"sigma", d.sigma},
                    {"threshold", d.thresholds.empty() ? 0.0 : d.thresholds[0]}};
  }
  const std::size_t n = z.size();
  const double duration = static_cast<double>(n) / rate_hz;
  const double max_lag_s = a.max_lag_s > 0 ? a.max_lag_s : std::min(duration / 10.0, 1000.0);
  const std::size_t max_lag =
      std::min<std::size_t>(n - 1, static_cast<std::size_t>(std::llround(max_lag_s * rate_hz)));
  const errormodels::Autocorrelation acf = errormodels::autocorrelation(
      z, rate_hz, max_lag, errormodels::AcfScaling::Biased);
  json ja;
  ja["lag_s"] = acf.lag;
  ja["r"] = acf.r;
  ja["unit"] = "(" + unit_si + ")^2, biased estimator, mean removed";
  ja["variance"] = acf.variance;
  j["acf"] = ja;

  errormodels::WelchOptions wo;
  wo.segment_length = a.segment;
  const errormodels::PowerSpectrum p = errormodels::welchPsd(z, rate_hz, wo);
  j["psd"] = {{"f_hz", p.f}, {"psd", p.psd}, {"unit", "(" + unit_si + ")^2/Hz, one-sided"},
              {"segment_length", p.segment_length}, {"segments", p.segments},
              {"window", "hann"}, {"overlap", 0.5}, {"enbw_hz", p.enbw_hz}};

  errormodels::AllanOptions ao;
  ao.grid = a.tau == "octave" ? errormodels::TauGrid::Octave : errormodels::TauGrid::PerDecade;
  ao.confidence = a.confidence;
  const AllanCurve c = errormodels::allanDeviation(y, rate_hz, errormodels::AllanVariant::Overlapping, ao);
  j["allan"] = {{"kind", "oadev"}, {"unit", unit_si}, {"tau_s", c.tau}, {"m", c.m}, {"adev", c.dev},
                {"lo", c.lo}, {"hi", c.hi}, {"edf", c.edf}, {"alpha", c.alpha},
                {"alpha_measured", c.alpha_measured}, {"count", c.count},
                {"confidence", c.confidence}};
  return j;
}

int runAnalyze(const AnalyzeArgs& a) {
  errormodels::RecordOptions ro;
  if (!a.gyro_unit.empty()) ro.gyro_unit = a.gyro_unit;
  if (!a.accel_unit.empty()) ro.accel_unit = a.accel_unit;
  if (a.rate_hz > 0) ro.rate_hz = a.rate_hz;
  ro.allow_irregular_time = a.allow_irregular;
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
  json channels = json::object();
  const char* gnames[3] = {"gx", "gy", "gz"};
  const char* anames[3] = {"ax", "ay", "az"};
  for (int k = 0; k < 3; ++k) {
    if (rec.hasGyro(k)) channels[gnames[k]] = channelJson(rec.gyro[k], rec.rate_hz, a, "rad/s");
    if (rec.hasAccel(k)) channels[anames[k]] = channelJson(rec.accel[k], rec.rate_hz, a, "m/s^2");
  }
  if (channels.empty()) throw InputError(a.data + ": no gx/gy/gz/ax/ay/az column to analyse");
  out["channels"] = channels;

  // Never leave a half-written file: write beside the target, then rename.
  const std::string tmp = a.json_out + ".tmp";
  {
    std::ofstream f(tmp);
    if (!f) throw InputError("cannot write " + a.json_out);
    f << out.dump(1) << "\n";
    if (!f) throw InputError("cannot write " + a.json_out);
  }
  std::error_code ec;
  std::filesystem::rename(tmp, a.json_out, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw InputError("cannot write " + a.json_out);
  }
  std::cout << "analyze: " << rec.size() << " samples at " << rec.rate_hz << " Hz, "
            << channels.size() << " channel(s) -> " << a.json_out << "\n";
  return 0;
}

}  // namespace

void addAnalyzeCommand(CLI::App& app, Action& action) {
  auto args = std::make_shared<AnalyzeArgs>();
  CLI::App* cmd = app.add_subcommand(
      "analyze", "Per-axis statistics of a measured record (ACF, Welch PSD, Allan with bounds) as JSON");
  cmd->add_option("DATA", args->data, "record: CSV or CSV.gz with header (t, gx gy gz, ax ay az, temp)")
      ->required();
  cmd->add_option("--json", args->json_out, "output JSON file")->required();
  cmd->add_option("--gyro-unit", args->gyro_unit, "unit of gx/gy/gz, e.g. deg/s (default: header or rad/s)");
  cmd->add_option("--accel-unit", args->accel_unit, "unit of ax/ay/az, e.g. g (default: header or m/s^2)");
  cmd->add_option("--rate", args->rate_hz, "sample rate [Hz] (required without a t column)");
  cmd->add_flag("--allow-irregular-time", args->allow_irregular,
                "accept irregular/gapped time stamps (reported, never resampled)");
  cmd->add_option("--max-lag", args->max_lag_s, "largest ACF lag [s] (default min(duration/10, 1000 s))");
  cmd->add_option("--segment", args->segment, "Welch segment length [samples] (default: power of 2 <= N/8)");
  cmd->add_option("--tau", args->tau, "Allan tau grid: octave | decade (10 per decade)");
  cmd->add_option("--confidence", args->confidence, "two-sided level of the Allan bounds (default 0.683)");
  cmd->add_option("--denoise", args->denoise, "db5 | none: denoise before ACF and PSD (Allan uses raw data)");
  cmd->callback([args, &action] { action = [args] { return runAnalyze(*args); }; });
}

}  // namespace sinsim::cli
