// Quantization. On a value lattice (exact evidence) its Allan slope tells rounding of each sample
// (white) from an increment output with the remainder carried (slope -1), and the lattice says
// the LSB. Without a lattice to see, it can only be quantization noise in the sense of IEEE Std 952
// and GMWM (their QN): the remainder of an integrating output whose input moves by many LSBs,
// uniform and independent from sample to sample, Allan variance 3 Q^2/tau^2 -- a candidate of free
// size like white noise, chosen by the trial only where the record's short-tau excess falls as
// tau^-2. (Before trial selection a lattice-free candidate was a signature score of any short-tau
// excess, which a base bent by a hidden trend also shows; it was removed then, issue 5.)
// Each sample rounded adds q^2/12 of white variance only when the noise sd is >= about q/2; on a
// coarser lattice the rounded record's short-scale variance depends on where its level sits in
// the cell and may lie below the input's, so the added variance is taken from the record
// (roundingAddedVariance; a fixed q^2/12 above the record's short-tau AVAR cost the trial ~2e4).
// The rounding variant's Allan term is the model's own realisations rounded onto the lattice at
// the record's level less the same unrounded (montecarlo.cpp), when measured: a correlated input
// rounded coarsely has a correlated rounding error, which no white term describes.
#include "errormodels/diagnose/detector.hpp"
#include "errormodels/diagnose/rounding.hpp"
#include "errormodels/diagnose/significance.hpp"
#include "errormodels/stats/lattice.hpp"

#include <cmath>

