// Error propagation of the full mechanization against outside truth, static at 45° N:
//  - a constant north accelerometer bias against the classical closed form (Britting 1971;
//    Titterton & Weston 2004 §12.3) and against an independently coded linear error model;
//  - a constant east gyro bias against the same linear error model;
//  - the Schuler period measured from zero crossings of the position error.
//
// The linear error model is the psi-angle model (Benson 1975; Titterton & Weston 2004 §12.3.4),
// written here from scratch for a vehicle at rest with the vertical channel held:
//   ψ̇  = -ω_ie × ψ - C_nb δω_b                    (platform vs computer frame attitude error)
//   δv̇ = -ψ × f_n - 2 ω_ie × δv + δg + C_nb δf_b  (f_n = -g_n = (0, 0, -g))
//   δṙ = δv,  δg = -(g/M δr_N, g/N δr_E)           (normal rotates by δN/M, δE/N on the ellipsoid)
// with the vertical components of δv, δr held at zero. It is linear time-invariant, so it is
// solved exactly by the matrix exponential of the augmented system (Van Loan 1978) — no
// integrator truncation. For a vehicle at rest this model is the exact first-order expansion of
// the navigation equations (c-frame rate = ω_ie + O(δv/R), the dropped terms are second order).
#include <catch2/catch.hpp>

#include <unsupported/Eigen/MatrixFunctions>

#include <complex>
#include <cstdio>
#include <vector>

#include "nav_test_support.hpp"

using namespace navtest;

namespace {

using Mat8 = Eigen::Matrix<double, 8, 8>;
using Vec8 = Eigen::Matrix<double, 8, 1>;

/// Psi-angle model at rest, state x = [ψN ψE ψD δvN δvE δrN δrE 1] (the trailing 1 carries the
/// constant sensor errors). eps_n: gyro bias in NED [rad/s], acc_n: accelerometer bias [m/s^2].
Mat8 psiModel(const Earth& earth, double lat, const Vec3& eps_n, const Vec3& acc_n) {
  double M = 0.0, N = 0.0;
  earth.radii(lat, M, N);
  const double g = earth.gravity_n(lat, 0.0).z();
  const Vec3 w = earth.omega_ie_n(lat);
  Mat8 A = Mat8::Zero();
  A.block<3, 3>(0, 0) = -skew(w);
  A.block<3, 1>(0, 7) = -eps_n;
  // -ψ × f with f = (0, 0, -g): (gψE, -gψN, 0)
  A(3, 1) = g;
  A(4, 0) = -g;
  // -2 ω_ie × δv, horizontal rows and columns only (δv_D ≡ 0)
  const Mat3 Wc = -2.0 * skew(w);
  A.block<2, 2>(3, 3) = Wc.block<2, 2>(0, 0);
  A(3, 5) = -g / M;
  A(4, 6) = -g / N;
  A(3, 7) = acc_n.x();
  A(4, 7) = acc_n.y();
  A(5, 3) = 1.0;
  A(6, 4) = 1.0;
  return A;
}

/// Horizontal position error (north, east) [m] of the linear model at time t [s].
Eigen::Vector2d psiPosition(const Mat8& A, double t) {
  Vec8 x0 = Vec8::Zero();
  x0(7) = 1.0;
  const Vec8 x = (A * t).exp() * x0;
  return x.segment<2>(5);
}

struct Run {
  std::vector<double> t;       // [s]
  std::vector<Vec3> err;       // NED position error [m]
};

/// The mechanization at rest at (lat, 0, h = 0) with the static ideal IMU plus constant errors
/// (given in NED, converted to body), held vertical channel; position error every `every` s.
Run runBiased(double lat, const Vec3& rpy, const Vec3& eps_n, const Vec3& acc_n, double duration,
              double every, const Vec3& v0 = Vec3::Zero()) {
  const Earth earth;
  NavState s0;
  s0.lat = lat;
  s0.q_nb = quatFromEuler(rpy);
  s0.v_n = v0;
  StrapdownOptions opt;
  opt.vertical = VerticalChannel::Held;
  Strapdown ins(earth, s0, opt);
  const double rate = 100.0, dt = 1.0 / rate;
  ImuSample imu = staticSample(earth, lat, 0.0, s0.q_nb, dt);
  const Mat3 C_bn = s0.q_nb.toRotationMatrix().transpose();
  imu.dtheta_b += C_bn * eps_n * dt;
  imu.dv_b += C_bn * acc_n * dt;
  Run r;
  const long n = std::lround(duration * rate), m = std::lround(every * rate);
  for (long k = 1; k <= n; ++k) {
    imu.t = k * dt;
    ins.update(imu, 0.0);
    if (k % m == 0) {
      r.t.push_back(imu.t);
      r.err.push_back(positionError(earth, ins.state(), lat, 0.0, 0.0));
    }
  }
  return r;
}

const Vec3 kRpy(4.0 * kDeg, -7.0 * kDeg, 33.0 * kDeg);  // any attitude; errors are given in NED

}  // namespace

