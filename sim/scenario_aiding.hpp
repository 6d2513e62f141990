// The scenario's aided navigation (initial errors, alignment, GNSS/INS filter; docs/aided.md) as
// the navigation loop's aiding hook (nav_loop.hpp): it sets where the navigation starts and runs
// sim/aided/AidedNavigation after every interval, writing filter.csv rows when given a file.
#pragma once

#include <cstdio>
#include <memory>
#include <string>

#include "sim/aided/aided_navigation.hpp"
#include "sim/nav_loop.hpp"
#include "sim/scenario.hpp"

namespace sinsim::sim {

class ScenarioAiding final : public NavAiding {
 public:
  /// The filter's sensor model is the scenario's (`filter: {model: ...}`). The earth must outlive
  /// the object.
  ScenarioAiding(const nav::Earth& earth, const Scenario& sc, const errormodels::StreamKey& key)
      : ScenarioAiding(earth, sc.aiding, sc.strapdown, key) {}
  /// The same from a scenario's aiding keys and vertical channel (a Monte Carlo reference's).
  ScenarioAiding(const nav::Earth& earth, const aided::AidingConfig& aiding,
                 const nav::StrapdownOptions& strapdown, const errormodels::StreamKey& key);

  nav::NavState start(const nav::NavState& truth) override { return aided_.initialState(truth); }
  nav::ImuSample compensate(const ImuEpoch& e) override {
    return aided_.compensate(e.measured, e.temperature);
  }
  void epoch(const ImuEpoch& e, const nav::ImuSample& integrated,
             nav::Strapdown& strapdown) override;

  /// filter.csv rows go here from now on (nullptr: none).
  void writeFilterRows(std::FILE* f) { filterCsv_ = f; }
  /// From now on, at every output epoch e (IMU epochs e · decimation) the filter's NEES, NIS, its
  /// degrees of freedom and the epoch class go to view[e · kAidedEpochFields + field]
  /// (sim/reference.hpp); epochs without a filter step are left as they are.
  void recordEpochs(float* view, std::size_t decimation) {
    view_ = view;
    decimation_ = decimation;
  }
  const aided::AidedNavigation& aided() const { return aided_; }

  /// A warning when the GNSS innovations so far are far from what the filter's model predicts:
  /// their summed NIS outside its chi-square 99.9 % band and its mean off by more than a factor
  /// of 2 per degree of freedom (a model that understates the errors by ~1.4x in sigma, or
  /// overstates them); empty with fewer than 10 fixes or when consistent. One run cannot tell
  /// chance from a wrong model as well as `mc`'s NEES bands can: the warning points there.
  std::string innovationWarning() const;

 private:
  aided::AidedNavigation aided_;
  std::FILE* filterCsv_ = nullptr;
  float* view_ = nullptr;
  std::size_t decimation_ = 1;
  double nisSum_ = 0.0;    // Σ NIS over the fixes used
  double nisDof_ = 0.0;    // Σ of their degrees of freedom
  std::size_t fixes_ = 0;  // fixes used
};

}  // namespace sinsim::sim
