// The navigation verdict as terminal lines and as the diagnosis JSON's "navigation" member
// (diagnose_nav.hpp).
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

#include "common/number_text.hpp"
#include "sim/diagnose_nav.hpp"
#include "common/json_text.hpp"

namespace sinsim::sim {
namespace {

std::string tauText(double s) { return s >= 100 ? significant(std::round(s), 6) + " s" : significant(s, 2) + " s"; }

// A time as minutes with one decimal from 2 min on ("34.6 min"), else seconds.
std::string minutes(double s) { return s >= 120 ? significant(s / 60.0, 3) + " min" : significant(s, 3) + " s"; }

std::string pct(double fraction) {
  const double p = 100 * fraction;
  return (p >= 99.5 ? std::string("100") : p >= 10 ? significant(std::round(p), 2) : p >= 0.1 ? significant(p, 2) : std::string("< 0.1")) + " %";
}

std::string verdictWords(const std::string& direction, std::size_t runs, double tail) {
  if (direction == "consistent") return "consistent";
  const bool under = direction == "under-predicts";
  return std::string("the model ") + (under ? "UNDER" : "OVER") + "-predicts it (" +
         (under ? "above" : "below") + " all " + std::to_string(runs) +
         " runs; a correct model leaves a record there in " + significant(tail, 2) + " % of cases)";
}

std::string modelLines(const ModelDrift& d, const NavVerdict& v) {
  std::string s = "  " + d.label + ": drift along " + v.scenario + " at " + minutes(v.duration) +
                  ": median " + lengthText(d.scenario.endP50(), 3) + ", 95 % " +
                  lengthText(d.scenario.endP95(), 3) + "\n";
  if (!d.terms.empty()) {
    s += "    driven by";
    for (std::size_t i = 0; i < d.terms.size() && i < 3; ++i)
      s += std::string(i ? ", " : " ") + d.terms[i].sensor + " " + d.terms[i].effect + " (" +
           pct(d.terms[i].share) + ")";
    s += " of the mean-square drift (each term alone, same seeds)\n";
  }
  const BandVerdict& b = d.bands;
  s += "    at rest, tau " + tauText(b.from) + " - " + tauText(b.to) + " drives the drift (" +
       pct(b.shareInBand) + "); the record's drift from there: " + lengthText(b.recordDrift, 3) +
       ", the model's median " + lengthText(b.modelP50, 3) + ", 95 % " + lengthText(b.modelP95, 3) +
       " -> percentile " + significant(b.percentile, 3) + ": " +
       verdictWords(b.direction, v.runs, d.tail) + "\n";
  if (b.excessBand >= 0) {
    const std::size_t j = std::size_t(b.excessBand);
    s += "    but at tau " + tauText(b.tau[j]) + " the record drifts " + lengthText(b.record[j], 3) + ", " +
         significant(b.record[j] / b.modelRms[j], 3) + "x the model's rms there (" +
         lengthText(b.modelRms[j], 3) + ", beyond all " + std::to_string(v.runs) +
         " runs): the model lacks what drives the record's drift at that tau\n";
  }
  s += "    the record at rest drifts " + lengthText(v.record.endP50(), 3) + " in " +
       minutes(v.replayDuration) + "; the model at rest: median " + lengthText(d.replay.endP50(), 3) +
       ", 95 % " + lengthText(d.replay.endP95(), 3) + " -> percentile " +
       significant(d.recordPercentile, 3) + " (median over time " + significant(d.medianPercentile, 3) +
       "): " + verdictWords(d.direction, v.runs, d.tail) + "\n";
  return s;
}

nlohmann::json curveJson(const DriftCurve& c) {
  return {{"t_s", c.t}, {"horizontal_p50_m", c.p50}, {"horizontal_p95_m", c.p95}};
}

nlohmann::json modelJson(const ModelDrift& d) {
  nlohmann::json terms = nlohmann::json::array();
  for (const auto& t : d.terms)
    terms.push_back({{"sensor", t.sensor},
                     {"effect", t.effect},
                     {"mean_square_m2", t.meanSquare},
                     {"share", t.share},
                     {"deterministic", t.deterministic}});
  const BandVerdict& b = d.bands;
  const nlohmann::json bands{{"tau_s", b.tau},
                             {"share", b.share},
                             {"model_rms_m", b.modelRms},
                             {"record_m", b.record},
                             {"driving_tau_from_s", b.from},
                             {"driving_tau_to_s", b.to},
                             {"driving_share", b.shareInBand},
                             {"driving_model_p50_m", b.modelP50},
                             {"driving_model_p95_m", b.modelP95},
                             {"driving_record_m", b.recordDrift},
                             {"driving_record_percentile", b.percentile},
                             {"driving_direction", b.direction},
                             {"record_linear_m", b.recordLinear},
                             {"excess_tau_s", b.excessBand >= 0 ? nlohmann::json(b.tau[std::size_t(b.excessBand)])
                                                                : nlohmann::json(nullptr)}};
  return {{"model", d.label},
          {"scenario_drift", curveJson(d.scenario)},
          {"replay_drift", curveJson(d.replay)},
          {"terms", terms},
          {"record_percentile", d.recordPercentile},
          {"record_median_percentile_over_time", d.medianPercentile},
          {"direction", d.direction},
          {"tail_percent", d.tail},
          {"bands_at_rest", bands}};
}

nlohmann::json verdictJson(const NavVerdict& v) {
  nlohmann::json j{{"scenario", v.scenario},
                   {"duration_s", v.duration},
                   {"replay_duration_s", v.replayDuration},
                   {"bias_window_s", v.biasWindow},
                   {"runs", v.runs},
                   {"term_runs", v.termRuns},
                   {"seed", v.seed},
                   {"record_drift", {{"t_s", v.record.t}, {"horizontal_m", v.record.p50}}},
                   {"model", modelJson(v.model)},
                   {"definitions",
                    "drift = horizontal position error [m] of a free-inertial run with the first "
                    "bias_window_s of (measured - ideal) removed; terms: each (sensor, effect) "
                    "alone along the scenario, share of the summed mean square at the end; "
                    "direction: the record's drift at rest above (under-predicts) or below "
                    "(over-predicts) every run of the model at rest"}};
  if (v.improved) {
    j["improved"] = modelJson(*v.improved);
    j["drift_ratio"] = v.ratio;
    j["warn_ratio"] = v.warnRatio;
    j["warning"] = v.warning;
  }
  return j;
}

const TermShare* findTerm(const std::vector<TermShare>& terms, const TermShare& t) {
  for (const auto& u : terms)
    if (u.sensor == t.sensor && u.effect == t.effect) return &u;
  return nullptr;
}

}  // namespace

std::string navWarningText(const NavVerdict& v) {
  if (!v.improved || !(v.ratio > v.warnRatio || v.ratio < 1.0 / v.warnRatio)) return "";
  const bool up = v.ratio > 1.0;
  std::vector<std::pair<double, const TermShare*>> moved;  // change of mean square [m²]
  for (const auto& t : v.improved->terms) {
    const TermShare* was = findTerm(v.model.terms, t);
    const double change = t.meanSquare - (was ? was->meanSquare : 0.0);
    if (up ? change > 0 : change < 0) moved.emplace_back(std::fabs(change), &t);
  }
  // A group the improved model dropped (an edited model without the random walk): its whole mean
  // square went; the warning named no group for such a fall.
  std::vector<const TermShare*> dropped;
  if (!up)
    for (const auto& t : v.model.terms)
      if (!findTerm(v.improved->terms, t)) moved.emplace_back(t.meanSquare, &t), dropped.push_back(&t);
  std::sort(moved.begin(), moved.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::string s = "the improved model predicts " + significant(v.ratio, 3) +
                  "x the horizontal drift of the model along " + v.scenario + " (median " +
                  lengthText(v.improved->scenario.endP50(), 3) + " vs " +
                  lengthText(v.model.scenario.endP50(), 3) + " at the end)";
  bool deterministic = false;
  for (std::size_t i = 0; i < moved.size() && i < 3; ++i) {
    const TermShare& t = *moved[i].second;
    const bool gone = std::find(dropped.begin(), dropped.end(), &t) != dropped.end();
    s += std::string(i == 0 ? "; it comes from " : ", ") + t.sensor + " " + t.effect + " (" +
         (gone ? "left out: it held " + pct(t.share) + " of the model's mean-square drift"
               : pct(t.share) + " of the improved model's mean-square drift, " +
                     pct(t.deterministic) + " of it deterministic") +
         ")";
    deterministic = deterministic || (up && t.deterministic > 0.5);
  }
  s += ".";
  if (deterministic)
    s += " A deterministic term (warm-up, ramp, a fixed bias) acts the same in every run from "
         "t = 0, like an uncalibrated bias; a navigation start that calibrates the bias "
         "(alignment, a longer --bias-window in mc) removes most of it: check that before using "
         "the improved model for navigation.";
  return s;
}

std::string navVerdictText(const NavVerdict& v) {
  std::string s = "\nNavigation verdict along " + v.scenario + " (" + minutes(v.duration) + ", " +
                  std::to_string(v.runs) + " runs per model; the record replayed at rest for " +
                  minutes(v.replayDuration) + ", bias window " + significant(v.biasWindow, 3) +
                  " s; horizontal drift):\n";
  s += modelLines(v.model, v);
  if (v.improved) s += modelLines(*v.improved, v);
  if (!v.warning.empty()) s += "  WARNING: " + v.warning + "\n";
  return s;
}

std::string diagnoseJsonWithNav(const errormodels::diagnose::Diagnosis& d, const NavVerdict* v) {
  nlohmann::json j = errormodels::diagnose::toJsonValue(d);
  if (v) j["navigation"] = verdictJson(*v);
  return jsonText(j, 1);
}

std::string diagnoseJsonWithNav(const errormodels::diagnose::Improvement& imp, const NavVerdict* v) {
  nlohmann::json j = errormodels::diagnose::toJsonValue(imp);
  if (v) j["navigation"] = verdictJson(*v);
  return jsonText(j, 1);
}

}  // namespace sinsim::sim
