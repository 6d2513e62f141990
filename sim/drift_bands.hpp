// Which τ band of the sensor errors drives the horizontal drift of a run at rest: the linearised
// free-inertial error model of a static INS (local level, Schuler-coupled; Titterton & Weston
// 2004 §12.2, Earth-rate and vertical couplings neglected) applied to octave bands of the error
// signal.
//
// For an accelerometer error a_n and a gyro error ω_n (nav axes) the position error at T is
//   δp_N(T) = ∫ [ a_N(t) K_a(T − t) − g ω_E(t) K_g(T − t) ] dt,
//   δp_E(T) = ∫ [ a_E(t) K_a(T − t) + g ω_N(t) K_g(T − t) ] dt,
//   K_a(u) = sin(ω_s u)/ω_s,   K_g(u) = (1 − cos(ω_s u))/ω_s²,
// from δv̇ = f × ψ + a_n, ψ̇ = −ω_n, the Schuler feedback −ω_s² δp; for ω_s T ≪ 1 they are the
// familiar u and u²/2. The signal is split into dyadic Haar bands: s_j = block means over 2^j
// samples (blocks from t = 0), band j = s_j − s_{j+1} (j = 0..J−1, τ_j = 2^j/rate, the Allan τ
// of that detail), and the remainder s_J (block means over 2^J samples, 2^J ≥ N/2: the run's
// mean level). The bias window (the mean of the first W s removed from every sample) is applied
// to each band, so the calibration error is charged to the bands that cause it (τ ≈ W). The
// response is linear, so the bands' responses add up to the whole signal's.
#pragma once

#include <array>
#include <utility>
#include <vector>

#include "common/types.hpp"

namespace sinsim::sim {

/// Sensor errors (measured − ideal) as rates, body axes, one value per IMU sample.
struct ErrorSignal {
  double rate = 0.0;                      // [Hz]
  std::array<std::vector<double>, 3> gyro;   // [rad/s]
  std::array<std::vector<double>, 3> accel;  // [m/s²]
};

/// Where the run is and how its errors are prepared (as the navigation loop does it).
struct DriftKernel {
  Mat3 C_nb = Mat3::Identity();  // attitude at rest, body → NED
  double g = 9.81;               // [m/s²]
  double schuler = 0.0;          // ω_s [rad/s]; 0: no Schuler feedback (u, u²/2)
  double biasWindow = 0.0;       // [s] the mean over the first biasWindow s is removed (0: none)
};

/// τ [s] of the bands of an n-sample record at rate: 2^j / rate for j = 0..J−1, then 2^J / rate
/// (the remainder).
std::vector<double> driftBandTaus(std::size_t n, double rate);

/// Per band (driftBandTaus order) the horizontal position error (north, east) [m] at the end of
/// the signal that the band alone causes. Throws InputError for an empty or uneven signal.
std::vector<std::array<double, 2>> driftByBand(const ErrorSignal& x, const DriftKernel& kernel);

/// The driving band of per-band shares (of a drift's mean square): the fewest adjacent bands
/// whose shares add up to >= 1/2 (of equal counts, the largest sum), as [first, last]; {0, 0} for
/// no bands. It was the fewest bands in any order, reported as the range from the smallest to the
/// largest: shares 0.21 0.10 0.41 0.19 gave the first three (72 %), the 10 % between counted,
/// where the last two hold 60 %.
std::pair<std::size_t, std::size_t> drivingBands(const std::vector<double>& share);

}  // namespace sinsim::sim
