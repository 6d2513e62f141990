#include "errormodels/fit/start_settling.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "errormodels/fit/ar_fit.hpp"
#include "errormodels/fit/block_likelihood.hpp"

namespace sinsim::errormodels::fit {
namespace {

constexpr int kPerOctave = 8;

/// Mean over block j (samples jB .. jB + B - 1, sample k at (k + 1/2) dt) of exp(-t / tau).
std::vector<double> blockShape(std::size_t blocks, std::size_t B, double dt, double tau) {
  const double a = dt / tau;
  // (1/B) sum_{r<B} e^{-(r + 1/2) a} = e^{-a/2} (1 - e^{-aB}) / (B (1 - e^{-a}))
  const double within = std::exp(-0.5 * a) * std::expm1(-a * double(B)) / (double(B) * std::expm1(-a));
  std::vector<double> s(blocks);
  for (std::size_t j = 0; j < blocks; ++j) s[j] = within * std::exp(-a * double(j * B));
  return s;
}

/// The model with its AR term replaced by the white noise of the same long-run variance,
/// dt E / A(1)^2 per unit density (the sum of the AR's autocovariances): what the means of blocks
/// much longer than its correlation time see. None when its slowest pole's correlation time is not
/// below a quarter of a block (there the AR is a slow process at the block scale).
std::optional<LatentModel> blockLevelModel(const LatentModel& model, double dt, std::size_t B) {
  if (model.arPolynomial.empty() || !(model.arVariance > 0.0)) return model;
  const double r = arMaxPoleMagnitude(model.arPolynomial);
  if (!(r < 1.0) || -dt / std::log(r) >= 0.25 * dt * double(B)) return std::nullopt;
  LatentModel m = model;
  m.white = std::sqrt(model.white * model.white + dt * arLongRunVariance(model.arPolynomial, model.arVariance));
  m.arPolynomial.clear();
  m.arVariance = 0.0;
  return m;
}

}  // namespace

std::optional<StartSettling> testStartSettling(const std::vector<double>& x, double dt,
                                               const LatentModel& given) {
  const std::size_t B = blockSize(x.size(), 1);
  if (x.size() / B < kMinBlocks) return std::nullopt;
  const std::optional<LatentModel> blockModel = blockLevelModel(given, dt, B);
  if (!blockModel) return std::nullopt;
  const LatentModel& model = *blockModel;
  const BlockMeans b = blockMeans(x, dt, B);
  const std::size_t M = b.y.size();
  const double L = dt * double(B), T = L * double(M);
  const double lo = 8.0 * L, hi = T / 10.0;
  const double octaves = std::log2(hi / lo);
  if (!(octaves >= 1.0)) return std::nullopt;
  const int count = int(std::floor(octaves * kPerOctave)) + 1;
  std::vector<double> taus(static_cast<std::size_t>(count));
  std::vector<std::vector<double>> shapes;
  for (int k = 0; k < count; ++k) {
    taus[std::size_t(k)] = lo * std::exp2(double(k) / kPerOctave);
    shapes.push_back(blockShape(M, B, dt, taus[std::size_t(k)]));
  }
  const Eigen::MatrixXd A = blockGlsProducts(b, model, shapes);
  // Nuisance columns: the level (1) and a straight trend (t).
  const std::vector<Eigen::Index> nuisance = {1, 2};
  StartSettling best;
  double bestRss = 0.0;
  best.octaves = octaves;
  best.blocks = M;
  for (int k = 0; k < count; ++k) {
    std::vector<Eigen::Index> cols = nuisance;
    cols.push_back(3 + k);
    const Eigen::Index p = Eigen::Index(cols.size());
    Eigen::MatrixXd XX(p, p);
    Eigen::VectorXd a(p);
    for (Eigen::Index u = 0; u < p; ++u) {
      a[u] = A(cols[std::size_t(u)], 0);
      for (Eigen::Index v = 0; v < p; ++v) XX(u, v) = A(cols[std::size_t(u)], cols[std::size_t(v)]);
    }
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(XX);
    if (ldlt.info() != Eigen::Success) continue;
    const Eigen::VectorXd beta = ldlt.solve(a);
    const Eigen::VectorXd unit = Eigen::VectorXd::Unit(p, p - 1);
    const double var = unit.dot(ldlt.solve(unit));
    if (!(var > 0.0) || !std::isfinite(beta[p - 1])) continue;
    const double z = beta[p - 1] / std::sqrt(var);
    if (std::fabs(z) > std::fabs(best.z)) {
      best.z = z;
      bestRss = A(0, 0) - a.dot(beta);  // y'V^-1 y less what the columns explain
      best.amplitude = beta[p - 1];
      best.tau = taus[std::size_t(k)];
    }
  }
  if (best.tau == 0.0) return std::nullopt;
  best.residualScale = bestRss / double(M - nuisance.size() - 1);
  if (best.residualScale > 1.0) best.z /= std::sqrt(best.residualScale);
  best.pValue = std::min(1.0, octaves * std::erfc(std::fabs(best.z) / std::sqrt(2.0)));
  const std::size_t m = std::max<std::size_t>(1, std::size_t(std::llround(best.tau / dt)));
  const double adev = std::sqrt(latentAllanVariance(model, dt, {m}).at(0));
  best.settledAfter = best.tau * std::max(1.0, std::log(std::fabs(best.amplitude) / adev));
  return best;
}

}  // namespace sinsim::errormodels::fit
