// The navigation-relevant verdict of a diagnosis (diagnose_nav.hpp): the Monte Carlo runs, the
// term shares and their Allan bands, the record's percentile and the warning.
#include "sim/diagnose_nav.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <numeric>
#include <utility>

#include "common/error.hpp"
#include "common/parallel.hpp"
#include "common/progress.hpp"
#include "errormodels/imu_model.hpp"
#include "sim/mc_output.hpp"
#include "sim/mc_stats.hpp"
#include "sim/drift_bands.hpp"
#include "sim/measured.hpp"
#include "sim/nav_loop.hpp"
#include "sim/reference.hpp"

namespace sinsim::sim {
namespace {

namespace dg = errormodels::diagnose;
using errormodels::ImuErrorModel;

// Runs 0..runs-1 of one model along one reference; errors: runs × ref->runFloats().
struct Job {
  const Reference* ref = nullptr;
  ImuErrorModel model;
  std::size_t runs = 0;
  std::vector<float> errors;
};

// Every job's runs on worker threads. Run k of every job uses StreamKey{seed, k}: the jobs'
// comparisons are paired, and the result does not depend on which thread ran which run.
void runJobs(std::vector<Job>& jobs, const NavigateOptions& nav, std::uint64_t seed,
             unsigned threads) {
  std::vector<std::pair<std::size_t, std::size_t>> items;  // (job, run)
  for (std::size_t j = 0; j < jobs.size(); ++j) {
    jobs[j].errors.assign(jobs[j].runs * jobs[j].ref->runFloats(), 0.0f);
    for (std::size_t k = 0; k < jobs[j].runs; ++k) items.emplace_back(j, k);
  }
  std::atomic<std::size_t> done{0};
  parallelFor<int>(items.size(), threads, [&](std::size_t i, int&) {
    Job& job = jobs[items[i].first];
    const std::size_t k = items[i].second;
    const errormodels::StreamKey key{seed, k};
    std::unique_ptr<errormodels::ImuCorruptor> c;
    if (!job.model.empty()) c = job.model.instantiate(job.ref->imuRate, key);
    float* out = job.errors.data() + k * job.ref->runFloats();
    if (!navigateRealisation(*job.ref, c.get(), nav, out, &progress::interruptFlag(), key))
      throw Interrupted();
    progress::checkpoint("navigation verdict: runs", ++done, items.size());
  });
}

double horizontalAt(const Job& job, std::size_t run, std::size_t epoch) {
  return metricValue(job.errors.data() + run * job.ref->runFloats() + epoch * kErrorFields,
                     kHorizontal);
}

std::vector<double> sortedHorizontal(const Job& job, std::size_t epoch) {
  std::vector<double> v(job.runs);
  for (std::size_t k = 0; k < job.runs; ++k) v[k] = horizontalAt(job, k, epoch);
  std::sort(v.begin(), v.end());
  return v;
}

// About ten epochs spread over the run, the last one included.
std::vector<std::size_t> curveEpochs(std::size_t epochs) {
  std::vector<std::size_t> e;
  for (int i = 1; i <= 10; ++i) {
    const auto k = std::size_t(std::llround(double(i) * double(epochs - 1) / 10.0));
    if (k > 0 && (e.empty() || k != e.back())) e.push_back(k);
  }
  return e;
}

DriftCurve driftCurve(const Job& job) {
  DriftCurve c;
  for (std::size_t e : curveEpochs(job.ref->epochs())) {
    const auto v = sortedHorizontal(job, e);
    c.t.push_back(job.ref->epochTime(e));
    c.p50.push_back(mcstats::percentileSorted(v, 50));
    c.p95.push_back(mcstats::percentileSorted(v, 95));
  }
  return c;
}

// ---- term groups: (sensor, effect type) -------------------------------------------------------

// "gyro.x[0].white", "accel.all[1].ar(y)", "gyro.triad[0].scale_factor" -> ("gyro", "white").
std::pair<std::string, std::string> groupOf(const std::string& effectName) {
  std::string s = effectName.substr(0, effectName.find('('));
  return {s.substr(0, s.find('.')), s.substr(s.rfind('.') + 1)};
}

std::vector<std::pair<std::string, std::string>> groupsOf(const ImuErrorModel& m) {
  std::vector<std::pair<std::string, std::string>> g;
  for (const auto& n : m.effectNames())
    if (std::find(g.begin(), g.end(), groupOf(n)) == g.end()) g.push_back(groupOf(n));
  return g;
}

ImuErrorModel groupAlone(const ImuErrorModel& m, const std::pair<std::string, std::string>& g) {
  return m.filtered([&](const std::string& n) { return groupOf(n) == g; });
}

struct Setting {
  MeasuredSetup setup;  // the record and its static scenario
  Reference scenario, rest;
  std::vector<float> record;  // the record's errors along `rest`
  NavigateOptions nav;
};

// One realisation's sensor errors along the static reference (measured − ideal, as rates).
ErrorSignal modelSignal(const ImuErrorModel& m, const Reference& rest,
                        const errormodels::StreamKey& key) {
  const std::size_t n = rest.samples.size();
  ErrorSignal x;
  x.rate = rest.imuRate;
  for (int a = 0; a < 3; ++a) x.gyro[a].resize(n), x.accel[a].resize(n);
  auto c = m.instantiate(rest.imuRate, key);
  for (std::size_t k = 0; k < n; ++k) {
    const ImuSample& ideal = rest.samples[k];
    ImuSample s = ideal;
    c->corrupt(s, rest.temperature.at(s.t - 0.5 * s.dt));
    for (int a = 0; a < 3; ++a) {
      x.gyro[a][k] = (s.dtheta_b[a] - ideal.dtheta_b[a]) / s.dt;
      x.accel[a][k] = (s.dv_b[a] - ideal.dv_b[a]) / s.dt;
    }
  }
  return x;
}

// The record's errors along the same reference: its rates minus the ideal (as RecordSource
// replays it: interval k's increments are row k's rates times dt).
ErrorSignal recordSignal(const errormodels::Record& r, const Reference& rest) {
  const std::size_t n = rest.samples.size();
  ErrorSignal x;
  x.rate = rest.imuRate;
  for (int a = 0; a < 3; ++a) x.gyro[a].resize(n), x.accel[a].resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const ImuSample& ideal = rest.samples[k];
    for (int a = 0; a < 3; ++a) {
      x.gyro[a][k] = r.gyro[a][k] - ideal.dtheta_b[a] / ideal.dt;
      x.accel[a][k] = r.accel[a][k] - ideal.dv_b[a] / ideal.dt;
    }
  }
  return x;
}

DriftKernel restKernel(const Reference& rest, double biasWindow) {
  DriftKernel k;
  k.C_nb = rest.initial.q_nb.toRotationMatrix();
  k.g = sharedEarth().gravity_n(rest.initial.lat, rest.initial.h).z();
  k.schuler = sharedEarth().schulerFrequency(rest.initial.lat);
  k.biasWindow = biasWindow;
  return k;
}

std::string directionOf(double percentile) {
  return percentile >= 100.0 ? "under-predicts" : percentile <= 0.0 ? "over-predicts" : "consistent";
}

/// BandVerdict::excessBand of b (modelRms already as rms; total: the model's summed mean square).
/// A correct model puts a band's drift (2-D, about Rayleigh) beyond 3x its rms with chance
/// ~exp(-9) = 1e-4, so over ~16 bands it is named for ~0.2 % of records.
int excessBand(const std::vector<std::vector<std::array<double, 2>>>& runs, const BandVerdict& b,
               double total) {
  int best = -1;
  for (std::size_t j = 0; j < b.tau.size(); ++j) {
    if (!(b.record[j] >= BandVerdict::kExcessRatio * b.modelRms[j]) ||
        !(b.record[j] * b.record[j] >= 0.25 * total))
      continue;
    const bool beyondAll = std::all_of(runs.begin(), runs.end(), [&](const auto& r) {
      return std::hypot(r[j][0], r[j][1]) < b.record[j];
    });
    if (beyondAll && (best < 0 || b.record[j] > b.record[std::size_t(best)])) best = int(j);
  }
  return best;
}

// The band verdict from the model's band drifts (per run) and the record's.
BandVerdict bandVerdict(const std::vector<std::vector<std::array<double, 2>>>& runs,
                        const std::vector<std::array<double, 2>>& record, std::vector<double> tau) {
  BandVerdict b;
  const std::size_t nb = tau.size();
  b.tau = std::move(tau);
  b.modelRms.assign(nb, 0.0);
  double total = 0.0;
  for (std::size_t j = 0; j < nb; ++j) {
    for (const auto& r : runs) b.modelRms[j] += r[j][0] * r[j][0] + r[j][1] * r[j][1];
    b.modelRms[j] /= double(runs.size());
    total += b.modelRms[j];
    b.record.push_back(std::hypot(record[j][0], record[j][1]));
  }
  for (std::size_t j = 0; j < nb; ++j) b.share.push_back(total > 0 ? b.modelRms[j] / total : 0.0);
  const std::pair<std::size_t, std::size_t> band = drivingBands(b.share);
  const std::size_t lo = band.first, hi = band.second;
  b.from = b.tau[lo];
  b.to = b.tau[hi];
  auto inBand = [&](const std::vector<std::array<double, 2>>& r) {
    double n = 0.0, e = 0.0;
    for (std::size_t j = lo; j <= hi; ++j) n += r[j][0], e += r[j][1];
    return std::hypot(n, e);
  };
  std::vector<double> model;
  for (const auto& r : runs) model.push_back(inBand(r));
  std::sort(model.begin(), model.end());
  for (std::size_t j = lo; j <= hi; ++j) b.shareInBand += b.share[j];
  for (double& m : b.modelRms) m = std::sqrt(m);
  b.modelP50 = mcstats::percentileSorted(model, 50);
  b.modelP95 = mcstats::percentileSorted(model, 95);
  b.recordDrift = inBand(record);
  const auto all = std::accumulate(record.begin(), record.end(), std::array<double, 2>{0.0, 0.0},
                                   [](auto a, const auto& r) { return std::array<double, 2>{a[0] + r[0], a[1] + r[1]}; });
  b.recordLinear = std::hypot(all[0], all[1]);
  b.percentile = mcstats::percentileOf(model, b.recordDrift);
  b.direction = directionOf(b.percentile);
  b.excessBand = excessBand(runs, b, total);
  return b;
}

BandVerdict restBands(const ImuErrorModel& m, const Setting& s, const NavVerdictOptions& o) {
  const DriftKernel kernel = restKernel(s.rest, s.nav.biasWindow);
  std::vector<std::vector<std::array<double, 2>>> runs(o.runs);
  parallelFor<int>(o.runs, o.threads, [&](std::size_t r, int&) {
    runs[r] = driftByBand(modelSignal(m, s.rest, {o.seed, r}), kernel);
    progress::checkpoint("navigation verdict: drift bands", r + 1, o.runs);
  });
  return bandVerdict(runs, driftByBand(recordSignal(s.setup.record, s.rest), kernel),
                     driftBandTaus(s.rest.samples.size(), s.rest.imuRate));
}

// Each group alone along the scenario: mean square of the horizontal error at the end, its share
// and deterministic part (the mean north/east error over the runs, squared, over the mean square).
std::vector<TermShare> termShares(const std::vector<std::pair<std::string, std::string>>& groups,
                                  const std::vector<Job>& jobs, std::size_t first) {
  std::vector<TermShare> terms;
  double sum = 0.0;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const Job& job = jobs[first + g];
    const std::size_t last = job.ref->epochs() - 1;
    double ms = 0.0, mn = 0.0, me = 0.0;
    for (std::size_t k = 0; k < job.runs; ++k) {
      const float* row = job.errors.data() + k * job.ref->runFloats() + last * kErrorFields;
      ms += double(row[kNorth]) * row[kNorth] + double(row[kEast]) * row[kEast];
      mn += row[kNorth];
      me += row[kEast];
    }
    const double r = double(job.runs);
    TermShare t;
    t.sensor = groups[g].first;
    t.effect = groups[g].second;
    t.meanSquare = ms / r;
    t.deterministic = ms > 0 ? std::min(1.0, ((mn / r) * (mn / r) + (me / r) * (me / r)) / (ms / r)) : 0.0;
    sum += t.meanSquare;
    terms.push_back(t);
  }
  for (auto& t : terms) t.share = sum > 0 ? t.meanSquare / sum : 0.0;
  std::stable_sort(terms.begin(), terms.end(),
                   [](const TermShare& a, const TermShare& b) { return a.share > b.share; });
  return terms;
}

