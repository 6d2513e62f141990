#include "errormodels/fit/model_writer.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <utility>

#include "common/error.hpp"
#include "common/units.hpp"
#include "common/number_text.hpp"
#include "errormodels/fit/block_likelihood.hpp"
#include "errormodels/model_io.hpp"

namespace sinsim::errormodels::fit {

namespace {

// Output units per sensor and quantity: the model writer's (displayUnit); the factor comes from
// the same parser that reads them.
struct Units {
  std::string level;      // signal: sigma, B
  std::string density;    // signal * sqrt(time): N
  std::string walk;       // signal / sqrt(time): K
  std::string increment;  // signal * time: quantization LSB
  std::string slope;      // signal / time: ramp
};
Units unitsOf(Sensor s) {
  const Dimension sig = s == Sensor::gyro ? Dimension::angularRate() : Dimension::acceleration();
  const Dimension t = Dimension::time();
  return {displayUnit(sig, s), displayUnit(sig * t.sqrt(), s), displayUnit(sig / t.sqrt(), s),
          displayUnit(sig * t, s), displayUnit(sig / t, s)};
}
const Units& unitsFor(SensorSignal s) {
  static const Units gyro = unitsOf(Sensor::gyro), accel = unitsOf(Sensor::accel);
  return s == SensorSignal::Gyro ? gyro : accel;
}

// "<value in unit> <unit>" with 9 significant digits (relative rounding <= 5e-9).
std::string q(double si, const std::string& unit) {
  const double factor = parseUnit(unit).si;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g %s", si / factor, unit.c_str());
  return buf;
}

// The same with 4 significant digits, for comments that state an estimate with its uncertainty.
std::string q4(double si, const std::string& unit) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4g %s", si / parseUnit(unit).si, unit.c_str());
  return buf;
}

std::string num(double v, int digits = 10) {
  return significant(v, digits);
}

Sensor sensorOf(SensorSignal s) { return s == SensorSignal::Gyro ? Sensor::gyro : Sensor::accel; }
Dimension signalOf(SensorSignal s) {
  return s == SensorSignal::Gyro ? Dimension::angularRate() : Dimension::acceleration();
}

// The effects of one list as they are built: comment lines wait for the next effect, and those
// left at the end are the list's trailing comments.
struct ListBuilder {
  std::vector<EffectSpec>& effects;
  std::vector<std::string>& trailing;
  std::vector<std::string> pending;
  std::ostringstream line;

