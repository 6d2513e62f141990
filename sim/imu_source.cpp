#include "sim/imu_source.hpp"

#include <algorithm>
#include <string>

#include "common/error.hpp"
#include "sim/reference.hpp"

namespace sinsim::sim {

TrajectorySource::TrajectorySource(const Trajectory& trajectory, double imuRate,
                                   errormodels::ImuCorruptor* corruptor,
                                   const TemperatureProfile& temperature)
    : imu_(trajectory, imuRate),
      rate_(imuRate),
      corruptor_(corruptor),
      temperature_(temperature),
      initial_(imu_.truth()) {}

bool TrajectorySource::next(ImuEpoch& e) {
  if (imu_.done()) return false;
  e.ideal = imu_.next();
  e.measured = e.ideal;
  // The temperature at the interval's midpoint, as the sensor sees it while integrating.
  e.temperature = temperature_.at(e.ideal.t - 0.5 * e.ideal.dt);
  if (corruptor_) corruptor_->corrupt(e.measured, e.temperature);
  e.index = imu_.index();
  e.truth = imu_.truth();
  e.hTrue = e.truth.h;
  e.hasTruth = true;
  return true;
}

ReferenceSource::ReferenceSource(const Reference& ref, errormodels::ImuCorruptor* corruptor)
    : ref_(ref), corruptor_(corruptor) {}

const nav::NavState& ReferenceSource::initial() const { return ref_.initial; }
double ReferenceSource::rate() const { return ref_.imuRate; }
long long ReferenceSource::sampleCount() const { return static_cast<long long>(ref_.samples.size()); }

void ReferenceSource::corruptNextBlock() {
  constexpr std::size_t kBlock = 128;  // intervals; the block's work space stays in L1
  blockStart_ = k_;
  const std::size_t n = std::min(kBlock, ref_.samples.size() - k_);
  measured_.assign(ref_.samples.begin() + std::ptrdiff_t(k_),
                   ref_.samples.begin() + std::ptrdiff_t(k_ + n));
  temperature_.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    temperature_[i] = ref_.temperature.at(measured_[i].t - 0.5 * measured_[i].dt);
  corruptor_->corruptBlock(measured_.data(), temperature_.data(), n);
}

bool ReferenceSource::next(ImuEpoch& e) {
  if (k_ >= ref_.samples.size()) return false;
  e.ideal = ref_.samples[k_];
  if (corruptor_) {
    if (k_ >= blockStart_ + measured_.size()) corruptNextBlock();
    e.measured = measured_[k_ - blockStart_];
    e.temperature = temperature_[k_ - blockStart_];
  } else {
    e.measured = e.ideal;
    e.temperature = ref_.temperature.at(e.ideal.t - 0.5 * e.ideal.dt);
  }
  e.hTrue = ref_.hRef[k_];
  ++k_;
  e.index = static_cast<long long>(k_);
  if (!ref_.truthAll.empty()) {  // an aided reference: the truth at every interval
    e.hasTruth = true;
    e.truth = ref_.truthAll[k_ - 1];
    return true;
  }
  const auto dec = static_cast<std::size_t>(ref_.decimation);
  e.hasTruth = k_ % dec == 0;
  if (e.hasTruth) e.truth = ref_.truth[k_ / dec];
  return true;
}

RecordSource::RecordSource(const Reference& ref, const errormodels::Record& record)
    : ideal_(ref, nullptr), record_(record) {}

const nav::NavState& RecordSource::initial() const { return ideal_.initial(); }
double RecordSource::rate() const { return ideal_.rate(); }
long long RecordSource::sampleCount() const { return ideal_.sampleCount(); }

bool RecordSource::next(ImuEpoch& e) {
  if (!ideal_.next(e)) return false;
  if (k_ >= record_.size())
    throw InputError(record_.source + ": the record has no sample for t = " +
                     std::to_string(e.ideal.t) + " s");
  for (int a = 0; a < 3; ++a) {
    e.measured.dtheta_b[a] = record_.gyro[a][k_] * e.measured.dt;
    e.measured.dv_b[a] = record_.accel[a][k_] * e.measured.dt;
  }
  ++k_;
  return true;
}

}  // namespace sinsim::sim
