// The filter's attitude prior after a coarse alignment (ErrorStateFilter::startAfterAlignment).
//
// The alignment turns the window's mean sensor errors into an attitude error, ψ = J [δf̄_n; δω̄_n]
// (nav/alignment.hpp), so ψ is as uncertain as the filter's own model says those means are, and
// correlated with the bias states it estimates next: an accelerometer bias that tilted the
// alignment is the same bias the filter then sees. Without this the filter started with the
// user's initial attitude sigma (or none) after a gyrocompass that a 10 deg/h gyro turns by tens
// of degrees, and its NEES ran into the thousands.
//
// Each block's window mean, given its value x_T at the window's end (Gaussian projection):
//   mean = gain · x_T + r, r independent of x_T, Var r = Var(mean) − gain² Var(x_T):
//   bias / walk from x_0 (variance p0, walk intensity q):  Var x_T = p0 + q T,
//       Cov(mean, x_T) = p0 + q T / 2, Var(mean) = p0 + q T / 3;
//   stationary Gauss-Markov (σ², τ; a = τ / T, E = 1 − e^(−1/a)):  gain = a E,
//       Var(mean) = 2 σ² a (1 − a E);
//   sampled (AR) block: its whole mean as independent noise, from the autocovariance
//       r(k) = c A^k P0 cᵀ: Var(mean of N) = Σ_{|k|<N} (N − |k|) r(k) / N² (its correlation with
//       the block's end state is left out: exact for the fast processes these blocks model);
//   white noise of density N: N² / T.
#include <algorithm>
#include <cmath>

#include "sim/aided/error_state_filter.hpp"

namespace sinsim::sim::aided {
namespace {

struct WindowMean {
  double gain = 1.0;      // on the block's end value
  double variance = 0.0;  // of the part independent of it
};

// A one-state continuous block ẋ = f x + w, E[w w] = q δ, over a window of T [s]; p0 the state's
// variance at the window's start (a Gauss-Markov's is its stationary σ²).
WindowMean continuousWindowMean(double f, double q, double p0, double T) {
  if (f == 0.0) {  // bias (q = 0) or random walk
    const double end = p0 + q * T, cross = p0 + 0.5 * q * T, mean = p0 + q * T / 3.0;
    if (!(end > 0.0)) return {};
    return {cross / end, std::max(0.0, mean - cross * cross / end)};
  }
  const double tau = -1.0 / f, s2 = 0.5 * q * tau, a = tau / T;
  if (a > 1e3)  // series in 1/a (the closed form cancels to rounding there)
    return {1.0 - 0.5 / a + 1.0 / (6.0 * a * a), s2 * (2.0 / (3.0 * a) - 0.5 / (a * a))};
  const double E = -std::expm1(-1.0 / a);
  return {a * E, s2 * std::max(0.0, 2.0 * a * (1.0 - a * E) - a * a * E * E)};
}

// Variance of a sampled block's mean c x over T [s] (N of its periods), stationary.
double sampledWindowMeanVariance(const StateBlock& b, double T) {
  const long long N = std::max(1LL, std::llround(T / b.period));
  Eigen::VectorXd v = b.P0 * b.c.transpose();  // A^k P0 cᵀ
  const double r0 = b.c.dot(v);
  double sum = double(N) * r0;
  for (long long k = 1; k < N; ++k) {
    v = b.A * v;
    const double r = b.c.dot(v);
    sum += 2.0 * double(N - k) * r;
    if (std::abs(r) <= 1e-17 * std::abs(r0) && k > 64) break;  // decayed (a stable AR)
  }
  return std::max(0.0, sum / (double(N) * double(N)));
}

}  // namespace

void ErrorStateFilter::startAfterAlignment(const Eigen::Matrix<double, 3, 6>& J,
                                           const nav::Mat3& C_nb, const nav::Vec3& f_b,
                                           const nav::Vec3& omega_b, double T) {
  const int n = size();
  // Rows 0-2 the accelerometers' window means, 3-5 the gyros' (J's order), body axes.
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(6, n);
  Eigen::Matrix<double, 6, 1> w = Eigen::Matrix<double, 6, 1>::Zero();
  auto rowOf = [](int axis) { return axis < 3 ? 3 + axis : axis - 3; };
  for (int axis = 0; axis < 6; ++axis) {
    const double N = axis < 3 ? model_.gyro[axis].whiteDensity : model_.accel[axis - 3].whiteDensity;
    w[rowOf(axis)] += N * N / T;
  }
  for (const Placed& pl : placed_) {
    const StateBlock& b = pl.block;
    const int row = rowOf(pl.axis);
    if (b.discrete) {
      w[row] += sampledWindowMeanVariance(b, T);
      continue;
    }
    // Continuous blocks have one state (sensor_states.hpp).
    const int o = pl.offset;
    const double input = !b.scale ? 1.0 : pl.axis < 3 ? omega_b[pl.axis] : f_b[pl.axis - 3];
    const double c = b.c[0] * input, f = b.F(0, 0), q = b.Qc(0, 0);
    const WindowMean m = continuousWindowMean(f, q, P_(o, o), T);
    S(row, o) = m.gain * c;
    w[row] += m.variance * c * c;
    if (f == 0.0) P_(o, o) += q * T;  // the walk over the window
  }
  Eigen::Matrix<double, 6, 6> R = Eigen::Matrix<double, 6, 6>::Zero();
  R.topLeftCorner<3, 3>() = C_nb;
  R.bottomRightCorner<3, 3>() = C_nb;
  const Eigen::MatrixXd G = J * R * S;  // ψ from the end states; zero on the navigation states
  const Eigen::Matrix3d W = J * R * w.asDiagonal() * R.transpose() * J.transpose();
  const Eigen::MatrixXd GP = G * P_;
  P_.middleRows<3>(nav::kAtt) = GP;
  P_.middleCols<3>(nav::kAtt) = GP.transpose();
  P_.block<3, 3>(nav::kAtt, nav::kAtt) = GP * G.transpose() + W;
  x_.segment<3>(nav::kAtt) = G * x_;
}

}  // namespace sinsim::sim::aided