namespace sinsim::errormodels::diagnose::detail {

namespace {

/// Quantization noise without a lattice: rate error (r[k-1] - r[k]) / dt, r uniform and
/// independent of variance Q^2 (angle or velocity units). theta = 3 Q^2: AVAR theta / tau^2 exactly
/// at every tau = m dt (the mean over m samples is (r[0] - r[m]) / (m dt)), autocovariance
/// (2/3, -1/3) theta / dt^2 at lags 0 and 1. Written as the catalogue's dithered quantization, LSB
/// sqrt(12) Q = 2 sqrt(theta) of the increment.
Candidate quantizationNoise(const DetectorContext& ctx) {
  const Units& u = ctx.units;
  const double dt = ctx.dt;
  Candidate c;
  c.effect = "quantization";
  c.parameters = 1;
  c.g = ctx.shape([](double t) { return 1.0 / (t * t); });
  c.acovSpan = 2;
  c.acov = [dt](std::size_t maxLag) {
    std::vector<double> r(maxLag + 1, 0.0);
    r[0] = 2.0 / (3.0 * dt * dt);
    if (maxLag >= 1) r[1] = -1.0 / (3.0 * dt * dt);
    return r;
  };
  c.evidence = "Allan deviation falling with slope -1 (3 Q^2/tau^2) where the model is too low, and no value "
               "lattice: quantization noise (IEEE 952 Q) of an output whose input moves by many LSBs";
  const Dimension increment = ctx.signal * Dimension::time();
  c.describe = [u, increment](double theta, Finding& f) {
    const double lsb = 2.0 * std::sqrt(std::max(theta, 0.0)), Q = lsb / std::sqrt(12.0);
    f.size = "Q = " + quantity(Q, u.increment) + " (LSB " + quantity(lsb, u.increment) + ", dithered)";
    f.spec = EffectSpec::make("quantization", {ParamSpec::quantity("lsb", stated(lsb, u.increment), increment),
                                               ParamSpec::flagValue("dithered", true)});
    f.params["lsb"] = lsb;
    f.params["Q"] = Q;
  };
  return c;
}

}  // namespace

std::vector<Candidate> detect_quantization(const DetectorContext& ctx) {
  const double q = ctx.lattice, dt = ctx.dt;
  if (!(q > 0)) return {quantizationNoise(ctx)};
  const Units& u = ctx.units;
  const double added = roundingAddedVariance(channelData(ctx.record, ctx.channel), q);  // [SI^2]
  const double share = added / ctx.var;
  // On a lattice coarser than the noise the rounding removes variance (most samples round to one
  // value): said so, as the unrounded input's variance against the record's.
  const std::string ev = "values on a lattice of " + quantity(q, u.level) + " (" +
                         "differences are integer multiples of it); " +
                         (share >= 0.0 ? "rounding adds " + num(100 * share, 3) + " % of the sample variance"
                                       : "rounding removes variance: the unrounded input's would be " +
                                             num(1.0 - share, 3) + "x the record's") +
                         " at the shortest scales";
  Candidate rateLsb;
  rateLsb.effect = "quantization";
  rateLsb.freeSize = false;
  rateLsb.g = ctx.shape([&](double t) { return added * dt / t; });  // white
  // The model's own realisations rounded onto the lattice say exactly what the rounding adds at
  // every tau: on a lattice coarser than the noise the rounding error of a correlated input is
  // itself correlated (and may remove variance), which no white term describes.
  if (ctx.roundingAvar.size() == rateLsb.g.size()) {
    rateLsb.g = ctx.roundingAvar;
    rateLsb.roundedRealisations = true;
  }
  rateLsb.roundingVar = added;
  rateLsb.keepsBaseLevel = added < 0.0;  // the rounding hides noise: g holds at the base's level
  rateLsb.zSpecial = kMaxScore;
  rateLsb.lsbRate = q;
  rateLsb.evidence = ev + "; each sample rounded alone (white rounding noise)";
  const Dimension signalDim = ctx.signal;
  rateLsb.describe = [q, u, signalDim](double, Finding& f) {
    f.size = "LSB " + quantity(q, u.level) + " (rate output, each sample rounded)";
    f.spec = EffectSpec::make("quantization", {ParamSpec::quantity("lsb", stated(q, u.level), signalDim)});
    f.params["lsb"] = q;
    f.params["lattice"] = q;
  };
  Candidate carry = rateLsb;
  carry.carry = true;
  carry.roundedRealisations = false;
  // Increment output with carry: AVAR = 3 Q^2 / tau^2, Q = q dt / sqrt(12) (IEEE 952 C).
  carry.g = ctx.shape([&](double t) { return q * q * dt * dt / (4.0 * t * t); });
  carry.evidence = ev + "; remainder carried (Allan slope -1)";
  carry.describe = [q, dt, u, signalDim](double, Finding& f) {
    f.size = "LSB " + quantity(q * dt, u.increment) + " (increment output, carried)";
    // An increment LSB: the effect carries the remainder (effects/quantization.cpp).
    f.spec = EffectSpec::make("quantization", {ParamSpec::quantity("lsb", stated(q * dt, u.increment),
                                                                   signalDim * Dimension::time())});
    f.params["lsb"] = q * dt;
    f.params["lattice"] = q;
  };
  // A variant whose nominal Allan variance at one sample (q^2/12 rounded per sample, q^2/4
  // carried) is below the scatter of the record's own there (relative sd sqrt(3/N) for white
  // noise) is no effect any statistic here can see: the printing precision of a CSV (9.81 written
  // with 7 digits sits on a 1e-6 lattice whose rounding is 1e-10 of a MEMS accelerometer's
  // variance), not a sensor's LSB. Nominal, not the variance the rounding added to this record: on
  // a lattice coarser than the noise that can be ~0 while the rounding shapes every sample.
  std::vector<Candidate> out;
  if (latticeVisible(ctx.y, q)) out.push_back(std::move(rateLsb));
  if (latticeVisible(ctx.y, q, true)) out.push_back(std::move(carry));
  if (out.empty()) out.push_back(quantizationNoise(ctx));  // a lattice no rounding of it can show
  return out;
}

}  // namespace sinsim::errormodels::diagnose::detail