TEST_CASE("north accelerometer bias: Schuler-Foucault closed form and linear model") {
  const Earth earth;
  const double lat = 45.0 * kDeg;
  const double bias = 1e-4;  // [m/s^2] ≈ 10 µg: a 130 m peak, far inside the linear regime
  const Run run = runBiased(lat, kRpy, Vec3::Zero(), Vec3(bias, 0.0, 0.0), 5400.0, 60.0);

  double M = 0.0, N = 0.0;
  earth.radii(lat, M, N);
  const double g = earth.gravity_n(lat, 0.0).z();
  const double wf = earth.rate() * std::sin(lat);  // Foucault frequency [rad/s]

  // Closed form (derivation: with z = δN + iδE, the held-vertical psi model at rest reduces to
  // z̈ - 2iω_f ż + ω_s² z = ∇, z(0) = ż(0) = 0, whose solution is
  // z = (∇/ω_s²)[1 - e^{iω_f t}(cos ωt - i(ω_f/ω) sin ωt)], ω² = ω_s² + ω_f²; δE > 0 is east,
  // i.e. in the northern hemisphere the error ellipse turns clockwise seen from above, as the
  // Foucault pendulum does). The only approximation is one Schuler frequency for both axes,
  // whereas the ellipsoid has M ≠ N (0.34% apart at 45°).
  auto closedForm = [&](double R, double t) {
    const double ws2 = g / R, w = std::sqrt(ws2 + wf * wf);
    const std::complex<double> I(0.0, 1.0);
    return (bias / ws2) *
           (1.0 - std::exp(I * wf * t) * (std::cos(w * t) - I * (wf / w) * std::sin(w * t)));
  };
  const double peak = 2.0 * bias * std::sqrt(M * N) / g;  // 2∇/ω_s² [m]

  struct Candidate {
    const char* name;
    double R;
    double worst = 0.0;
  };
  std::vector<Candidate> cands = {{"sqrt(MN)", std::sqrt(M * N)},
                                  {"M", M},
                                  {"N", N},
                                  {"a", earth.a()}};
  for (auto& c : cands)
    for (std::size_t i = 0; i < run.t.size(); ++i) {
      const std::complex<double> z = closedForm(c.R, run.t[i]);
      c.worst = std::max(c.worst, std::hypot(run.err[i].x() - z.real(), run.err[i].y() - z.imag()));
    }
  for (const auto& c : cands)
    std::printf("accel bias: closed form with R = %-8s worst deviation %.4f m = %.3f %% of peak "
                "%.2f m\n",
                c.name, c.worst, 100.0 * c.worst / peak, peak);
  // Which R? A north bias drives mainly the north channel, whose restoring acceleration is
  // g·δN/M (the ellipsoid normal turns by δN/M), so the meridian radius M fits best; the east
  // error is the small Foucault-rotated part. sqrt(MN) (the Gaussian mean radius, ≈ a at 45°)
  // splits the 0.34 % M/N difference and still meets the 1 % requirement. Measured above:
  // M best (0.06 % of the peak), then sqrt(MN) and a (0.29 %), N worst (0.57 %).
  CHECK(cands[0].worst < 0.01 * peak);
  CHECK(cands[1].worst < 0.01 * peak);
  for (std::size_t k = 0; k < cands.size(); ++k) CHECK(cands[1].worst <= cands[k].worst);

  // The linear model keeps M and N apart and has no approximation beyond linearisation: the
  // mechanization must match it far more closely. Second-order terms are ~ (δr/R) ≈ 2e-5 of the
  // error, discretisation O((ω_s h)²) ≈ 1.5e-10: 1e-4 of the peak is a safe, still sharp bound.
  const Mat8 A = psiModel(earth, lat, Vec3::Zero(), Vec3(bias, 0.0, 0.0));
  double worstLin = 0.0;
  for (std::size_t i = 0; i < run.t.size(); ++i)
    worstLin = std::max(worstLin, (run.err[i].head<2>() - psiPosition(A, run.t[i])).norm());
  std::printf("accel bias: linear psi model worst deviation %.3g m = %.2g %% of peak\n", worstLin,
              100.0 * worstLin / peak);
  CHECK(worstLin < 1e-4 * peak);
}

