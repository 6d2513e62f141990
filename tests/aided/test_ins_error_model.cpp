// The INS error dynamics against closed forms: at rest, the horizontal error modes oscillate at
// the Schuler frequency split by the Foucault rate, ω_s ± Ω sin L (Titterton & Weston 2004,
// §12.3.4; Britting 1971), and the attitude carries the Earth-rate mode Ω.
#include <catch2/catch.hpp>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "common/constants.hpp"
#include "nav/attitude.hpp"
#include "nav/ins_error_model.hpp"

using namespace sinsim::nav;
using sinsim::kRadPerDeg;

TEST_CASE("static error dynamics: Schuler frequencies split by the Foucault rate") {
  const Earth earth;
  for (double latDeg : {20.0, 55.0}) {
    InsErrorPoint p;
    p.lat = latDeg * kRadPerDeg;
    p.h = 0.0;
    p.f_n = -earth.gravity_n(p.lat, 0.0);
    const Mat9 F = insErrorDynamics(earth, p, VerticalChannel::Held);
    const Eigen::VectorXcd ev = Eigen::EigenSolver<Mat9>(F).eigenvalues();
    double M = 0, N = 0;
    earth.radii(p.lat, M, N);
    const double g = -p.f_n.z();
    const double ws = std::sqrt(g / std::sqrt(M * N)), W = earth.rate(), sL = std::sin(p.lat);
    // The exact roots differ from ω_s ± Ω sin L by O(Ω²/ω_s) ≈ 4e-6 ω_s and by the N ≠ M
    // ellipticity of the radius (~ e² ≈ 7e-3 relative between the two axes): 1e-2 relative on
    // each frequency, with the Foucault split ≈ 1e-1 ω_s checked to 10 % of itself below.
    auto closest = [&](double w) {
      double best = 1e9;
      for (int i = 0; i < ev.size(); ++i) best = std::min(best, std::abs(std::abs(ev[i].imag()) - w));
      return best;
    };
    CHECK(closest(ws + W * sL) <= 1e-2 * ws);
    CHECK(closest(ws - W * sL) <= 1e-2 * ws);
    CHECK(closest(ws + W * sL) <= 0.1 * W * sL);
    CHECK(closest(ws - W * sL) <= 0.1 * W * sL);
    CHECK(closest(W) <= 1e-2 * W);
    for (int i = 0; i < ev.size(); ++i) CHECK(std::abs(ev[i].real()) <= 1e-9);  // undamped
  }
}

TEST_CASE("sensor errors enter through the attitude and the velocity") {
  const Mat3 C = dcmFromEuler(Vec3(0.1, -0.2, 2.0));
  const Mat93 Gg = gyroErrorInput(C), Ga = accelErrorInput(C, VerticalChannel::Free);
  CHECK((Gg.block<3, 3>(kAtt, 0) + C).norm() == 0.0);
  CHECK((Ga.block<3, 3>(kVel, 0) - C).norm() == 0.0);
  CHECK(accelErrorInput(C, VerticalChannel::Held).row(kVel + 2).norm() == 0.0);
}
