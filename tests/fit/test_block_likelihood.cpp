// The block-mean likelihood (errormodels/fit/block_likelihood.hpp): its Kalman filter against the
// restricted Gaussian log-likelihood computed directly from the dense covariance of the block
// means, which is built here sample by sample from each term's autocovariance (not from the
// filter's block laws), and its handling of hostile input.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <Eigen/Dense>

#include "common/constants.hpp"
#include "common/error.hpp"
#include "errormodels/fit/block_likelihood.hpp"

using namespace sinsim::errormodels::fit;

namespace {

constexpr double kDt = 0.01;       // [s]
constexpr std::size_t kB = 5;      // samples per block
constexpr std::size_t kM = 96;     // blocks

/// Covariance of the samples x_k (k = 0..n-1) of the model's white, quantization, GM and random
/// walk terms, from their definitions (latent_model.hpp): white N^2/dt delta; quantization
/// (e_k - e_k-1)/dt with e white of variance Q^2 (e_-1 included); the GM sigma^2 phi^|k-l|; the walk
/// the interval averages of a Brownian motion from 0 at t = 0: K^2 dt (min(k, l) + 1/2), k != l,
/// and K^2 dt (k + 1/3) on the diagonal.
Eigen::MatrixXd sampleCovariance(const LatentModel& m, std::size_t n) {
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(Eigen::Index(n), Eigen::Index(n));
  const double Q2 = m.quantization * m.quantization, K2 = m.randomWalk * m.randomWalk;
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t l = 0; l < n; ++l) {
      const std::size_t d = k > l ? k - l : l - k;
      double v = 0.0;
      if (d == 0) v += m.white * m.white / kDt + 2.0 * Q2 / (kDt * kDt);
      if (d == 1) v -= Q2 / (kDt * kDt);
      for (const GmTerm& g : m.gm) v += g.sigma * g.sigma * std::pow(std::exp(-kDt / g.tau), double(d));
      v += K2 * kDt * (d == 0 ? double(k) + 1.0 / 3.0 : double(std::min(k, l)) + 0.5);
      C(Eigen::Index(k), Eigen::Index(l)) = v;
    }
  return C;
}

struct Dense {
  double level, drift, slope, slopeVariance;
};

/// -2 log L of block means y (without (M - 1) ln 2 pi) with the level profiled out as a diffuse
/// fixed effect (X = [1]): ln det V + y'V^-1 y - (1'V^-1 y)^2 / 1'V^-1 1 + ln 1'V^-1 1 (Harville
/// 1974); `drift` the same with the slope of t_j - t_mid profiled out too (the quadratic form of
/// X = [1, t], the same ln 1'V^-1 1); by Cholesky of the dense V.
Dense denseRestricted(const std::vector<double>& y, const Eigen::MatrixXd& V) {
  const auto M = Eigen::Index(y.size());
  const Eigen::LLT<Eigen::MatrixXd> llt(V);
  REQUIRE(llt.info() == Eigen::Success);
  Eigen::MatrixXd X(M, 2);
  const double L = kDt * double(kB);
  for (Eigen::Index j = 0; j < M; ++j) X(j, 0) = 1.0, X(j, 1) = (double(j) - 0.5 * double(M - 1)) * L;
  const Eigen::VectorXd yv = Eigen::Map<const Eigen::VectorXd>(y.data(), M);
  const Eigen::VectorXd Viy = llt.solve(yv);
  const Eigen::MatrixXd ViX = llt.solve(X);
  const Eigen::Matrix2d XVX = X.transpose() * ViX;
  const Eigen::Vector2d XVy = X.transpose() * Viy;
  const Eigen::Vector2d beta = XVX.ldlt().solve(XVy);
  double logDetV = 0.0;
  for (Eigen::Index i = 0; i < M; ++i) logDetV += 2.0 * std::log(llt.matrixL()(i, i));
  const double common = logDetV + yv.dot(Viy) + std::log(XVX(0, 0));
  return {common - XVy(0) * XVy(0) / XVX(0, 0), common - XVy.dot(beta), beta(1), XVX.inverse()(1, 1)};
}

