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
  bool readsSignal() const override { return true; }
  std::unique_ptr<EffectState> instantiate(const InstanceContext&) const override {
    return std::make_unique<GSensitivityState>(G_);
  }

 private:
  Mat3 G_;
};

}  // namespace

const std::vector<ParamSchema>& paramsOf_g_sensitivity() {
  static const std::vector<ParamSchema> p =
      matrixParams(fixed(Dimension::angularRate() / Dimension::acceleration()), false);
  return p;
}

std::unique_ptr<Effect> buildEffect_g_sensitivity(const EffectSpec& spec, const EffectSite& site,
                                                  SpecProblems& problems) {
  if (site.sensor != Sensor::gyro) {
    problems.add("type", "g_sensitivity is a gyro effect (gyro bias per specific force)");
    return nullptr;
  }
  return std::make_unique<GSensitivity>(matrix3Of(spec));
}

}  // namespace sinsim::errormodels