// The record's end drift among the replay runs, and the verdict rule: above every run
// (percentile 100) "under-predicts", below every run (0) "over-predicts" — for a correct model
// each happens with probability 1/(runs + 1).
void placeRecord(ModelDrift& d, const Job& replay, const std::vector<float>& record) {
  const std::size_t epochs = replay.ref->epochs();
  auto recordAt = [&](std::size_t e) { return metricValue(record.data() + e * kErrorFields, kHorizontal); };
  d.recordPercentile = mcstats::percentileOf(sortedHorizontal(replay, epochs - 1), recordAt(epochs - 1));
  std::vector<double> over;
  for (std::size_t e = 1; e < epochs; ++e)
    over.push_back(mcstats::percentileOf(sortedHorizontal(replay, e), recordAt(e)));
  std::sort(over.begin(), over.end());
  d.medianPercentile = mcstats::percentileSorted(over, 50);
  d.tail = 100.0 / double(replay.runs + 1);
  d.direction = directionOf(d.recordPercentile);
}

// One model: jobs appended (scenario, replay, then each group alone); finish() reads them back.
struct ModelRuns {
  std::string label;
  ImuErrorModel model;
  std::vector<std::pair<std::string, std::string>> groups;
  std::size_t first = 0;  // index of its scenario job
};

