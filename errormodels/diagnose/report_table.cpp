// The terminal table of a diagnosis and of an improvement (diagnose.hpp: summaryTable).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "errormodels/diagnose/channels.hpp"
#include "errormodels/diagnose/diagnose.hpp"
#include "errormodels/diagnose/noise_level.hpp"
#include "errormodels/stats/special.hpp"

namespace sinsim::errormodels::diagnose {

using detail::num;

namespace {

/// s padded to display width w (counting UTF-8 lead bytes).
std::string pad(std::string s, std::size_t w) {
  std::size_t n = 0;
  for (unsigned char ch : s) n += (ch & 0xC0) != 0x80;
  if (n < w) s.append(w - n, ' ');
  return s;
}

/// "level steps at t = 12.5 s (+0.01 deg/s) ..." in the channel's unit: the first kShownSteps, then
/// how many more over which span (a noise whose level rises for a while listed 70 steps in one
/// line; the JSON keeps them all).
std::string stepsText(const AxisDiagnosis& a, const std::vector<LevelStep>& steps) {
  constexpr std::size_t kShownSteps = 8;
  std::ostringstream o;
  o << "level step" << (steps.size() > 1 ? "s" : "") << " at";
  for (std::size_t i = 0; i < steps.size() && i < kShownSteps; ++i)
    o << " t = " << num(steps[i].time, 4) << " s (" << (steps[i].size > 0 ? "+" : "") << num(steps[i].size / a.unitFactor, 3)
      << " " << a.unit << ")";
  if (steps.size() > kShownSteps)
    o << " and " << steps.size() - kShownSteps << " more up to t = " << num(steps.back().time, 4) << " s";
  return o.str();
}

/// Whether a channel that does not fit the model as given (its printed chi2) fits it with the
/// level refitted: no finding, nothing unexplained, and chi2 with the level (chi2_selected) below
/// its 0.999 quantile. The record then differs from the model in its level alone, which no
/// effect of the catalogue is (before, "no effect above threshold" stood beside a chi2 of 75.6/27).
bool levelOnly(const AxisDiagnosis& a) {
  return a.chi2Points > 0 && a.chi2Selected < chiSquareQuantile(0.999, double(a.chi2Points));
}

std::string findingsText(const AxisDiagnosis& a) {
  std::string s;
  for (const auto& f : a.findings)
    if (f.reported) s += (s.empty() ? "" : ", ") + f.effect + " (" + num(f.score, 3) + ")";
  if (a.leftUnexplained()) s += std::string(s.empty() ? "" : ", ") + "unexplained";
  if (s.empty()) s = a.fits() ? "fits" : levelOnly(a) ? "level only (x" + num(std::sqrt(a.noiseScale), 3) + " in ADEV)"
                                                     : "no effect above threshold";
  return s;
}

/// "gx fails: adev 5..900 s above (x4);" and one line per reported finding.
void failsAndFindings(std::ostringstream& o, const AxisDiagnosis& a) {
  bool head = false;
  for (const auto& f : a.fails) {
    if (!head) o << a.channel << " fails:";
    head = true;
    o << " " << f.statistic << " " << num(f.from, 3) << ".." << num(f.to, 3)
      << (f.statistic == "adev" ? " s " : " Hz ") << (f.direction > 0 ? "above" : "below")
      << " (x" << num(f.worstRatio, 3) << ");";
  }
  if (head) o << "\n";
  if (a.modelDrift != 0.0)
    o << "  " << a.channel << " drift: the model's ramp " << detail::quantity(a.modelDrift, detail::unitsFor(detail::channelIndex(a.channel)).slope)
      << " was taken out of the record and the model before the comparison (a ramp found is the slope beyond it)\n";
  for (const ModelWarmup& w : a.modelWarmups)
    o << "  " << a.channel << " drift: the model's warm-up " << detail::quantity(w.amplitude, detail::unitsFor(detail::channelIndex(a.channel)).level)
      << " (tau " << num(w.tau, 4) << " s) was taken out of the record and the model before the comparison (a warm-up found is what is beyond it)\n";
  if (a.modelTemperature)
    o << "  " << a.channel << " drift: the model's temperature polynomial, at the record's temperatures, was taken out of the record and the model before the comparison (a temperature found is what is beyond it)\n";
  for (const auto& f : a.findings)
    if (f.reported) o << "  " << a.channel << " " << f.effect << ": " << f.size << " — " << f.evidence << "\n";
  for (const std::string& u : unexplainedSentences(a)) o << "  " << a.channel << " unexplained: " << u << "\n";
  if (const std::string s = switchingSentence(a); !s.empty()) o << "  " << a.channel << " steps: " << s << "\n";
  // The shapes are compared at the level the record shows (the fitted variance factor s): a base
  // off by more than 2x in ADEV is said (no effect can lower a model that is too high). Beside
  // findings s also absorbs their fit (a line's, a coarse lattice's); a model far above the record
  // scaled down as a whole may leave a finding standing in for a base term it overstated alone (a
  // white density 3x too high beside a right AR: a Gauss-Markov of 0.08 s "found"), said too.
  const bool reported = std::any_of(a.findings.begin(), a.findings.end(), [](const Finding& f) { return f.reported; });
  if (a.noiseScale > 0 && (a.noiseScale < 0.25 || a.noiseScale > 4)) {
    o << "  " << a.channel << " level: the record's noise is x" << num(std::sqrt(a.noiseScale), 3)
      << " the model's base noise in ADEV (Allan variance factor " << num(a.noiseScale, 3)
      << ", fitted with the findings): "
      << (a.noiseLevelChange ? "the record's noise level changes over it (above), which one factor cannot hold"
                             : "check the model's units and densities");
    if (reported && a.noiseScale < 0.25)
      o << "; the findings are sized beside the whole base scaled by that factor, so where the model "
           "overstates one term alone (a white density above the record's) a finding may stand in for the "
           "other terms it scaled down: check the base first";
    o << "\n";
  }
}

}  // namespace

std::vector<std::string> unexplainedSentences(const AxisDiagnosis& a) {
  std::vector<std::string> out;
  if (const auto& u = a.unexplained) {
    std::ostringstream o;
    o << "ADEV " << num(u->from, 3) << ".." << num(u->to, 3) << " s " << (u->direction > 0 ? "above" : "below")
      << " the model with its findings (x" << num(u->worstRatio, 3)
      << "); no candidate of the catalogue lowers the criterion there";
    out.push_back(o.str());
  }
  if (!a.unexplainedSteps.empty())
    out.push_back(stepsText(a, a.unexplainedSteps) +
                  "; no reported finding takes it out (bias_jumps: below the threshold)");
  if (const auto& c = a.noiseLevelChange) {
    std::ostringstream o;
    o << "the noise level changes over the record: the shortest scale's level (mean |first difference|) "
         "in "
      << detail::kNoiseLevelBlocks << " blocks spans x" << num(c->lo, 3) << "..x" << num(c->hi, 3)
      << " of their median, x" << num(c->worst, 3) << " at " << num(c->from, 4) << ".." << num(c->to, 4)
      << " s, where the model's realisations depart at most x" << num(c->modelMost, 3)
      << "; no effect of the catalogue changes with time (a vibration that comes and goes, a noise "
         "that follows temperature): the findings are sized as if it did not; its quiet blocks are x"
      << num(c->quiet, 4) << " the model's level (" << num(c->quietZ, 3) << " sd of its realisations')";
    if (!c->averaged.empty()) {
      std::string names;
      for (const auto& e : c->averaged) names += (names.empty() ? "" : ", ") + e;
      o << ", less than half of what " << names
        << " would add there sized to the whole record: a stationary noise that would mostly average the change, "
           "not named";
    }
    out.push_back(o.str());
  }
  return out;
}

std::string switchingSentence(const AxisDiagnosis& a) {
  if (a.switchingSteps.empty()) return "";
  return stepsText(a, a.switchingSteps) +
         "; they go back and forth: the switching of the gauss_markov found (a telegraph's autocorrelation is a "
         "Gauss-Markov's)";
}

std::string summaryTable(const Diagnosis& d) {
  std::ostringstream o;
  o << "diagnosis of " << d.data << " (" << d.samples << " samples at " << num(d.rate, 6)
    << " Hz) against " << d.model << ", " << d.realisations << " realisations, "
    << num(100 * d.bandLevel, 3) << " % bands, reporting threshold " << num(d.threshold, 3)
    << " (a further effect " << num(d.nextThreshold, 3) << ")\n";
  o << pad("channel", 8) << pad("misfit", 8) << pad("outside", 9) << pad("chi2/K", 13)
    << pad("Ljung-Box p", 13) << "findings (score)\n";
  for (const auto& a : d.axes) {
    o << pad(a.channel, 8) << pad(num(a.misfit, 3), 8)
      << pad(num(100 * a.fractionOutside, 3) + " %", 9)
      << pad(num(a.chi2, 4) + "/" + std::to_string(a.chi2Points), 13)
      << pad(a.ljungBox ? num(a.ljungBox->pValue, 2) : "-", 13) << findingsText(a) << "\n";
  }
  for (const auto& a : d.axes) failsAndFindings(o, a);
  return o.str();
}

std::string summaryTable(const Improvement& imp) {
  std::ostringstream o;
  o << summaryTable(imp.before) << "\n";
  o << pad("channel", 8) << pad("misfit before", 15) << pad("after", 8) << pad("outside before", 16)
    << pad("after", 8) << "added\n";
  for (const auto& ch : imp.changes) {
    std::string added;
    for (const auto& a : ch.added) added += (added.empty() ? "" : "; ") + effectText(a, ch.channel);
    o << pad(ch.channel, 8) << pad(num(ch.misfitBefore, 3), 15) << pad(num(ch.misfitAfter, 3), 8)
      << pad(num(100 * ch.fractionOutsideBefore, 3) + " %", 16)
      << pad(num(100 * ch.fractionOutsideAfter, 3) + " %", 8) << (added.empty() ? "-" : added) << "\n";
  }
  for (const auto& n : imp.notes) o << "note: " << n << "\n";
  return o.str();
}

}  // namespace sinsim::errormodels::diagnose