/// Block means' covariance: (1/B^2) sums of the sample covariance over each pair of blocks.
Eigen::MatrixXd blockCovariance(const Eigen::MatrixXd& C) {
  const auto M = static_cast<Eigen::Index>(kM);
  Eigen::MatrixXd V(M, M);
  for (std::size_t i = 0; i < kM; ++i)
    for (std::size_t j = 0; j < kM; ++j)
      V(Eigen::Index(i), Eigen::Index(j)) =
          C.block(Eigen::Index(i * kB), Eigen::Index(j * kB), Eigen::Index(kB), Eigen::Index(kB)).sum() /
          double(kB * kB);
  return V;
}

std::vector<double> someRecord(std::size_t n) {
  std::mt19937_64 rng(77);
  std::normal_distribution<double> normal;
  std::vector<double> x(n);
  double walk = 0.0;
  for (std::size_t k = 0; k < n; ++k) x[k] = 0.3 + 0.002 * double(k) + normal(rng) + (walk += 0.05 * normal(rng));
  return x;
}

}  // namespace

TEST_CASE("block likelihood: the Kalman filter equals the dense Gaussian likelihood", "[fit][block]") {
  const std::vector<double> x = someRecord(kM * kB + 3);  // the 3 samples beyond the last block are left out
  const BlockMeans b = blockMeans(x, kDt, kB);
  REQUIRE(b.y.size() == kM);
  LatentModel models[4];
  models[0].white = 0.1;                                                   // white alone
  models[1].white = 0.1, models[1].quantization = 0.004;                   // + quantization
  models[2].white = 0.1, models[2].gm = {{0.8, 0.02}, {0.5, 0.4}};         // two GMs, T < L and T > L
  models[3].white = 0.1, models[3].quantization = 0.003, models[3].gm = {{0.6, 0.12}};
  models[3].randomWalk = 0.7;                                              // every stated term
  for (const LatentModel& m : models) {
    const Dense d = denseRestricted(b.y, blockCovariance(sampleCovariance(m, kM * kB)));
    const BlockLikelihood k = blockLikelihood(b, m);
    INFO(m.termNames());
    // Both are exact: they differ by rounding only (the dense Cholesky of a 96 x 96 covariance,
    // condition number <= ~1e5 here, loses ~1e-11 relative; 1e-9 of |-2 log L| ~ 1e2 is 1e-7).
    CHECK(k.m2LogLik == Approx(d.level).epsilon(1e-9));
    CHECK(k.m2LogLikDrift == Approx(d.drift).epsilon(1e-9));
    CHECK(k.slope == Approx(d.slope).epsilon(1e-8));
    CHECK(k.slopeVariance == Approx(d.slopeVariance).epsilon(1e-8));
  }
}

TEST_CASE("block likelihood: GLS products of extra regressors equal the dense Z' V^-1 Z", "[fit][block]") {
  // blockGlsProducts (the filter with more columns) against Z' V^-1 Z from the dense covariance
  // of the block means, Z = [y, 1, t, two settling shapes]: every entry, in the scale of its
  // diagonal (sqrt(A_ii A_jj)).
  const std::vector<double> x = someRecord(kM * kB);
  const BlockMeans b = blockMeans(x, kDt, kB);
  const auto M = Eigen::Index(kM);
  const double L = kDt * double(kB);
  std::vector<std::vector<double>> extra(2, std::vector<double>(kM));
  for (std::size_t j = 0; j < kM; ++j) extra[0][j] = std::exp(-double(j) * L / 0.15), extra[1][j] = std::exp(-double(j) * L / 1.1);
  Eigen::MatrixXd Z(M, 5);
  for (Eigen::Index j = 0; j < M; ++j) {
    Z(j, 0) = b.y[std::size_t(j)], Z(j, 1) = 1.0, Z(j, 2) = (double(j) - 0.5 * double(M - 1)) * L;
    Z(j, 3) = extra[0][std::size_t(j)], Z(j, 4) = extra[1][std::size_t(j)];
  }
  LatentModel models[3];
  models[0].white = 0.1;
  models[1].white = 0.1, models[1].quantization = 0.003, models[1].gm = {{0.6, 0.12}}, models[1].randomWalk = 0.7;
  models[2].white = 0.1, models[2].gm = {{0.8, 0.02}, {0.5, 0.4}};
  for (const LatentModel& m : models) {
    INFO(m.termNames());
    const Eigen::LLT<Eigen::MatrixXd> llt(blockCovariance(sampleCovariance(m, kM * kB)));
    REQUIRE(llt.info() == Eigen::Success);
    const Eigen::MatrixXd dense = Z.transpose() * llt.solve(Z);
    const Eigen::MatrixXd A = blockGlsProducts(b, m, extra);
    REQUIRE(A.rows() == 5);
    for (Eigen::Index i = 0; i < 5; ++i)
      for (Eigen::Index k = 0; k < 5; ++k) {
        INFO(i << "," << k);
        CHECK(std::fabs(A(i, k) - dense(i, k)) <= 1e-9 * std::sqrt(dense(i, i) * dense(k, k)));
      }
  }
  LatentModel ar;
  ar.white = 0.1, ar.arPolynomial = {1.0, -0.5}, ar.arVariance = 0.01;
  CHECK_THROWS_AS(blockGlsProducts(b, ar, extra), sinsim::InputError);
  CHECK_THROWS_AS(blockGlsProducts(b, models[0], {std::vector<double>(kM - 1)}), sinsim::InputError);
}

