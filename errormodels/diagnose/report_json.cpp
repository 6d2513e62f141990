// JSON of a diagnosis and of an improvement (diagnose.hpp: toJson).
#include <nlohmann/json.hpp>

#include "errormodels/diagnose/diagnose.hpp"
#include "common/json_text.hpp"

namespace sinsim::errormodels::diagnose {

namespace {

nlohmann::json curveJson(const Comparison& c, const char* xname) {
  nlohmann::json j;
  j[xname] = c.x;
  j["meas"] = c.meas;
  j["model"] = c.model;
  j["lo"] = c.lo;
  j["hi"] = c.hi;
  j["outside"] = c.outside;
  return j;
}

nlohmann::json failJson(const FailRange& f) {
  return {{"statistic", f.statistic}, {"from", f.from}, {"to", f.to},
          {"unit", f.statistic == "adev" ? "s" : "Hz"}, {"direction", f.direction > 0 ? "above" : "below"},
          {"worst_ratio", f.worstRatio}, {"points", f.points}};
}

nlohmann::json failsJson(const std::vector<FailRange>& fails) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& f : fails) j.push_back(failJson(f));
  return j;
}

nlohmann::json findingsJson(const AxisDiagnosis& a) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& f : a.findings)
    j.push_back({{"effect", f.effect}, {"evidence", f.evidence}, {"size", f.size},
                 {"yaml", effectText(f.spec, a.channel)}, {"params", f.params}, {"score", f.score},
                 {"drop", f.drop}, {"reported", f.reported}});
  return j;
}

nlohmann::json axisJson(const AxisDiagnosis& a) {
  nlohmann::json j;
  j["channel"] = a.channel;
  j["misfit"] = a.misfit;
  j["misfit_raw"] = a.misfitRaw;
  j["misfit_floor"] = a.misfitFloor;
  j["fraction_outside"] = a.fractionOutside;
  j["chi2"] = a.chi2;
  j["chi2_points"] = a.chi2Points;
  j["noise_scale"] = a.noiseScale;
  if (a.modelDrift != 0.0) j["model_drift_si"] = a.modelDrift;  // absent: the model has no ramp
  for (const ModelWarmup& w : a.modelWarmups)  // absent: the model has no warm-up
    j["model_warmups_si"].push_back({{"amplitude", w.amplitude}, {"tau", w.tau}});
  if (a.modelTemperature) j["model_temperature_taken_out"] = true;  // absent: none taken out
  j["fits"] = a.fits();
  j["chi2_selected"] = a.chi2Selected;
  if (a.unexplained) j["unexplained"] = failJson(*a.unexplained);  // absent: nothing unexplained
  for (const auto& st : a.unexplainedSteps)  // absent: no level step left
    j["unexplained_steps"].push_back({{"t_s", st.time}, {"size", st.size}});
  if (const auto& c = a.noiseLevelChange)  // absent: the noise keeps its level
    j["noise_level_change"] = {{"lo", c->lo}, {"hi", c->hi}, {"worst", c->worst}, {"from_s", c->from},
                               {"to_s", c->to}, {"model_most", c->modelMost},
                               {"quiet", c->quiet}, {"quiet_z", c->quietZ}, {"averaged", c->averaged},
                               {"stretches_s", c->stretches}};
  for (const auto& st : a.switchingSteps)  // absent: none a switching process explains
    j["switching_steps"].push_back({{"t_s", st.time}, {"size", st.size}});
  if (a.ljungBox)
    j["ljung_box"] = {{"lags", a.ljungBox->lags}, {"dof", a.ljungBox->dof}, {"Q", a.ljungBox->Q},
                      {"p", a.ljungBox->pValue}};
  else
    j["ljung_box"] = nullptr;
  j["fails"] = failsJson(a.fails);
  j["findings"] = findingsJson(a);
  j["units"] = {{"adev", "SI (rad/s or m/s^2)"}, {"psd", "SI^2/Hz"}, {"tau", "s"}, {"f", "Hz"}};
  j["curves"] = {{"adev", curveJson(a.adev, "tau")}, {"psd", curveJson(a.psd, "f")},
                 {"acf", curveJson(a.acf, "lag")}};
  return j;
}

nlohmann::json diagnosisJson(const Diagnosis& d) {
  nlohmann::json j;
  j["data"] = d.data;
  j["model"] = d.model;
  j["rate_hz"] = d.rate;
  j["samples"] = d.samples;
  j["realisations"] = d.realisations;
  j["threshold"] = d.threshold;
  j["next_threshold"] = d.nextThreshold;
  j["band_level"] = d.bandLevel;
  j["record_warnings"] = d.recordWarnings;
  j["axes"] = nlohmann::json::array();
  for (const auto& a : d.axes) j["axes"].push_back(axisJson(a));
  return j;
}

}  // namespace

std::string toJson(const Diagnosis& d) { return jsonText(toJsonValue(d), 1); }

std::string toJson(const Improvement& imp) { return jsonText(toJsonValue(imp), 1); }

nlohmann::json toJsonValue(const Diagnosis& d) { return diagnosisJson(d); }

nlohmann::json toJsonValue(const Improvement& imp) {
  nlohmann::json j;
  j["model_written"] = imp.model.source;
  j["notes"] = imp.notes;
  j["axes"] = nlohmann::json::array();
  for (const auto& ch : imp.changes) {
    nlohmann::json a = axisJson(imp.before.axis(ch.channel));
    a["misfit_before"] = ch.misfitBefore;
    a["misfit_after"] = ch.misfitAfter;
    a["fraction_outside_before"] = ch.fractionOutsideBefore;
    a["fraction_outside_after"] = ch.fractionOutsideAfter;
    std::vector<std::string> added;
    for (const auto& e : ch.added) added.push_back(effectText(e, ch.channel));
    a["added"] = added;
    a["noise_scale_applied"] = ch.noiseScale;
    a["after"] = axisJson(imp.after.axis(ch.channel));
    j["axes"].push_back(a);
  }
  j["before"] = {{"model", imp.before.model}, {"data", imp.before.data},
                 {"realisations", imp.before.realisations}};
  return j;
}

}  // namespace sinsim::errormodels::diagnose
