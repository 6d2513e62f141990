// The simulate path from Python: Scenario, run, mc and synth, each calling the library functions
// the CLI commands call (cli/cmd_run.cpp, cmd_mc.cpp, cmd_synth.cpp) and returning NumPy arrays.
#include <pybind11/stl.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/error.hpp"
#include "errormodels/model_io.hpp"
#include "common/limits.hpp"
#include "common/read_file.hpp"
#include "python/bindings.hpp"
#include "python/interrupt.hpp"
#include "sim/mc_batch.hpp"
#include "sim/mc_headlines.hpp"
#include "sim/mc_models.hpp"
#include "sim/mc_output.hpp"
#include "sim/montecarlo.hpp"
#include "sim/run.hpp"
#include "sim/synth.hpp"

namespace sinsim::python {
namespace {

namespace fs = std::filesystem;

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The scenario with `model` as its error model, refused like `sinsim run --model` refuses it
// (sim::requireTemperatureFor).
sim::Scenario withModel(sim::Scenario sc, const Model& m) {
  sc.errors = imuModel(m);
  sim::requireTemperatureFor(sc, sc.errors, m.label);
  return sc;
}

// A (rows, 3) array of the vectors get(row).
template <class Get>
py::array_t<double> rows3(std::size_t n, Get get) {
  py::array_t<double> a({static_cast<py::ssize_t>(n), py::ssize_t(3)});
  auto w = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < n; ++i) {
    const nav::Vec3 v = get(i);
    for (int j = 0; j < 3; ++j) w(py::ssize_t(i), j) = v[j];
  }
  return a;
}

py::dict runToDict(const sim::RunSummary& s, const std::vector<sim::NavError>& rows) {
  py::dict d;
  std::vector<double> t, hor, ver;
  for (const auto& e : rows) t.push_back(e.t), hor.push_back(e.horizontal()), ver.push_back(e.vertical());
  d["t"] = array(t);
  d["pos_error_ned"] = rows3(rows.size(), [&](std::size_t i) { return rows[i].pos_n; });
  d["vel_error_ned"] = rows3(rows.size(), [&](std::size_t i) { return rows[i].vel_n; });
  d["att_error_rpy"] = rows3(rows.size(), [&](std::size_t i) { return rows[i].euler; });
  d["horizontal"] = array(hor);
  d["vertical"] = array(ver);
  py::dict sum;
  sum["scenario"] = strOf(s.scenario);
  sum["model"] = strOf(s.model);
  sum["seed"] = s.seed;
  sum["duration"] = s.duration;
  sum["imu_samples"] = s.imuSamples;
  sum["distance"] = s.distance;
  sum["final_horizontal"] = s.final.horizontal();
  sum["final_vertical"] = s.final.vertical();
  sum["max_horizontal"] = s.maxHorizontal;
  sum["max_vertical"] = s.maxVertical;
  sum["rms_horizontal"] = s.rmsHorizontal;
  sum["rms_vertical"] = s.rmsVertical;
  sum["wall_time"] = s.wallTime;
  sum["line"] = strOf(sim::summaryLine(s));
  py::list outages;  // as summary.json's: NaN for a window the filter never ran in
  for (const auto& o : s.outages) {
    py::dict w;
    w["start"] = o.window.start;
    w["end"] = o.window.end;
    w["max_horizontal"] = o.maxHorizontal;
    w["at"] = o.t;
    w["filter_sigma_horizontal"] = o.sigmaHorizontal;
    outages.append(w);
  }
  sum["outages"] = outages;
  sum["warnings"] = strs(s.warnings);
  d["summary"] = sum;
  d["output"] = strOf(s.outDir);
  return d;
}

py::dict run(const py::object& scenario, const py::object& model, const std::optional<py::int_>& seed,
             const py::object& biasWindow, const py::object& output, bool imu) {
  const InputFilesScope inputs;  // the outputs never replace a file the call read (the CLI's rule)
  const InterruptScope interrupt;  // Ctrl-C stops the work (python/interrupt.hpp)
  sim::Scenario sc = toScenario(scenario);
  sim::RunOptions opt;
  if (!model.is_none()) {
    if (py::isinstance<py::str>(model)) opt.model = pathArg(model);  // as --model
    else sc = withModel(sc, toModel(model));
  }
  if (seed) opt.seed = countArg(*seed, "seed");
  opt.biasWindow = quantityArg(biasWindow, Dimension::time(), "bias_window");
  opt.outDir = pathArg(output);
  opt.writeImu = imu;
  std::vector<sim::NavError> rows;
  opt.onRow = [&rows](const sim::NavError& e) { rows.push_back(e); };
  sim::RunSummary s;
  {
    py::gil_scoped_release release;
    s = sim::run(sc, opt);
  }
  // The run's warnings (a filter's start, no fix used, innovations beyond its model) as Python
  // warnings, as `sinsim run` prints them and `fit`'s are.
  const py::object warn = py::module_::import("warnings").attr("warn");
  for (const std::string& w : s.warnings) warn(strOf("run: " + w));
  return runToDict(s, rows);
}

// The batch's models: the scenario's errors (none given), files and "none" as `sinsim mc --model`
// reads them (sim::loadMcModels), Model objects and dicts with their labels.
std::vector<sim::McModel> mcModels(const sim::Scenario& sc, const std::string& identity,
                                   const py::object& models) {
  if (models.is_none()) return sim::loadMcModels({}, sc, identity);
  // One model (a file name, a dict, a Model) is a batch of one: a string was iterated by its
  // characters ("s: cannot open file").
  const bool one = py::isinstance<py::str>(models) || py::isinstance<py::dict>(models) ||
                   py::isinstance<Model>(models) || py::hasattr(models, "__fspath__");
  py::list items;
  if (one) items.append(models);
  else items = py::list(models);
  std::vector<sim::McModel> out;
  for (const auto& item : items) {
    if (py::isinstance<py::str>(item)) {
      out.push_back(sim::loadMcModels({pathArg(item)}, sc, identity).at(0));
    } else {
      const Model m = toModel(item);
      sim::McModel mc = sim::loadMcModels({}, withModel(sc, m), identity).at(0);
      mc.label = m.label;
      mc.identity = "python:" + errormodels::errorModelYaml(m.spec);  // resume fingerprint only
      out.push_back(std::move(mc));
    }
    if (out.back().label.empty())  // an empty label named the batch's files and columns ""
      throw InputError("models: a model's label is empty: give it a name (Model.label)");
    for (std::size_t i = 0; i + 1 < out.size(); ++i)
      if (out[i].label == out.back().label)
        throw InputError("two models of the batch are labelled \"" + out.back().label +
                         "\": give them different Model.label values");
  }
  if (out.empty()) throw InputError("models: give at least one model (or None: the scenario's)");
  return out;
}

// Per model: runs × epochs × fields errors, and the final value of every metric per run.
py::dict mcToDict(const sim::Reference& ref, const sim::McResult& r, std::size_t models,
                  std::uint64_t runs) {
  const std::size_t epochs = ref.epochs();
  std::vector<double> t(epochs);
  for (std::size_t e = 0; e < epochs; ++e) t[e] = ref.epochTime(e);
  py::dict errors, final;
  for (std::size_t m = 0; m < r.labels.size(); ++m) {
    py::array_t<float> a({py::ssize_t(runs), py::ssize_t(epochs), py::ssize_t(sim::kErrorFields)});
    const std::size_t perRun = ref.runFloats(), n = epochs * sim::kErrorFields;
    for (std::uint64_t run = 0; run < runs; ++run)  // the errors of each run (not an aided view)
      std::copy_n(r.errors[m].begin() + long(run * perRun), n, a.mutable_data() + run * n);
    errors[strOf(r.labels[m])] = a;
    py::dict metrics;
    for (int k = 0; k < sim::kMetrics; ++k) {
      std::vector<double> v(runs);
      for (std::uint64_t run = 0; run < runs; ++run)
        v[run] = sim::metricValue(&r.errors[m][run * perRun + (epochs - 1) * sim::kErrorFields], k);
      metrics[sim::metricName(k)] = array(v);
    }
    final[strOf(r.labels[m])] = metrics;
  }
  py::dict head;
  for (const auto& h : sim::mcHeadlines(ref, r, models, {}).models)  // at the last epoch
    head[strOf(h.label)] = py::dict(py::arg("t") = h.t, py::arg("cep") = h.cep,
                                     py::arg("r95") = h.r95);
  py::dict d;
  d["labels"] = strs(r.labels);
  d["t"] = array(t);
  d["fields"] = std::vector<std::string>{"north_m", "east_m", "down_m", "vn_mps", "ve_mps",
                                         "vd_mps", "roll_rad", "pitch_rad", "yaw_rad"};
  d["errors"] = errors;
  d["final"] = final;
  d["headline"] = head;
  d["files"] = strs(r.files);
  d["wall_time"] = r.wallTime;
  return d;
}

// A folder for a batch the caller does not keep (runMonteCarlo writes its checkpoints there).
struct ScratchDir {
  std::string path;
  ScratchDir() {
    std::string tmpl = (fs::temp_directory_path() / "sinsim-mc-XXXXXX").string();
    if (!::mkdtemp(tmpl.data())) throw Error("cannot create a temporary folder in " + tmpl);
    path = tmpl;
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

py::dict mc(const py::object& scenario, const py::object& models, const py::int_& runs,
            const std::optional<py::int_>& seed, const py::int_& threads, const py::object& times,
            const py::object& biasWindow, bool budget, const py::object& outputArg) {
  const InputFilesScope inputs;
  const sim::Scenario sc = toScenario(scenario);
  const std::string identity = py::isinstance<py::str>(scenario)
                                   ? slurp(pathArg(scenario))
                                   : "python:" + sc.name;
  const std::vector<sim::McModel> list = mcModels(sc, identity, models);
  sim::McOptions opt;
  opt.runs = countArg(runs, "runs");
  opt.seed = seed ? countArg(*seed, "seed") : sc.seed.value_or(0);
  opt.threads = static_cast<unsigned>(countArg(threads, "threads", std::numeric_limits<unsigned>::max()));
  limits::requireThreads(opt.threads, "threads");
  if (py::isinstance<py::str>(times)) {  // iterated by its characters: "got \"3\" with no unit"
    const std::string text = times.cast<std::string>();
    if (text.find(',') != std::string::npos)
      throw InputError("times: give a list of times ([\"5 min\", \"10 min\"]), not one string \"" + text + "\"");
    opt.times.push_back(quantityArg(times, Dimension::time(), "times"));
  } else if (!times.is_none()) {
    for (const auto& t : times) opt.times.push_back(quantityArg(t, Dimension::time(), "times"));
  }
  opt.budget = budget;
  opt.navigate.biasWindow = quantityArg(biasWindow, Dimension::time(), "bias_window");
  opt.scenarioIdentity = identity;
  const std::string output = pathArg(outputArg);
  std::optional<ScratchDir> scratch;
  if (output.empty()) scratch.emplace();
  opt.outDir = output.empty() ? scratch->path : output;
  // Ctrl-C in Python stops the batch: the progress callback (calling thread) checks signals.
  std::atomic<bool> interrupted{false};
  opt.interrupt = &interrupted;
  opt.onProgress = [&interrupted](const sim::McProgress&) {
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) interrupted.store(true);
  };
  const sim::Reference ref = [&] {
    py::gil_scoped_release release;
    return sim::buildReference(sc);
  }();
  sim::McResult r;
  {
    py::gil_scoped_release release;
    r = sim::runMonteCarlo(ref, list, opt);
  }
  if (interrupted.load()) throw py::error_already_set();  // the KeyboardInterrupt
  if (!r.complete) throw Error("mc: the batch did not complete");
  py::dict d = mcToDict(ref, r, list.size(), opt.runs);
  d["output"] = strOf(output);
  // About every run (the duration's rounding, an aided filter's start), as `sinsim mc` prints them: a key and Python warnings.
  const std::vector<std::string> warnings = sim::batchWarnings(sc, ref);
  d["warnings"] = warnings;
  const py::object warn = py::module_::import("warnings").attr("warn");
  for (const std::string& w : warnings) warn(strOf("mc: " + w));
  return d;
}

py::dict synth(const py::object& model, double rate, const py::object& duration,
               const py::object& pathObj, const py::int_& seed, const py::int_& run,
               const std::string& temperature, const py::object& latitude, const py::object& height,
               const py::object& attitude) {
  const InputFilesScope inputs;
  const InterruptScope interrupt;
  const errormodels::ImuErrorModel m = imuModel(toModel(model));
  const std::string path = pathArg(pathObj);
  sim::StaticRecordSpec spec;
  spec.rate = rate;
  spec.duration = quantityArg(duration, Dimension::time(), "duration");
  spec.key = {countArg(seed, "seed"), countArg(run, "run")};
  spec.lat = quantityArg(latitude, Dimension::angle(), "latitude");
  spec.h = quantityArg(height, Dimension::length(), "height");
  int i = 0;
  for (const auto& a : attitude) {
    if (i == 3) throw InputError("attitude: expected (roll, pitch, yaw)");
    spec.rpy[i++] = quantityArg(a, Dimension::angle(), "attitude");
  }
  if (i != 3) throw InputError("attitude: expected (roll, pitch, yaw)");
  const sim::TemperatureProfile temp = sim::temperatureFromText(temperature, spec.duration);
  {
    py::gil_scoped_release release;
    sim::writeStaticRecord(m, spec, temp, path);
  }
  // sim/ writes the record only to a file (no in-memory entry point): read back at the edge.
  return recordDict(errormodels::loadRecord(path));
}

}  // namespace

void bindSimulate(py::module_& mod) {
  py::class_<sim::Scenario>(mod, "Scenario", "A scenario (docs/simulate.md), read and validated.")
      .def(py::init([](const py::object& src) { return toScenario(src); }), py::arg("source"))
      .def_readonly("name", &sim::Scenario::name)
      .def_readonly("description", &sim::Scenario::description)
      .def_readonly("file", &sim::Scenario::file)
      .def_readonly("imu_rate", &sim::Scenario::imuRate, "[Hz]")
      .def_readonly("output_rate", &sim::Scenario::outputRate, "[Hz]")
      .def_readonly("seed", &sim::Scenario::seed)
      .def_property_readonly("duration", &sim::Scenario::duration, "[s]")
      .def_property_readonly("segments", [](const sim::Scenario& s) { return s.segments.size(); })
      .def_property_readonly("error_effects",
                             [](const sim::Scenario& s) { return s.errors.effectNames(); })
      .def("__repr__", [](const sim::Scenario& s) {
        const std::string seconds = py::str(py::float_(s.duration()));
        return "<sinsim.Scenario " + s.name + ": " + seconds + " s>";
      });
  mod.def("load_scenario", [](const py::object& src) { return toScenario(src); },
          py::arg("source"), "Scenario(source): a scenario file path or a dict of its layout");
  mod.def("run", &run, py::arg("scenario"), py::arg("model") = py::none(),
          py::arg("seed") = py::none(), py::arg("bias_window") = 0.0, py::arg("output") = py::none(),
          py::arg("imu") = false,
          "sinsim run: one realisation; errors at every output epoch as arrays (SI).");
  mod.def("mc", &mc, py::arg("scenario"), py::arg("models") = py::none(), py::arg("runs") = 100,
          py::arg("seed") = py::none(), py::arg("threads") = 0, py::arg("times") = py::none(),
          py::arg("bias_window") = 0.0, py::arg("budget") = false, py::arg("output") = py::none(),
          "sinsim mc: N realisations per model; per-run errors and final metrics as arrays.");
  mod.def("synth", &synth, py::arg("model"), py::arg("rate"), py::arg("duration"), py::arg("path"),
          py::arg("seed") = 0, py::arg("run") = 0, py::arg("temperature") = "25 degC",
          py::arg("latitude") = "45 deg", py::arg("height") = "0 m",
          py::arg("attitude") = py::make_tuple(0.0, 0.0, 0.0),
          "sinsim synth: writes a static record with the model's errors to path; returns it.");
}

}  // namespace sinsim::python
