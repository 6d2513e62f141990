// The legend of a plot (plot_detail.hpp).
#include <algorithm>

#include "sim/report/plot_detail.hpp"
#include "sim/report/report.hpp"

namespace sinsim::report::plot_detail {

std::string legendSvg(const std::vector<LegendEntry>& legend, double x, double y, double w,
                      double h, double row, double swatch) {
  std::string o;
  o += "<g font-size=\"" + num(kLegendSize) + "\">\n";
  o += "<rect x=\"" + num(x) + "\" y=\"" + num(y) + "\" width=\"" + num(w) +
       "\" height=\"" + num(h) +
       "\" rx=\"3\" fill=\"#ffffff\" fill-opacity=\"0.9\" stroke=\"#bbb\"/>\n";
  for (std::size_t i = 0; i < legend.size(); ++i) {
    const LegendEntry& e = legend[i];
    const double cy = y + 8 + row * (static_cast<double>(i) + 0.5);
    const double sx = x + 10;
    if (e.kind == LegendEntry::Line) {
      o += "<line x1=\"" + num(sx) + "\" y1=\"" + num(cy) + "\" x2=\"" + num(sx + swatch) +
           "\" y2=\"" + num(cy) + "\" stroke=\"" + escape(e.color) + "\" stroke-width=\"" +
           formatFixed(e.width, 2) + "\"" +
           (e.dashed ? " stroke-dasharray=\"" + formatFixed(4 * e.width, 2) + " " +
                           formatFixed(2.5 * e.width, 2) + "\""
                     : std::string()) +
           "/>\n";
      if (e.markers)
        o += "<circle cx=\"" + num(sx + swatch / 2) + "\" cy=\"" + num(cy) + "\" r=\"" +
             formatFixed(e.width + 1.2, 2) + "\" fill=\"" + escape(e.color) + "\"/>\n";
    } else {
      o += "<rect x=\"" + num(sx) + "\" y=\"" + num(cy - 6) + "\" width=\"" + num(swatch) +
           "\" height=\"12\" fill=\"" + escape(e.color) + "\" fill-opacity=\"" +
           formatFixed(std::max(e.opacity, 0.15), 3) + "\"" +
           (e.outline ? " stroke=\"" + escape(e.color) +
                            "\" stroke-opacity=\"0.6\" stroke-width=\"0.8\""
                      : std::string()) +
           "/>\n";
    }
    o += "<text x=\"" + num(sx + swatch + 8) + "\" y=\"" + num(cy + kLegendSize * 0.36) +
         "\" fill=\"#222\">" + escape(e.label) + "</text>\n";
  }
  o += "</g>\n";
  return o;
}

}  // namespace sinsim::report::plot_detail
