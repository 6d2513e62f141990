// The report of one run (`sinsim run --html FILE`): the track of truth and navigation on a map,
// the position errors and the attitude errors against time, and the summary — one HTML file
// drawn with sim/report.
#pragma once

#include <GeographicLib/LocalCartesian.hpp>

#include <cstddef>
#include <string>
#include <vector>

#include "nav/types.hpp"
#include "sim/run.hpp"

namespace sinsim::sim {

/// The run as the report shows it, at output epochs (every `stride`-th one, so that a long run
/// keeps at most about kMaxPoints points: memory stays bounded).
class RunTrack {
 public:
  static constexpr std::size_t kMaxPoints = 20000;
  /// `rows`: output epochs the run will have; `start`: the true start (origin of the map).
  RunTrack(const nav::NavState& start, long long rows);
  /// One output epoch (call for every one, in order).
  void add(const nav::NavState& truth, const nav::NavState& nav, const NavError& error);

  std::vector<double> t;                                 // [s]
  std::vector<double> eastTrue, northTrue, eastNav, northNav;  // [m] local tangent plane at the start
  std::vector<double> north, east, down, horizontal;     // errors [m]
  std::vector<double> roll, pitch, yaw;                  // errors [rad]

 private:
  GeographicLib::LocalCartesian map_;  // east, north, up of the start
  long long stride_, seen_ = 0;
};

/// The page. Throws InputError when a plot cannot be drawn (no epochs).
std::string runReportHtml(const RunSummary& summary, const RunTrack& track);

}  // namespace sinsim::sim
