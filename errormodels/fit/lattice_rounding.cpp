#include "errormodels/fit/lattice_rounding.hpp"

#include <algorithm>
#include <cmath>

#include "common/constants.hpp"
#include "common/error.hpp"
#include "errormodels/random.hpp"
#include "errormodels/stats/allan.hpp"

namespace sinsim::errormodels::fit {

namespace {

constexpr double kTwoPi2 = 2.0 * kPi * kPi;
/// Lines of the PSD with phi_n below this are left out (their K_n is 1 to this level).
constexpr double kLineCut = 1e-9;
/// The PSD's motion floor, relative to the step (at most ~2000 lines).
constexpr double kPsdMotionFloor = 5e-4;

double phiOf(double x) { return std::exp(-0.5 * x * x) / std::sqrt(2.0 * kPi); }

/// P(a <= U <= b) of a standard normal, without cancellation in either tail.
double normalMass(double a, double b) {
  constexpr double r = 0.70710678118654752440;  // 1 / sqrt 2
  if (a >= 0.0) return 0.5 * (std::erfc(a * r) - std::erfc(b * r));
  if (b <= 0.0) return 0.5 * (std::erfc(-b * r) - std::erfc(-a * r));
  return 1.0 - 0.5 * std::erfc(-a * r) - 0.5 * std::erfc(b * r);
}

double fracProduct(double z) {
  const double f = z - std::floor(z);
  return f * (1.0 - f);
}

/// Cell by cell: sum_j E[Y (1 - Y); 0 <= Y < 1], Y = Z - j, from the truncated normal moments.
double byCells(double mean, double sd) {
  const auto lo = static_cast<long long>(std::floor(mean - 12.0 * sd));
  const auto hi = static_cast<long long>(std::floor(mean + 12.0 * sd));
  double sum = 0.0;
  for (long long j = lo; j <= hi; ++j) {
    const double c = mean - double(j);  // Y's mean
    const double a = -c / sd, b = (1.0 - c) / sd;
    const double P = normalMass(a, b), fa = phiOf(a), fb = phiOf(b);
    const double EU = fa - fb, EU2 = P + a * fa - b * fb;
    const double EY = c * P + sd * EU, EY2 = c * c * P + 2.0 * c * sd * EU + sd * sd * EU2;
    sum += EY - EY2;
  }
  return sum;
}

/// The Fourier series 1/6 - sum_n cos(2 pi n a) exp(-2 pi^2 n^2 v) / (pi^2 n^2).
double bySeries(double mean, double sd) {
  const double v = sd * sd;
  double sum = 0.0;
  for (int n = 1;; ++n) {
    const double nn = double(n) * double(n);
    const double t = std::exp(-kTwoPi2 * nn * v) / (kPi * kPi * nn);
    if (t < 1e-18) break;
    sum += std::cos(2.0 * kPi * double(n) * mean) * t;
  }
  return 1.0 / 6.0 - sum;
}

/// g(k) / (D^2 / 2): E[h(frac(X_k / D))], X_k ~ N(k mu, k s^2).
double lagGap(const RoundingLattice& L, double k) {
  return expectedFracProduct(k * L.drift / L.step, std::sqrt(k) * L.motion / L.step);
}

void requireActive(const RoundingLattice& L, double dt) {
  if (!(std::isfinite(L.step) && L.step > 0.0 && std::isfinite(L.motion) && L.motion > 0.0 &&
        std::isfinite(L.drift)))
    throw InputError("lattice quantization: need a step > 0, a motion > 0 and a finite drift");
  if (!(std::isfinite(dt) && dt > 0.0)) throw InputError("lattice quantization: dt must be > 0");
}

}  // namespace

bool RoundingLattice::correlated() const {
  return active() && std::exp(-kTwoPi2 * (motion / step) * (motion / step)) > kLineCut;
}

double expectedFracProduct(double mean, double sd) {
  if (!(std::isfinite(mean) && std::isfinite(sd) && sd >= 0.0))
    throw InputError("lattice quantization: a finite mean and sd >= 0 expected");
  if (sd == 0.0) return fracProduct(mean);
  // Invariant to integer shifts of the mean: its fractional part keeps the cells' indices small
  // for any mean (a drift of many LSB over a long lag).
  const double a = mean - std::floor(mean);
  return sd >= 0.3 ? bySeries(a, sd) : byCells(a, sd);
}

double latticeQuantizationAllanVariance(const RoundingLattice& L, double dt, std::size_t m) {
  requireActive(L, dt);
  if (m == 0) throw InputError("lattice quantization: averaging factor m must be >= 1");
  const double md = double(m);
  const double half = 0.5 * L.step * L.step;  // g(k) = half * lagGap(k)
  return (8.0 * half * lagGap(L, md) - 2.0 * half * lagGap(L, 2.0 * md)) / (2.0 * md * md * dt * dt);
}

double latticeQuantizationPsd(const RoundingLattice& L, double dt, double w) {
  requireActive(L, dt);
  const double D2 = L.step * L.step;
  const double r = std::max(L.motion / L.step, kPsdMotionFloor);
  double Se = D2 / 12.0;
  for (int n = 1;; ++n) {
    const double nn = double(n) * double(n);
    const double x = kTwoPi2 * nn * r * r;
    const double phi = std::exp(-x);
    if (phi < kLineCut) break;
    const double om = -std::expm1(-x);  // 1 - phi
    const double beta = 2.0 * kPi * double(n) * L.drift / L.step;
    auto P = [&](double u) {
      const double s = std::sin(0.5 * u);
      return om * (1.0 + phi) / (om * om + 4.0 * phi * s * s);
    };
    Se += D2 / (2.0 * kPi * kPi * nn) * (0.5 * (P(w - beta) + P(w + beta)) - 1.0);
  }
  const double s = std::sin(0.5 * w);
  return 4.0 * s * s / (dt * dt) * Se;
}

Eigen::MatrixXd latticeAllanCovariance(const RoundingLattice& L, double dt, std::size_t n,
                                       const std::vector<std::size_t>& m, int realisations,
                                       std::uint64_t seed) {
  requireActive(L, dt);
  constexpr std::size_t kMaxLength = std::size_t(1) << 18;
  const std::size_t len = std::min(n, kMaxLength);
  if (realisations < 2 || m.empty() || m.back() * 10 > len)
    throw InputError("lattice quantization: need >= 2 realisations and factors <= length / 10");
  const auto k = static_cast<Eigen::Index>(m.size());
  Eigen::MatrixXd est(realisations, k);
  AllanOptions ao;
  ao.factors = m;
  ao.confidence_intervals = false;
  std::vector<double> y(len);
  for (int r = 0; r < realisations; ++r) {
    NormalStream z(seed, std::uint64_t(r), 0);
    // The phase on the lattice: uniform (from one normal through its CDF), kept in [-D/2, D/2)
    // after each output so that the rounding stays exact over any length.
    double phase = L.step * (0.5 * std::erfc(-z.next() / std::sqrt(2.0)) - 0.5);
    for (std::size_t i = 0; i < len; ++i) {
      phase += L.drift + L.motion * z.next();
      const double steps = std::round(phase / L.step);
      y[i] = steps * L.step / dt;
      phase -= steps * L.step;
    }
    const AllanCurve c = allanDeviation(y, 1.0 / dt, AllanVariant::Overlapping, ao);
    for (Eigen::Index j = 0; j < k; ++j) est(r, j) = c.dev[std::size_t(j)] * c.dev[std::size_t(j)];
  }
  const Eigen::RowVectorXd mean = est.colwise().mean();
  const Eigen::MatrixXd d = est.rowwise() - mean;
  return (d.transpose() * d) / double(realisations - 1) * (double(len) / double(n));
}

double latticeMotionFromAllan(const RoundingLattice& L, double dt, double avar1) {
  RoundingLattice t = L;
  auto avarAt = [&](double s) {
    t.motion = s;
    return s * s / (dt * dt) + latticeQuantizationAllanVariance(t, dt, 1);
  };
  double lo = 1e-6 * L.step, hi = 10.0 * L.step;
  requireActive({L.step, lo, L.drift}, dt);
  if (!(avar1 > avarAt(lo))) return 0.0;
  if (!(avar1 < avarAt(hi))) return hi;
  for (int i = 0; i < 60; ++i) {
    const double mid = std::sqrt(lo * hi);
    (avarAt(mid) < avar1 ? lo : hi) = mid;
  }
  return std::sqrt(lo * hi);
}

}  // namespace sinsim::errormodels::fit
