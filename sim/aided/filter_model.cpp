#include "sim/aided/filter_model.hpp"

#include <cmath>
#include <string>

#include "common/limits.hpp"
#include "errormodels/effect.hpp"
#include "errormodels/effects/quantization.hpp"
#include "sim/aided/known_errors.hpp"

namespace sinsim::sim::aided {
namespace {

using errormodels::EffectList;
using errormodels::EffectSpec;
using errormodels::Sensor;

const char* kSupported =
    "white, bias, random_walk, gauss_markov, bias_instability, ar, quantization, and bias_jumps and "
    "outliers by their second moments; scale_factor on the triad; and compensates the known "
    "misalignment, g_sensitivity, ramp, warmup, sinusoid and temperature";

void problem(std::vector<Diagnostic>& out, const EffectSpec& e, const std::string& message) {
  out.push_back({e.where.file, e.where.line, e.where.key, e.type + ": " + message});
}

// A bias_instability's Gauss-Markov components, the ones the simulation draws: a state each, but
// a component faster than the filter step (which the step's series cannot take, and which the
// step averages away) enters as white noise of its low-frequency density, N² = 2 σ² τ.
void addFlicker(const EffectSpec& e, double step, SensorAxisModel& axis) {
  const errormodels::FlickerGms g = errormodels::biasInstabilityGmsOf(e);
  for (double tau : g.taus) {
    if (tau < step) {
      const double N2 = 2.0 * g.sigma * g.sigma * tau;
      axis.whiteDensity = std::sqrt(axis.whiteDensity * axis.whiteDensity + N2);
      continue;
    }
    StateBlock b = gaussMarkovState(g.sigma, tau);
    b.name = "bias_instability";
    axis.blocks.push_back(std::move(b));
  }
}

// A quantization as the filter sees it, read by the effect's own rule (quantizationRule).
// Carried (an increment LSB's default, dithered or not): the outputs' running sum is the inputs'
// less the last remainder, within one step, so the integrated angle or velocity is off by a
// bounded amount that does not grow: no state and no noise. Each sample rounded alone (a rate
// LSB's default): on an input busier than the step (or dithered) the rounding errors are
// independent and uniform on +-step/2, white noise of variance step^2/12 at the IMU rate:
// N^2 += step^2 / (12 rate).
void addQuantization(const EffectSpec& e, Sensor sensor, double imuRate, SensorAxisModel& axis) {
  const errormodels::QuantizationRule r = errormodels::quantizationRule(
      e, sensor == Sensor::gyro ? Dimension::angularRate() : Dimension::acceleration());
  if (r.carry || !(std::isfinite(imuRate) && imuRate > 0.0)) return;  // a bad rate: the scenario's error
  const double q = r.rateStep(imuRate);
  axis.whiteDensity = std::hypot(axis.whiteDensity, q / std::sqrt(12.0 * imuRate));
}

// A bias_jumps by the process with its second moments (biasJumpsEquivalentOf): steps a random
// walk, a telegraph a Gauss-Markov; the linear filter that is best for those moments.
void addBiasJumps(const EffectSpec& e, double imuRate, SensorAxisModel& axis) {
  if (!(std::isfinite(imuRate) && imuRate > 0.0)) return;  // a bad rate: the scenario's error
  const errormodels::JumpsEquivalent j = errormodels::biasJumpsEquivalentOf(e, imuRate);
  StateBlock b = j.telegraph ? gaussMarkovState(j.sigma, j.tau) : randomWalkState(j.K);
  b.name = "bias_jumps";
  axis.blocks.push_back(std::move(b));
}

// Adds one effect of an axis to the filter's model of that axis.
void addEffect(const EffectSpec& e, Sensor sensor, double step, double imuRate, SensorAxisModel& axis,
               std::vector<Diagnostic>& problems) {
  using errormodels::valueOr;
  try {
    if (e.type == "white") {
      const double N = errormodels::whiteDensityOf(e);
      axis.whiteDensity = std::sqrt(axis.whiteDensity * axis.whiteDensity + N * N);
    } else if (e.type == "bias") {
      const double value = valueOr(e, "value", 0.0), sigma = valueOr(e, "sigma", 0.0);
      if (value == 0.0 && sigma == 0.0) return;  // a known zero: no state to carry
      StateBlock b = biasState(sigma);
      b.x0(0) = value;
      axis.blocks.push_back(std::move(b));
    } else if (e.type == "random_walk") {
      axis.blocks.push_back(randomWalkState(valueOr(e, "K", NAN)));
    } else if (e.type == "gauss_markov") {
      const double sigma = valueOr(e, "sigma", NAN), tau = valueOr(e, "tau", NAN);
      const double rate = valueOr(e, "rate", 0.0);
      axis.blocks.push_back(rate > 0.0 ? sampledGaussMarkovState(sigma, tau, rate)
                                       : gaussMarkovState(sigma, tau));
    } else if (e.type == "bias_instability") {
      addFlicker(e, step, axis);
    } else if (e.type == "ar") {
      axis.blocks.push_back(arState(errormodels::valuesOf(e, "a"),
                                    errormodels::arDrivingSigmaOf(e), valueOr(e, "rate", NAN)));
    } else if (e.type == "quantization") {
      addQuantization(e, sensor, imuRate, axis);
    } else if (e.type == "bias_jumps") {
      addBiasJumps(e, imuRate, axis);
    } else if (e.type == "outliers") {
      if (std::isfinite(imuRate) && imuRate > 0.0)  // a bad rate: the scenario's error
        axis.whiteDensity = std::hypot(axis.whiteDensity, errormodels::outliersWhiteDensityOf(e, imuRate));
    } else if (isKnownEffect(e.type)) {
      return;  // no state: compensated as known (known_errors.hpp)
    } else {
      problem(problems, e,
              std::string("the GNSS/INS filter has no states for this effect (it carries ") +
                  kSupported + "); leave it out of the filter's model or set enabled: no");
    }
  } catch (const InputError& err) {
    problem(problems, e, err.what());
    return;
  }
  // A sampled process is propagated in whole periods of its rate within each filter step.
  if ((e.type == "ar" || e.type == "gauss_markov") && !axis.blocks.empty() &&
      axis.blocks.back().discrete && axis.blocks.back().period > step * (1.0 + 1e-9))
    problem(problems, e,
            "a process sampled every " + limits::fmt(axis.blocks.back().period) +
                " s is slower than the filter's step of " + limits::fmt(step) +
                " s (the GNSS interval, at most 1 s), which propagates it in whole periods; give "
                "the model at a rate of at least " + limits::fmt(1.0 / step) + " Hz");
}

// A triad's scale_factor effects as one constant state per axis (several add: their means and
// variances, first order in the scale errors); a matrix's off-diagonal part, misalignment and
// g-sensitivity have no states: they are compensated as known (known_errors.hpp).
// Returns the prior mean and variance per axis; an axis with neither gets no state.
void addScaleFactors(const errormodels::SensorSpec& ss, Eigen::Vector3d& mean, Eigen::Vector3d& var,
                     std::vector<Diagnostic>& problems) {
  mean.setZero();
  var.setZero();
  for (const EffectSpec& e : ss.triad) {
    if (!e.enabled) continue;
    if (isKnownEffect(e.type)) continue;
    if (e.type != "scale_factor") {
      problem(problems, e,
              "the GNSS/INS filter has no states for this triad effect (it carries scale_factor "
              "and compensates misalignment and g_sensitivity); leave it out of the filter's "
              "model or set enabled: no");
      continue;
    }
    const Eigen::Matrix3d S = errormodels::matrix3Of(e);
    const double sigma = errormodels::valueOr(e, "sigma", 0.0);
    mean += S.diagonal();
    var += Eigen::Vector3d::Constant(sigma * sigma);
  }
}

}  // namespace

FilterSensorModel filterModelFromSpec(const errormodels::ErrorModelSpec& spec, double step,
                                      double imuRate, std::vector<Diagnostic>& problems) {
  FilterSensorModel m;
  for (Sensor s : {Sensor::gyro, Sensor::accel}) {
    const errormodels::SensorSpec& ss = spec.sensor(s);
    Eigen::Vector3d scaleMean, scaleVar;
    addScaleFactors(ss, scaleMean, scaleVar, problems);
    for (int axis = 0; axis < 3; ++axis) {
      SensorAxisModel& am = s == Sensor::gyro ? m.gyro[axis] : m.accel[axis];
      std::vector<Diagnostic> repeated;  // an `all` effect's problem is reported once, at x
      for (EffectList l : {EffectList::all, errormodels::axisList(axis)})
        for (const EffectSpec& e : ss.list(l))
          if (e.enabled) addEffect(e, s, step, imuRate, am, axis > 0 && l == EffectList::all ? repeated : problems);
      if (scaleMean[axis] != 0.0 || scaleVar[axis] != 0.0) {  // after the axis's own states
        StateBlock b = scaleFactorState(std::sqrt(scaleVar[axis]));
        b.x0(0) = scaleMean[axis];
        am.blocks.push_back(std::move(b));
      }
    }
  }
  return m;
}

FilterSensorModel filterModelFromSpec(const errormodels::ErrorModelSpec& spec, double step,
                                      double imuRate) {
  std::vector<Diagnostic> problems;
  FilterSensorModel m = filterModelFromSpec(spec, step, imuRate, problems);
  if (!problems.empty()) throw ConfigError(problems);
  return m;
}

bool operator==(const StateBlock& a, const StateBlock& b) {
  auto same = [](const auto& x, const auto& y) {
    return x.rows() == y.rows() && x.cols() == y.cols() && x == y;
  };
  return a.name == b.name && a.size == b.size && a.discrete == b.discrete && a.scale == b.scale &&
         a.period == b.period && same(a.F, b.F) && same(a.Qc, b.Qc) && same(a.A, b.A) &&
         same(a.Qs, b.Qs) && same(a.c, b.c) && same(a.P0, b.P0) && same(a.x0, b.x0);
}

bool operator==(const SensorAxisModel& a, const SensorAxisModel& b) {
  return a.whiteDensity == b.whiteDensity && a.blocks == b.blocks;
}

bool operator==(const FilterSensorModel& a, const FilterSensorModel& b) {
  for (int i = 0; i < 3; ++i)
    if (!(a.gyro[i] == b.gyro[i] && a.accel[i] == b.accel[i])) return false;
  return true;
}

}  // namespace sinsim::sim::aided
