#include "sim/mc_headlines.hpp"

#include <algorithm>
#include <cmath>

#include "common/number_text.hpp"
#include "sim/mc_stats.hpp"

namespace sinsim::sim {

std::string McPairedHeadline::sentence() const {
  // Said of the model with the larger mean drift, relative to the other.
  const bool bMore = meanB > meanA;
  const std::string& more = bMore ? b : a;
  const std::string& less = bMore ? a : b;
  const double hi = std::max(meanA, meanB), lo = std::min(meanA, meanB);
  const std::string evidence = " (mean " + lengthText(hi, 3) + " vs " + lengthText(lo, 3) + ", " +
                               std::to_string(runs) + (runs == 1 ? " paired run" : " paired runs") +
                               ", paired t-test " + pStatement(pT) + ").";
  const std::string when = " at " + durationText(t);
  if (!(pT < 0.05) || !(lo > 0))
    return "No significant difference in horizontal drift between " + more + " and " + less +
           when + evidence;
  // "2 times" or "94 % more", decided on the ratio as printed (two digits): 1.9999999 is 2 times,
  // not "1e+02 % more"; large ratios without an exponent ("2200 times").
  const double ratio = hi / lo;
  const bool times = std::stod(significant(ratio, 2)) >= 2.0;
  const std::string amount = times ? plainSignificant(ratio, 2) + " times the horizontal drift of "
                                   : plainSignificant(100.0 * (ratio - 1.0), 2) +
                                         " % more horizontal drift than ";
  return more + " predicts " + amount + less + when + evidence;
}

McHeadlines mcHeadlines(const McBatch& batch, std::size_t models) {
  McHeadlines out;
  for (std::size_t e : batch.timeEpochs) {
    const double t = batch.ref.epochTime(e);
    std::vector<std::vector<double>> h(models);
    for (std::size_t m = 0; m < models; ++m) {
      h[m] = metricAcrossRuns(batch, m, e, kHorizontal);
      std::vector<double> v = h[m];
      std::sort(v.begin(), v.end());
      out.models.push_back({batch.entries[m].label, t, mcstats::percentileSorted(v, 50),
                            mcstats::percentileSorted(v, 95)});
    }
    for (std::size_t a = 0; a < models; ++a)
      for (std::size_t b = 0; b < models; ++b) {
        const bool wanted = batch.reference.empty() ? b > a
                                                    : a != b && batch.entries[a].label == batch.reference;
        if (!wanted) continue;
        McPairedHeadline p;
        p.a = batch.entries[a].label;
        p.b = batch.entries[b].label;
        p.t = t;
        p.runs = h[a].size();
        p.meanA = mcstats::moments(h[a]).mean;
        p.meanB = mcstats::moments(h[b]).mean;
        p.pT = mcstats::pairedT(h[a], h[b]).p;
        p.pWilcoxon = mcstats::wilcoxonSignedRank(h[a], h[b]).p;
        out.pairs.push_back(p);
      }
  }
  if (batch.ref.aiding.filter.enabled) out.aided = mcAidedSummaries(batch, models);
  if (batch.measured && !batch.timeEpochs.empty()) {
    const std::size_t e = batch.timeEpochs.back();
    const double hm = metricValue(batch.measured->errors.data() + e * kErrorFields, kHorizontal);
    out.measured = "The measured record drifted " + lengthText(hm, 3) + " at " +
                   durationText(batch.ref.epochTime(e)) + ": ";
    for (std::size_t m = 0; m < models; ++m) {
      auto v = metricAcrossRuns(batch, m, e, kHorizontal);
      std::sort(v.begin(), v.end());
      const double p = mcstats::percentileOf(v, hm);  // 0..100; "100", not significant()'s "1e+02"
      out.measured += (m ? ", " : "") + std::string("percentile ") +
                      (p >= 10.0 ? std::to_string(std::llround(p)) : significant(p, 2)) + " of " +
                      batch.entries[m].label;
    }
    out.measured += " (near 50: the model predicts it; near 0 or 100: it does not).";
  }
  return out;
}

McHeadlines mcHeadlines(const Reference& ref, const McResult& r, std::size_t models,
                        const std::vector<double>& times, const McMeasured* measured, const std::string& reference) {
  McBatch batch(ref);
  batch.measured = measured;
  batch.reference = reference;
  batch.runs = r.errors.empty() ? 0 : r.errors[0].size() / ref.runFloats();
  batch.timeEpochs = reportEpochs(ref, times);
  for (std::size_t m = 0; m < models; ++m) batch.entries.push_back({r.labels[m], "", -1, ""});
  batch.errors.assign(r.errors.begin(), r.errors.begin() + long(models));
  return mcHeadlines(batch, models);
}

}  // namespace sinsim::sim
