// SVG rendering of a Plot. The data area is a nested <svg> element: it clips everything drawn in
// it to the plot rectangle without a clipPath id, so many plots can share one HTML page.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

#include "common/error.hpp"
#include "sim/report/report.hpp"
#include "sim/report/plot_detail.hpp"
#include "sim/report/report_detail.hpp"

namespace sinsim::report {
namespace {

using namespace plot_detail;

}  // namespace

Plot& Plot::add(Series s) {
  order_.emplace_back(Kind::Series, series_.size());
  seriesColor_.push_back(s.color.empty() ? paletteColor(nextColor_++) : s.color);
  series_.push_back(std::move(s));
  return *this;
}

Plot& Plot::add(Band b) {
  order_.emplace_back(Kind::Band, bands_.size());
  bandColor_.push_back(b.color.empty() ? paletteColor(nextColor_++) : b.color);
  bands_.push_back(std::move(b));
  return *this;
}

Plot& Plot::add(Shade s) {
  order_.emplace_back(Kind::Shade, shades_.size());
  shades_.push_back(std::move(s));
  return *this;
}

std::string Plot::svg(int width, int height) const {
  if (width < 120 || height < 100)
    throw InputError("plot size " + std::to_string(width) + "×" + std::to_string(height) +
                     " px is too small (need at least 120×100)");
  for (const Series& s : series_)
    if (s.x.size() != s.y.size())
      throw InputError("plot \"" + title + "\": series \"" + s.label + "\" has " +
                       std::to_string(s.x.size()) + " x values but " + std::to_string(s.y.size()) +
                       " y values");
  for (const Band& b : bands_)
    if (b.x.size() != b.lo.size() || b.x.size() != b.hi.size())
      throw InputError("plot \"" + title + "\": band \"" + b.label + "\" has " +
                       std::to_string(b.x.size()) + " x, " + std::to_string(b.lo.size()) +
                       " lo and " + std::to_string(b.hi.size()) + " hi values");
  checkRange(xRange, xLog, "x");
  checkRange(yRange, yLog, "y");

  Axis xa, ya;
  xa.log = xLog;
  ya.log = yLog;
  ya.flip = true;

  // --- ranges: x from every usable point, y from the usable points inside the x range ----------
  {
    std::vector<double> xs;
    auto addX = [&](double x, double y) {
      if (xa.usable(x) && ya.usable(y)) xs.push_back(x);
    };
    for (const Series& s : series_)
      for (std::size_t i = 0; i < s.x.size(); ++i) addX(s.x[i], s.y[i]);
    for (const Band& b : bands_)
      for (std::size_t i = 0; i < b.x.size(); ++i) {
        addX(b.x[i], b.lo[i]);
        addX(b.x[i], b.hi[i]);
      }
    for (const Shade& s : shades_)
      for (double x : {s.x0, s.x1})
        if (xa.usable(x)) xs.push_back(x);
    std::tie(xa.lo, xa.hi) = xRange ? *xRange : autoRange(xs, xLog);

    std::vector<double> ys;
    auto addY = [&](double x, double y) {
      if (xa.usable(x) && ya.usable(y) && x >= xa.lo && x <= xa.hi) ys.push_back(y);
    };
    for (const Series& s : series_)
      for (std::size_t i = 0; i < s.x.size(); ++i) addY(s.x[i], s.y[i]);
    for (const Band& b : bands_)
      for (std::size_t i = 0; i < b.x.size(); ++i) {
        addY(b.x[i], b.lo[i]);
        addY(b.x[i], b.hi[i]);
      }
    std::tie(ya.lo, ya.hi) = yRange ? *yRange : autoRange(ys, yLog);
  }

  // --- legend entries ---------------------------------------------------------------------------
  std::vector<LegendEntry> legend;
  for (const auto& [kind, i] : order_) {
    if (kind == Kind::Series && !series_[i].label.empty()) {
      legend.push_back({LegendEntry::Line, series_[i].label, seriesColor_[i], series_[i].dashed,
                        series_[i].width, 1, series_[i].markers});
    } else if (kind == Kind::Band && !bands_[i].label.empty()) {
      legend.push_back({LegendEntry::Fill, bands_[i].label, bandColor_[i], false, 0,
                        std::clamp(bands_[i].opacity, 0.0, 1.0), false, bands_[i].edges});
    } else if (kind == Kind::Shade && !shades_[i].label.empty()) {
      const Shade& s = shades_[i];
      const bool dup = std::any_of(legend.begin(), legend.end(), [&](const LegendEntry& e) {
        return e.kind == LegendEntry::Fill && e.label == s.label && e.color == s.color;
      });
      if (!dup)
        legend.push_back({LegendEntry::Fill, s.label, s.color, false, 0,
                          std::clamp(s.opacity, 0.0, 1.0)});
    }
  }
  const double legendRow = kLegendSize + 6, legendSwatch = 26;
  double legendW = 0, legendH = 0;
  if (!legend.empty()) {
    double maxText = 0;
    for (const auto& e : legend) maxText = std::max(maxText, textWidth(e.label, kLegendSize));
    legendW = 10 + legendSwatch + 8 + maxText + 10;
    legendH = 8 + legendRow * static_cast<double>(legend.size()) + 4;
  }

  // --- ticks, fitted to the pixel space so labels never overlap ---------------------------------
  auto ticksFor = [](const Axis& a, int target) {
    return a.log ? logTicks(a.lo, a.hi) : linearTicks(a.lo, a.hi, target);
  };
  // Blank every label but each n-th until neighbours keep `gap` px apart (log axes, and linear
  // axes whose target cannot drop further).
  auto thin = [](Ticks& t, const Axis& a, double gap, bool horizontal) {
    for (int n = 1; n <= static_cast<int>(t.major.size()); ++n) {
      bool ok = true;
      double lastEdge = -1e300;
      for (std::size_t i = 0; i < t.major.size(); ++i) {
        if (t.labels[i].empty() || (n > 1 && i % n != 0)) continue;
        const double p = a.flip ? a.len - a.px(t.major[i]) : a.px(t.major[i]);
        const double half = horizontal ? textWidth(t.labels[i], kTickSize) / 2 : kTickSize / 2;
        if (p - half < lastEdge + gap) ok = false;
        lastEdge = p + half;
      }
      if (ok) {
        if (n > 1)
          for (std::size_t i = 0; i < t.major.size(); ++i)
            if (i % n != 0) t.labels[i].clear();
        return;
      }
    }
  };

  const double W = width, H = height;
  const double top = title.empty() ? 14 : 14 + kTitleSize + 12;
  const double bottom = 8 + kTickSize + 10 + (xLabel.empty() ? 0 : kLabelSize + 8) + 4;

  Ticks xt, yt;
  // The y labels set the left margin, which sets the x pixel length, which sets the x ticks.
  auto layoutFor = [&](bool legendOutside) {
    ya.len = H - top - bottom;
    yt = ticksFor(ya, std::max(2, static_cast<int>(ya.len / 55)));
    thin(yt, ya, 4, false);
    double yLabW = 0;
    for (const auto& s : yt.labels) yLabW = std::max(yLabW, textWidth(s, kTickSize));
    const double left = 10 + (yLabel.empty() ? 0 : kLabelSize + 10) + yLabW + 8;
    const double right = 18 + (legendOutside ? legendW + 4 : 0);
    xa.len = std::max(40.0, W - left - right);
    // Fewer x ticks until neighbouring labels keep 12 px apart (log axes thin their labels).
    for (int target = std::max(2, static_cast<int>(xa.len / 80)); target >= 1; --target) {
      xt = ticksFor(xa, target);
      bool overlap = false;
      for (std::size_t i = 1; i < xt.major.size(); ++i) {
        const double gap = xa.px(xt.major[i]) - xa.px(xt.major[i - 1]);
        const double need =
            (textWidth(xt.labels[i], kTickSize) + textWidth(xt.labels[i - 1], kTickSize)) / 2 + 12;
        if (!xt.labels[i].empty() && !xt.labels[i - 1].empty() && gap < need) overlap = true;
      }
      if (!overlap || xa.log) break;
    }
    thin(xt, xa, 12, true);
    return Layout{W, H, left, top, xa.len, ya.len, legendOutside};
  };
  Layout L = layoutFor(false);

  // --- data in pixels -----------------------------------------------------------------------------
  auto buildRuns = [&](const std::vector<double>& x, const std::vector<double>& y) {
    std::vector<Run> runs;
    Run cur;
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (xa.usable(x[i]) && ya.usable(y[i])) {
        cur.emplace_back(xa.px(x[i]), ya.px(y[i]));
      } else if (!cur.empty()) {
        runs.push_back(std::move(cur));
        cur.clear();
      }
    }
    if (!cur.empty()) runs.push_back(std::move(cur));
    return runs;
  };

