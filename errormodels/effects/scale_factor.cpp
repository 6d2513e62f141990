// `scale_factor`: scale-factor error of a triad, u ← (I + S) u on the ideal increments.
//   value: 300 ppm                     the same on every axis
//   diagonal: [300 ppm, -200 ppm, 0]   per axis
//   matrix: [[..], [..], [..]]         full 3×3 (off-diagonal terms act like misalignment)
#include "errormodels/effect.hpp"

namespace sinsim::errormodels {
namespace {

class LinearState final : public EffectState {
 public:
  explicit LinearState(const Mat3& M) : M_(M) {}
  void apply(Vec3& u, const Interval&) override { u += M_ * u; }

 private:
  Mat3 M_;
};

class ScaleFactor final : public Effect {
 public:
  explicit ScaleFactor(const Mat3& S) : S_(S) {}
  Stage stage() const override { return Stage::linear; }
  std::unique_ptr<EffectState> instantiate(const InstanceContext&) const override {
    return std::make_unique<LinearState>(S_);
  }

 private:
  Mat3 S_;
};

}  // namespace

std::unique_ptr<Effect> parseEffect_scale_factor(const ConfigNode& node, const EffectSite&) {
  node.allowKeys({"type", "enabled", "value", "diagonal", "matrix"});
  Mat3 S;
  if (!readMatrix3(node, Dimension::none(), S)) return nullptr;
  return std::make_unique<ScaleFactor>(S);
}

}  // namespace sinsim::errormodels
