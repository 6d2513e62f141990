#include "sim/motion.hpp"

#include "common/constants.hpp"
#include <algorithm>
#include <cmath>
#include <sstream>

namespace sinsim::sim {
namespace {

constexpr double kTwoPi = 2.0 * kPi;
// Steepest flight-path angle a climb may reach at its peak: γ̇ = ḧ/(s cos γ) grows without
// bound as γ → 90°, and a vertical climb has no heading.
constexpr double kMaxPathAngle = 80.0 * kRadPerDeg;  // [rad]

// Excursion E(u): 0 → 1 along S(2u) on [0, 1/2], back along 1 − S(2u − 1) on [1/2, 1].
// Returns E and dE/du.
void excursion(double u, double& e, double& de) {
  if (u <= 0.5) {
    const SmoothStep st = smoothStep(2.0 * u);
    e = st.s;
    de = 2.0 * st.ds;
  } else {
    const SmoothStep st = smoothStep(2.0 * u - 1.0);
    e = 1.0 - st.s;
    de = -2.0 * st.ds;
  }
}

std::string fmt(double x) {
  std::ostringstream os;
  os.precision(4);
  os << x;
  return os.str();
}

}  // namespace

SmoothStep smoothStep(double u) {
  u = std::clamp(u, 0.0, 1.0);
  const double a = kTwoPi * u;
  return {u - std::sin(a) / kTwoPi, 1.0 - std::cos(a), kTwoPi * std::sin(a),
          kTwoPi * kTwoPi * std::cos(a)};
}

std::string planSegment(Segment& seg, PlanCursor& c) {
  seg.t0 = c.t;
  seg.speed0 = c.speed;
  seg.heading0 = c.heading;
  seg.h0 = c.h;
  std::string problem;
  if (!(std::isfinite(seg.duration) && seg.duration > 0.0)) {
    // reported by the parser where the duration is read; keep the cursor sane
    seg.duration = 0.0;
    return problem;
  }
  switch (seg.kind) {
    case SegmentKind::Static:
      if (c.speed != 0.0)
        problem = "a static segment needs the vehicle at rest, but it moves at " + fmt(c.speed) +
                  " m/s here (add an accelerate to 0 m/s before it, or use cruise)";
      break;
    case SegmentKind::Cruise:
    case SegmentKind::Pitch:
    case SegmentKind::Roll:
      break;
    case SegmentKind::Accelerate:
      c.speed += seg.change;
      if (std::abs(c.speed) < 1e-12) c.speed = 0.0;  // exact rest after "to 0 m/s"
      break;
    case SegmentKind::Turn:
      c.heading += seg.change;
      break;
    case SegmentKind::Climb: {
      if (!(c.speed > 0.0)) {
        problem = "a climb or descent needs forward speed, but the vehicle is at rest here";
        break;
      }
      // peak vertical speed 2Δh/T = s sin γ_max
      const double sinPeak = 2.0 * std::abs(seg.change) / (seg.duration * c.speed);
      if (!(sinPeak <= std::sin(kMaxPathAngle)))
        problem = "too steep: " + fmt(std::abs(seg.change)) + " m in " + fmt(seg.duration) +
                  " s at " + fmt(c.speed) + " m/s needs a peak flight-path angle above 80 deg" +
                  " (lengthen the duration to at least " +
                  fmt(2.0 * std::abs(seg.change) / (c.speed * std::sin(kMaxPathAngle))) + " s)";
      c.h += seg.change;
      break;
    }
  }
  c.t += seg.duration;
  return problem;
}

SegmentPeaks segmentPeaks(const Segment& g) {
  SegmentPeaks p;
  const double T = g.duration, d = std::abs(g.change), s = g.speed0;
  if (!(T > 0.0)) return p;
  // S'(u) peaks at 2 and S''(u) at 2π (smoothStep); an excursion runs S at twice the pace.
  switch (g.kind) {
    case SegmentKind::Static:
    case SegmentKind::Cruise:
      break;
    case SegmentKind::Accelerate:
      p.acceleration = 2.0 * d / T;
      break;
    case SegmentKind::Turn: {
      const double psidot = 2.0 * d / T;
      p.acceleration = s * psidot;
      p.angularRate = psidot;
      // bank rate |φ̇| ≤ s |ψ̈| / g0 (d atan(x)/dx ≤ 1)
      if (g.bank == BankMode::Coordinated) p.angularRate += s * kTwoPi * d / (T * T) / kBankGravity;
      break;
    }
    case SegmentKind::Climb: {
      if (!(s > 0.0)) break;
      const double hddot = kTwoPi * d / (T * T);
      const double sinPeak = std::min(2.0 * d / (T * s), std::sin(kMaxPathAngle));
      p.angularRate = hddot / (s * std::sqrt(1.0 - sinPeak * sinPeak));  // γ̇ = ḧ / (s cos γ)
      p.acceleration = s * p.angularRate;
      break;
    }
    case SegmentKind::Pitch:
    case SegmentKind::Roll:
      p.angularRate = 4.0 * d / T;
      break;
  }
  return p;
}

MotionProfile::MotionProfile(const MotionStart& start, std::vector<Segment> segments)
    : start_(start), segments_(std::move(segments)) {
  ends_.reserve(segments_.size());
  for (const auto& s : segments_) {
    ends_.push_back(s.t1());
    if (s.kind == SegmentKind::Pitch || s.kind == SegmentKind::Roll)
      knots_.push_back(s.t0 + 0.5 * s.duration);
    knots_.push_back(s.t1());
  }
  duration_ = ends_.empty() ? 0.0 : ends_.back();
}

double MotionProfile::nextKnot(double t) const {
  const auto it = std::upper_bound(knots_.begin(), knots_.end(), t);
  return it == knots_.end() ? INFINITY : *it;
}

MotionPoint MotionProfile::at(double t) const {
  MotionPoint p;
  double s = start_.speed, sdot = 0.0;
  double psi = start_.heading, psidot = 0.0, psiddot = 0.0;
  double gamma = 0.0, gammadot = 0.0;
  double rollM = 0.0, rollMdot = 0.0, pitchM = 0.0, pitchMdot = 0.0;
  double h = start_.h;
  bool coordinated = false;

  if (!segments_.empty()) {
    // first segment whose end is after t; past the end: the final state of the last segment
    auto it = std::upper_bound(ends_.begin(), ends_.end(), t);
    const bool past = it == ends_.end();
    const Segment& g = past ? segments_.back() : segments_[it - ends_.begin()];
    const double T = g.duration;
    const double u = past ? 1.0 : std::clamp((t - g.t0) / T, 0.0, 1.0);
    s = g.speed0;
    psi = g.heading0;
    h = g.h0;
    const SmoothStep st = smoothStep(u);
    switch (g.kind) {
      case SegmentKind::Static:
      case SegmentKind::Cruise:
        break;
      case SegmentKind::Accelerate:
        s += g.change * st.s;
        sdot = g.change / T * st.ds;
        break;
      case SegmentKind::Turn:
        psi += g.change * st.s;
        psidot = g.change / T * st.ds;
        psiddot = g.change / (T * T) * st.d2s;
        coordinated = g.bank == BankMode::Coordinated;
        break;
      case SegmentKind::Climb: {
        // vertical speed ḣ = Δh/T·S'(u) = s sin γ at constant s
        const double hdot = g.change / T * st.ds;
        const double hddot = g.change / (T * T) * st.d2s;
        h += g.change * st.s;
        gamma = std::asin(hdot / s);
        gammadot = hddot / (s * std::cos(gamma));
        break;
      }
      case SegmentKind::Pitch: {
        double e = 0.0, de = 0.0;
        excursion(u, e, de);
        pitchM = g.change * e;
        pitchMdot = g.change / T * de;
        break;
      }
      case SegmentKind::Roll: {
        double e = 0.0, de = 0.0;
        excursion(u, e, de);
        rollM = g.change * e;
        rollMdot = g.change / T * de;
        break;
      }
    }
    if (past) {  // at rest in the final state: no rates
      sdot = psidot = psiddot = gammadot = rollMdot = pitchMdot = 0.0;
      coordinated = false;
    }
  }

  // Coordinated bank φc = atan(s ψ̇ / g0); φ̇c by the chain rule (s constant in a turn, but keep ṡ).
  double bank = 0.0, bankdot = 0.0;
  if (coordinated) {
    const double x = s * psidot / kBankGravity;
    bank = std::atan(x);
    bankdot = (sdot * psidot + s * psiddot) / kBankGravity / (1.0 + x * x);
  }

  p.speed = s;
  p.speedRate = sdot;
  p.heading = psi;
  p.headingRate = psidot;
  p.pathAngle = gamma;
  p.pathAngleRate = gammadot;
  p.plannedHeight = h;
  p.euler = nav::Vec3(start_.roll + bank + rollM, start_.pitch + gamma + pitchM, psi);
  p.eulerRate = nav::Vec3(bankdot + rollMdot, gammadot + pitchMdot, psidot);

  // v_n = s [cos γ cos ψ, cos γ sin ψ, −sin γ] and its exact time derivative.
  const double cg = std::cos(gamma), sg = std::sin(gamma), cp = std::cos(psi), sp = std::sin(psi);
  const nav::Vec3 u_n(cg * cp, cg * sp, -sg);
  const nav::Vec3 du_dgamma(-sg * cp, -sg * sp, -cg);
  const nav::Vec3 du_dpsi(-cg * sp, cg * cp, 0.0);
  p.v_n = s * u_n;
  p.a_n = sdot * u_n + s * (gammadot * du_dgamma + psidot * du_dpsi);
  return p;
}

}  // namespace sinsim::sim
