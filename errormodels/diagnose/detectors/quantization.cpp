// Quantization: only on a value lattice (exact evidence); its Allan slope then tells rounding of
// each sample (white) from an increment output with the remainder carried (slope -1). Without a
// lattice there is no candidate: the signature is the lattice AND the short-tau excess (issue 5).
// A short-tau excess alone is what a base model fitted to a record with a trend or a transient
// shows (the fit bends its short-tau level), and scoring it as quantization was a false alarm
// that grew with the hidden ramp.
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

#include <cmath>

namespace sinsim::errormodels::diagnose::detail {

std::vector<Candidate> detect_quantization(const DetectorContext& ctx) {
  const double q = ctx.lattice, dt = ctx.dt;
  if (!(q > 0)) return {};
  const Units& u = ctx.units;
  const double added = roundingAddedVariance(channelData(ctx.record, ctx.channel), q);  // [SI^2]
  const double share = added / ctx.var;
  const std::string ev = "values on a lattice of " + quantity(q, u.level) + " (" +
                         "differences are integer multiples of it); rounding adds " +
                         num(100 * share, 3) + " % of the sample variance at the shortest scales";
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
  const double seen = oneSampleAvarScatter(ctx.y, ctx.setup);
  std::vector<Candidate> out;
  if (q * q / 12.0 > seen) out.push_back(std::move(rateLsb));
  if (q * q / 4.0 > seen) out.push_back(std::move(carry));
  return out;
}

}  // namespace sinsim::errormodels::diagnose::detail
