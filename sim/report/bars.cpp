// SVG rendering of a BarChart: horizontal bars, one row per item in the order given, the label
// left of the bar and the value text right of it.
#include <algorithm>
#include <cmath>
#include <string>

#include "common/error.hpp"
#include "sim/report/plot_detail.hpp"
#include "sim/report/report.hpp"

namespace sinsim::report {

std::string BarChart::svg(int width) const {
  if (width < 240) throw InputError("bar chart width " + std::to_string(width) + " px is too small");
  constexpr double kRow = 22.0, kTop = 34.0, kFont = 12.0;  // [px]
  double labelWidth = 40.0, valueMax = 0.0;
  for (const Bar& b : bars) {
    labelWidth = std::max(labelWidth, plot_detail::textWidth(b.label, kFont) + 12.0);
    if (std::isfinite(b.value)) valueMax = std::max(valueMax, b.value);
  }
  labelWidth = std::min(labelWidth, 0.45 * width);
  const double x0 = labelWidth, x1 = width - 90.0;  // room for the value text
  const double height = kTop + kRow * double(bars.size()) + 28.0;
  std::string s = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(width) +
                  "\" height=\"" + formatFixed(height, 0) + "\" viewBox=\"0 0 " +
                  std::to_string(width) + " " + formatFixed(height, 0) +
                  "\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n";
  s += "<text x=\"" + formatFixed(0.5 * width, 1) + "\" y=\"20\" text-anchor=\"middle\" " +
       "font-size=\"15\" font-weight=\"bold\">" + escape(title) + "</text>\n";
  for (std::size_t i = 0; i < bars.size(); ++i) {
    const Bar& b = bars[i];
    const double y = kTop + kRow * double(i);
    const double len = valueMax > 0 && std::isfinite(b.value) && b.value > 0
                           ? (x1 - x0) * b.value / valueMax
                           : 0.0;
    s += "<text x=\"" + formatFixed(x0 - 6, 1) + "\" y=\"" + formatFixed(y + 15, 1) +
         "\" text-anchor=\"end\" font-size=\"" + formatFixed(kFont, 0) + "\">" + escape(b.label) +
         "</text>\n";
    s += "<rect x=\"" + formatFixed(x0, 1) + "\" y=\"" + formatFixed(y + 3, 1) + "\" width=\"" +
         formatFixed(len, 1) + "\" height=\"" + formatFixed(kRow - 6, 1) + "\" fill=\"" +
         (b.color.empty() ? paletteColor(0) : b.color) + "\"/>\n";
    s += "<text x=\"" + formatFixed(x0 + len + 6, 1) + "\" y=\"" + formatFixed(y + 15, 1) +
         "\" font-size=\"" + formatFixed(kFont, 0) + "\">" + escape(b.text) + "</text>\n";
  }
  s += "<line x1=\"" + formatFixed(x0, 1) + "\" y1=\"" + formatFixed(kTop, 1) + "\" x2=\"" +
       formatFixed(x0, 1) + "\" y2=\"" + formatFixed(kTop + kRow * double(bars.size()), 1) +
       "\" stroke=\"#444\"/>\n";
  s += "<text x=\"" + formatFixed(0.5 * (x0 + x1), 1) + "\" y=\"" + formatFixed(height - 8, 1) +
       "\" text-anchor=\"middle\" font-size=\"13\">" + escape(xLabel) + "</text>\n";
  return s + "</svg>\n";
}

}  // namespace sinsim::report
