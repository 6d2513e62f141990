#include "sim/scenario_aiding.hpp"

#include <cmath>

#include "common/error.hpp"
#include "common/limits.hpp"
#include "errormodels/stats/special.hpp"
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
  if (fe.aiding && std::isfinite(fe.nis)) nisSum_ += fe.nis, nisDof_ += fe.nisDof, ++fixes_;
  const auto k = std::size_t(e.index);
  if (view_ && fe.filtered && k % decimation_ == 0) {
    float* row = view_ + (k / decimation_) * kAidedEpochFields;
    row[kNees] = float(fe.nees);
    row[kNis] = float(fe.nis);
    row[kNisDof] = float(fe.nisDof);
    row[kEpochClass] = fe.aiding ? 1.0f : fe.outage ? 2.0f : 0.0f;
  }
}

std::string ScenarioAiding::innovationWarning() const {
  if (fixes_ < 10 || !(nisDof_ > 0.0)) return "";
  const double ratio = nisSum_ / nisDof_;
  const double lo = errormodels::chiSquareQuantile(0.0005, nisDof_), hi = errormodels::chiSquareQuantile(0.9995, nisDof_);
  const bool above = nisSum_ > hi && ratio > 2.0, below = nisSum_ < lo && ratio < 0.5;
  if (!above && !below) return "";
  return "filter: the GNSS innovations are " + limits::fmt(ratio, 3) + " times the variance its model predicts "
         "(mean NIS per degree of freedom over " + std::to_string(fixes_) + " fixes; 99.9 % band " +
         limits::fmt(lo / nisDof_, 3) + " to " + limits::fmt(hi / nisDof_, 3) + "): its sensor model " +
         (above ? "understates the errors (over-confident: its sigmas are too small)"
                : "overstates the errors (pessimistic)") +
         ", or the GNSS sigmas are off; `sinsim mc` gives the NEES verdict over many runs (docs/aided.md)";
}

}  // namespace sinsim::sim
