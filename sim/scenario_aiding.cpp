#include "sim/scenario_aiding.hpp"

#include "common/error.hpp"
#include "sim/aided/aided_output.hpp"
#include "sim/reference.hpp"

namespace sinsim::sim {

ScenarioAiding::ScenarioAiding(const nav::Earth& earth, const aided::AidingConfig& aiding,
                               const nav::StrapdownOptions& strapdown,
                               const errormodels::StreamKey& key)
    : aided_(earth, aiding, aiding.filter.sensors, strapdown, key) {}

void ScenarioAiding::epoch(const ImuEpoch& e, const nav::ImuSample& integrated,
                           nav::Strapdown& strapdown) {
  if (!e.hasTruth)
    throw InputError("aided navigation needs the truth at every IMU epoch (GNSS is simulated "
                     "from it); this IMU source has it only at output epochs");
  const aided::FilterEpoch fe = aided_.afterInterval(integrated, e.ideal, e.truth, strapdown);
  if (filterCsv_ && fe.filtered) aided::writeFilterRow(filterCsv_, fe);
  const auto k = std::size_t(e.index);
  if (view_ && fe.filtered && k % decimation_ == 0) {
    float* row = view_ + (k / decimation_) * kAidedEpochFields;
    row[kNees] = float(fe.nees);
    row[kNis] = float(fe.nis);
    row[kNisDof] = float(fe.nisDof);
    row[kEpochClass] = fe.aiding ? 1.0f : fe.outage ? 2.0f : 0.0f;
  }
}

}  // namespace sinsim::sim