ModelRuns addJobs(const errormodels::ErrorModelSpec& spec, const Setting& s,
                  const NavVerdictOptions& o, std::vector<Job>& jobs) {
  ModelRuns m;
  m.label = spec.source.empty() ? "model" : spec.source;
  m.model = ImuErrorModel::fromSpec(spec, m.label);
  if (m.model.needsTemperature())
    throw InputError(m.label + ": the navigation verdict cannot run a model with temperature "
                     "effects (the record's static replay has no temperature profile)");
  m.groups = groupsOf(m.model);
  m.first = jobs.size();
  jobs.push_back({&s.scenario, m.model, o.runs, {}});
  jobs.push_back({&s.rest, m.model, o.runs, {}});
  for (const auto& g : m.groups) jobs.push_back({&s.scenario, groupAlone(m.model, g), o.termRuns, {}});
  return m;
}

ModelDrift finish(const ModelRuns& m, const std::vector<Job>& jobs, const Setting& s,
                  const NavVerdictOptions& o) {
  ModelDrift r;
  r.label = m.label;
  r.scenario = driftCurve(jobs[m.first]);
  r.replay = driftCurve(jobs[m.first + 1]);
  placeRecord(r, jobs[m.first + 1], s.record);
  r.terms = termShares(m.groups, jobs, m.first + 2);
  r.bands = restBands(m.model, s, o);
  return r;
}

}  // namespace

