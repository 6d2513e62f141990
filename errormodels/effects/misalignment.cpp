// `misalignment`: non-orthogonality / mounting misalignment of a triad, u ← (I + M) u, M with a
// zero diagonal (the diagonal is scale_factor's). Entries are small angles (deg, mrad, arcsec) or
// plain numbers: M(i, j) is the sensitivity of axis i to the true signal along axis j.
//   matrix: [[0, 0.1 deg, -0.05 deg], [0.02 deg, 0, 0.1 deg], [0, 0, 0]]
#include "errormodels/effect.hpp"

namespace sinsim::errormodels {
namespace {

class MisalignmentState final : public EffectState {
 public:
  explicit MisalignmentState(const Mat3& M) : M_(M) {}
  void apply(Vec3& u, const Interval&) override { u += M_ * u; }

 private:
  Mat3 M_;
};

class Misalignment final : public Effect {
 public:
  explicit Misalignment(const Mat3& M) : M_(M) {}
  Stage stage() const override { return Stage::linear; }
  std::unique_ptr<EffectState> instantiate(const InstanceContext&) const override {
    return std::make_unique<MisalignmentState>(M_);
  }

 private:
  Mat3 M_;
};

}  // namespace

std::unique_ptr<Effect> parseEffect_misalignment(const ConfigNode& node, const EffectSite&) {
  node.allowKeys({"type", "enabled", "matrix"});
  Mat3 M;
  if (!node.require("matrix").exists()) return nullptr;
  if (!readMatrix3(node, Dimension::none(), M, /*alsoAngle=*/true)) return nullptr;
  if (M.diagonal().cwiseAbs().maxCoeff() != 0.0) {
    node["matrix"].error("the diagonal must be 0 (scale errors belong to scale_factor)");
    return nullptr;
  }
  return std::make_unique<Misalignment>(M);
}

}  // namespace sinsim::errormodels