  // Legend corner: the one covering the fewest data vertices; outside the frame when every corner
  // covers some (the plot shrinks, the data stay visible).
  double legendX = 0, legendY = 0;
  auto chooseLegend = [&]() -> bool {  // true = fits inside
    if (legend.empty()) return true;
    std::vector<std::pair<double, double>> pts;
    for (const Series& s : series_)
      for (const Run& r : buildRuns(s.x, s.y)) pts.insert(pts.end(), r.begin(), r.end());
    for (const Band& b : bands_) {
      for (const Run& r : buildRuns(b.x, b.lo)) pts.insert(pts.end(), r.begin(), r.end());
      for (const Run& r : buildRuns(b.x, b.hi)) pts.insert(pts.end(), r.begin(), r.end());
    }
    const double inset = 8;
    const double cx[] = {L.pw - inset - legendW, inset, L.pw - inset - legendW, inset};
    const double cy[] = {inset, inset, L.ph - inset - legendH, L.ph - inset - legendH};
    std::size_t best = 0, bestCount = std::numeric_limits<std::size_t>::max();
    for (std::size_t c = 0; c < 4; ++c) {
      std::size_t count = 0;
      for (const auto& [px, py] : pts)
        if (px >= cx[c] - 4 && px <= cx[c] + legendW + 4 && py >= cy[c] - 4 &&
            py <= cy[c] + legendH + 4)
          ++count;
      if (count < bestCount) {
        bestCount = count;
        best = c;
      }
    }
    legendX = L.left + cx[best];
    legendY = L.top + cy[best];
    return bestCount == 0 && legendW + 2 * inset < L.pw && legendH + 2 * inset < L.ph;
  };
  if (!chooseLegend()) {
    L = layoutFor(true);
    legendX = L.left + L.pw + 10;
    legendY = L.top;
  }

