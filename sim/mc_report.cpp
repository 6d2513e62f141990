// report.html of a Monte Carlo batch (sim/report: self-contained, inline SVG, deterministic).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/constants.hpp"
#include "common/number_text.hpp"
#include "sim/mc_output.hpp"
#include "sim/mc_stats.hpp"
#include "sim/report/report.hpp"

namespace sinsim::sim {
namespace {

std::string num(double v, int sig = 4) {
  if (!std::isfinite(v)) return "–";
  return significant(v, sig);
}

std::string pText(double p) {
  if (!std::isfinite(p)) return "–";
  char buf[64];
  if (p < 1e-4) std::snprintf(buf, sizeof buf, "%.1e", p);
  else std::snprintf(buf, sizeof buf, "%.4f", p);
  return buf;
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

  // Drift envelopes side by side, on one y range.
  double yMax = 0;
  for (std::size_t m : prim)
    for (std::size_t e = 0; e < st.epochs; ++e)
      if (std::isfinite(st.at(m, e, kHorizontal).p[2]))
        yMax = std::max(yMax, st.at(m, e, kHorizontal).p[2]);
  if (!(yMax > 0)) yMax = 1;
  page.heading("Horizontal drift envelopes");
  std::vector<Plot> side;
  const std::vector<double> zero(st.epochs, 0.0);
  for (std::size_t i = 0; i < prim.size(); ++i) {
    const std::size_t m = prim[i];
    Plot p(batch.entries[m].label, "time [s]", "horizontal error [m]");
    const std::string& c = paletteColor(i);
    p.add(Band{"0 – 95 %", t, zero, column(m, kHorizontal, 2), c, 0.15});
    p.add(Band{"0 – 68 %", t, zero, column(m, kHorizontal, 1), c, 0.25});
    p.add(Series{"median", t, column(m, kHorizontal, 0), c, false, 1.8, false});
    p.add(Series{"99 %", t, column(m, kHorizontal, 3), c, true, 1.2, false});
    if (batch.measured) {
      std::vector<double> y(st.epochs);
      for (std::size_t e = 0; e < st.epochs; ++e)
        y[e] = metricValue(batch.measured->errors.data() + e * kErrorFields, kHorizontal);
      p.add(Series{"measured", t, y, "#000000", false, 1.5, false});
    }
    p.yRange = std::make_pair(0.0, 1.05 * yMax);
    side.push_back(p);
  }
  page.plotRow(side);

  {
    Plot p("Models together: median (solid) and 95 % (dashed)", "time [s]",
           "horizontal error [m]");
    for (std::size_t i = 0; i < prim.size(); ++i) {
      const std::string& c = paletteColor(i);
      p.add(Series{batch.entries[prim[i]].label + " median", t, column(prim[i], kHorizontal, 0), c,
                   false, 1.8, false});
      p.add(Series{batch.entries[prim[i]].label + " 95 %", t, column(prim[i], kHorizontal, 2), c,
                   true, 1.4, false});
    }
    Plot v("Vertical error: median and 95 %", "time [s]", "vertical error [m]");
    Plot y("Yaw error: median and 95 % of |δψ|", "time [s]", "|yaw error| [deg]");
    for (std::size_t i = 0; i < prim.size(); ++i) {
      const std::string& c = paletteColor(i);
      v.add(Series{batch.entries[prim[i]].label + " median", t, column(prim[i], kVertical, 0), c,
                   false, 1.8, false});
      v.add(Series{batch.entries[prim[i]].label + " 95 %", t, column(prim[i], kVertical, 2), c,
                   true, 1.4, false});
      auto deg = [](std::vector<double> a) {
        for (double& x : a) x *= kDegPerRad;
        return a;
      };
      y.add(Series{batch.entries[prim[i]].label + " median", t, deg(column(prim[i], kYawAbs, 0)),
                   c, false, 1.8, false});
      y.add(Series{batch.entries[prim[i]].label + " 95 %", t, deg(column(prim[i], kYawAbs, 2)),
                   c, true, 1.4, false});
    }
    page.plotRow({p, v, y});
  }

  // Statistics at the report times.
  {
    Table tb;
    tb.caption = "Horizontal error across runs (CEP = median, R95 = 95th percentile), vertical 95th "
                 "percentile, RMS velocity error";
    tb.header = {"model", "t [s]", "CEP [m]", "R95 [m]", "99 % [m]", "RMS [m]", "vertical 95 % [m]",
                 "velocity RMS [m/s]"};
    for (std::size_t m : prim)
      for (std::size_t e : batch.timeEpochs) {
        const MetricStats& h = st.at(m, e, kHorizontal);
        tb.rows.push_back({batch.entries[m].label, Cell(num(ref.epochTime(e), 6), "num"),
                           Cell(num(h.p[0]), "num"), Cell(num(h.p[2]), "num"),
                           Cell(num(h.p[3]), "num"), Cell(num(h.rms), "num"),
                           Cell(num(st.at(m, e, kVertical).p[2]), "num"),
                           Cell(num(st.at(m, e, kVelocity).rms), "num")});
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
    tb.header = {"a", "b", "t [s]", "mean a [m]", "mean b [m]", "mean a − b [m]",
                 "95 % CI [m]", "t", "p (t-test)", "p (Wilcoxon)"};
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
               Cell(num(ref.epochTime(e), 6), "num"), Cell(num(st.at(prim[i], e, kHorizontal).mean), "num"),
               Cell(num(st.at(prim[k], e, kHorizontal).mean), "num"), Cell(num(tt.meanDiff), "num"),
               Cell("[" + num(tt.ciLow) + ", " + num(tt.ciHigh) + "]", "num"),
               Cell(num(tt.t), "num"), Cell(pText(tt.p), tt.p < 0.05 ? "num warn" : "num"),
               Cell(pText(w.p), w.p < 0.05 ? "num warn" : "num")});
        }
    page.heading("Model against model");
    page.table(tb);
  }

