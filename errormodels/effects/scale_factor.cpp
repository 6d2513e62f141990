// `scale_factor`: scale-factor error of a triad, u ← (I + S) u on the ideal increments.
//   value: 300 ppm                     the same on every axis
//   diagonal: [300 ppm, -200 ppm, 0]   per axis
//   matrix: [[..], [..], [..]]         full 3×3 (off-diagonal terms act like misalignment)
//   sigma: 3000 ppm                    optional: each diagonal entry gets its own N(0, sigma²),
//                                      drawn once per run (x, y, z from the effect's stream)
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
  ScaleFactor(const Mat3& S, double sigma) : S_(S), sigma_(sigma) {}
  Stage stage() const override { return Stage::linear; }
  std::unique_ptr<EffectState> instantiate(const InstanceContext& ctx) const override {
    Mat3 S = S_;
    if (sigma_ > 0) {  // no draw without a sigma: a fixed scale factor keeps its streams unused
      NormalStream w = ctx.stream();
      for (int i = 0; i < 3; ++i) S(i, i) += sigma_ * w.next();
    }
    return std::make_unique<LinearState>(S);
  }

 private:
  Mat3 S_;
  double sigma_;  // [-]
};

}  // namespace

const std::vector<ParamSchema>& paramsOf_scale_factor() {
  static const std::vector<ParamSchema> p = [] {
    std::vector<ParamSchema> m = matrixParams(fixed(Dimension::none()), false);
    m.push_back(param("sigma", ParamKind::quantity, fixed(Dimension::none()))
                    .optional("0").nonNegative().zeroWithoutUnit()
                    .doc("standard deviation of each diagonal entry's turn-on part, drawn once per run"));
    return m;
  }();
  return p;
}

std::unique_ptr<Effect> buildEffect_scale_factor(const EffectSpec& spec, const EffectSite&,
                                                 SpecProblems&) {
  return std::make_unique<ScaleFactor>(matrix3Of(spec), valueOr(spec, "sigma", 0.0));
}

}  // namespace sinsim::errormodels