TEST_CASE("block likelihood: flicker as the documented sum of GMs", "[fit][block]") {
  // The flicker's GMs (block_likelihood.hpp step 2): sigma^2 = B^2 ln 10 / (2 pi) each, T at
  // dt/10 * 10^((j + 0.5)/2) up to 10 M L. Those faster than L/4 enter the filter as white at the
  // block level (their covariance between neighbouring blocks dropped): the only approximation.
  const std::vector<double> x = someRecord(kM * kB);
  const BlockMeans b = blockMeans(x, kDt, kB);
  LatentModel m;
  m.white = 0.1, m.flicker = 0.3;
  LatentModel asGm;
  asGm.white = m.white;
  const double L = kDt * double(kB);
  for (int j = 0;; ++j) {
    const double T = kDt / 10.0 * std::pow(10.0, (j + 0.5) / 2.0);
    if (T > 10.0 * L * double(kM)) break;
    asGm.gm.push_back({m.flicker * std::sqrt(std::log(10.0) / (2.0 * sinsim::kPi)), T});
  }
  const Dense d = denseRestricted(b.y, blockCovariance(sampleCovariance(asGm, kM * kB)));
  const BlockLikelihood k = blockLikelihood(b, m);
  // The dropped neighbour covariance of the fast components is < 1 % of the block variance here
  // (T <= L/4 gives a lag-1 block correlation <= ~T/(2L) of their share); its effect on -2 log L
  // is well under 1 (the level at which a set choice could move), checked as 0.5.
  CHECK(std::fabs(k.m2LogLik - d.level) < 0.5);
  // The same sum of GMs given as GM terms is exact (no folding: every GM gets a state).
  CHECK(blockLikelihood(b, asGm).m2LogLik == Approx(d.level).epsilon(1e-9));
}

TEST_CASE("block likelihood: hostile input", "[fit][block]") {
  std::vector<double> x(100, 1.0);
  CHECK_THROWS_AS(blockMeans(x, kDt, 0), sinsim::InputError);
  CHECK_THROWS_AS(blockMeans(x, kDt, 20), sinsim::InputError);  // 5 blocks
  CHECK_THROWS_AS(blockMeans(x, 0.0, 2), sinsim::InputError);
  x[7] = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(blockMeans(x, kDt, 2), sinsim::InputError);
  // A model without any variance: not positive, +inf (no hang, no throw).
  const BlockMeans b = blockMeans(std::vector<double>(100, 1.0), kDt, 2);
  CHECK(std::isinf(blockLikelihood(b, LatentModel{}).m2LogLik));
  LatentModel ar;
  ar.white = 1.0, ar.arVariance = 1.0, ar.arPolynomial = {1.0, -0.5};
  CHECK_THROWS_AS(blockLikelihood(b, ar), sinsim::InputError);
}
