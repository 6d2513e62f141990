// The diagnosis report (diagnose_report.hpp).
#include "sim/diagnose_report.hpp"

#include <cmath>
#include <cstdio>

#include "common/atomic_file.hpp"
#include "common/number_text.hpp"
#include "sim/report/report.hpp"

namespace sinsim {

namespace dg = errormodels::diagnose;
using namespace report;

namespace {

const char* kMeas = "#1f77b4";    // measurement
const char* kModel = "#ff7f0e";   // model (before)
const char* kAfter = "#2ca02c";   // improved model
const char* kFail = "#d62728";    // failing ranges

std::string fmt(double v, int digits = 3) {
  return significant(v, digits);
}

std::vector<double> scaled(const std::vector<double>& v, double f) {
  std::vector<double> o(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) o[i] = v[i] / f;
  return o;
}

/// Half the geometric step between neighbouring points (shades cover whole points).
double halfStep(const std::vector<double>& x) {
  return x.size() > 1 ? std::sqrt(x[1] / x[0]) : 1.5;
}

/// Measurement, model and the model's band on log-log axes, the ranges where the measurement
/// leaves the band shaded. `statistic` ("adev" or "psd") selects the failing ranges; values are
/// divided by `factor` (SI → display unit).
Plot bandPlot(const dg::AxisDiagnosis& a, const dg::Comparison& c, const std::string& statistic,
              double factor, Plot p, const std::string& shadeLabel) {
  p.xLog = p.yLog = true;
  const double h = halfStep(c.x);
  bool first = true;
  for (const auto& r : a.fails)
    if (r.statistic == statistic) {
      p.add(Shade(r.from / h, r.to * h, kFail, first ? shadeLabel : ""));
      first = false;
    }
  p.add(Band("model band", c.x, scaled(c.lo, factor), scaled(c.hi, factor), kModel));
  p.add(Series("model", c.x, scaled(c.model, factor), kModel));
  p.add(Series("measurement", c.x, scaled(c.meas, factor), kMeas, false, 1.6, true));
  return p;
}

Plot adevPlot(const dg::AxisDiagnosis& a, const std::string& title) {
  return bandPlot(a, a.adev, "adev", a.unitFactor,
                  Plot(title, "averaging time τ [s]", "σ(τ) [" + a.unit + "]"),
                  "measurement outside the band");
}

Plot psdPlot(const dg::AxisDiagnosis& a) {
  return bandPlot(a, a.psd, "psd", a.unitFactor * a.unitFactor,
                  Plot("PSD — " + a.channel, "frequency [Hz]", "PSD [(" + a.unit + ")²/Hz]"),
                  "outside the band");
}

Plot acfPlot(const dg::AxisDiagnosis& a) {
  Plot p("ACF — " + a.channel, "lag [s]", "normalised autocorrelation");
  p.add(Band("model band", a.acf.x, a.acf.lo, a.acf.hi, kModel));
  p.add(Series("model", a.acf.x, a.acf.model, kModel));
  p.add(Series("measurement", a.acf.x, a.acf.meas, kMeas));
  return p;
}

Table findingsTable(const dg::AxisDiagnosis& a, double threshold, double next) {
  Table t;
  t.header = {"effect", "score", "fitted size", "evidence", "model-file line"};
  t.caption = "Candidate effects for " + a.channel + " (reported when score ≥ " + fmt(threshold) +
              ", a further effect ≥ " + fmt(next) + ")";
  for (const auto& f : a.findings) {
    const bool rep = f.reported;
    t.rows.push_back({Cell(f.effect, rep ? "fail" : "muted"), Cell(fmt(f.score, 3), rep ? "num fail" : "num muted"),
                      Cell(f.size, rep ? "" : "muted"), Cell(f.evidence, rep ? "" : "muted"),
                      Cell(rep ? dg::effectText(f.spec, a.channel) : "", "muted")});
  }
  return t;
}

std::string verdict(const dg::AxisDiagnosis& a) {
  if (a.fits()) return "fits";
  std::string s;
  for (const auto& f : a.findings)
    if (f.reported) s += (s.empty() ? "missing: " : ", ") + f.effect;
  if (a.leftUnexplained()) s += std::string(s.empty() ? "" : ", ") + "unexplained";
  return s.empty() ? "misfit, no catalogue effect explains it" : s;
}

/// A shell command broken before its options into lines of at most ~90 characters (" \\").
std::string wrapCommand(const std::string& cmd) {
  std::string out, line;
  std::size_t at = 0;
  while (at < cmd.size()) {
    std::size_t next = cmd.find(" --", at + 1);
    if (next == std::string::npos) next = cmd.size();
    const std::string piece = cmd.substr(at, next - at);
    if (!line.empty() && line.size() + piece.size() > 90) {
      out += line + " \\\n   ";
      line.clear();
    }
    line += piece;
    at = next;
  }
  return out + line;
}

/// "What still fails" after --add, and the command to run next.
void nextSteps(HtmlPage& page, const dg::Diagnosis& d, const dg::Improvement* imp,
               const DiagnoseCommand& cmd) {
  page.heading("What next");
  if (imp) {
    std::string still;
    for (const auto& a : imp->after.axes)
      if (!a.fits())
        still += (still.empty() ? "" : "; ") + a.channel + " (" + verdict(a) +
                 ", misfit " + fmt(a.misfit) + ", " + fmt(100 * a.fractionOutside, 2) +
                 " % of τ outside the band)";
    page.paragraph(still.empty() ? "After the additions every channel fits."
                                 : "Still failing after the additions: " + still + ".");
    const std::string& m = cmd.improvedModel.empty() ? cmd.model : cmd.improvedModel;
    if (still.empty())
      page.paragraph("Navigate with the improved model:")
          .preformatted(wrapCommand("sinsim run scenarios/car.yaml --model " + m + " --html run.html"));
    else
      page.paragraph("Diagnose the improved model again (and add what it finds):")
          .preformatted(wrapCommand(cmd.base + " --model " + m + " --html diagnose2.html"));
    return;
  }
  bool anyFail = false, anyFound = false;
  for (const auto& a : d.axes) {
    anyFail = anyFail || !a.fits();
    for (const auto& f : a.findings) anyFound = anyFound || f.reported;
  }
  if (!anyFail)
    page.paragraph("The model fits every channel. Navigate with it:")
        .preformatted(wrapCommand("sinsim run scenarios/car.yaml --model " + cmd.model + " --html run.html"));
  else if (anyFound)
    page.paragraph("Add what was found, refit it to the record and see the misfit before → after:")
        .preformatted(wrapCommand(cmd.base + " --model " + cmd.model + " --add found -o improved.yaml --html improve.html"));
  else
    page.paragraph("No catalogue effect explains the misfit. Fit the record's Allan variance "
                   "jointly (white, quantization, GM, random walk, flicker, drift):")
        .preformatted(wrapCommand("sinsim fit" + cmd.base.substr(std::string("sinsim diagnose").size()) +
                      " --kind latent -o latent.yaml"));
}

// The navigation verdict: its lines, the warning, and the drift at rest (record against the
// models' median and 95 %) and along the scenario.
void navSection(HtmlPage& page, const sim::NavVerdict& v) {
  page.heading("Navigation verdict along " + v.scenario, 2);
  if (!v.warning.empty()) page.paragraph("Warning: " + v.warning);
  page.preformatted(sim::navVerdictText(v).substr(1));
  Plot rest("Horizontal drift at rest: the record against the model", "time [s]", "horizontal error [m]");
  Plot along("Predicted horizontal drift along " + v.scenario, "time [s]", "horizontal error [m]");
  rest.add(Series("record", v.record.t, v.record.p50, kMeas, false, 1.6));
  auto add = [&](const sim::ModelDrift& m, const char* colour, const std::string& name) {
    rest.add(Series(name + " median", m.replay.t, m.replay.p50, colour));
    rest.add(Series(name + " 95 %", m.replay.t, m.replay.p95, colour, true));
    along.add(Series(name + " median", m.scenario.t, m.scenario.p50, colour));
    along.add(Series(name + " 95 %", m.scenario.t, m.scenario.p95, colour, true));
  };
  add(v.model, kModel, "model");
  if (v.improved) add(*v.improved, kAfter, "improved");
  page.plotRow({rest, along});
}

}  // namespace

std::string diagnoseReportHtml(const dg::Diagnosis& d, const dg::Improvement* imp,
                               const DiagnoseCommand* command, const sim::NavVerdict* nav) {
  HtmlPage page("Diagnosis: " + d.model + " against " + d.data);
  page.paragraph(std::to_string(d.samples) + " samples at " + fmt(d.rate, 6) + " Hz; model bands from " +
                 std::to_string(d.realisations) + " Monte Carlo realisations of the model at the record's length and rate (" +
                 fmt(100 * d.bandLevel, 3) + " % central intervals). Misfit = RMS over τ of log10(ADEV_meas / ADEV_model) beyond the RMS a perfect model shows (its estimation-noise floor). "
                 "Score = Gaussian-equivalent significance of a candidate effect (see the README, \"Diagnose\").");
  for (const std::string& w : d.recordWarnings) page.paragraph("Record warning: " + w);
  Table overview;
  overview.header = {"channel", "misfit", "τ outside band", "χ² / points", "Ljung-Box p", "verdict"};
  for (const auto& a : d.axes) {
    const bool ok = a.fits();
    overview.rows.push_back({Cell(a.channel), Cell(fmt(a.misfit), "num"),
                             Cell(fmt(100 * a.fractionOutside, 3) + " %", ok ? "num pass" : "num fail"),
                             Cell(fmt(a.chi2, 4) + " / " + std::to_string(a.chi2Points), "num"),
                             Cell(a.ljungBox ? fmt(a.ljungBox->pValue, 2) : "–", "num"),
                             Cell(verdict(a), ok ? "pass" : "fail")});
  }
  page.table(overview);
  if (imp) {
    Table t;
    t.caption = "After adding the effects";
    t.header = {"channel", "misfit before", "misfit after", "τ outside before", "after", "added"};
    for (const auto& ch : imp->changes) {
      std::string added;
      for (const auto& x : ch.added) added += (added.empty() ? "" : "; ") + dg::effectText(x, ch.channel);
      t.rows.push_back({Cell(ch.channel), Cell(fmt(ch.misfitBefore), "num"),
                        Cell(fmt(ch.misfitAfter), ch.misfitAfter <= 0.5 * ch.misfitBefore ? "num pass" : "num"),
                        Cell(fmt(100 * ch.fractionOutsideBefore, 3) + " %", "num"),
                        Cell(fmt(100 * ch.fractionOutsideAfter, 3) + " %",
                             ch.fractionOutsideAfter <= 0.1 ? "num pass" : "num warn"),
                        Cell(added.empty() ? "–" : added)});
    }
    page.table(t);
    for (const auto& n : imp->notes) page.paragraph("Note: " + n);
  }
  if (nav) navSection(page, *nav);
  if (command) nextSteps(page, d, imp, *command);
  for (const auto& a : d.axes) {
    page.heading(a.channel + " — " + verdict(a) + " (misfit " + fmt(a.misfit) + ")", 2);
    std::string fails;
    for (const auto& r : a.fails)
      fails += (fails.empty() ? "" : "; ") + r.statistic + " " + fmt(r.from) + "–" + fmt(r.to) +
               (r.statistic == "adev" ? " s " : " Hz ") + (r.direction > 0 ? "above" : "below") +
               " the band (×" + fmt(r.worstRatio) + ")";
    page.paragraph(fails.empty() ? "The measurement stays inside the model's band everywhere."
                                 : "Where it fails: " + fails + ".");
    page.plotRow({adevPlot(a, "Allan deviation — " + a.channel), psdPlot(a)});
    page.plotRow({acfPlot(a)});
    page.table(findingsTable(a, d.threshold, d.nextThreshold));
    for (const std::string& u : dg::unexplainedSentences(a)) page.paragraph("Unexplained: " + u + ".");
    if (const std::string s = dg::switchingSentence(a); !s.empty()) page.paragraph("Level steps: " + s + ".");
    if (imp) {
      const auto& after = imp->after.axis(a.channel);
      Plot p("Before → after — " + a.channel, "averaging time τ [s]", "σ(τ) [" + a.unit + "]");
      p.xLog = p.yLog = true;
      const double f = a.unitFactor;
      p.add(Band("improved model band", after.adev.x, scaled(after.adev.lo, f), scaled(after.adev.hi, f), kAfter));
      p.add(Series("model before", a.adev.x, scaled(a.adev.model, f), kModel, true));
      p.add(Series("improved model", after.adev.x, scaled(after.adev.model, f), kAfter));
      p.add(Series("measurement", a.adev.x, scaled(a.adev.meas, f), kMeas, false, 1.6, true));
      page.plot(p, "misfit " + fmt(a.misfit) + " → " + fmt(after.misfit) + ", τ outside the band " +
                       fmt(100 * a.fractionOutside, 3) + " % → " + fmt(100 * after.fractionOutside, 3) + " %");
    }
  }
  return page.html();
}

void writeDiagnoseReport(const std::string& path, const dg::Diagnosis& d, const dg::Improvement* imp,
                         const DiagnoseCommand* command, const sim::NavVerdict* nav) {
  const std::string html = diagnoseReportHtml(d, imp, command, nav);
  writeFileAtomic(path, html);
}

}  // namespace sinsim