  /// Ends the comment line being written with `<<` on `line`.
  void endComment() {
    pending.push_back(line.str());
    line.str("");
  }
  void add(EffectSpec e) {
    e.comments = std::move(pending);
    pending.clear();
    effects.push_back(std::move(e));
  }
  void finish() { trailing = std::move(pending); }
};

ParamSpec withSigma(ParamSpec p, std::vector<double> sigma) {
  p.sigma = std::move(sigma);
  return p;
}

void addAr(ListBuilder& b, const ArFit& ar, double rate, const Units& u, Dimension signal,
           const std::optional<OrderSelection>& orders, const std::string& what) {
  if (!(std::isfinite(rate) && rate > 0.0))
    throw InputError("model writer: " + what + ": the AR rate must be a positive frequency");
  b.line << "AR(" << ar.order << ") by " << toString(ar.method) << ", N = " << ar.n
         << " samples at " << num(rate, 7) << " Hz, mean removed " << num(ar.mean, 7)
         << " (SI). sigma = sqrt(E), E = " << num(ar.drivingVariance, 7) << " +- "
         << num(ar.drivingVarianceStdError, 2) << " (SI^2)";
  b.endComment();
  b.line << "1-sigma of a1..a" << ar.order << " (sigma^2 Gamma^-1 / N):";
  for (double s : ar.stdError) b.line << ' ' << num(s, 3);
  b.endComment();
  b.line << "largest pole " << num(arMaxPoleMagnitude(ar.a), 6);
  b.endComment();
  if (orders) {
    b.line << "order criteria: AIC -> " << orders->aicOrder << ", MDL -> " << orders->mdlOrder
           << ", FPE -> " << orders->fpeOrder;
    if (orders->paperOrder)
      b.line << ", paper's rule -> " << *orders->paperOrder << " (T_c "
             << num(*orders->correlationTime * 1e3, 4) << " ms)";
    b.line << "; selected " << orders->selectedOrder << " by " << toString(orders->selectedBy);
    if (orders->paperCapped)
      b.line << " (the rule's order capped at the largest fitted, --max-order " << orders->selectedOrder << ")";
    if (orders->selectedOrder == 0)
      b.line << " (order 0 is white noise; an AR needs one coefficient: AR(1) written, its a1 near 0)";
    b.endComment();
  }
  (void)u;
  const std::vector<double> a(ar.a.begin() + 1, ar.a.end());
  const double sigmaE = std::sqrt(ar.drivingVariance);
  // d sqrt(E) = dE / (2 sqrt(E)), first order.
  const double sigmaEStd = sigmaE > 0 ? ar.drivingVarianceStdError / (2 * sigmaE) : NAN;
  b.add(EffectSpec::make(
      "ar", {withSigma(ParamSpec::numbers("a", a), ar.stdError),
             withSigma(ParamSpec::quantity("sigma", sigmaE, signal), {sigmaEStd}),
             ParamSpec::quantity("rate", rate, Dimension::frequency())}));
}

/// The quantization effect of a fitted LSB (an increment LSB: the remainder carried), dithered
/// where the record shows no lattice it would leave (AxisFitResult::ditheredQuantization).
EffectSpec quantizationSpec(ParamSpec lsb, bool dithered) {
  std::vector<ParamSpec> params{std::move(lsb)};
  if (dithered) params.push_back(ParamSpec::flagValue("dithered", true));
  return EffectSpec::make("quantization", std::move(params));
}

/// `rampSign` (+-1) signs a ramp: the record's trend's (AxisFitResult::trendSlope).
void addAllanTerm(ListBuilder& b, const AllanFit& fit, AllanTermKind kind, const Units& u,
                  Dimension signal, bool dithered, double rampSign) {
  const AllanTerm& t = fit.term(kind);
  if (!t.enabled) return;
  std::string unit;
  double scale = 1.0;  // written value = scale * t.value (SI)
  Dimension dim = signal;
  const Dimension time = Dimension::time();
  switch (kind) {
    case AllanTermKind::Quantization: unit = u.increment; scale = std::sqrt(12.0); dim = signal * time; break;
    case AllanTermKind::White: unit = u.density; dim = signal * time.sqrt(); break;
    case AllanTermKind::BiasInstability: unit = u.level; break;
    case AllanTermKind::RandomWalk: unit = u.walk; dim = signal / time.sqrt(); break;
    case AllanTermKind::Ramp: unit = u.slope; dim = signal / time; break;
  }
  if (!t.detected) {
    b.line << toString(kind) << ": not supported by the data, upper bound "
           << q(scale * t.upperBound, unit) << (kind == AllanTermKind::Quantization ? " (lsb)" : "");
    b.endComment();
    return;
  }
  b.line << toString(kind) << " +- " << q(scale * t.stdError, unit) << " (1 sigma)";
  b.endComment();
  auto value = [&](const char* key, double sign = 1.0) {
    return withSigma(ParamSpec::quantity(key, sign * scale * t.value, dim), {scale * t.stdError});
  };
  switch (kind) {
    case AllanTermKind::Quantization: b.add(quantizationSpec(value("lsb"), dithered)); break;
    case AllanTermKind::White: b.add(EffectSpec::make("white", {value("density")})); break;
    case AllanTermKind::BiasInstability:
      b.add(EffectSpec::make(
          "bias_instability",
          {value("B"), ParamSpec::quantities("tau_range", {fit.tau.front(), fit.tau.back()}, time)}));
      break;
    case AllanTermKind::RandomWalk: b.add(EffectSpec::make("random_walk", {value("K")})); break;
    case AllanTermKind::Ramp: b.add(EffectSpec::make("ramp", {value("slope", rampSign)})); break;
  }
}

/// Beyond this ln half-width (a factor e^20 = 5e8 either way) an interval says only that the
/// record does not bound the parameter: an unidentified term's Wald interval in ln (a rarely
/// included second GM's sigma, ln half-width 1e5) would print as "0..inf".
constexpr double kUnboundedLogWidth = 20.0;

/// A parameter's ln-space 1-sigma interval exp(logCenter - logLower)..exp(logCenter + logUpper)
/// (LatentParameter::logScale), each end formatted by `at`; "not bounded by the record" past
/// kUnboundedLogWidth on either side.
template <class P, class At>
std::string lnRange(const P& p, At at) {
  if (!(p.logLower <= kUnboundedLogWidth && p.logUpper <= kUnboundedLogWidth)) return "not bounded by the record";
  return at(std::exp(p.logCenter - p.logLower)) + ".." + at(std::exp(p.logCenter + p.logUpper));
}

/// The selection-aware statement (LatentFit::averaged) as comments: every parameter of the sets
/// the data support, with its weight of inclusion and the 1-sigma that includes the set choice.
void addLatentAveraged(ListBuilder& b, const LatentFit& f, const Units& u) {
  if (f.averaged.empty()) return;
  b.line << "averaged over the term sets (weight exp(-score/2); value if present +- 1 sigma incl. the set "
            "choice, weight of inclusion):";
  b.endComment();
  for (const auto& a : f.averaged) {
    const std::string& n = a.name;
    const bool tau = n.size() > 4 && n.compare(n.size() - 4, 4, ".tau") == 0;
    double k = 1.0;  // the stated quantity per fitted amplitude (an LSB is sqrt(12) quantization sd)
    std::string unit = u.level;  // sigma, flicker, ar.sigma
    if (n == "quantization") k = std::sqrt(12.0), unit = u.increment;
    else if (n == "white") unit = u.density;
    else if (n == "random_walk") unit = u.walk;
    else if (n == "drift") unit = u.slope;
    auto at = [&](double si) { return tau ? num(si, 4) + " s" : q4(k * si, unit); };
    std::string value = at(a.value) + " +- " + (tau ? num(a.stdError, 3) + " s" : q4(k * a.stdError, unit)) +
                        (n == "quantization" ? " (lsb)" : "");
    if (a.logScale)  // the ln-space interval (a tau's profile, an amplitude's Wald in ln; LatentParameter)
      value += std::string(tau ? " (profile" : " (ln-space") + " 1-sigma " + lnRange(a, at) + ")";
    b.line << "  " << n << " " << value << ", weight " << num(a.inclusion, 2);
    b.endComment();
  }
}

/// The latent fit's terms (latent_fit.hpp), each with its 1-sigma as a comment and in the spec;
/// a drift signed by its GLS slope (LatentFit::driftSlope) or else by `rampSign` (+-1, the record's
/// least-squares trend's).
void addLatent(ListBuilder& b, const LatentFit& f, const Units& u, Dimension signal, bool dithered,
               double latticeLsb, double rampSign) {
  const double rate = 1.0 / f.sampleInterval;
  b.line << "composite latent-process fit (GLS on the octave Allan variance, tau "
         << num(f.tau.front(), 4) << ".." << num(f.tau.back(), 6) << " s): " << f.terms.name()
         << "; chi2 " << num(f.chi2, 4) << " / " << f.dof << " dof (p = " << num(f.pValue, 3) << ")";
  if (f.blockSelected)
    b.line << "; set chosen by the exact likelihood of the block means with the periodogram above them";
  else if (f.whittleSelected)
    b.line << "; set chosen by the Whittle likelihood of the periodogram";
  if (const LatentCandidate* r = f.runnerUp()) {
    const LatentCandidate& c = f.candidates.front();
    const bool k = f.blockSelected && std::isfinite(r->blockScore);
    const bool w = !k && f.whittleSelected && std::isfinite(r->whittleScore);
    const double delta = k ? r->blockScore - c.blockScore : w ? r->whittleScore - c.whittleScore : r->score - c.score;
    b.line << "; runner-up " << r->terms.name() << " (" << (k ? "block " : w ? "Whittle " : "") << "score "
           << num(delta, 3) << " higher)";
  }
  b.endComment();
  if (!f.parameterNote.empty()) {
    b.line << f.parameterNote;
    b.endComment();
  }
  for (const auto& w : f.warnings) {
    b.line << "WARNING: " << w;
    b.endComment();
  }
  addLatentAveraged(b, f, u);
  auto sd = [&](const std::string& name) { return f.parameter(name).stdError; };
  // An amplitude's ln-space 1-sigma interval (LatentParameter::logScale), in the comment's unit.
  auto ln = [&](const std::string& name, double k, const std::string& unit) {
    return "; ln-space " + lnRange(f.parameter(name), [&](double si) { return q4(k * si, unit); });
  };
  const Dimension time = Dimension::time();
  const LatentModel& m = f.model;
  if (m.quantization > 0.0) {
    const double k = std::sqrt(12.0);  // LSB of the quantization noise Q
    if (latticeLsb > 0.0) {
      b.line << "quantization lsb: the record's value lattice step times the sample interval, exact (the Allan "
                "fit gave " << q(k * m.quantization, u.increment) << " +- " << q(k * sd("quantization"), u.increment)
             << ")";
      b.endComment();
      if (m.lattice.correlated()) {
        b.line << "the true integral moves " << significant(m.lattice.motion / m.lattice.step, 3)
               << " LSB per sample (white noise): successive roundings are correlated, fitted with their exact "
                  "Allan variance (fit/lattice_rounding.hpp); the simulator's quantization rounds the same way";
        b.endComment();
      }
      b.add(quantizationSpec(ParamSpec::quantity("lsb", latticeLsb, signal * time), false));
    } else {
      b.line << "quantization lsb +- " << q(k * sd("quantization"), u.increment) << " (1 sigma"
             << ln("quantization", k, u.increment) << ")";
      b.endComment();
      b.add(quantizationSpec(withSigma(ParamSpec::quantity("lsb", k * m.quantization, signal * time),
                                       {k * sd("quantization")}),
                             dithered));
    }
  }
  if (m.white > 0.0) {
    // LatentParameter::gmConventionShift, flickerConventionShift: the other discretisations, which
    // the record fits alike (above the 1-sigma line, which stays next to its effect)
    const LatentParameter& white = f.parameter("white");
    const std::pair<double, const char*> others[] = {
        {white.gmConventionShift, "the GM averaged over each sample interval (an integrating sensor) instead of "
                                  "sampled as written"},
        {white.flickerConventionShift, "the flicker sampled at each instant (digital 1/f noise) instead of "
                                       "averaged over each interval"}};
    for (const auto& [shift, how] : others)
      if (std::fabs(shift) > 1e-3 * m.white) {
        b.line << "white would be " << q(m.white + shift, u.density) << " with " << how
               << ": the record fits both alike; the difference is in the 1 sigma";
        b.endComment();
      }
    b.line << "white +- " << q(sd("white"), u.density) << " (1 sigma" << ln("white", 1.0, u.density) << ")";
    b.endComment();
    b.add(EffectSpec::make("white", {withSigma(ParamSpec::quantity("density", m.white,
                                                                   signal * time.sqrt()),
                                               {sd("white")})}));
  }
  if (m.arVariance > 0.0) {
    // The AR term (fit/ar_slow_fit.hpp): Burg's polynomial, its driving sigma = sqrt(E) refitted
    // with the other terms; `rate:` the record's, the rate the polynomial belongs to.
    b.line << "ar: AR(" << m.arPolynomial.size() - 1 << "), driving sigma +- " << q(sd("ar.sigma"), u.level)
           << " (1 sigma, from the joint fit; the polynomial Burg's, less a value lattice's rounding where a note says"
              " so)";
    b.endComment();
    b.add(EffectSpec::make(
        "ar", {ParamSpec::numbers("a", std::vector<double>(m.arPolynomial.begin() + 1, m.arPolynomial.end())),
               withSigma(ParamSpec::quantity("sigma", std::sqrt(m.arVariance), signal), {sd("ar.sigma")}),
               ParamSpec::quantity("rate", rate, Dimension::frequency())}));
  }
  for (std::size_t g = 0; g < m.gm.size(); ++g) {
    const std::string n = "gm" + std::to_string(g + 1);
    const LatentParameter& tau = f.parameter(n + ".tau");
    b.line << n << ": sigma +- " << q(sd(n + ".sigma"), u.level) << " (1 sigma" << ln(n + ".sigma", 1.0, u.level)
           << "), tau +- " << num(tau.stdError, 4) << " s (1 sigma; profile-likelihood 1-sigma interval "
           << lnRange(tau, [](double v) { return num(v, 4) + " s"; }) << ")";
    b.endComment();
    b.add(EffectSpec::make(
        "gauss_markov",
        {withSigma(ParamSpec::quantity("sigma", m.gm[g].sigma, signal), {sd(n + ".sigma")}),
         withSigma(ParamSpec::quantity("tau", m.gm[g].tau, time), {sd(n + ".tau")}),
         ParamSpec::quantity("rate", rate, Dimension::frequency())}));
  }
  if (m.flicker > 0.0) {
    b.line << "flicker +- " << q(sd("flicker"), u.level) << " (1 sigma" << ln("flicker", 1.0, u.level) << ")";
    b.endComment();
    b.add(EffectSpec::make(
        "bias_instability",
        {withSigma(ParamSpec::quantity("B", m.flicker, signal), {sd("flicker")}),
         ParamSpec::quantities("tau_range", {f.tau.front(), f.tau.back()}, time)}));
  }
  if (m.randomWalk > 0.0) {
    b.line << "random_walk +- " << q(sd("random_walk"), u.walk) << " (1 sigma"
           << ln("random_walk", 1.0, u.walk) << ")";
    b.endComment();
    b.add(EffectSpec::make("random_walk", {withSigma(ParamSpec::quantity("K", m.randomWalk,
                                                                         signal / time.sqrt()),
                                                     {sd("random_walk")})}));
  }
  if (m.drift > 0.0) {
    const bool gls = std::isfinite(f.driftSlope);
    if (gls) rampSign = f.driftSlope < 0.0 ? -1.0 : 1.0;
    b.line << "drift (ramp) +- " << q(sd("drift"), u.slope) << " (1 sigma" << ln("drift", 1.0, u.slope)
           << (gls ? "; the GLS slope of the record's block means under the other terms"
                   : "; its size from the Allan variance, its sign the record's least-squares trend's")
           << (f.trendDrift ? "; chosen by the likelihood's slope test, where the Allan variance alone put it at zero" : "")
           << ")";
    if (f.driftWalkGap < kDriftSlopeChi2)
      b.line << "; a random_walk of K " << q(f.driftWalkK, u.walk) << " explains this trend nearly as well (-2 log L "
             << num(f.driftWalkGap, 3) << " above the ramp's): a ramp repeats in every Monte Carlo run, a walk's "
             << "trend does not";
    b.endComment();
    b.add(EffectSpec::make("ramp", {withSigma(ParamSpec::quantity("slope", rampSign * m.drift, signal / time),
                                              {sd("drift")})}));
  }
}

void addAxis(ListBuilder& b, const AxisFitResult& ax, const std::string& what) {
  const Units& u = unitsFor(ax.sensor);
  const Dimension signal = signalOf(ax.sensor);
  for (const auto& n : ax.notes) b.pending.push_back(n);
  if (ax.composite) {
    const auto& c = *ax.composite;
    b.line << "composite AR + random walk: K from the Allan curve (tau >= "
           << num(c.allan.tau.front(), 4) << " s), random-walk level removed by an RTS "
           << "smoother (T_s " << num(c.smootherTimeConstant, 4) << " s vs AR T_c "
           << num(c.arCorrelationTime * 1e3, 4) << " ms"
           << (c.separated ? "" : "; NOT well separated") << ")";
    b.endComment();
    addAr(b, c.ar.fit, ax.arRate, u, signal, c.ar, what);
    if (c.randomWalkDetected) {
      b.line << "random_walk +- " << q(c.randomWalk.stdError, u.walk) << " (1 sigma)";
      b.endComment();
      b.add(EffectSpec::make(
          "random_walk", {withSigma(ParamSpec::quantity("K", c.randomWalk.value,
                                                        signal / Dimension::time().sqrt()),
                                    {c.randomWalk.stdError})}));
    } else {
      b.line << "random_walk: not detected, upper bound " << q(c.randomWalk.upperBound, u.walk);
      b.endComment();
    }
  }
  if (ax.ar) addAr(b, *ax.ar, ax.arRate, u, signal, ax.arOrders, what);
  if (ax.gaussMarkov) {
    const auto& g = *ax.gaussMarkov;
    b.line << "first-order GM from the ACF (lags " << g.firstLag << ".." << g.lastLag
           << "): sigma +- " << q(g.sigmaStdError, u.level) << ", tau +- "
           << num(g.tauStdError, 4) << " s"
           << (g.bartlettCovariance ? " (Bartlett)" : " (LS residuals; underestimates)");
    b.endComment();
    b.add(EffectSpec::make(
        "gauss_markov",
        {withSigma(ParamSpec::quantity("sigma", g.sigma, signal), {g.sigmaStdError}),
         withSigma(ParamSpec::quantity("tau", g.tau, Dimension::time()), {g.tauStdError})}));
  }
  const double rampSign = ax.trendSlope < 0.0 ? -1.0 : 1.0;
  if (ax.latent) addLatent(b, *ax.latent, u, signal, ax.ditheredQuantization, ax.latticeLsb, rampSign);
  if (ax.roundedRateLsb > 0.0) {
    b.line << "quantization lsb: the record's value lattice, exact; each sample rounded (a rate output)";
    b.endComment();
    b.add(EffectSpec::make("quantization", {ParamSpec::quantity("lsb", ax.roundedRateLsb, signal)}));
  }
  if (ax.allan) {
    b.line << "Allan-term fit: " << ax.allan->pointsUsed << " points, tau "
           << num(ax.allan->tau.front(), 4) << ".." << num(ax.allan->tau.back(), 6) << " s, chi2 "
           << num(ax.allan->chi2, 4) << " / " << ax.allan->dof << " dof"
           << (ax.allan->correlated ? ", correlated points (GLS)" : ", independent points");
    b.endComment();
    for (std::size_t j = 0; j < kAllanTermCount; ++j)
      if (ax.allanWrite[j])
        addAllanTerm(b, *ax.allan, static_cast<AllanTermKind>(j), u, signal, ax.ditheredQuantization, rampSign);
  }
  for (const FittedLine& l : ax.lines) {
    b.line << "a narrow line, taken out of the record before the noise terms were fitted (phase at "
              "the first sample used)";
    b.endComment();
    b.add(EffectSpec::make("sinusoid", {ParamSpec::quantity("amplitude", l.amplitude, signal),
                                        ParamSpec::quantity("frequency", l.frequency, Dimension::frequency()),
                                        ParamSpec::quantity("phase", l.phase, Dimension::angle())}));
  }
  b.finish();
}

}  // namespace

