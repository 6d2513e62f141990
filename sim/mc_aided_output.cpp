#include "sim/mc_aided_output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "errormodels/stats/special.hpp"
#include "sim/aided/aided_output.hpp"
#include "sim/mc_stats.hpp"
#include "sim/output.hpp"

namespace sinsim::sim {
namespace {

// One epoch's run-averaged NEES or NIS and its band.
struct EpochAverage {
  std::size_t runs = 0;
  double mean = NAN, dof = NAN, lo = NAN, hi = NAN;
  bool inside() const { return runs > 0 && mean >= lo && mean <= hi; }
};

// Average over the runs of field `f` (kNees or kNis) at epoch e; dof 9 for the NEES, the stored
// NIS dof for the NIS. Runs without a value there (NaN) are left out.
EpochAverage averageAt(const McBatch& batch, std::size_t entry, std::size_t e, int f) {
  const Reference& ref = batch.ref;
  const std::size_t perRun = ref.runFloats();
  const float* view = batch.errors[entry].data() + ref.epochs() * kErrorFields +
                      e * kAidedEpochFields;
  EpochAverage a;
  double sum = 0.0;
  for (std::uint64_t k = 0; k < batch.runs; ++k) {
    const float* row = view + k * perRun;
    if (!std::isfinite(row[f])) continue;
    sum += row[f];
    a.dof = f == kNees ? 9.0 : double(row[kNisDof]);
    ++a.runs;
  }
  if (a.runs == 0) return a;
  a.mean = sum / double(a.runs);
  chiSquareMeanBand99(a.dof, a.runs, a.lo, a.hi);
  return a;
}

// The epoch's class in run 0 (outage windows are the scenario's: the same in every run).
int epochClass(const McBatch& batch, std::size_t entry, std::size_t e) {
  const float c = batch.errors[entry][batch.ref.epochs() * kErrorFields + e * kAidedEpochFields +
                                      kEpochClass];
  return std::isfinite(c) ? int(c) : 0;
}

const char* className(int c) { return c == 1 ? "aiding" : c == 2 ? "outage" : "none"; }

nlohmann::json classJson(std::size_t epochs, std::size_t inside, double sumMean) {
  return {{"epochs", epochs},
          {"inside_99", inside},
          {"fraction_inside_99", epochs ? double(inside) / double(epochs) : NAN},
          {"mean_of_run_averages", epochs ? sumMean / double(epochs) : NAN}};
}

}  // namespace

void chiSquareMeanBand99(double dof, std::size_t runs, double& lo, double& hi) {
  const double n = dof * double(runs);
  lo = errormodels::chiSquareQuantile(0.005, n) / double(runs);
  hi = errormodels::chiSquareQuantile(0.995, n) / double(runs);
}

nlohmann::json writeMcAidedOutputs(const McBatch& batch, OutputFiles& out,
                                   std::vector<std::string>& files) {
  const Reference& ref = batch.ref;
  const std::size_t perRun = ref.runFloats(), epochs = ref.epochs();
  const std::size_t outageBase = epochs * (kErrorFields + kAidedEpochFields);
  const auto& windows = ref.aiding.gnss.outages;
  nlohmann::json models = nlohmann::json::array();

  std::FILE* fo = out.open("outages.csv");
  std::fputs("model,run,outage,start_s,end_s,max_horizontal_m,sigma_horizontal_m\n", fo);
  std::FILE* fc = out.open("filter_consistency.csv");
  std::fputs("model,t_s,class,runs,nees_mean,nees_lo99,nees_hi99,nis_mean,nis_dof,nis_lo99,"
             "nis_hi99\n", fc);
  for (std::size_t m = 0; m < batch.entries.size(); ++m) {
    const std::string label = csvField(batch.entries[m].label);
    nlohmann::json outages = nlohmann::json::array();
    for (std::size_t w = 0; w < windows.size(); ++w) {
      std::vector<double> mx, sg, ratio;
      for (std::uint64_t k = 0; k < batch.runs; ++k) {
        const float* o = batch.errors[m].data() + k * perRun + outageBase + w * kOutageFields;
        std::fprintf(fo, "%s,%llu,%zu,%.6f,%.6f", label.c_str(),
                     static_cast<unsigned long long>(k), w, windows[w].start, windows[w].end);
        aided::writeCsvNumber(fo, "%.9g", o[kOutageMaxHorizontal]);  // empty: no filter there
        aided::writeCsvNumber(fo, "%.9g", o[kOutageSigmaHorizontal]);
        std::fputc('\n', fo);
        if (!(std::isfinite(o[kOutageMaxHorizontal]) && o[kOutageSigmaHorizontal] > 0.0f))
          continue;  // a window the filter never ran in (before the alignment's end)
        mx.push_back(o[kOutageMaxHorizontal]);
        sg.push_back(o[kOutageSigmaHorizontal]);
        ratio.push_back(mx.back() / sg.back());
      }
      nlohmann::json oj{{"start_s", windows[w].start}, {"end_s", windows[w].end},
                        {"runs", mx.size()}};
      if (!mx.empty()) {
        for (auto* v : {&mx, &sg, &ratio}) std::sort(v->begin(), v->end());
        oj["max_horizontal_m"] = {{"p50", mcstats::percentileSorted(mx, 50)},
                                  {"p95", mcstats::percentileSorted(mx, 95)},
                                  {"mean", mcstats::moments(mx).mean}};
        oj["sigma_horizontal_m"] = {{"p50", mcstats::percentileSorted(sg, 50)},
                                    {"p95", mcstats::percentileSorted(sg, 95)}};
        oj["max_over_sigma"] = {{"p50", mcstats::percentileSorted(ratio, 50)},
                                {"p95", mcstats::percentileSorted(ratio, 95)}};
      }
      outages.push_back(oj);
    }

    std::size_t n[3] = {0, 0, 0}, neesIn[3] = {0, 0, 0}, nisN = 0, nisIn = 0;
    double neesSum[3] = {0, 0, 0}, nisSum = 0;
    for (std::size_t e = 0; e < epochs; ++e) {
      const EpochAverage nees = averageAt(batch, m, e, kNees);
      if (nees.runs == 0) continue;
      const EpochAverage nis = averageAt(batch, m, e, kNis);
      const int c = epochClass(batch, m, e);
      std::fprintf(fc, "%s,%.6f,%s,%zu", label.c_str(), ref.epochTime(e), className(c), nees.runs);
      // The NIS of an epoch without fixes (an outage) does not exist: empty fields.
      for (double v : {nees.mean, nees.lo, nees.hi, nis.mean, nis.dof, nis.lo, nis.hi})
        aided::writeCsvNumber(fc, "%.9g", v);
      std::fputc('\n', fc);
      ++n[c];
      neesIn[c] += nees.inside() ? 1 : 0;
      neesSum[c] += nees.mean;
      if (nis.runs > 0) {
        ++nisN;
        nisIn += nis.inside() ? 1 : 0;
        nisSum += nis.mean;
      }
    }
    models.push_back({{"model", batch.entries[m].label},
                      {"outages", outages},
                      {"nees", {{"aiding", classJson(n[1], neesIn[1], neesSum[1])},
                                {"outage", classJson(n[2], neesIn[2], neesSum[2])}}},
                      {"nis", {{"aiding", classJson(nisN, nisIn, nisSum)}}}});
  }
  files.push_back("outages.csv");
  files.push_back("filter_consistency.csv");
  return {{"band", "two-sided 99 % chi-square band of the run-average at each epoch"},
          {"models", models}};
}

}  // namespace sinsim::sim
