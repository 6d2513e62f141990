#include "sim/run_report.hpp"

#include <GeographicLib/Geocentric.hpp>

#include <algorithm>
#include <cmath>

#include "common/constants.hpp"
#include "common/number_text.hpp"
#include "sim/report/report.hpp"

namespace sinsim::sim {

using namespace report;

RunTrack::RunTrack(const nav::NavState& start, long long rows)
    : map_(start.lat * kDegPerRad, start.lon * kDegPerRad, start.h,
           GeographicLib::Geocentric::WGS84()),
      stride_(std::max<long long>(1, (rows + static_cast<long long>(kMaxPoints) - 1) /
                                         static_cast<long long>(kMaxPoints))) {}

void RunTrack::add(const nav::NavState& truth, const nav::NavState& navState, const NavError& e) {
  if (seen_++ % stride_ != 0) return;
  // The map: east/north of the tangent plane at the start (GeographicLib, exact on the WGS84
  // ellipsoid), the same for truth and navigation.
  double x = 0, y = 0, z = 0;
  map_.Forward(truth.lat * kDegPerRad, truth.lon * kDegPerRad, truth.h, x, y, z);
  eastTrue.push_back(x);
  northTrue.push_back(y);
  map_.Forward(navState.lat * kDegPerRad, navState.lon * kDegPerRad, navState.h, x, y, z);
  eastNav.push_back(x);
  northNav.push_back(y);
  t.push_back(e.t);
  north.push_back(e.pos_n.x());
  east.push_back(e.pos_n.y());
  down.push_back(e.pos_n.z());
  horizontal.push_back(e.horizontal());
  roll.push_back(e.euler.x());
  pitch.push_back(e.euler.y());
  yaw.push_back(e.euler.z());
}

namespace {

DisplayUnit angleUnit(double maxAbs) {  // [rad]
  if (maxAbs * kDegPerRad < 0.05) return {kDegPerRad * 3600.0, "arcsec"};
  return {kDegPerRad, "deg"};
}

double maxAbs(std::initializer_list<const std::vector<double>*> vs) {
  double m = 0;
  for (const auto* v : vs)
    for (double x : *v)
      if (std::isfinite(x)) m = std::max(m, std::fabs(x));
  return m;
}

std::vector<double> times(const std::vector<double>& v, double f) {
  std::vector<double> o(v);
  for (double& x : o) x *= f;
  return o;
}

// The map on equal scales in east and north (a circle stays round), in m or km.
Plot trackMap(const RunTrack& tr) {
  const DisplayUnit u =
      lengthUnit(maxAbs({&tr.eastTrue, &tr.northTrue, &tr.eastNav, &tr.northNav}));
  Plot p("Track: truth and navigation", std::string("east [") + u.name + "]",
         std::string("north [") + u.name + "]");
  const auto e = times(tr.eastTrue, u.factor), n = times(tr.northTrue, u.factor);
  const auto en = times(tr.eastNav, u.factor), nn = times(tr.northNav, u.factor);
  p.add(Series{"truth", e, n, paletteColor(0), false, 2.4});
  p.add(Series{"navigation", en, nn, paletteColor(3), true, 1.6});
  p.add(Series{"start", {e.front()}, {n.front()}, "#000000", false, 1.0, true});
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const auto* v : {&e, &en})
    for (double x : *v)
      if (std::isfinite(x)) x0 = std::min(x0, x), x1 = std::max(x1, x);
  for (const auto* v : {&n, &nn})
    for (double y : *v)
      if (std::isfinite(y)) y0 = std::min(y0, y), y1 = std::max(y1, y);
  if (x0 < x1 || y0 < y1) {
    // The 760 × 440 frame is about 640 × 340 px inside the axes: equal metres per pixel.
    const double perPx = 1.08 * std::max((x1 - x0) / 640.0, (y1 - y0) / 340.0);
    const double xc = 0.5 * (x0 + x1), yc = 0.5 * (y0 + y1);
    p.xRange = std::make_pair(xc - 320.0 * perPx, xc + 320.0 * perPx);
    p.yRange = std::make_pair(yc - 170.0 * perPx, yc + 170.0 * perPx);
  }
  return p;
}

Plot positionErrors(const RunTrack& tr) {
  const DisplayUnit u = lengthUnit(maxAbs({&tr.north, &tr.east, &tr.down, &tr.horizontal}));
  Plot p("Position error (navigation − truth)", "time [s]", std::string("error [") + u.name + "]");
  p.add(Series{"horizontal", tr.t, times(tr.horizontal, u.factor), "#000000", false, 2.2});
  p.add(Series{"north", tr.t, times(tr.north, u.factor), paletteColor(0)});
  p.add(Series{"east", tr.t, times(tr.east, u.factor), paletteColor(1)});
  p.add(Series{"down", tr.t, times(tr.down, u.factor), paletteColor(2), true});
  return p;
}

Plot attitudeErrors(const RunTrack& tr) {
  const DisplayUnit u = angleUnit(maxAbs({&tr.roll, &tr.pitch, &tr.yaw}));
  Plot p("Attitude error (navigation − truth)", "time [s]", std::string("error [") + u.name + "]");
  p.add(Series{"roll", tr.t, times(tr.roll, u.factor), paletteColor(0)});
  p.add(Series{"pitch", tr.t, times(tr.pitch, u.factor), paletteColor(1)});
  p.add(Series{"yaw", tr.t, times(tr.yaw, u.factor), paletteColor(2)});
  return p;
}

}  // namespace

std::string runReportHtml(const RunSummary& s, const RunTrack& tr) {
  HtmlPage page("sinsim run: " + s.scenario + " with model " + s.model);
  page.paragraph("After " + durationText(s.duration) + " and " + lengthText(s.distance, 3) +
                 " travelled, the navigation is " + lengthText(s.final.horizontal(), 3) +
                 " off horizontally (at most " + lengthText(s.maxHorizontal, 3) + ", at " +
                 durationText(s.maxHorizontalTime) + ") and " + lengthText(s.final.vertical(), 3) +
                 " vertically.");
  Table t{{"quantity", "value"}, {}, "Summary"};
  auto row = [&](const std::string& k, const std::string& v) { t.rows.push_back({k, Cell(v, "num")}); };
  row("seed", std::to_string(s.seed));
  row("duration", durationText(s.duration));
  row("distance", lengthText(s.distance));
  row("final horizontal error", lengthText(s.final.horizontal()));
  row("final vertical error", lengthText(s.final.vertical()));
  row("max horizontal error", lengthText(s.maxHorizontal));
  row("RMS horizontal error", lengthText(s.rmsHorizontal));
  if (s.distance > 0 && s.final.horizontal() > 0) {
    // Three significant digits without exponent (1e-6 % for a navigation-grade drift).
    const double pct = 100.0 * s.final.horizontal() / s.distance;
    const int decimals = std::clamp(2 - int(std::floor(std::log10(pct))), 0, 12);
    row("final horizontal error / distance", formatFixed(pct, decimals) + " %");
  }
  page.table(t);
  page.heading("Track");
  page.plot(trackMap(tr), "East and north of the start on the tangent plane (equal scales). The "
                          "navigation track drifts from the truth by the position error below.");
  page.heading("Errors against time");
  page.plot(positionErrors(tr));
  page.plot(attitudeErrors(tr), "Wrapped differences of the Euler angles.");
  return page.html();
}

}  // namespace sinsim::sim
