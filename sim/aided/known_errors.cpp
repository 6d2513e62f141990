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

// Calls visit(sensor, list, index in the list, effect, off-diagonal part or nullptr) for each
// enabled known effect of spec, in file order within each list.
template <class Visit>
void forEachKnown(const errormodels::ErrorModelSpec& spec, Visit&& visit) {
  for (errormodels::Sensor s : {errormodels::Sensor::gyro, errormodels::Sensor::accel})
    for (EffectList l : {EffectList::triad, EffectList::all, EffectList::x, EffectList::y,
                         EffectList::z}) {
      const std::vector<EffectSpec>& list = spec.sensor(s).list(l);
      for (std::size_t i = 0; i < list.size(); ++i) {
        const EffectSpec& e = list[i];
        EffectSpec offDiagonal;
        if (!e.enabled) continue;
        if (isKnownEffect(e.type))
          visit(s, l, i, e, nullptr);
        else if (e.type == "scale_factor" && offDiagonalPart(e, offDiagonal))
          visit(s, l, i, e, &offDiagonal);
      }
    }
}

}  // namespace

bool isKnownEffect(const std::string& type) {
  const errormodels::EffectType* t = errormodels::findEffectType(type);
  return t && t->nature == errormodels::Nature::fixed;
}

errormodels::ErrorModelSpec knownPart(const errormodels::ErrorModelSpec& spec, bool linear) {
  errormodels::ErrorModelSpec known;
  known.source = spec.source;
  forEachKnown(spec, [&](errormodels::Sensor s, EffectList l, std::size_t, const EffectSpec& e,
                         const EffectSpec* offDiagonal) {
    const EffectSpec& part = offDiagonal ? *offDiagonal : e;
    if ((part.type == "misalignment") == linear) known.sensor(s).list(l).push_back(part);
  });
  return known;
}

std::vector<std::string> knownLabels(const errormodels::ErrorModelSpec& spec) {
  std::vector<std::string> labels;
  forEachKnown(spec, [&](errormodels::Sensor s, EffectList l, std::size_t i, const EffectSpec& e,
                         const EffectSpec* offDiagonal) {
    labels.push_back(std::string(errormodels::sensorName(s)) + "." + errormodels::listName(l) + "[" +
                     std::to_string(i) + "]." + e.type + (offDiagonal ? " off-diagonal" : ""));
  });
  return labels;
}

KnownErrors::KnownErrors(const errormodels::ImuErrorModel& added,
                         const errormodels::ImuErrorModel& linear, double imuRate) {
  if (!added.empty()) added_ = added.instantiate(imuRate, errormodels::StreamKey{});
  sensesForce_ = added.readsSignal();
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