TEST_CASE("east gyro bias: linear psi-angle error model") {
  // No closed form holds to 1 % here without carrying the 24 h Earth-rate terms, so the truth is
  // the linear model above, solved exactly (matrix exponential) — an implementation independent
  // of the mechanization. 0.01 °/h gives ≈ R ε t ≈ 1.7 km after 1.5 h.
  const Earth earth;
  const double lat = 45.0 * kDeg;
  const Vec3 eps_n(0.0, 0.01 * kDeg / 3600.0, 0.0);
  const Run run = runBiased(lat, kRpy, eps_n, Vec3::Zero(), 5400.0, 60.0);
  const Mat8 A = psiModel(earth, lat, eps_n, Vec3::Zero());
  double worst = 0.0, peak = 0.0;
  for (std::size_t i = 0; i < run.t.size(); ++i) {
    const Eigen::Vector2d lin = psiPosition(A, run.t[i]);
    peak = std::max(peak, lin.norm());
    worst = std::max(worst, (run.err[i].head<2>() - lin).norm());
  }
  std::printf("east gyro bias: peak %.1f m, worst deviation from the psi model %.3g m = %.2g %%\n",
              peak, worst, 100.0 * worst / peak);
  // Requirement 1 % of the peak; second-order terms are ~ ψ ≈ 3e-4 of the error (the tilt
  // itself), so the expected agreement is ~1e-3 of the peak or better.
  CHECK(peak > 1000.0);
  CHECK(worst < 0.01 * peak);
  CHECK(worst < 0.001 * peak);
}

TEST_CASE("Schuler period from zero crossings of the position error") {
  // An initial north velocity error δv0 gives z = (δv0/ω) e^{iω_f t} sin ωt (same equation as
  // above, z(0) = 0, ż(0) = δv0), so δN = (δv0/ω) sin ωt cos ω_f t crosses zero every π/ω while
  // ω_f t < π/2 (4 h at 45° N). ω = sqrt(ω_s² + ω_f²) exceeds ω_s by ω_f²/2ω_s² ≈ 0.09 %.
  const Earth earth;
  const double lat = 45.0 * kDeg;
  const Run run = runBiased(lat, kRpy, Vec3::Zero(), Vec3::Zero(), 4.0 * 3600.0, 1.0,
                            Vec3(0.1, 0.0, 0.0));
  std::vector<double> crossings;
  for (std::size_t i = 1; i < run.t.size(); ++i) {
    const double a = run.err[i - 1].x(), b = run.err[i].x();
    if (a != 0.0 && ((a < 0.0) != (b < 0.0)))
      crossings.push_back(run.t[i - 1] + (run.t[i] - run.t[i - 1]) * a / (a - b));
  }
  REQUIRE(crossings.size() >= 4);
  // Period: least-squares slope of crossing time against index, times 2.
  const std::size_t n = crossings.size();
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < n; ++k) {
    sx += k;
    sy += crossings[k];
    sxx += double(k) * k;
    sxy += k * crossings[k];
  }
  const double measured = 2.0 * (n * sxy - sx * sy) / (n * sxx - sx * sx);
  double M = 0.0, N = 0.0;
  earth.radii(lat, M, N);
  const double g = earth.gravity_n(lat, 0.0).z();
  const double expected = 2.0 * kPi * std::sqrt(std::sqrt(M * N) / g);
  std::printf("Schuler period: measured %.2f s (%zu crossings), 2*pi*sqrt(R/g) = %.2f s with "
              "R = sqrt(MN): %+.3f %%\n",
              measured, n, expected, 100.0 * (measured / expected - 1.0));
  CHECK(std::abs(measured / expected - 1.0) < 0.01);
  // Sharper: δN is the north channel, restored by g/M, and the Foucault term shortens the period
  // to 2π/sqrt(g/M + ω_f²). What remains is the slight mixing of the east channel (N) through the
  // Foucault rotation, ω_f t ≤ 0.74 rad over the run: ≤ 0.05 % bounds it (measured ≈ 0.01 %).
  const double wf = earth.rate() * std::sin(lat);
  const double northPeriod = 2.0 * kPi / std::sqrt(g / M + wf * wf);
  std::printf("Schuler period: 2*pi/sqrt(g/M + wf^2) = %.2f s: %+.3f %%\n", northPeriod,
              100.0 * (measured / northPeriod - 1.0));
  CHECK(std::abs(measured / northPeriod - 1.0) < 0.0005);
}
