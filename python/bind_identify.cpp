// The identify path from Python: load_record, analyze, fit and diagnose, each calling the library
// functions the CLI commands call (cli/cmd_analyze.cpp, cmd_fit.cpp, cmd_diagnose.cpp).
#include <pybind11/stl.h>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "errormodels/diagnose/diagnose.hpp"
#include "errormodels/identify.hpp"
#include "errormodels/model_io.hpp"
#include "common/limits.hpp"
#include "common/read_file.hpp"
#include "python/bindings.hpp"
#include "python/interrupt.hpp"
#include "sim/analysis.hpp"

namespace sinsim::python {
namespace {

namespace em = errormodels;

// The loader's options as `--gyro-unit`, `--accel-unit`, `--rate`, `--allow-irregular-time`.
em::RecordOptions recordOptions(const std::optional<std::string>& gyroUnit,
                                const std::optional<std::string>& accelUnit,
                                const py::object& rate, bool allowIrregular) {
  em::RecordOptions o;
  o.gyro_unit = gyroUnit;
  o.accel_unit = accelUnit;
  if (!rate.is_none()) {  // a number [Hz] or a string with its unit ("100 Hz"), as --rate
    const double hz = quantityArg(rate, Dimension::frequency(), "rate");
    if (!(std::isfinite(hz) && hz > 0)) throw InputError("rate: expected a positive sample rate in Hz");
    o.rate_hz = hz;
  }
  o.allow_irregular_time = allowIrregular;
  return o;
}

// Python warnings "<command>: <text>", as the CLI prints them on stderr.
void warnAll(const std::string& command, const std::vector<std::string>& warnings) {
  if (warnings.empty()) return;
  const py::object warn = py::module_::import("warnings").attr("warn");
  for (const std::string& w : warnings) warn(strOf(command + ": " + w));
}

py::dict channelDict(const sim::ChannelStats& c) {
  py::dict d;
  d["unit"] = c.unit_si;
  d["mean"] = c.mean;
  d["sd"] = c.sd;
  d["constant"] = c.constant;  // every sample the same value: a dead sensor
  d["acf"] = py::dict(py::arg("lag") = array(c.acf.lag), py::arg("r") = array(c.acf.r));
  d["psd"] = py::dict(py::arg("f") = array(c.psd.f), py::arg("psd") = array(c.psd.psd));
  d["allan"] = py::dict(py::arg("tau") = array(c.allan.tau), py::arg("adev") = array(c.allan.dev),
                        py::arg("lo") = array(c.allan.lo), py::arg("hi") = array(c.allan.hi));
  return d;
}

py::dict analyze(const py::object& record, double maxLag, const py::int_& segment,
                 const std::string& tau, double confidence, bool denoise, const py::object& jsonArg,
                 const py::object& htmlArg, const std::optional<std::string>& gyroUnit,
                 const std::optional<std::string>& accelUnit, const py::object& rate) {
  const InputFilesScope inputs;  // the outputs never replace the record (the CLI's rule)
  const InterruptScope interrupt;  // Ctrl-C stops the work (python/interrupt.hpp)
  if (tau != "octave" && tau != "decade")
    throw InputError("tau: expected octave or decade, got \"" + tau + "\"");
  sim::AnalysisOptions opt;
  opt.max_lag_s = maxLag;
  opt.segment = countArg(segment, "segment");
  opt.tauPerDecade = tau == "decade";
  opt.confidence = confidence;
  opt.denoise = denoise;
  const std::string json = pathArg(jsonArg), html = pathArg(htmlArg);
  requireWritableTargets({json, html});  // before the work, as `sinsim analyze`
  const em::Record rec = toRecord(record, recordOptions(gyroUnit, accelUnit, rate, false));
  std::vector<sim::ChannelStats> stats;
  {
    py::gil_scoped_release release;
    stats = sim::analyzeRecord(rec, opt);
    if (!json.empty() || !html.empty()) sim::writeAnalysis(rec, stats, opt, json, html);
  }
  // As `sinsim analyze` warns (a constant channel, a forgotten unit, ms stamps read as seconds):
  // none was raised.
  warnAll("analyze", sim::analysisWarnings(stats));
  warnAll("analyze", em::recordWarnings(rec));
  py::dict d;
  for (const auto& c : stats) d[c.name.c_str()] = channelDict(c);
  return d;
}

Model fit(const py::object& record, const std::string& kind, const std::vector<std::string>& axes,
          const std::optional<py::int_>& orderArg, const std::string& criterion, const py::int_& maxOrderArg,
          bool denoise, const py::object& skip, const std::optional<std::string>& gyroUnit,
          const std::optional<std::string>& accelUnit, const py::object& rate, const std::string& lines) {
  const InputFilesScope inputs;
  const InterruptScope interrupt;
  em::IdentifyOptions opt;
  opt.kind = em::identifyKindByName(kind);
  opt.fitLines = em::fitLinesByName(lines);
  const std::optional<std::size_t> order =
      orderArg ? std::optional<std::size_t>(countArg(*orderArg, "order")) : std::nullopt;
  if (order && *order < 1) throw InputError("order: expected a positive integer or None (auto)");
  const std::size_t maxOrder = countArg(maxOrderArg, "max_order");
  opt.order = order;
  opt.maxOrder = std::max(maxOrder, order.value_or(0));
  opt.criterion = em::orderCriterionByName(criterion);
  opt.denoise = denoise ? em::DenoiseChoice::Db5 : em::DenoiseChoice::None;
  opt.axes = axes;
  if (py::isinstance<py::str>(skip) && skip.cast<std::string>() == "auto")
    opt.skipAuto = true;  // as `fit --skip auto`
  else
    opt.skipStart = quantityArg(skip, Dimension::time(), "skip");
  const em::Record rec = toRecord(record, recordOptions(gyroUnit, accelUnit, rate, false));
  std::optional<em::Identification> id;
  {
    py::gil_scoped_release release;
    id = em::identify(rec, opt);
  }
  warnAll("fit", id->warnings);
  return {id->modelSpec(), "fit"};
}

py::dict findingDict(const em::diagnose::Finding& f, const std::string& channel) {
  py::dict d;
  d["effect"] = f.effect;
  d["evidence"] = f.evidence;
  d["size"] = f.size;
  d["yaml"] = em::diagnose::effectText(f.spec, channel);
  d["params"] = f.params;
  d["score"] = f.score;
  d["drop"] = f.drop;
  d["reported"] = f.reported;
  return d;
}

py::dict diagnose(const py::object& record, const py::object& model,
                  const std::vector<std::string>& channels, const py::int_& realisations,
                  const py::int_& seed, const py::int_& threads, double threshold, double nextThreshold,
                  const std::optional<std::string>& gyroUnit,
                  const std::optional<std::string>& accelUnit, const py::object& rate) {
  const InputFilesScope inputs;
  const InterruptScope interrupt;
  namespace dg = em::diagnose;
  const em::Record rec = toRecord(record, recordOptions(gyroUnit, accelUnit, rate, false));
  const Model m = toModel(model);  // a path is read as `--model` reads it (loadErrorModel)
  warnAll("diagnose", em::recordWarnings(rec));
  dg::DiagnoseOptions o;
  o.channels = channels;
  o.realisations = countArg(realisations, "realisations");
  o.seed = countArg(seed, "seed");
  o.threads = static_cast<unsigned>(countArg(threads, "threads", std::numeric_limits<unsigned>::max()));
  limits::requireThreads(o.threads, "threads");
  o.threshold = threshold;
  o.nextThreshold = nextThreshold;
  std::optional<dg::Diagnosis> d;
  {
    py::gil_scoped_release release;
    d = withContext(rec.source, [&] { return dg::diagnose(rec, m.spec, o); });
  }
  py::dict out;
  for (const auto& a : d->axes) {
    py::list findings, fails;
    for (const auto& f : a.findings) findings.append(findingDict(f, a.channel));
    for (const auto& f : a.fails)
      fails.append(py::dict(py::arg("statistic") = f.statistic, py::arg("from") = f.from,
                            py::arg("to") = f.to, py::arg("direction") = f.direction,
                            py::arg("worst_ratio") = f.worstRatio));
    py::dict ax;
    ax["fits"] = a.fits();
    ax["misfit"] = a.misfit;
    ax["chi2"] = a.chi2;
    ax["fraction_outside"] = a.fractionOutside;
    ax["findings"] = findings;
    ax["fails"] = fails;
    ax["unexplained"] = dg::unexplainedSentences(a);  // as the CLI's "gx unexplained: ..." lines
    ax["adev"] = py::dict(py::arg("tau") = array(a.adev.x), py::arg("meas") = array(a.adev.meas),
                          py::arg("model") = array(a.adev.model), py::arg("lo") = array(a.adev.lo),
                          py::arg("hi") = array(a.adev.hi));
    out[a.channel.c_str()] = ax;
  }
  return out;
}

}  // namespace

void bindIdentify(py::module_& mod) {
  mod.def(
      "load_record",
      [](const py::object& path, const std::optional<std::string>& gyroUnit,
         const std::optional<std::string>& accelUnit, const py::object& rate,
         bool allowIrregular) {
        return recordDict(em::loadRecord(pathArg(path), recordOptions(gyroUnit, accelUnit, rate, allowIrregular)));
      },
      py::arg("path"), py::arg("gyro_unit") = py::none(), py::arg("accel_unit") = py::none(),
      py::arg("rate") = py::none(), py::arg("allow_irregular_time") = false,
      "reads a record (CSV, .gz) into a dict of SI arrays: rate, t, gx..az, temp");
  mod.def("analyze", &analyze, py::arg("record"), py::arg("max_lag") = 0.0, py::arg("segment") = 0,
          py::arg("tau") = "octave", py::arg("confidence") = 0.683, py::arg("denoise") = false,
          py::arg("json") = py::none(), py::arg("html") = py::none(), py::arg("gyro_unit") = py::none(),
          py::arg("accel_unit") = py::none(), py::arg("rate") = py::none(),
          "sinsim analyze: per channel mean, sd, ACF, Welch PSD, Allan deviation with bounds (SI)");
  mod.def("fit", &fit, py::arg("record"), py::arg("kind") = "auto",
          py::arg("axes") = std::vector<std::string>{}, py::arg("order") = py::none(),
          py::arg("criterion") = "mdl", py::arg("max_order") = 20, py::arg("denoise") = false,
          py::arg("skip") = 0.0, py::arg("gyro_unit") = py::none(),
          py::arg("accel_unit") = py::none(), py::arg("rate") = py::none(), py::arg("lines") = "fit",
          "sinsim fit: identifies an error model from a static record; returns a Model");
  mod.def("diagnose", &diagnose, py::arg("record"), py::arg("model"),
          py::arg("channels") = std::vector<std::string>{}, py::arg("realisations") = 32,
          py::arg("seed") = em::diagnose::DiagnoseOptions{}.seed, py::arg("threads") = 0,
          py::arg("threshold") = em::diagnose::DiagnoseOptions{}.threshold,
          py::arg("next_threshold") = em::diagnose::DiagnoseOptions{}.nextThreshold,
          py::arg("gyro_unit") = py::none(), py::arg("accel_unit") = py::none(),
          py::arg("rate") = py::none(),
          "sinsim diagnose: compares a model with a record; findings per channel");
}

}  // namespace sinsim::python
