#include "sim/aided/known_errors.hpp"

#include <cmath>

#include "errormodels/effect.hpp"

namespace sinsim::sim::aided {
namespace {

using errormodels::EffectList;
using errormodels::EffectSpec;

// A scale_factor's off-diagonal entries as a misalignment (u ← (I + M) u alike), or nothing.
bool offDiagonalPart(const EffectSpec& e, EffectSpec& out) {
  const Mat3 S = errormodels::matrix3Of(e);
  Mat3 M = S;
  M.diagonal().setZero();
  if (M.isZero(0.0)) return false;
  std::vector<double> rowMajor(9);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) rowMajor[std::size_t(3 * i + j)] = M(i, j);
  out = EffectSpec::make("misalignment",
                         {errormodels::ParamSpec::matrix("matrix", rowMajor, Dimension::none())});
  out.where = e.where;
  return true;
}

}  // namespace

bool isKnownEffect(const std::string& type) {
  return type == "misalignment" || type == "g_sensitivity" || type == "ramp" ||
         type == "warmup" || type == "sinusoid" || type == "temperature";
}

errormodels::ErrorModelSpec knownPart(const errormodels::ErrorModelSpec& spec, bool linear) {
  errormodels::ErrorModelSpec known;
  known.source = spec.source;
  for (errormodels::Sensor s : {errormodels::Sensor::gyro, errormodels::Sensor::accel})
    for (EffectList l : {EffectList::triad, EffectList::all, EffectList::x, EffectList::y,
                         EffectList::z})
      for (const EffectSpec& e : spec.sensor(s).list(l)) {
        if (!e.enabled) continue;
        EffectSpec offDiagonal;
        if (isKnownEffect(e.type) && (e.type == "misalignment") == linear)
          known.sensor(s).list(l).push_back(e);
        else if (linear && e.type == "scale_factor" && offDiagonalPart(e, offDiagonal))
          known.sensor(s).list(l).push_back(std::move(offDiagonal));
      }
  return known;
}

KnownErrors::KnownErrors(const errormodels::ImuErrorModel& added,
                         const errormodels::ImuErrorModel& linear, double imuRate) {
  if (!added.empty()) added_ = added.instantiate(imuRate, errormodels::StreamKey{});
  for (const std::string& name : added.effectNames())
    sensesForce_ = sensesForce_ || name.find("g_sensitivity") != std::string::npos;
  if (!linear.empty()) linear_ = linear.instantiate(imuRate, errormodels::StreamKey{});
}

// s less what the corruptor c adds to it at the sensor temperature [K].
ImuSample KnownErrors::less(const ImuSample& s, errormodels::ImuCorruptor& c, double temperature) {
  ImuSample with = s;
  c.corrupt(with, temperature);
  ImuSample out = s;
  out.dtheta_b -= with.dtheta_b - s.dtheta_b;
  out.dv_b -= with.dv_b - s.dv_b;
  return out;
}

// The corruptor reads the specific force from the sample it corrupts; the other added errors do
// not depend on the signal.
ImuSample KnownErrors::withoutAdded(const ImuSample& s, const Vec3& dv, double temperature) {
  if (!added_) return s;
  ImuSample forced = s;
  forced.dv_b = dv;
  const ImuSample compensated = less(forced, *added_, temperature);
  ImuSample out = s;
  out.dtheta_b = compensated.dtheta_b;
  out.dv_b += compensated.dv_b - dv;
  return out;
}

// x = (I + K)^-1 s by two fixed-point steps x <- s - K x from x = s: error O(K^3 s).
ImuSample KnownErrors::withoutLinear(const ImuSample& s) {
  if (!linear_) return s;
  ImuSample x = less(s, *linear_, NAN);
  ImuSample Kx = x;
  linear_->corrupt(Kx, NAN);
  x.dtheta_b = s.dtheta_b - (Kx.dtheta_b - x.dtheta_b);
  x.dv_b = s.dv_b - (Kx.dv_b - x.dv_b);
  return x;
}

}  // namespace sinsim::sim::aided