  // --- write ---------------------------------------------------------------------------------------
  std::string o;
  o.reserve(4096);
  o += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + num(W) + "\" height=\"" + num(H) +
       "\" viewBox=\"0 0 " + num(W) + " " + num(H) + "\" font-family=\"" + kFont +
       "\" role=\"img\">\n";
  if (!title.empty()) o += "<title>" + escape(title) + "</title>\n";
  o += "<rect width=\"" + num(W) + "\" height=\"" + num(H) + "\" fill=\"#ffffff\"/>\n";
  if (!title.empty())
    o += "<text x=\"" + num(L.left + L.pw / 2) + "\" y=\"" + num(14 + kTitleSize) +
         "\" text-anchor=\"middle\" font-size=\"" + num(kTitleSize) +
         "\" font-weight=\"bold\" fill=\"#222\">" + escape(title) + "</text>\n";

  const double x0 = L.left, y0 = L.top, x1 = L.left + L.pw, y1 = L.top + L.ph;
  // grid
  o += "<g stroke-width=\"1\" fill=\"none\">\n";
  for (double v : xt.minor)
    o += "<line x1=\"" + num(x0 + xa.px(v)) + "\" y1=\"" + num(y0) + "\" x2=\"" +
         num(x0 + xa.px(v)) + "\" y2=\"" + num(y1) + "\" stroke=\"#f0f0f0\"/>\n";
  for (double v : yt.minor)
    o += "<line x1=\"" + num(x0) + "\" y1=\"" + num(y0 + ya.px(v)) + "\" x2=\"" + num(x1) +
         "\" y2=\"" + num(y0 + ya.px(v)) + "\" stroke=\"#f0f0f0\"/>\n";
  for (double v : xt.major)
    o += "<line x1=\"" + num(x0 + xa.px(v)) + "\" y1=\"" + num(y0) + "\" x2=\"" +
         num(x0 + xa.px(v)) + "\" y2=\"" + num(y1) + "\" stroke=\"#dcdcdc\"/>\n";
  for (double v : yt.major)
    o += "<line x1=\"" + num(x0) + "\" y1=\"" + num(y0 + ya.px(v)) + "\" x2=\"" + num(x1) +
         "\" y2=\"" + num(y0 + ya.px(v)) + "\" stroke=\"#dcdcdc\"/>\n";
  o += "</g>\n";