  // Error budget.
  bool anyBudget = false;
  for (const auto& en : batch.entries) anyBudget = anyBudget || en.parent >= 0;
  if (anyBudget) {
    Table tb;
    tb.caption = "Share of each effect: (E[h²] − E[h²] without the effect) / E[h²], h the horizontal "
                 "error, E the mean over the runs; the kept effects draw the same random numbers, "
                 "so the difference is paired. Shares of independent effects add up to about 1.";
    tb.header = {"model", "effect", "t [s]", "share", "± se", "RMS without [m]"};
    for (std::size_t m : prim)
      for (std::size_t v = 0; v < batch.entries.size(); ++v) {
        if (batch.entries[v].parent != int(m)) continue;
        for (std::size_t e : batch.timeEpochs) {
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
          tb.rows.push_back({batch.entries[m].label, batch.entries[v].removed,
                             Cell(num(ref.epochTime(e), 6), "num"), Cell(num(mo.mean / ms, 3), "num"),
                             Cell(num(mo.sd / std::sqrt(double(d.size())) / ms, 2), "num"),
                             Cell(num(std::sqrt(msw)), "num")});
        }
      }
    page.heading("Error budget");
    page.table(tb);
  }

  if (batch.measured) {
    Table tb;
    tb.caption = "Percentile of the measured horizontal error within each model's runs at the same "
                 "epoch (mid-rank); near 50 the model predicts the measured drift, near 0 or 100 "
                 "it does not.";
    tb.header = {"model", "t [s]", "measured [m]", "model median [m]", "model 95 % [m]",
                 "percentile"};
    for (std::size_t m : prim)
      for (std::size_t e : batch.timeEpochs) {
        auto v = metricAcrossRuns(batch, m, e, kHorizontal);
        std::sort(v.begin(), v.end());
        const double h = metricValue(batch.measured->errors.data() + e * kErrorFields, kHorizontal);
        const double p = mcstats::percentileOf(v, h);
        tb.rows.push_back({batch.entries[m].label, Cell(num(ref.epochTime(e), 6), "num"),
                           Cell(num(h), "num"), Cell(num(st.at(m, e, kHorizontal).p[0]), "num"),
                           Cell(num(st.at(m, e, kHorizontal).p[2]), "num"),
                           Cell(num(p, 3), (p < 2.5 || p > 97.5) ? "num fail" : "num pass")});
      }
    page.heading("Measured record " + batch.measured->source + " against the models");
    page.table(tb);
  }
  return page.html();
}

}  // namespace sinsim::sim
