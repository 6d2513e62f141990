// A fitted drift against the same trend as a random walk (errormodels/fit/drift_gls.hpp,
// driftWalkAlternative): records made here with std::mt19937_64 (white noise plus a Brownian
// walk or a straight ramp, no sinsim generator), their block means scored under the true white
// noise with the trend as a ramp and as a walk.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "errormodels/fit/block_likelihood.hpp"
#include "errormodels/fit/drift_gls.hpp"

using namespace sinsim::errormodels::fit;

namespace {

constexpr double kRate = 10.0, kDuration = 1200.0, kN = 1e-3;  // [Hz], [s], [U sqrt(s)]
constexpr std::size_t kPerBlock = 4;

struct Scored {
  double slopeChi2 = 0.0;  ///< the GLS slope's b^2 / var(b) under white noise alone
  DriftWalkAlternative walk;
};

/// White noise of density kN plus a walk of K [U/sqrt(s)] and a ramp of R [U/s^2], scored as
/// fit.cpp's drift is: the other terms (here the true white noise) held, the slope profiled out.
Scored scoredRecord(double K, double R, std::uint64_t seed) {
  const double dt = 1.0 / kRate;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g;
  std::vector<double> x(std::size_t(kDuration * kRate));
  double walk = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    walk += K * std::sqrt(dt) * g(rng);
    x[k] = kN / std::sqrt(dt) * g(rng) + walk + R * dt * double(k);
  }
  const BlockMeans means = blockMeans(x, dt, kPerBlock);
  LatentModel white;
  white.white = kN;
  const BlockLikelihood l = blockLikelihood(means, white);
  return {l.m2LogLik - l.m2LogLikDrift, driftWalkAlternative(means, white, l, std::fabs(l.slope))};
}

}  // namespace

// A walk's chance trend passes a ramp's slope test under white noise alone (b^2 / var ~ tens
// here), and the walk fitted to it explains it at least as well: the ramp's gain over the walk
// stays below the drift's own cost (the chi^2_1 1 % point) in >= 36 of 40 records. A ramp at ~12
// sigma of its GLS slope beside white noise is no walk: the gain exceeds that cost in >= 36 of 40.
TEST_CASE("drift against a walk: a walk's trend is told from a ramp's", "[fit][drift]") {
  const double K = 50.0 * kN / kDuration;  // the walk's trend over the record ~ 25x the white's
  const double sdSlope = std::sqrt(12.0 * kN * kN / std::pow(kDuration, 3.0));  // GLS slope sd, white
  int walkPassed = 0, walkLike = 0, rampLike = 0;
  for (std::uint64_t seed = 0; seed < 40; ++seed) {
    const Scored w = scoredRecord(K, 0.0, 5100 + seed);
    INFO("walk seed " << seed << ": slope chi2 " << w.slopeChi2 << ", walk - ramp " << w.walk.gap << ", K "
                      << w.walk.K << " (true " << K << ")");
    CHECK(std::isfinite(w.walk.gap));
    CHECK(w.walk.K > 0.0);
    if (w.slopeChi2 > kDriftSlopeChi2) ++walkPassed, walkLike += w.walk.gap < kDriftSlopeChi2;
    const double sign = seed % 2 ? -1.0 : 1.0;
    const Scored r = scoredRecord(0.0, sign * 12.0 * sdSlope, 5200 + seed);
    INFO("ramp seed " << seed << ": slope chi2 " << r.slopeChi2 << ", walk - ramp " << r.walk.gap);
    rampLike += r.walk.gap >= kDriftSlopeChi2;
  }
  INFO("walk records passing the slope test " << walkPassed << ", walk-like among them " << walkLike
                                              << "; ramps told from a walk " << rampLike << "/40");
  CHECK(walkPassed >= 30);
  CHECK(walkLike >= 0.9 * walkPassed);
  CHECK(rampLike >= 36);
}
