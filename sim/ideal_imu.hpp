// The ideal IMU: angle and velocity increments a perfect strapdown IMU delivers along a
// trajectory, with the true navigation state at every epoch. Streams: one interval per call,
// memory independent of the duration.
#pragma once

#include "nav/types.hpp"
#include "sim/trajectory.hpp"

namespace sinsim::sim {

class IdealImu {
 public:
  /// trajectory must outlive the generator. imuRate [Hz] > 0. Integration steps are at most
  /// maxSubstep [s] > 0 long and end on every knot of the motion (see next()).
  IdealImu(const Trajectory& trajectory, double imuRate, double maxSubstep = 0.01);

  /// Number of IMU intervals that cover the trajectory: round(duration · rate).
  long long sampleCount() const { return count_; }
  /// Index of the next interval (0 before the first call of next()).
  long long index() const { return k_; }
  bool done() const { return k_ >= count_; }

  /// Integrates the augmented state y = [lat, lon, h, ∫ω_ib^b dt, ∫f^b dt] over the next IMU
  /// interval (t_k, t_k + dt] with classical RK4. The interval is first cut at the knots of the
  /// motion inside it (MotionProfile::nextKnot: there the angular acceleration and the jerk
  /// jump, and a step across would be only O(h²) accurate — 3e-9 rad per boundary at 100 Hz in
  /// the aircraft scenario, 1-2 cm of position after 20 min); each piece is split into equal
  /// steps h ≤ maxSubstep. The position rate depends on the position, the two integrals only on
  /// (t, position): one RK4 pass gives the truth and the increments from the same stages. Local
  /// error O(h^5): for the raised-cosine profiles (highest angular frequency 2π/T for a segment
  /// of length T) the increments are exact to ~(h·2π/T)^4/2880 relative, < 1e-11 for h = 10 ms
  /// and T ≥ 5 s.
  /// Returns the interval's ideal sample; truth() is then the state at its end.
  nav::ImuSample next();

  /// True navigation state at the current epoch t_k = k·dt (t_0 = 0: the scenario's start).
  const nav::NavState& truth() const { return truth_; }
  /// Rates and everything else at the current epoch (ω_ib^b, f^b, v̇_n, ...), for users who want
  /// rates rather than increments.
  Kinematics rates() const;

  double dt() const { return dt_; }  // [s]
  const Trajectory& trajectory() const { return trajectory_; }

 private:
  const Trajectory& trajectory_;
  double rate_;   // [Hz]
  double dt_;     // [s]
  double maxSubstep_;  // [s]
  long long count_;
  long long k_ = 0;
  nav::NavState truth_;
};

}  // namespace sinsim::sim