  // data, clipped by the nested viewport
  o += "<svg x=\"" + num(x0) + "\" y=\"" + num(y0) + "\" width=\"" + num(L.pw) + "\" height=\"" +
       num(L.ph) + "\" viewBox=\"0 0 " + num(L.pw) + " " + num(L.ph) + "\" overflow=\"hidden\">\n";
  for (const Shade& s : shades_) {
    if (!(xa.usable(s.x0) && xa.usable(s.x1))) continue;
    double a = xa.px(s.x0), b = xa.px(s.x1);
    if (a > b) std::swap(a, b);
    a = std::max(a, -1.0);
    b = std::min(b, L.pw + 1);
    if (b <= a) continue;
    o += "<rect x=\"" + num(a) + "\" y=\"0\" width=\"" + num(b - a) + "\" height=\"" + num(L.ph) +
         "\" fill=\"" + escape(s.color) + "\" fill-opacity=\"" +
         formatFixed(std::clamp(s.opacity, 0.0, 1.0), 3) + "\"/>\n";
  }
  for (std::size_t bi = 0; bi < bands_.size(); ++bi) {
    const Band& b = bands_[bi];
    // A piece is a run of indices where x, lo and hi are all usable.
    std::size_t i = 0;
    while (i < b.x.size()) {
      auto ok = [&](std::size_t k) {
        return xa.usable(b.x[k]) && ya.usable(b.lo[k]) && ya.usable(b.hi[k]);
      };
      if (!ok(i)) {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j < b.x.size() && ok(j)) ++j;
      Run upper, lower;
      for (std::size_t k = i; k < j; ++k) {
        upper.emplace_back(xa.px(b.x[k]), ya.px(b.hi[k]));
        lower.emplace_back(xa.px(b.x[k]), ya.px(b.lo[k]));
      }
      upper = decimate(upper, L.pw);
      lower = decimate(lower, L.pw);
      std::string d;
      for (std::size_t k = 0; k < upper.size(); ++k)
        d += (k == 0 ? "M" : " L") + num(upper[k].first) + "," + num(upper[k].second);
      for (std::size_t k = lower.size(); k-- > 0;)
        d += " L" + num(lower[k].first) + "," + num(lower[k].second);
      d += " Z";
      o += "<path d=\"" + d + "\" fill=\"" + escape(bandColor_[bi]) + "\" fill-opacity=\"" +
           formatFixed(std::clamp(b.opacity, 0.0, 1.0), 3) + "\" stroke=\"none\"/>\n";
      if (b.edges) {
        std::string e;
        for (const Run* r : {&upper, &lower})
          for (std::size_t k = 0; k < r->size(); ++k)
            e += (k == 0 ? (e.empty() ? "M" : " M") : " L") + num((*r)[k].first) + "," +
                 num((*r)[k].second);
        o += "<path d=\"" + e + "\" fill=\"none\" stroke=\"" + escape(bandColor_[bi]) +
             "\" stroke-opacity=\"0.6\" stroke-width=\"0.8\"/>\n";
      }
      i = j;
    }
  }
  for (std::size_t si = 0; si < series_.size(); ++si) {
    const Series& s = series_[si];
    const std::string color = escape(seriesColor_[si]);
    const double w = std::isfinite(s.width) && s.width > 0 ? s.width : 1.8;
    std::string d;
    std::vector<Run> runs = buildRuns(s.x, s.y);
    for (const Run& r0 : runs) {
      const Run r = s.markers ? r0 : decimate(r0, L.pw);
      for (std::size_t k = 0; k < r.size(); ++k)
        d += (d.empty() ? "M" : (k == 0 ? " M" : " L")) + num(r[k].first) + "," +
             num(r[k].second);
      if (r.size() == 1) d += " h0.01";  // a lone point still shows (round cap)
    }
    if (!d.empty())
      o += "<path d=\"" + d + "\" fill=\"none\" stroke=\"" + color + "\" stroke-width=\"" +
           formatFixed(w, 2) + "\" stroke-linejoin=\"round\" stroke-linecap=\"round\"" +
           (s.dashed ? " stroke-dasharray=\"" + formatFixed(4 * w, 2) + " " +
                           formatFixed(2.5 * w, 2) + "\""
                     : std::string()) +
           "/>\n";
    if (s.markers) {
      o += "<g fill=\"" + color + "\">\n";
      for (const Run& r : runs)
        for (const auto& [px, py] : r)
          o += "<circle cx=\"" + num(px) + "\" cy=\"" + num(py) + "\" r=\"" +
               formatFixed(w + 1.2, 2) + "\"/>\n";
      o += "</g>\n";
    }
  }
  o += "</svg>\n";