NavVerdict navigationVerdict(const errormodels::Record& record,
                             const errormodels::ErrorModelSpec& model,
                             const errormodels::ErrorModelSpec* improved, const Scenario& scenario,
                             const NavVerdictOptions& o) {
  if (o.runs < 8 || o.termRuns < 4)
    throw InputError("the navigation verdict needs at least 8 runs (4 per term)");
  if (!scenario.aiding.inert())
    throw InputError("navigation verdict: the scenario " + scenario.name + " has aiding keys "
                     "(initial_errors, alignment, gnss, filter); the verdict is free-inertial, as "
                     "the record's replay (mc --measured): give a scenario without them");
  Setting s;
  s.scenario = buildReference(scenario);
  // The record at rest where the scenario starts, for as long as the scenario lasts (at most). With
  // the bias window the assumed place and heading only change a constant, which the window removes.
  MeasuredOptions mo;
  mo.lat = scenario.start.lat;
  mo.lon = scenario.start.lon;
  mo.h = scenario.start.h;
  mo.duration = scenario.duration();
  mo.biasWindow = o.biasWindow;
  mo.biasWindowOption = "--nav-bias-window";
  s.setup = measuredSetup(record, mo);
  s.rest = buildReference(s.setup.scenario);
  s.nav.biasWindow = s.setup.biasWindow;
  s.record = navigateMeasured(s.setup, s.rest, s.nav).errors;

  std::vector<Job> jobs;
  const ModelRuns m0 = addJobs(model, s, o, jobs);
  std::optional<ModelRuns> m1;
  if (improved) m1 = addJobs(*improved, s, o, jobs);
  runJobs(jobs, s.nav, o.seed, o.threads);

  NavVerdict v;
  v.scenario = scenario.name;
  v.duration = s.scenario.epochTime(s.scenario.epochs() - 1);
  v.replayDuration = s.rest.epochTime(s.rest.epochs() - 1);
  v.biasWindow = s.nav.biasWindow;
  v.runs = o.runs;
  v.termRuns = o.termRuns;
  v.seed = o.seed;
  v.warnRatio = o.warnRatio;
  for (std::size_t e : curveEpochs(s.rest.epochs())) {
    v.record.t.push_back(s.rest.epochTime(e));
    const double h = metricValue(s.record.data() + e * kErrorFields, kHorizontal);
    v.record.p50.push_back(h);
    v.record.p95.push_back(h);
  }
  v.model = finish(m0, jobs, s, o);
  if (m1) {
    v.improved = finish(*m1, jobs, s, o);
    const double a = v.model.scenario.endP50();
    v.ratio = a > 0 ? v.improved->scenario.endP50() / a : 1.0;
    v.warning = navWarningText(v);
  }
  return v;
}

}  // namespace sinsim::sim
