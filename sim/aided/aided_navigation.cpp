#include "sim/aided/aided_navigation.hpp"

#include <cmath>
#include <cstdio>

#include "nav/alignment.hpp"
#include "nav/attitude.hpp"
#include "nav/lever_arm.hpp"

namespace sinsim::sim::aided {
namespace {

using Vec9 = Eigen::Matrix<double, 9, 1>;

// ψ of Ĉ = (I − [ψ×]) C from Ĉ Cᵀ (antisymmetric part; exact to first order).
nav::Vec3 attitudeError(const nav::Quat& q_est, const nav::Quat& q_true) {
  const nav::Mat3 E = (q_est * q_true.conjugate()).toRotationMatrix();
  return 0.5 * nav::Vec3(E(1, 2) - E(2, 1), E(2, 0) - E(0, 2), E(0, 1) - E(1, 0));
}

/// errorᵀ P⁻¹ error over the neesDof(vertical) states: a held vertical channel's down position
/// and velocity (states 2 and 5) left out.
double nees(const Eigen::Matrix<double, 9, 1>& error, const Eigen::Matrix<double, 9, 9>& P,
            nav::VerticalChannel vertical) {
  if (neesDof(vertical) == 9) return error.dot(P.ldlt().solve(error));
  static const std::vector<int> kept{0, 1, 3, 4, 6, 7, 8};
  const Eigen::VectorXd e = error(kept);
  const Eigen::MatrixXd Pk = P(kept, kept);
  return e.dot(Pk.ldlt().solve(e));
}

FilterOptions filterOptions(const AidingConfig& c, const nav::StrapdownOptions& sd) {
  FilterOptions o;
  o.vertical = sd.vertical;
  o.sigma0 << c.initialErrors.position.spread(), c.initialErrors.velocity.spread(),
      c.initialErrors.attitude.spread();
  // A filter must not start certain of what it does not know: floor the start at 1 mm, 1 mm/s,
  // 1 µrad (numbers far below any GNSS/INS accuracy, above rounding).
  for (int i = 0; i < 9; ++i) o.sigma0[i] = std::max(o.sigma0[i], i < 6 ? 1e-3 : 1e-6);
  return o;
}

}  // namespace

std::vector<std::string> startWarnings(const nav::Earth& earth, const AidingConfig& config,
                                       const nav::StrapdownOptions& strapdownOptions,
                                       const nav::NavState& start) {
  if (!config.filter.enabled) return {};
  std::vector<std::string> out;
  if (std::string w = noFixWarning(config.gnss, config.alignment.duration); !w.empty()) out.push_back(std::move(w));
  constexpr double deg = kDegPerRad;
  char text[720];
  const double position = config.initialErrors.position.spread().head<2>().maxCoeff();
  if (position > kMaxStartPositionSigma) {
    std::snprintf(text, sizeof text,
                  "initial_errors.position: the filter starts with a horizontal 1-sigma of %.4g km; "
                  "its error model is linear in the position error too, and beyond about %.0f km "
                  "its errors and sigmas are not to be trusted, not even after the first fixes",
                  position / 1000.0, kMaxStartPositionSigma / 1000.0);
    out.push_back(text);
  }
  if (!(config.alignment.duration > 0.0)) {
    const nav::Vec3 s = config.initialErrors.attitude.spread();
    if (!(s.maxCoeff() > kMaxStartAttitudeSigma)) return out;
    std::snprintf(text, sizeof text,
                  "initial_errors.attitude: the filter starts with an attitude 1-sigma of %.3g deg "
                  "(roll, pitch, yaw: %.3g, %.3g, %.3g deg); the error-state filter is linear in the "
                  "attitude error and holds to about %.0f deg, which more than 5 %% of the runs start "
                  "beyond at a 1-sigma above %.3g deg: its errors and sigmas until the attitude is "
                  "observed, and for a while after, are not to be trusted",
                  s.maxCoeff() * deg, s.x() * deg, s.y() * deg, s.z() * deg, kSmallAngle * deg,
                  kMaxStartAttitudeSigma * deg);
    out.push_back(text);
    return out;
  }
  // The alignment at the true start as the filter's model predicts it (ideal mean signals).
  ErrorStateFilter f(earth, config.filter.sensors, filterOptions(config, strapdownOptions));
  const nav::Mat3 C = start.q_nb.toRotationMatrix();
  const nav::Vec3 g_n = earth.gravity_n(start.lat, start.h);
  f.startAfterAlignment(nav::coarseAlignmentSensitivity(start.lat, g_n.norm(), earth.rate()), C,
                        -C.transpose() * g_n, C.transpose() * earth.omega_ie_n(start.lat),
                        config.alignment.duration);
  const double yaw = std::sqrt(f.P()(nav::kAtt + 2, nav::kAtt + 2));
  if (!(yaw > kMaxStartAttitudeSigma)) return out;
  std::snprintf(text, sizeof text,
                "coarse alignment: the filter's own sensor model makes the gyrocompassed heading "
                "uncertain by %.3g deg (1-sigma); the error-state filter is linear in the attitude "
                "error and holds to about %.0f deg, which more than 5 %% of the runs start beyond at "
                "a 1-sigma above %.3g deg: its errors and sigmas until the heading is observed are "
                "not to be trusted. Gyrocompassing needs gyro errors well "
                "below the Earth rate's horizontal part (%.1f deg/h here); with these gyros give "
                "the heading instead (no alignment, initial_errors.attitude as its accuracy)",
                yaw * deg, kSmallAngle * deg, kMaxStartAttitudeSigma * deg,
                earth.rate() * std::cos(start.lat) * deg * 3600.0);
  out.push_back(text);
  return out;
}

int neesDof(nav::VerticalChannel vertical) { return vertical == nav::VerticalChannel::Held ? 7 : 9; }

Vec9 navErrorStates(const nav::Earth& earth, const nav::NavState& nav,
                    const nav::NavState& truth) {
  double M = 0.0, N = 0.0;
  earth.radii(truth.lat, M, N);
  Vec9 e;
  e.segment<3>(0) = nav::Vec3((nav.lat - truth.lat) * (M + truth.h),
                              nav::wrapAngle(nav.lon - truth.lon) * (N + truth.h) * std::cos(truth.lat),
                              -(nav.h - truth.h));
  e.segment<3>(3) = nav.v_n - truth.v_n;
  e.segment<3>(6) = attitudeError(nav.q_nb, truth.q_nb);
  return e;
}

AidedNavigation::AidedNavigation(const nav::Earth& earth, const AidingConfig& config,
                                 FilterSensorModel model,
                                 const nav::StrapdownOptions& strapdownOptions,
                                 const errormodels::StreamKey& key)
    : earth_(&earth),
      config_(config),
      filter_(earth, std::move(model), filterOptions(config, strapdownOptions)),
      known_(config.filter.knownAdded, config.filter.knownLinear, config.filter.imuRate),
      sdOptions_(strapdownOptions),
      posNoise_(key.seed, key.run, errormodels::streamId(2, 1, 0)),
      velNoise_(key.seed, key.run, errormodels::streamId(2, 2, 0)) {
  errormodels::NormalStream init(key.seed, key.run, errormodels::streamId(2, 0, 0));
  const ValueOrSigma* parts[3] = {&config.initialErrors.position, &config.initialErrors.velocity,
                                  &config.initialErrors.attitude};
  for (int p = 0; p < 3; ++p)
    for (int i = 0; i < 3; ++i) {
      const double w = init.next();  // drawn always: the streams do not shift with the config
      initialError_[3 * p + i] = parts[p]->random ? parts[p]->sigma[i] * w : parts[p]->value[i];
    }
  aligned_ = !(config.alignment.duration > 0.0);
  for (const TimeWindow& w : config.gnss.outages) outages_.push_back({w, NAN, NAN, NAN});
  sum_.f_n.setZero();
  sum_.C_nb.setZero();
}

nav::NavState AidedNavigation::initialState(const nav::NavState& truth) const {
  nav::NavState s = truth;
  double M = 0.0, N = 0.0;
  earth_->radii(truth.lat, M, N);
  s.lat += initialError_[0] / (M + truth.h);
  s.lon += initialError_[1] / ((N + truth.h) * std::cos(truth.lat));
  s.h -= initialError_[2];
  s.v_n += initialError_.segment<3>(3);
  // Without an attitude error the start keeps the true quaternion's bits (no Euler round trip).
  if (!initialError_.segment<3>(6).isZero())
    s.q_nb = nav::quatFromEuler(nav::eulerFromQuat(truth.q_nb) + initialError_.segment<3>(6));
  return s;
}

void AidedNavigation::align(const nav::ImuSample& m, const nav::NavState& truth,
                            nav::Strapdown& sd) {
  if (sumDt_ == 0.0) alignAnchor_ = sd.state();  // the start as the user believes it
  sumDtheta_ += m.dtheta_b;
  sumDv_ += m.dv_b;
  sumDt_ += m.dt;
  // Static: hold position and velocity at the start (a zero-velocity hold), leave attitude free.
  Vec9 e = navErrorStates(*earth_, sd.state(), alignAnchor_);
  sd.correct(e.segment<3>(0), e.segment<3>(3), nav::Vec3::Zero());
  if (truth.t + 0.5 * m.dt < config_.alignment.duration) return;
  const nav::Quat q = nav::coarseAlignment(sumDv_ / sumDt_, sumDtheta_ / sumDt_);
  // The exact rotation from the navigated to the aligned attitude (correct() applies R(ψ) q_nb;
  // the first-order attitudeError would leave θ³/6, 1e-4 rad for a 5° start).
  sd.correct(nav::Vec3::Zero(), nav::Vec3::Zero(),
             nav::rotationVectorFromQuat(q * sd.state().q_nb.conjugate()));
  if (config_.filter.enabled) {
    // The filter's attitude uncertainty is now the alignment's, from its own sensor model.
    const nav::Vec3 f = sumDv_ / sumDt_;
    filter_.startAfterAlignment(
        nav::coarseAlignmentSensitivity(alignAnchor_.lat, f.norm(), earth_->rate()),
        q.toRotationMatrix(), f, sumDtheta_ / sumDt_, sumDt_);
  }
  aligned_ = true;
  fixIndex_ = static_cast<long long>(std::floor(truth.t * config_.gnss.rate + 1e-9));
  stepTime_ = 0.0;
}

void AidedNavigation::fix(const nav::NavState& truth, const nav::Vec3& rateNav,
                          const nav::Vec3& rateTrue, nav::Strapdown& sd, FilterEpoch& out) {
  const GnssConfig& g = config_.gnss;
  const nav::NavState& s = sd.state();
  const Vec9 e = navErrorStates(*earth_, s, truth);
  const nav::Vec3 lever_n = s.q_nb * g.leverArm_b;
  nav::Vec3 noise(posNoise_.next(), posNoise_.next(), posNoise_.next());
  out.nis = 0.0;
  out.nisDof = 0;
  if (g.positionSigma) {
    const nav::Vec3 dzPos = e.segment<3>(0) + lever_n - truth.q_nb * g.leverArm_b -
                            g.positionSigma->cwiseProduct(noise);
    out.nis += filter_.updatePosition(dzPos, lever_n, *g.positionSigma).nis;
    out.nisDof += 3;
  }
  if (g.velocitySigma) {
    noise = nav::Vec3(velNoise_.next(), velNoise_.next(), velNoise_.next());
    // The antenna's velocity: the reference point's plus the rotation's lever-arm term (zero
    // without a lever arm), the navigation's from its own rate, the fix's from the truth's.
    const nav::Vec3 arm_n = nav::leverArmVelocity(*earth_, s, rateNav, g.leverArm_b);
    const nav::Vec3 dzVel = e.segment<3>(3) + arm_n -
                            nav::leverArmVelocity(*earth_, truth, rateTrue, g.leverArm_b) -
                            g.velocitySigma->cwiseProduct(noise);
    out.nis += filter_.updateVelocity(dzVel, arm_n, *g.velocitySigma).nis;
    out.nisDof += 3;
  }
  out.aiding = true;
  const Vec9 c = filter_.takeNavCorrection();
  sd.correct(c.segment<3>(0), c.segment<3>(3), c.segment<3>(6));
}

nav::ImuSample AidedNavigation::compensate(const nav::ImuSample& measured, double temperature) {
  if (!config_.filter.enabled) return measured;
  const nav::ImuSample c = compensate(measured, measured.dv_b, temperature);
  // A known g-sensitivity again, of the compensated specific force (the sensor's is of the true
  // one: the accelerometers' own errors times it are milli-g times deg/s/g). The whole second
  // pass costs 2 % of an aided aircraft run (examples/known-errors: 1.33 s against 1.30 s with
  // the g-sensitivity left out), less than splitting the triads' passes would be worth.
  return known_.sensesForce() ? compensate(measured, c.dv_b, temperature) : c;
}

nav::ImuSample AidedNavigation::compensate(const nav::ImuSample& measured, const nav::Vec3& dv,
                                           double temperature) {
  // The reverse of the sensor's order (known_errors.hpp): the known added errors, the estimated
  // bias, then the known misalignment and the estimated scale errors (b dt + diag(s) u: first
  // order in dt and in the scale errors). Nothing known or estimated, nothing touched: a filter
  // without fixes (and zero prior means) leaves the navigation bit-identical to the free run.
  const nav::ImuSample m = known_.withoutAdded(measured, dv, temperature);
  if (!aligned_) return known_.withoutLinear(m);
  const nav::Vec3 bg = filter_.gyroError(), ba = filter_.accelError();
  nav::ImuSample c = m;
  if (!(bg.isZero() && ba.isZero())) {
    c.dtheta_b -= bg * m.dt;
    c.dv_b -= ba * m.dt;
  }
  c = known_.withoutLinear(c);
  if (filter_.hasScaleStates()) {
    c.dtheta_b -= filter_.gyroScale().cwiseProduct(m.dtheta_b);
    c.dv_b -= filter_.accelScale().cwiseProduct(m.dv_b);
  }
  return c;
}

namespace {

double horizontalSigma(const ErrorStateFilter& f) { return std::sqrt(f.P()(0, 0) + f.P()(1, 1)); }

}  // namespace

// Propagates the filter over the step accumulated since the last one, linearised at its means.
void AidedNavigation::propagateStep(nav::Strapdown& sd) {
  nav::InsErrorPoint p;
  p.lat = sum_.lat / stepTime_;
  p.h = sum_.h / stepTime_;
  p.v_n = sum_.v_n / stepTime_;
  p.f_n = sum_.f_n / stepTime_;
  p.C_nb = sum_.C_nb / stepTime_;
  filter_.setVerticalGains(sd.dampingGainK1(), sd.dampingGainK2());
  ScaleInput scale;
  scale.C_omega = sumScale_.C_omega / stepTime_;
  scale.C_f = sumScale_.C_f / stepTime_;
  filter_.propagate(p, stepTime_, scale);
  if (pendingSigma_) outages_[*pendingSigma_].sigmaHorizontal = horizontalSigma(filter_);  // trackOutage
  pendingSigma_.reset();
  // The sampled (ar) blocks' predicted effect over the step (zero without them, or without fixes).
  const Vec9 drift = filter_.takeNavCorrection();
  if (!drift.isZero()) sd.correct(drift.segment<3>(0), drift.segment<3>(3), drift.segment<3>(6));
  sum_ = nav::InsErrorPoint();
  sum_.f_n.setZero();
  sum_.C_nb.setZero();
  sumScale_ = ScaleInput();
  stepTime_ = 0.0;
}

FilterEpoch AidedNavigation::afterInterval(const nav::ImuSample& m, const nav::ImuSample& ideal,
                                           const nav::NavState& truth, nav::Strapdown& sd) {
  FilterEpoch out;
  out.t = truth.t;
  if (!aligned_) {
    align(m, truth, sd);
    return out;
  }
  if (!config_.filter.enabled) return out;

  // Means of the linearisation point over the propagation step (m is compensated).
  const nav::NavState& s = sd.state();
  const nav::Mat3 C = s.q_nb.toRotationMatrix();
  sum_.lat += s.lat * m.dt;
  sum_.h += s.h * m.dt;
  sum_.v_n += s.v_n * m.dt;
  sum_.f_n += C * m.dv_b;
  sum_.C_nb += C * m.dt;
  if (filter_.hasScaleStates()) {  // Σ C_nb diag(u): the scale states' inputs
    sumScale_.C_omega += C * m.dtheta_b.asDiagonal();
    sumScale_.C_f += C * m.dv_b.asDiagonal();
  }
  stepTime_ += m.dt;

  const GnssConfig& g = config_.gnss;
  const double tick = static_cast<double>(fixIndex_ + 1) / g.rate;
  const bool fixDue = truth.t + 0.5 * m.dt >= tick;
  // Fixes further apart than kMaxPropagationStep: the filter propagates at least that often in
  // between, so that its linearisation follows the motion.
  if (fixDue || stepTime_ + 0.5 * m.dt >= kMaxPropagationStep) propagateStep(sd);
  if (fixDue) {
    ++fixIndex_;
    out.outage = g.inOutage(truth.t);
    if (!out.outage) fix(truth, m.dtheta_b / m.dt, ideal.dtheta_b / ideal.dt, sd, out);
    out.filtered = true;
    out.error = navErrorStates(*earth_, sd.state(), truth);
    const Eigen::Matrix<double, 9, 9> P = filter_.P().topLeftCorner<9, 9>();
    out.sigma = P.diagonal().cwiseSqrt();
    out.nees = nees(out.error, P, sdOptions_.vertical);
  }
  trackOutage(truth, sd, out);
  return out;
}

void AidedNavigation::trackOutage(const nav::NavState& truth, const nav::Strapdown& sd, const FilterEpoch& epoch) {
  for (std::size_t i = 0; i < outages_.size(); ++i) {
    OutageResult& o = outages_[i];
    if (!o.window.contains(truth.t)) continue;
    // A filter epoch has its error already; between them it is formed here (outage epochs only).
    const Vec9 e = epoch.filtered ? Vec9(epoch.error) : navErrorStates(*earth_, sd.state(), truth);
    const double hor = std::hypot(e[0], e[1]);
    if (hor < o.maxHorizontal) continue;  // NaN at first: the window's first epoch
    o.maxHorizontal = hor;
    o.t = truth.t;
    // A filter step now: its prediction; else the next step's (propagateStep), the last until then.
    o.sigmaHorizontal = horizontalSigma(filter_);
    pendingSigma_ = stepTime_ == 0.0 ? std::optional<std::size_t>() : std::optional<std::size_t>(i);
  }
}

}  // namespace sinsim::sim::aided
