#include "sim/mc_output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "common/error.hpp"
#include "sim/aided/aided_output.hpp"
#include "sim/mc_aided_output.hpp"
#include "sim/mc_per_run.hpp"
#include "sim/mc_stats.hpp"
#include "sim/output.hpp"
#include "common/json_text.hpp"

namespace sinsim::sim {

const char* metricName(int metric) {
  static const char* names[kMetrics] = {"horizontal_m", "vertical_m",     "velocity_mps",
                                        "roll_abs_rad", "pitch_abs_rad", "yaw_abs_rad"};
  return names[metric];
}

double metricValue(const float* row, int metric) {
  switch (metric) {
    case kHorizontal: return std::hypot(double(row[kNorth]), double(row[kEast]));
    case kVertical: return std::abs(double(row[kDown]));
    case kVelocity: {
      const double a = row[kVn], b = row[kVe], c = row[kVd];
      return std::sqrt(a * a + b * b + c * c);
    }
    case kRollAbs: return std::abs(double(row[kRoll]));
    case kPitchAbs: return std::abs(double(row[kPitch]));
    case kYawAbs: return std::abs(double(row[kYaw]));
  }
  return NAN;
}

std::vector<double> metricAcrossRuns(const McBatch& batch, std::size_t entry, std::size_t epoch,
                                     int metric) {
  const std::size_t perRun = batch.ref.runFloats();
  std::vector<double> v(batch.runs);
  const float* base = batch.errors[entry].data() + epoch * kErrorFields;
  for (std::uint64_t k = 0; k < batch.runs; ++k) v[k] = metricValue(base + k * perRun, metric);
  return v;
}

McStats computeMcStats(const McBatch& batch) {
  McStats s;
  s.epochs = batch.ref.epochs();
  const std::size_t perRun = s.epochs * kErrorFields;
  const auto& pct = mcPercentiles();
  s.metric.resize(batch.entries.size());
  s.fieldMean.resize(batch.entries.size());
  s.fieldSd.resize(batch.entries.size());
  std::vector<double> v(batch.runs);
  for (std::size_t m = 0; m < batch.entries.size(); ++m) {
    s.metric[m].resize(s.epochs * kMetrics);
    s.fieldMean[m].resize(perRun);
    s.fieldSd[m].resize(perRun);
    for (std::size_t e = 0; e < s.epochs; ++e) {
      for (int q = 0; q < kMetrics; ++q) {
        v = metricAcrossRuns(batch, m, e, q);
        const mcstats::Moments mo = mcstats::moments(v);
        MetricStats& ms = s.metric[m][e * kMetrics + q];
        ms.mean = mo.mean;
        ms.sd = mo.sd;
        ms.rms = mo.rms;
        std::sort(v.begin(), v.end());
        for (std::size_t i = 0; i < pct.size(); ++i) ms.p[i] = mcstats::percentileSorted(v, pct[i]);
      }
      for (int f = 0; f < kErrorFields; ++f) {
        const float* base = batch.errors[m].data() + e * kErrorFields + f;
        for (std::uint64_t k = 0; k < batch.runs; ++k) v[k] = base[k * batch.ref.runFloats()];
        const mcstats::Moments mo = mcstats::moments(v);
        s.fieldMean[m][e * kErrorFields + f] = mo.mean;
        s.fieldSd[m][e * kErrorFields + f] = mo.sd;
      }
    }
  }
  return s;
}

namespace {

const char* kFieldNames[kErrorFields] = {"north_m", "east_m",   "down_m",    "vn_mps",  "ve_mps",
                                         "vd_mps",  "roll_rad", "pitch_rad", "yaw_rad"};

nlohmann::json metricJson(const MetricStats& m) {
  nlohmann::json j{{"mean", m.mean}, {"sd", m.sd}, {"rms", m.rms}};
  const auto& pct = mcPercentiles();
  for (std::size_t i = 0; i < pct.size(); ++i) j["p" + std::to_string(int(pct[i]))] = m.p[i];
  return j;
}

}  // namespace

void writeMcOutputs(const McBatch& batch, const std::string& outDir,
                    std::vector<std::string>& files) {
  const Reference& ref = batch.ref;
  const McStats st = computeMcStats(batch);
  const auto& pct = mcPercentiles();
  OutputFiles out(outDir);

  // ---- stats.csv -----------------------------------------------------------------------------------
  {
    std::FILE* f = out.open("stats.csv");
    std::fputs("model,t_s", f);
    for (int q = 0; q < kMetrics; ++q) {
      const std::string n = metricName(q);
      std::fprintf(f, ",%s_mean,%s_sd,%s_rms", n.c_str(), n.c_str(), n.c_str());
      for (double p : pct) std::fprintf(f, ",%s_p%d", n.c_str(), int(p));
    }
    for (int fl = 0; fl < kErrorFields; ++fl)
      std::fprintf(f, ",%s_mean,%s_sd", kFieldNames[fl], kFieldNames[fl]);
    std::fputs("\n", f);
    for (std::size_t m = 0; m < batch.entries.size(); ++m) {
      const std::string label = csvField(batch.entries[m].label);
      for (std::size_t e = 0; e < st.epochs; ++e) {
        std::fprintf(f, "%s,%.6f", label.c_str(), ref.epochTime(e));
        for (int q = 0; q < kMetrics; ++q) {
          const MetricStats& ms = st.at(m, e, q);
          std::fprintf(f, ",%.9g", ms.mean);
          aided::writeCsvNumber(f, "%.9g", ms.sd);  // empty for one run: no sample sd
          std::fprintf(f, ",%.9g", ms.rms);
          for (std::size_t i = 0; i < pct.size(); ++i) std::fprintf(f, ",%.9g", ms.p[i]);
        }
        for (int fl = 0; fl < kErrorFields; ++fl)
        {
          std::fprintf(f, ",%.9g", st.fieldMean[m][e * kErrorFields + fl]);
          aided::writeCsvNumber(f, "%.9g", st.fieldSd[m][e * kErrorFields + fl]);
        }
        std::fputs("\n", f);
      }
    }
    files.push_back("stats.csv");
  }
  writePerRunCsv(batch, out.open("per_run.csv"));
  files.push_back("per_run.csv");

  // ---- summary.json ------------------------------------------------------------------------------
  nlohmann::json j;
  j["scenario"] = ref.name;
  j["runs_per_model"] = batch.runs;
  j["seed"] = batch.seed;
  j["streams"] = "run k of every model uses StreamKey{seed, k}: paired realisations";
  j["duration_s"] = ref.epochTime(st.epochs - 1);
  j["imu_rate_hz"] = ref.imuRate;
  j["output_rate_hz"] = ref.outputRate;
  j["epochs"] = st.epochs;
  if (batch.biasWindow > 0) j["initial_bias_window_s"] = batch.biasWindow;
  j["percentiles"] = "linear interpolation between order statistics (Hyndman-Fan type 7)";
  j["sd"] = "sample standard deviation (n - 1)";
  j["cep"] = "CEP = median, R95 = 95th percentile of the horizontal error across runs";
  nlohmann::json models = nlohmann::json::array();
  for (std::size_t m = 0; m < batch.entries.size(); ++m) {
    const auto& en = batch.entries[m];
    nlohmann::json mj{{"label", en.label}, {"source", en.source}, {"effects", batch.effectNames[m]}};
    if (en.parent >= 0) {
      mj["budget_variant_of"] = batch.entries[std::size_t(en.parent)].label;
      mj["effect_removed"] = en.removed;
    }
    nlohmann::json at = nlohmann::json::array();
    for (std::size_t e : batch.timeEpochs) {
      nlohmann::json aj{{"t_s", ref.epochTime(e)},
                        {"cep_m", st.at(m, e, kHorizontal).p[0]},
                        {"r95_m", st.at(m, e, kHorizontal).p[2]}};
      for (int q = 0; q < kMetrics; ++q) aj[metricName(q)] = metricJson(st.at(m, e, q));
      at.push_back(aj);
    }
    mj["at"] = at;
    models.push_back(mj);
  }
  j["models"] = models;

  // Paired comparisons of the given models on the per-run horizontal error.
  nlohmann::json comps = nlohmann::json::array();
  for (std::size_t a = 0; a < batch.entries.size(); ++a) {
    if (batch.entries[a].parent >= 0) continue;
    for (std::size_t b = a + 1; b < batch.entries.size(); ++b) {
      if (batch.entries[b].parent >= 0) continue;
      nlohmann::json cj{{"a", batch.entries[a].label}, {"b", batch.entries[b].label},
                        {"quantity", "horizontal position error of each run, a - b [m]"},
                        {"tests", "paired t-test (Student, n-1 dof); Wilcoxon signed-rank "
                                  "(exact for n <= 50 without ties, else normal approximation "
                                  "with tie and continuity corrections); two-sided"}};
      nlohmann::json at = nlohmann::json::array();
      for (std::size_t e : batch.timeEpochs) {
        const auto va = metricAcrossRuns(batch, a, e, kHorizontal);
        const auto vb = metricAcrossRuns(batch, b, e, kHorizontal);
        const auto t = mcstats::pairedT(va, vb);
        const auto w = mcstats::wilcoxonSignedRank(va, vb);
        at.push_back({{"t_s", ref.epochTime(e)},
                      {"mean_a_m", st.at(a, e, kHorizontal).mean},
                      {"mean_b_m", st.at(b, e, kHorizontal).mean},
                      {"rms_a_m", st.at(a, e, kHorizontal).rms},
                      {"rms_b_m", st.at(b, e, kHorizontal).rms},
                      {"mean_difference_m", t.meanDiff},
                      {"sd_difference_m", t.sdDiff},
                      {"ci95_difference_m", {t.ciLow, t.ciHigh}},
                      {"t", t.t},
                      {"p_t", t.p},
                      {"wilcoxon_w_plus", w.wPlus},
                      {"wilcoxon_n", w.n},
                      {"wilcoxon_z", w.z},
                      {"p_wilcoxon", w.p},
                      {"wilcoxon_exact", w.exact}});
      }
      cj["at"] = at;
      comps.push_back(cj);
    }
  }
  j["comparisons"] = comps;

  // Error budget: share_i = (E[h²]_full − E[h²]_without i) / E[h²]_full.
  nlohmann::json budget = nlohmann::json::array();
  for (std::size_t m = 0; m < batch.entries.size(); ++m) {
    if (batch.entries[m].parent >= 0) continue;
    std::vector<std::size_t> variants;
    for (std::size_t v = 0; v < batch.entries.size(); ++v)
      if (batch.entries[v].parent == int(m)) variants.push_back(v);
    if (variants.empty()) continue;
    nlohmann::json bj{{"model", batch.entries[m].label},
                      {"definition", "share = (E[h^2]_full - E[h^2]_without effect) / E[h^2]_full, "
                                     "h the horizontal position error, E the mean over runs; "
                                     "se = standard error of the paired mean difference / "
                                     "E[h^2]_full"}};
    nlohmann::json at = nlohmann::json::array();
    for (std::size_t e : batch.timeEpochs) {
      const auto full = metricAcrossRuns(batch, m, e, kHorizontal);
      double msFull = 0;
      for (double x : full) msFull += x * x;
      msFull /= double(full.size());
      nlohmann::json effs = nlohmann::json::array();
      double sum = 0;
      for (std::size_t v : variants) {
        const auto without = metricAcrossRuns(batch, v, e, kHorizontal);
        std::vector<double> d(full.size());
        for (std::size_t k = 0; k < d.size(); ++k) d[k] = full[k] * full[k] - without[k] * without[k];
        const auto mo = mcstats::moments(d);
        const double share = msFull > 0 ? mo.mean / msFull : NAN;
        const double se = msFull > 0 ? mo.sd / std::sqrt(double(d.size())) / msFull : NAN;
        double msWithout = 0;
        for (double x : without) msWithout += x * x;
        msWithout /= double(without.size());
        sum += share;
        effs.push_back({{"effect", batch.entries[v].removed},
                        {"ms_without_m2", msWithout},
                        {"share", share},
                        {"share_se", se}});
      }
      at.push_back({{"t_s", ref.epochTime(e)},
                    {"ms_full_m2", msFull},
                    {"rms_full_m", std::sqrt(msFull)},
                    {"effects", effs},
                    {"sum_of_shares", sum}});
    }
    bj["at"] = at;
    budget.push_back(bj);
  }
  if (!budget.empty()) j["budget"] = budget;

  // Measured record against each model's distribution.
  if (batch.measured) {
    const float* meas = batch.measured->errors.data();
    std::FILE* f = out.open("measured.csv");
    std::fputs("t_s,measured_horizontal_m,measured_vertical_m", f);
    std::vector<std::size_t> prim;
    for (std::size_t m = 0; m < batch.entries.size(); ++m)
      if (batch.entries[m].parent < 0) prim.push_back(m);
    for (std::size_t m : prim) {
      const std::string l = csvField(batch.entries[m].label);
      std::fprintf(f, ",%s horizontal percentile,%s horizontal p50_m,%s horizontal p95_m",
                   l.c_str(), l.c_str(), l.c_str());
    }
    std::fputs("\n", f);
    std::vector<std::vector<double>> pctOverTime(prim.size());
    for (std::size_t e = 0; e < st.epochs; ++e) {
      const double h = metricValue(meas + e * kErrorFields, kHorizontal);
      std::fprintf(f, "%.6f,%.9g,%.9g", ref.epochTime(e), h,
                   metricValue(meas + e * kErrorFields, kVertical));
      for (std::size_t i = 0; i < prim.size(); ++i) {
        auto v = metricAcrossRuns(batch, prim[i], e, kHorizontal);
        std::sort(v.begin(), v.end());
        const double p = mcstats::percentileOf(v, h);
        pctOverTime[i].push_back(p);
        std::fprintf(f, ",%.6g,%.9g,%.9g", p, st.at(prim[i], e, kHorizontal).p[0],
                     st.at(prim[i], e, kHorizontal).p[2]);
      }
      std::fputs("\n", f);
    }
    files.push_back("measured.csv");
    nlohmann::json mj{{"source", batch.measured->source},
                      {"percentile", "mid-rank percentile of the measured horizontal error among "
                                     "the model's runs at the same epoch"}};
    nlohmann::json per = nlohmann::json::array();
    // Epochs after the bias window (before it the removal has forced the drift to zero).
    const auto firstEpoch = std::size_t(std::ceil(batch.biasWindow * ref.outputRate)) + 1;
    for (std::size_t i = 0; i < prim.size(); ++i) {
      std::vector<double> after;
      for (std::size_t e = std::min(firstEpoch, st.epochs - 1); e < st.epochs; ++e)
        after.push_back(pctOverTime[i][e]);
      std::vector<double> sorted = after;
      std::sort(sorted.begin(), sorted.end());
      std::size_t inside = 0;
      for (double p : after) inside += (p >= 2.5 && p <= 97.5) ? 1 : 0;
      nlohmann::json at = nlohmann::json::array();
      for (std::size_t e : batch.timeEpochs)
        at.push_back({{"t_s", ref.epochTime(e)},
                      {"measured_horizontal_m", metricValue(meas + e * kErrorFields, kHorizontal)},
                      {"percentile", pctOverTime[i][e]}});
      per.push_back({{"model", batch.entries[prim[i]].label},
                     {"at", at},
                     {"median_percentile_over_time", mcstats::percentileSorted(sorted, 50)},
                     {"fraction_of_epochs_inside_2.5_97.5", double(inside) / double(after.size())}});
    }
    mj["models"] = per;
    j["measured"] = mj;
  }

  if (ref.aiding.filter.enabled) j["aided"] = writeMcAidedOutputs(batch, out, files);

  std::vector<std::string> names = files;
  names.push_back("summary.json");
  names.push_back("report.html");
  names.push_back("runs/ (checkpoints)");
  j["files"] = names;
  std::FILE* fs = out.open("summary.json");
  const std::string text = jsonText(j, 2);
  std::fputs(text.c_str(), fs);
  files.push_back("summary.json");

  std::FILE* fh = out.open("report.html");
  const std::string html = mcReportHtml(batch, st);
  std::fputs(html.c_str(), fh);
  files.push_back("report.html");
  out.commit();
}

}  // namespace sinsim::sim
