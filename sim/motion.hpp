// The analytic motion of a scenario: speed, heading, flight-path angle and attitude as smooth
// functions of time, segment after segment. Position is not here: it follows from the velocity by
// integration on the ellipsoid (sim/trajectory.hpp).
//
// Every segment changes one quantity x by Δ over its duration T along the smooth step
//   x(t) = x0 + Δ·S(u),  u = (t − t0)/T,  S(u) = u − sin(2πu)/(2π)            (raised-cosine rate)
// so that ẋ = Δ/T·(1 − cos 2πu) and ẍ = Δ/T²·2π sin 2πu both vanish at the segment ends: speed,
// heading, flight-path angle and attitude are C² across segment boundaries, the acceleration and
// the angular rate are continuous and the jerk is bounded by 2πΔ/T² (plus the terms listed at
// Segment::jerkBound). Excursions (pitch, roll manoeuvres) go up along S(2u) and back along
// 1 − S(2u − 1), also C² everywhere.
#pragma once

#include <string>
#include <vector>

#include "nav/types.hpp"

namespace sinsim::sim {

/// Bank angle of a turn.
enum class BankMode {
  None,         ///< wings level / car: the turn is a pure yaw rotation
  Coordinated,  ///< roll φ = atan(s·ψ̇/g0): no lateral specific force from the turn itself
};

/// Standard gravity used to bank coordinated turns [m/s^2]. The turn is coordinated with g0, not
/// with the local normal gravity, so a coordinated turn leaves a lateral specific force of order
/// |g − g0|/g0 ≈ 0.3 % of the centripetal acceleration; the IMU is still exact for the motion.
constexpr double kBankGravity = 9.80665;

/// The vehicle state at the start of the motion (a scenario's `start:` block).
struct MotionStart {
  double lat = 0.0;      // geodetic latitude [rad]
  double lon = 0.0;      // longitude [rad]
  double h = 0.0;        // height above the WGS-84 ellipsoid [m]
  double speed = 0.0;    // speed along the path [m/s], ≥ 0
  double heading = 0.0;  // course over ground = body yaw [rad]
  double roll = 0.0;     // constant roll offset of the body [rad]
  double pitch = 0.0;    // constant pitch offset of the body above the flight path [rad]
};

enum class SegmentKind { Static, Cruise, Accelerate, Turn, Climb, Pitch, Roll };

/// One motion segment, already planned (its start time and start state are known).
struct Segment {
  SegmentKind kind = SegmentKind::Cruise;
  std::string type;        // the YAML type name, for reports
  double duration = 0.0;   // T [s], > 0
  double change = 0.0;     // Δ: speed [m/s], heading [rad], height [m] or peak angle [rad]
  BankMode bank = BankMode::None;  // turns only

  // Planned state at the segment start:
  double t0 = 0.0;     // [s]
  double speed0 = 0.0; // [m/s]
  double heading0 = 0.0;  // [rad]
  double h0 = 0.0;     // height the profile reaches at t0 [m]

  double t1() const { return t0 + duration; }
};

/// Analytic motion at one instant. Derivatives are exact (no finite differences).
struct MotionPoint {
  double speed = 0.0, speedRate = 0.0;      // s [m/s], ṡ [m/s^2]
  double heading = 0.0, headingRate = 0.0;  // ψ [rad], ψ̇ [rad/s]
  double pathAngle = 0.0, pathAngleRate = 0.0;  // flight-path angle γ (up +) [rad], γ̇ [rad/s]
  nav::Vec3 euler = nav::Vec3::Zero();      // body roll, pitch, yaw [rad] (C_nb = Rz Ry Rx)
  nav::Vec3 eulerRate = nav::Vec3::Zero();  // their time derivatives [rad/s]
  nav::Vec3 v_n = nav::Vec3::Zero();        // velocity w.r.t. Earth, NED [m/s]
  nav::Vec3 a_n = nav::Vec3::Zero();        // d(v_n)/dt of the NED components [m/s^2]
  double plannedHeight = 0.0;               // height the profile prescribes [m] (= the ODE's h)
};

/// The whole motion: a start and planned segments back to back from t = 0.
class MotionProfile {
 public:
  MotionProfile() = default;
  /// segments must be planned (see planSegments) and contiguous from t = 0.
  MotionProfile(const MotionStart& start, std::vector<Segment> segments);

  /// Motion at time t [s], 0 ≤ t ≤ duration() (clamped outside: the vehicle keeps its final
  /// state). Cost O(log #segments).
  MotionPoint at(double t) const;

  /// The first knot strictly after t [s], or +inf. Knots are the instants where the motion's
  /// third derivatives (angular acceleration, jerk) may jump: segment boundaries and the turning
  /// points of excursions. Between knots every profile is analytic, so an integrator that steps
  /// on the knots keeps its full order (one that steps across them drops to O(h²) there).
  double nextKnot(double t) const;

  double duration() const { return duration_; }  // [s]
  const MotionStart& start() const { return start_; }
  const std::vector<Segment>& segments() const { return segments_; }

 private:
  MotionStart start_;
  std::vector<Segment> segments_;
  std::vector<double> ends_;   // t1 of each segment, for the lookup
  std::vector<double> knots_;  // sorted, see nextKnot
  double duration_ = 0.0;
};

/// The running state while segments are laid out one after another.
struct PlanCursor {
  double t = 0.0;        // [s]
  double speed = 0.0;    // [m/s]
  double heading = 0.0;  // [rad]
  double h = 0.0;        // [m]
};

/// Fills the start fields of `segment` from the cursor and advances the cursor to its end.
/// Returns an empty string when the segment can be flown, else what is wrong (e.g. a climb too
/// steep for the speed, a static segment while moving) for the caller to report with its line.
std::string planSegment(Segment& segment, PlanCursor& cursor);

/// Largest body angular rate [rad/s] and path acceleration [m/s^2] a planned segment reaches,
/// from the closed forms of its smooth-step profile (exact for accelerations, flat turns and
/// excursions; an upper bound for coordinated turns and climbs). Earth and transport rates are
/// not included: they are bounded by the speed and height limits.
struct SegmentPeaks {
  double angularRate = 0.0;
  double acceleration = 0.0;
};
SegmentPeaks segmentPeaks(const Segment& segment);

/// Smooth step S(u) = u − sin(2πu)/(2π) on [0, 1] and its first three derivatives w.r.t. u.
struct SmoothStep {
  double s, ds, d2s, d3s;
};
SmoothStep smoothStep(double u);

}  // namespace sinsim::sim
