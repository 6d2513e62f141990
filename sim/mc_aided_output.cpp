#include "sim/mc_aided_output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/constants.hpp"
#include "common/number_text.hpp"
#include "errormodels/stats/special.hpp"
#include "sim/aided/aided_navigation.hpp"
#include "sim/aided/aided_output.hpp"
#include "sim/filter_summary.hpp"
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

// Average over the runs of field `f` (kNees or kNis) at epoch e; dof aided::neesDof for the NEES
// (9, or 7 with a held vertical channel), the stored NIS dof for the NIS. Runs without a value
// there (NaN) are left out.
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
    a.dof = f == kNees ? double(aided::neesDof(ref.strapdown.vertical)) : double(row[kNisDof]);
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

nlohmann::json classJson(const McConsistencyClass& c) {
  return {{"epochs", c.epochs},
          {"inside_99", c.inside},
          {"fraction_inside_99", c.fractionInside()},
          {"above_99", c.above},
          {"below_99", c.epochs - c.inside - c.above},
          {"mean_of_run_averages", c.meanOfAverages}};
}

// Counts one epoch's run-average into its class.
void count(McConsistencyClass& c, const EpochAverage& a, double& sum) {
  ++c.epochs;
  c.inside += a.inside() ? 1 : 0;
  c.above += a.runs > 0 && a.mean > a.hi ? 1 : 0;
  sum += a.mean;
  c.meanOfAverages = sum / double(c.epochs);
}

// Outage window w of model m over the runs; outages.csv's rows written when fo is given.
McOutageSummary outageSummary(const McBatch& batch, std::size_t m, std::size_t w, std::FILE* fo) {
  const Reference& ref = batch.ref;
  const std::size_t perRun = ref.runFloats();
  const std::size_t outageBase = ref.epochs() * (kErrorFields + kAidedEpochFields);
  const aided::TimeWindow& win = ref.aiding.gnss.outages[w];
  const std::string label = csvField(batch.entries[m].label);
  McOutageSummary o;
  o.start = win.start;
  o.end = win.end;
  std::vector<double> mx, sg, ratio;
  for (std::uint64_t k = 0; k < batch.runs; ++k) {
    const float* v = batch.errors[m].data() + k * perRun + outageBase + w * kOutageFields;
    if (fo) {
      std::fprintf(fo, "%s,%llu,%zu,%.6f,%.6f", label.c_str(), static_cast<unsigned long long>(k),
                   w, win.start, win.end);
      aided::writeCsvNumber(fo, "%.9g", v[kOutageMaxHorizontal]);  // empty: no filter there
      aided::writeCsvNumber(fo, "%.9g", v[kOutageSigmaHorizontal]);
      std::fputc('\n', fo);
    }
    if (!(std::isfinite(v[kOutageMaxHorizontal]) && v[kOutageSigmaHorizontal] > 0.0f))
      continue;  // a window the filter never ran in (before the alignment's end)
    mx.push_back(v[kOutageMaxHorizontal]);
    sg.push_back(v[kOutageSigmaHorizontal]);
    ratio.push_back(mx.back() / sg.back());
  }
  o.runs = mx.size();
  if (mx.empty()) return o;
  for (auto* v : {&mx, &sg, &ratio}) std::sort(v->begin(), v->end());
  o.maxP50 = mcstats::percentileSorted(mx, 50);
  o.maxP95 = mcstats::percentileSorted(mx, 95);
  o.maxMean = mcstats::moments(mx).mean;
  o.sigmaP50 = mcstats::percentileSorted(sg, 50);
  o.sigmaP95 = mcstats::percentileSorted(sg, 95);
  o.ratioP50 = mcstats::percentileSorted(ratio, 50);
  o.ratioP95 = mcstats::percentileSorted(ratio, 95);
  return o;
}

// Epoch e's attitude errors over the runs that have a NEES there, counted into s: beyond
// kSmallAngle, and the largest; runSeen / runLarge (one per run) mark the runs with a filter
// epoch and those that passed kSmallAngle.
void countAttitude(const McBatch& batch, std::size_t m, std::size_t e, McAidedSummary& s,
                   std::vector<char>& runSeen, std::vector<char>& runLarge) {
  const Reference& ref = batch.ref;
  const std::size_t perRun = ref.runFloats();
  for (std::uint64_t k = 0; k < batch.runs; ++k) {
    const float* run = batch.errors[m].data() + k * perRun;
    if (!std::isfinite(run[ref.epochs() * kErrorFields + e * kAidedEpochFields + kNees])) continue;
    const float* err = run + e * kErrorFields;
    const double a = std::max({std::abs(double(err[kRoll])), std::abs(double(err[kPitch])),
                               std::abs(double(err[kYaw]))});
    ++s.filterEpochs;
    s.largeAttitudeEpochs += a > kSmallAngle ? 1 : 0;
    runSeen[k] = 1;
    if (a > kSmallAngle) runLarge[k] = 1;
    if (!(a <= s.largestAttitude)) s.largestAttitude = a;  // NaN at first
  }
}