  // frame, ticks, labels
  o += "<rect x=\"" + num(x0) + "\" y=\"" + num(y0) + "\" width=\"" + num(L.pw) + "\" height=\"" +
       num(L.ph) + "\" fill=\"none\" stroke=\"#444\" stroke-width=\"1\"/>\n";
  o += "<g stroke=\"#444\" stroke-width=\"1\">\n";
  for (double v : xt.minor)
    o += "<line x1=\"" + num(x0 + xa.px(v)) + "\" y1=\"" + num(y1) + "\" x2=\"" +
         num(x0 + xa.px(v)) + "\" y2=\"" + num(y1 + 3) + "\"/>\n";
  for (double v : xt.major)
    o += "<line x1=\"" + num(x0 + xa.px(v)) + "\" y1=\"" + num(y1) + "\" x2=\"" +
         num(x0 + xa.px(v)) + "\" y2=\"" + num(y1 + 6) + "\"/>\n";
  for (double v : yt.minor)
    o += "<line x1=\"" + num(x0 - 3) + "\" y1=\"" + num(y0 + ya.px(v)) + "\" x2=\"" + num(x0) +
         "\" y2=\"" + num(y0 + ya.px(v)) + "\"/>\n";
  for (double v : yt.major)
    o += "<line x1=\"" + num(x0 - 6) + "\" y1=\"" + num(y0 + ya.px(v)) + "\" x2=\"" + num(x0) +
         "\" y2=\"" + num(y0 + ya.px(v)) + "\"/>\n";
  o += "</g>\n";
  o += "<g font-size=\"" + num(kTickSize) + "\" fill=\"#333\">\n";
  for (std::size_t i = 0; i < xt.major.size(); ++i)
    if (!xt.labels[i].empty())
      o += "<text x=\"" + num(x0 + xa.px(xt.major[i])) + "\" y=\"" + num(y1 + 8 + kTickSize) +
           "\" text-anchor=\"middle\">" + escape(xt.labels[i]) + "</text>\n";
  for (std::size_t i = 0; i < yt.major.size(); ++i)
    if (!yt.labels[i].empty())
      o += "<text x=\"" + num(x0 - 9) + "\" y=\"" + num(y0 + ya.px(yt.major[i]) + kTickSize * 0.36) +
           "\" text-anchor=\"end\">" + escape(yt.labels[i]) + "</text>\n";
  o += "</g>\n";
  if (!xLabel.empty())
    o += "<text x=\"" + num(x0 + L.pw / 2) + "\" y=\"" + num(H - 8) +
         "\" text-anchor=\"middle\" font-size=\"" + num(kLabelSize) + "\" fill=\"#222\">" +
         escape(xLabel) + "</text>\n";
  if (!yLabel.empty()) {
    const double lx = 10 + kLabelSize * 0.8, ly = y0 + L.ph / 2;
    o += "<text x=\"" + num(lx) + "\" y=\"" + num(ly) + "\" transform=\"rotate(-90 " + num(lx) +
         " " + num(ly) + ")\" text-anchor=\"middle\" font-size=\"" + num(kLabelSize) +
         "\" fill=\"#222\">" + escape(yLabel) + "</text>\n";
  }

  if (!legend.empty()) o += legendSvg(legend, legendX, legendY, legendW, legendH, legendRow, legendSwatch);
  o += "</svg>\n";
  return o;
}

}  // namespace sinsim::report
