// report.html of a Monte Carlo batch (sim/report: self-contained, inline SVG, deterministic).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/constants.hpp"
#include "common/number_text.hpp"
#include "sim/mc_headlines.hpp"
#include "sim/mc_output.hpp"
#include "sim/mc_stats.hpp"
#include "sim/report/report.hpp"

namespace sinsim::sim {
namespace {

// `sig` significant digits, never in exponent notation (tables are read, not parsed).
std::string num(double v, int sig = 4) { return plainSignificant(v, sig); }

std::string pText(double p) { return std::isfinite(p) ? pValueText(p) : "–"; }
// A percentage without exponent: "70", "8.2", "0.41", "0".
std::string percentText(double p) {
  if (!std::isfinite(p)) return "–";
  return report::formatFixed(p, std::fabs(p) >= 10 ? 0 : std::fabs(p) >= 1 ? 1 : 2);
}
std::string len(double m) { return std::isfinite(m) ? lengthText(m) : "–"; }

/// One effect's share of the mean-square horizontal error of model m at epoch e: the paired mean
/// of h² − h²(without the effect, variant v) over E[h²], its standard error, the RMS without it.
struct BudgetShare {
  double share = NAN, se = NAN, rmsWithout = NAN;
};
BudgetShare budgetShare(const McBatch& batch, std::size_t m, std::size_t v, std::size_t e) {
  const auto full = metricAcrossRuns(batch, m, e, kHorizontal);
  const auto wo = metricAcrossRuns(batch, v, e, kHorizontal);
  std::vector<double> d(full.size());
  double ms = 0, msw = 0;
  for (std::size_t k = 0; k < d.size(); ++k) {
    d[k] = full[k] * full[k] - wo[k] * wo[k];
    ms += full[k] * full[k];
    msw += wo[k] * wo[k];
  }
  ms /= double(d.size());
  msw /= double(d.size());
  const auto mo = mcstats::moments(d);
  return {mo.mean / ms, mo.sd / std::sqrt(double(d.size())) / ms, std::sqrt(msw)};
}

std::vector<double> scaled(std::vector<double> v, double f) {
  for (double& x : v) x *= f;
  return v;
}

}  // namespace

std::string mcReportHtml(const McBatch& batch, const McStats& st) {
  using namespace sinsim::report;
  const Reference& ref = batch.ref;
  std::vector<std::size_t> prim;
  for (std::size_t m = 0; m < batch.entries.size(); ++m)
    if (batch.entries[m].parent < 0) prim.push_back(m);

  HtmlPage page("sinsim mc: " + ref.name);
  page.paragraph(std::to_string(batch.runs) + " runs per model, seed " +
                 std::to_string(batch.seed) + "; run k of every model uses the random streams "
                 "StreamKey{seed, k}, so the models are compared on paired realisations. " +
                 "IMU " + num(ref.imuRate) + " Hz, statistics every " + num(1.0 / ref.outputRate) +
                 " s over " + num(ref.epochTime(st.epochs - 1)) + " s." +
                 (batch.biasWindow > 0 ? " The mean error of the first " + num(batch.biasWindow) +
                                             " s was removed from every run (initial bias)."
                                       : ""));

  // The answer first, in words.
  {
    const McHeadlines h = mcHeadlines(batch, prim.size());
    page.heading("Answer");
    for (const McPairedHeadline& p : h.pairs) page.paragraph(p.sentence());
    if (h.pairs.empty())
      for (const McHeadline& m : h.models)
        page.paragraph(m.label + ": horizontal error at " + durationText(m.t) + ": half of the " +
                       "runs within " + lengthText(m.cep, 3) + " (CEP), 95 % within " +
                       lengthText(m.r95, 3) + " (R95).");
    if (!h.measured.empty()) page.paragraph(h.measured);
    for (const McAidedSummary& s : h.aided)
      for (const std::string& line : s.sentences()) page.paragraph(line);
  }

  std::vector<double> t(st.epochs);
  for (std::size_t e = 0; e < st.epochs; ++e) t[e] = ref.epochTime(e);
  auto column = [&](std::size_t m, int metric, int what) {  // what: 0..3 percentiles, 4 rms
    std::vector<double> y(st.epochs);
    for (std::size_t e = 0; e < st.epochs; ++e) {
      const MetricStats& ms = st.at(m, e, metric);
      y[e] = what < 4 ? ms.p[what] : ms.rms;
    }
    return y;
  };

  // Drift envelopes side by side, on one log-log range that holds every model's 99 % and the
  // measured record (no curve runs off the axis).
  std::vector<double> measuredH;
  if (batch.measured) {
    measuredH.resize(st.epochs);
    for (std::size_t e = 0; e < st.epochs; ++e)
      measuredH[e] = metricValue(batch.measured->errors.data() + e * kErrorFields, kHorizontal);
  }
  double yMax = 0, yMin = INFINITY;
  for (std::size_t m : prim)
    for (std::size_t e = 1; e < st.epochs; ++e) {
      const MetricStats& h = st.at(m, e, kHorizontal);
      if (std::isfinite(h.p[3])) yMax = std::max(yMax, h.p[3]);
      if (h.p[0] > 0) yMin = std::min(yMin, h.p[0]);
    }
  for (std::size_t e = 1; e < measuredH.size(); ++e)
    if (std::isfinite(measuredH[e])) yMax = std::max(yMax, measuredH[e]);
  const DisplayUnit ua = lengthUnit(yMax);
  page.heading("Horizontal drift envelopes");
  std::vector<Plot> side;
  for (std::size_t i = 0; i < prim.size(); ++i) {
    const std::size_t m = prim[i];
    Plot p(batch.entries[m].label, "time [s]", std::string("horizontal error [") + ua.name + "]");
    p.xLog = p.yLog = true;
    const std::string& c = paletteColor(i);
    p.add(Band{"68 – 95 %", t, scaled(column(m, kHorizontal, 1), ua.factor),
               scaled(column(m, kHorizontal, 2), ua.factor), c, 0.2});
    p.add(Series{"median", t, scaled(column(m, kHorizontal, 0), ua.factor), c, false, 1.8, false});
    p.add(Series{"99 %", t, scaled(column(m, kHorizontal, 3), ua.factor), c, true, 1.2, false});
    if (batch.measured)
      p.add(Series{"measured", t, scaled(measuredH, ua.factor), "#000000", false, 1.5, false});
    if (yMax > 0 && yMin < yMax)
      p.yRange = std::make_pair(yMin * ua.factor / 1.5, yMax * ua.factor * 1.3);
    side.push_back(p);
  }
  page.plotRow(side);

  {
    Plot p("Models together: median (solid) and 95 % (dashed)", "time [s]",
           std::string("horizontal error [") + ua.name + "]");
    p.xLog = p.yLog = true;
    double vMax = 0;
    for (std::size_t m : prim)
      for (std::size_t e = 0; e < st.epochs; ++e)
        if (std::isfinite(st.at(m, e, kVertical).p[2])) vMax = std::max(vMax, st.at(m, e, kVertical).p[2]);
    const DisplayUnit uv = lengthUnit(vMax);
    Plot v("Vertical error: median and 95 %", "time [s]",
           std::string("vertical error [") + uv.name + "]");
    Plot y("Yaw error: median and 95 % of |δψ|", "time [s]", "|yaw error| [deg]");
    v.xLog = v.yLog = y.xLog = y.yLog = true;
    for (std::size_t i = 0; i < prim.size(); ++i) {
      const std::string& c = paletteColor(i);
      const std::string& l = batch.entries[prim[i]].label;
      p.add(Series{l + " median", t, scaled(column(prim[i], kHorizontal, 0), ua.factor), c});
      p.add(Series{l + " 95 %", t, scaled(column(prim[i], kHorizontal, 2), ua.factor), c, true, 1.4});
      v.add(Series{l + " median", t, scaled(column(prim[i], kVertical, 0), uv.factor), c});
      v.add(Series{l + " 95 %", t, scaled(column(prim[i], kVertical, 2), uv.factor), c, true, 1.4});
      y.add(Series{l + " median", t, scaled(column(prim[i], kYawAbs, 0), kDegPerRad), c});
      y.add(Series{l + " 95 %", t, scaled(column(prim[i], kYawAbs, 2), kDegPerRad), c, true, 1.4});
    }
    // A held vertical channel (--measured) has no vertical error at all: no empty panel.
    if (vMax > 0)
      page.plotRow({p, v, y});
    else
      page.plotRow({p, y});
  }

  // Statistics at the report times.
  {
    Table tb;
    tb.caption = "Horizontal error across runs (CEP = median, R95 = 95th percentile), vertical 95th "
                 "percentile, RMS velocity error";
    tb.header = {"model", "t", "CEP", "R95", "99 %", "RMS", "vertical 95 %",
                 "velocity RMS [m/s]"};
    for (std::size_t m : prim)
      for (std::size_t e : batch.timeEpochs) {
        const MetricStats& h = st.at(m, e, kHorizontal);
        tb.rows.push_back({batch.entries[m].label, Cell(durationText(ref.epochTime(e)), "num"),
                           Cell(len(h.p[0]), "num"), Cell(len(h.p[2]), "num"),
                           Cell(len(h.p[3]), "num"), Cell(len(h.rms), "num"),
                           Cell(len(st.at(m, e, kVertical).p[2]), "num"),
                           Cell(num(st.at(m, e, kVelocity).rms, 3), "num")});
      }
    page.heading("Drift at the report times");
    page.table(tb);
  }

  // Paired differences.
  if (prim.size() > 1) {
    Table tb;
    tb.caption = "Differences of the per-run horizontal error (a − b, same run k = same random "
                 "streams). Paired t-test (n − 1 degrees of freedom) and Wilcoxon signed-rank test "
                 "(exact for n ≤ 50 without ties, otherwise normal approximation), two-sided; "
                 "p < 0.05 marked.";
    tb.header = {"a", "b", "t", "mean a", "mean b", "mean a − b",
                 "95 % CI", "t", "p (t-test)", "p (Wilcoxon)"};
    for (std::size_t i = 0; i < prim.size(); ++i)
      for (std::size_t k = i + 1; k < prim.size(); ++k)
        for (std::size_t e : batch.timeEpochs) {
          const auto va = metricAcrossRuns(batch, prim[i], e, kHorizontal);
          const auto vb = metricAcrossRuns(batch, prim[k], e, kHorizontal);
          const auto tt = mcstats::pairedT(va, vb);
          const auto w = mcstats::wilcoxonSignedRank(va, vb);
          const std::string cls = "num";
          tb.rows.push_back(
              {batch.entries[prim[i]].label, batch.entries[prim[k]].label,
               Cell(durationText(ref.epochTime(e)), "num"), Cell(len(st.at(prim[i], e, kHorizontal).mean), "num"),
               Cell(len(st.at(prim[k], e, kHorizontal).mean), "num"), Cell(len(tt.meanDiff), "num"),
               Cell("[" + len(tt.ciLow) + ", " + len(tt.ciHigh) + "]", "num"),
               Cell(num(tt.t, 3), "num"), Cell(pText(tt.p), tt.p < 0.05 ? "num warn" : "num"),
               Cell(pText(w.p), w.p < 0.05 ? "num warn" : "num")});
        }
    page.heading("Model against model");
    page.table(tb);
  }

  // Error budget: per model, its effects ranked by their share at the last report time.
  for (std::size_t m : prim) {
    std::vector<std::size_t> variants;
    for (std::size_t v = 0; v < batch.entries.size(); ++v)
      if (batch.entries[v].parent == int(m)) variants.push_back(v);
    if (variants.empty()) continue;
    const std::size_t eLast = batch.timeEpochs.back();
    std::vector<std::pair<BudgetShare, std::size_t>> ranked;
    for (std::size_t v : variants) ranked.emplace_back(budgetShare(batch, m, v, eLast), v);
    std::stable_sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) {
      return a.first.share > b.first.share;  // NaN shares (no drift) keep their place at the end
    });
    const std::string& label = batch.entries[m].label;
    page.heading("Error budget of " + label);
    BarChart chart{"Share of the mean-square horizontal error at " +
                       durationText(ref.epochTime(eLast)) + ", largest first",
                   "share of E[h²] [%]", {}};
    for (const auto& [b, v] : ranked)
      chart.bars.push_back({batch.entries[v].removed, 100.0 * b.share,
                            percentText(100.0 * b.share) + " % ± " + percentText(100.0 * b.se),
                            paletteColor(0)});
    page.bars(chart, "Effects with a negative or zero share (their removal does not reduce the "
                     "drift) have no bar.");
    Table tb;
    tb.caption = "Share of each effect: (E[h²] − E[h²] without the effect) / E[h²], h the horizontal "
                 "error, E the mean over the runs; the kept effects draw the same random numbers, "
                 "so the difference is paired. Shares of independent effects add up to about 1.";
    tb.header = {"effect", "t", "share", "± se", "RMS without"};
    for (const auto& [first, v] : ranked)
      for (std::size_t e : batch.timeEpochs) {
        const BudgetShare b = budgetShare(batch, m, v, e);
        tb.rows.push_back({batch.entries[v].removed, Cell(durationText(ref.epochTime(e)), "num"),
                           Cell(num(b.share, 3), "num"), Cell(num(b.se, 2), "num"),
                           Cell(len(b.rmsWithout), "num")});
      }
    page.table(tb);
  }

  if (batch.measured) {
    Table tb;
    tb.caption = "Percentile of the measured horizontal error within each model's runs at the same "
                 "epoch (mid-rank); near 50 the model predicts the measured drift, near 0 or 100 "
                 "it does not.";
    tb.header = {"model", "t", "measured", "model median", "model 95 %", "percentile"};
    for (std::size_t m : prim)
      for (std::size_t e : batch.timeEpochs) {
        auto v = metricAcrossRuns(batch, m, e, kHorizontal);
        std::sort(v.begin(), v.end());
        const double h = metricValue(batch.measured->errors.data() + e * kErrorFields, kHorizontal);
        const double p = mcstats::percentileOf(v, h);
        tb.rows.push_back({batch.entries[m].label, Cell(durationText(ref.epochTime(e)), "num"),
                           Cell(len(h), "num"), Cell(len(st.at(m, e, kHorizontal).p[0]), "num"),
                           Cell(len(st.at(m, e, kHorizontal).p[2]), "num"),
                           Cell(num(p, 3), (p < 2.5 || p > 97.5) ? "num fail" : "num pass")});
      }
    page.heading("Measured record " + batch.measured->source + " against the models");
    page.table(tb);
  }
  return page.html();
}

}  // namespace sinsim::sim