// Model m's summary; outages.csv's and filter_consistency.csv's rows written when fo, fc are given.
McAidedSummary summarize(const McBatch& batch, std::size_t m, std::FILE* fo, std::FILE* fc) {
  const Reference& ref = batch.ref;
  McAidedSummary s;
  s.label = batch.entries[m].label;
  s.neesDof = aided::neesDof(ref.strapdown.vertical);
  for (std::size_t w = 0; w < ref.aiding.gnss.outages.size(); ++w)
    s.outages.push_back(outageSummary(batch, m, w, fo));
  const std::string label = csvField(s.label);
  double sum[3] = {0, 0, 0};
  std::vector<char> runSeen(batch.runs, 0), runLarge(batch.runs, 0);
  for (std::size_t e = 0; e < ref.epochs(); ++e) {
    const EpochAverage nees = averageAt(batch, m, e, kNees);
    if (nees.runs == 0) continue;
    const EpochAverage nis = averageAt(batch, m, e, kNis);
    const int c = epochClass(batch, m, e);
    if (fc) {
      std::fprintf(fc, "%s,%.6f,%s,%zu", label.c_str(), ref.epochTime(e), className(c), nees.runs);
      // The NIS of an epoch without fixes (an outage) does not exist: empty fields.
      for (double v : {nees.mean, nees.lo, nees.hi, nis.mean, nis.dof, nis.lo, nis.hi})
        aided::writeCsvNumber(fc, "%.9g", v);
      std::fputc('\n', fc);
    }
    if (c == 1 || c == 2) countAttitude(batch, m, e, s, runSeen, runLarge);
    if (c == 1) count(s.neesAiding, nees, sum[0]);
    if (c == 2) count(s.neesOutage, nees, sum[1]);
    if (nis.runs > 0) count(s.nisAiding, nis, sum[2]);
  }
  s.filterRuns = std::size_t(std::count(runSeen.begin(), runSeen.end(), 1));
  s.largeAttitudeRuns = std::size_t(std::count(runLarge.begin(), runLarge.end(), 1));
  return s;
}

}  // namespace

void chiSquareMeanBand99(double dof, std::size_t runs, double& lo, double& hi) {
  const double n = dof * double(runs);
  lo = errormodels::chiSquareQuantile(0.005, n) / double(runs);
  hi = errormodels::chiSquareQuantile(0.995, n) / double(runs);
}

bool McAidedSummary::largeAttitudeNamed() const {
  return (filterEpochs && 20 * largeAttitudeEpochs >= filterEpochs) ||
         (filterRuns && 20 * largeAttitudeRuns >= filterRuns);
}

