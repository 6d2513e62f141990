// `g_sensitivity`: gyro bias proportional to specific force, omega_err_b = G f_b (gyro triad only).
//   value: 0.05 deg/s/g | diagonal: [...] | matrix: [[..], [..], [..]]   (angular rate per accel)
// The corruptor sees both triads of one ImuSample, so the ideal specific force is at hand:
// ∫ G f_b dt = G dv_b over the interval, exact for any f_b(t) since G is constant.
#include "errormodels/effect.hpp"

namespace sinsim::errormodels {
namespace {

class GSensitivityState final : public EffectState {
 public:
  explicit GSensitivityState(const Mat3& G) : G_(G) {}
  void apply(Vec3& u, const Interval& iv) override { u += G_ * iv.dv_ideal_b; }

 private:
  Mat3 G_;  // [rad/s per m/s²] = [rad·s/m]
};

class GSensitivity final : public Effect {
 public:
  explicit GSensitivity(const Mat3& G) : G_(G) {}
  std::unique_ptr<EffectState> instantiate(const InstanceContext&) const override {
    return std::make_unique<GSensitivityState>(G_);
  }

 private:
  Mat3 G_;
};

}  // namespace

std::unique_ptr<Effect> parseEffect_g_sensitivity(const ConfigNode& node, const EffectSite& site) {
  node.allowKeys({"type", "enabled", "value", "diagonal", "matrix"});
  if (site.sensor != Sensor::gyro) {
    node["type"].error("g_sensitivity is a gyro effect (gyro bias per specific force)");
    return nullptr;
  }
  Mat3 G;
  if (!readMatrix3(node, Dimension::angularRate() / Dimension::acceleration(), G)) return nullptr;
  return std::make_unique<GSensitivity>(G);
}

}  // namespace sinsim::errormodels