ErrorModelSpec modelSpec(const std::vector<AxisFitResult>& axes, const ModelProvenance& p) {
  ErrorModelSpec spec;
  spec.headerComments.push_back("Error model fitted by sinsim (errormodels/fit).");
  if (!p.dataFile.empty()) spec.headerComments.push_back("data: " + p.dataFile);
  if (p.rate > 0.0) spec.headerComments.push_back("rate: " + num(p.rate, 10) + " Hz");
  if (p.duration > 0.0) spec.headerComments.push_back("duration: " + num(p.duration, 10) + " s");
  if (!p.method.empty()) spec.headerComments.push_back("method: " + p.method);
  for (const auto& n : p.notes) spec.headerComments.push_back(n);
  std::string desc = p.description.empty() ? "fitted error model" : p.description;
  for (char& c : desc)
    if (c == '\n' || c == '"') c = ' ';
  spec.description = desc;
  if (p.duration > 0.0) spec.recordDuration = p.duration;
  std::map<std::pair<int, std::string>, int> seen;
  for (const auto& ax : axes) {
    if (ax.axis != "x" && ax.axis != "y" && ax.axis != "z" && ax.axis != "all")
      throw InputError("model writer: axis must be x, y, z or all, got \"" + ax.axis + "\"");
    const Sensor sensor = sensorOf(ax.sensor);
    const std::string what = std::string(sensorName(sensor)) + "." + ax.axis;
    if (seen[{int(sensor), ax.axis}]++) throw InputError("model writer: " + what + " given twice");
    const EffectList list = ax.axis == "all" ? EffectList::all
                                             : axisList(ax.axis[0] - 'x');
    SensorSpec& ss = spec.sensor(sensor);
    ss.keepEmpty[int(list)] = true;
    ListBuilder b{ss.list(list), ss.trailing[int(list)], {}, {}};
    addAxis(b, ax, what);
  }
  return spec;
}

std::string modelYaml(const std::vector<AxisFitResult>& axes, const ModelProvenance& provenance) {
  return errorModelYaml(modelSpec(axes, provenance));
}

void writeModelFile(const std::string& path, const std::vector<AxisFitResult>& axes,
                    const ModelProvenance& provenance) {
  writeErrorModel(path, modelSpec(axes, provenance));
}

}  // namespace sinsim::errormodels::fit