std::vector<std::string> McAidedSummary::sentences() const {
  std::vector<std::string> out;
  if (!neesAiding.epochs && !neesOutage.epochs) return out;  // no filter epoch in any run
  auto cls = [&](const char* what, const McConsistencyClass& c) {
    return std::to_string(c.inside) + "/" + std::to_string(c.epochs) + " " + what + " epochs (mean " +
           significant(c.meanOfAverages, 3) + ")";
  };
  std::string text = label + ": filter consistency: the run-averaged NEES (" + std::to_string(neesDof) +
                     " states) lies inside its 99 % band at " + cls("aiding", neesAiding);
  if (neesOutage.epochs) text += " and " + cls("outage", neesOutage);
  if (nisAiding.epochs) text += "; the NIS at " + cls("aiding", nisAiding);
  out.push_back(text + ".");
  bool overConfident = false;  // in either class: what the attitude sentence below qualifies
  for (const auto* c : {&neesAiding, &neesOutage}) {
    if (!(c->epochs && c->fractionInside() < 0.8)) continue;
    // Which side the epochs outside lie on, by count: a few far above pull the mean up over many
    // a little below. Both sides at 20 % of the epochs or more: neither word fits the class.
    const std::size_t below = c->epochs - c->inside - c->above;
    const bool mixed = 5 * c->above >= c->epochs && 5 * below >= c->epochs;
    const bool above = c->above > below;
    overConfident = overConfident || above || mixed;
    std::string text = label + ": " + (c == &neesAiding ? "while aided" : "in outages") +
                       " the NEES lies outside its band at " + std::to_string(c->epochs - c->inside) +
                       "/" + std::to_string(c->epochs) + " epochs (above it at " + std::to_string(c->above) +
                       ", below at " + std::to_string(below) + "; mean " + significant(c->meanOfAverages, 3) +
                       " against " + std::to_string(neesDof) + "): ";
    if (mixed)
      text += "the filter is over-confident at some epochs and pessimistic at others there: no "
              "scaling of its model fits them all (filter_consistency.csv shows when)";
    else
      text += std::string("the filter is ") + (above ? "over-confident" : "pessimistic") + " there, its model " +
              (above && largeAttitudeNamed() ? "or its linearisation (below) " : "") + (above ? "under" : "over") +
              "states the errors";
    out.push_back(text + " (a consistent filter leaves more than 20 % of the epochs outside with "
                         "probability <= 5 %).");
  }
  const double largeShare = filterEpochs ? double(largeAttitudeEpochs) / double(filterEpochs) : 0.0;
  if (overConfident && largeAttitudeNamed())
    out.push_back(label + ": the attitude error exceeds " + significant(radToDeg(kSmallAngle), 2) +
                  " deg in " + std::to_string(largeAttitudeRuns) + "/" + std::to_string(filterRuns) +
                  " runs, at " + significant(100.0 * largeShare, 2) + " % of their filter epochs " +
                  "(largest " + significant(radToDeg(largestAttitude), 3) + " deg): beyond small " +
                  "angles the error-state filter's linearisation, not only its model, sets the NEES, " +
                  "which is then no test of the model alone; a run that passed through large angles " +
                  "can stay over-confident after they shrink (what it learned there). A rerun with a " +
                  "smaller initial_errors attitude sigma tests the model alone.");
  for (const McOutageSummary& o : outages) {
    if (!o.runs) continue;
    out.push_back(label + ": outage " + significant(o.start, 6) + "-" + significant(o.end, 6) +
                  " s: largest horizontal error median " + lengthText(o.maxP50, 3) + ", 95 % " +
                  lengthText(o.maxP95, 3) + "; the filter's 1-sigma then, median " +
                  lengthText(o.sigmaP50, 3) + " (error / sigma median " + significant(o.ratioP50, 2) +
                  ").");
  }
  return out;
}

std::vector<McAidedSummary> mcAidedSummaries(const McBatch& batch, std::size_t models) {
  std::vector<McAidedSummary> out;
  for (std::size_t m = 0; m < models && m < batch.entries.size(); ++m)
    out.push_back(summarize(batch, m, nullptr, nullptr));
  return out;
}

nlohmann::json writeMcAidedOutputs(const McBatch& batch, OutputFiles& out,
                                   std::vector<std::string>& files) {
  std::FILE* fo = out.open("outages.csv");
  std::fputs("model,run,outage,start_s,end_s,max_horizontal_m,sigma_horizontal_m\n", fo);
  std::FILE* fc = out.open("filter_consistency.csv");
  std::fputs("model,t_s,class,runs,nees_mean,nees_lo99,nees_hi99,nis_mean,nis_dof,nis_lo99,"
             "nis_hi99\n", fc);
  nlohmann::json models = nlohmann::json::array();
  for (std::size_t m = 0; m < batch.entries.size(); ++m) {
    const McAidedSummary s = summarize(batch, m, fo, fc);
    nlohmann::json outages = nlohmann::json::array();
    for (const McOutageSummary& o : s.outages) {
      nlohmann::json oj{{"start_s", o.start}, {"end_s", o.end}, {"runs", o.runs}};
      if (o.runs) {
        oj["max_horizontal_m"] = {{"p50", o.maxP50}, {"p95", o.maxP95}, {"mean", o.maxMean}};
        oj["sigma_horizontal_m"] = {{"p50", o.sigmaP50}, {"p95", o.sigmaP95}};
        oj["max_over_sigma"] = {{"p50", o.ratioP50}, {"p95", o.ratioP95}};
      }
      outages.push_back(oj);
    }
    models.push_back({{"model", s.label},
                      {"outages", outages},
                      {"nees", {{"aiding", classJson(s.neesAiding)}, {"outage", classJson(s.neesOutage)}}},
                      {"nis", {{"aiding", classJson(s.nisAiding)}}},
                      {"attitude_beyond_small_angle",
                       {{"threshold_deg", radToDeg(kSmallAngle)},
                        {"filter_epochs", s.filterEpochs},
                        {"epochs_beyond", s.largeAttitudeEpochs},
                        {"runs", s.filterRuns},
                        {"runs_beyond", s.largeAttitudeRuns},
                        {"largest_deg", radToDeg(s.largestAttitude)}}}});
  }
  files.push_back("outages.csv");
  files.push_back("filter_consistency.csv");
  return {{"band", "two-sided 99 % chi-square band of the run-average at each epoch"},
          {"filter", filterSummaryJson(batch.ref.aiding.filter)},
          {"models", models}};
}

}  // namespace sinsim::sim
