// Internals of Plot::svg (plot.cpp), shared by the plot sources: text metrics, the data ->
// pixel axis mapping, line decimation, and the legend. Not part of the public API.
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sinsim::report::plot_detail {

inline constexpr const char* kFont = "DejaVu Sans, Helvetica, Arial, sans-serif";
inline constexpr double kTitleSize = 15, kLabelSize = 13, kTickSize = 12, kLegendSize = 12;  // [px]
// Average advance of a sans-serif glyph relative to the font size (DejaVu Sans digits: 0.636,
// lower case ≈ 0.6); used only to leave room, so err on the wide side.
inline constexpr double kCharWidth = 0.62;
// Pixel coordinates are written with 2 decimals (1/100 px: invisible, keeps files small) and
// clamped to ±1e5 px so a wild outlier cannot blow up the number width.
inline constexpr int kCoordDecimals = 2;
inline constexpr double kCoordLimit = 1e5;

/// Estimated width [px] of text at a font size [px].
double textWidth(const std::string& s, double size);
/// A pixel coordinate as SVG text: kCoordDecimals decimals, clamped to ±kCoordLimit.
std::string num(double v);

/// One plot axis: the data range shown and its pixel length; log or linear.
struct Axis {
  bool log = false;
  double lo = 0, hi = 1;  // data range shown
  double len = 1;         // [px]
  bool flip = false;      // y grows downwards in SVG
  bool usable(double v) const { return std::isfinite(v) && (!log || v > 0); }
  double t(double v) const { return log ? std::log10(v) : v; }
  double px(double v) const {
    const double f = (t(v) - t(lo)) / (t(hi) - t(lo));
    return flip ? (1 - f) * len : f * len;
  }
};

/// Data range from all usable values, with a 4 % margin (in log space on a log axis) so curves do
/// not run along the frame.
std::pair<double, double> autoRange(std::vector<double> v, bool log);
/// InputError when a user-set range is not finite, empty, or not positive on a log axis.
void checkRange(const std::optional<std::pair<double, double>>& r, bool log, const char* name);

using Run = std::vector<std::pair<double, double>>;  // pixel points of one unbroken piece
/// Consecutive points in the same pixel column collapse to first, lowest, highest and last: the
/// drawn line is the same to within a pixel, a 10^6-point record stays a few thousand vertices.
Run decimate(const Run& in, double width);

struct LegendEntry {
  enum Kind { Line, Fill } kind;
  std::string label, color;
  bool dashed = false;
  double width = 1.8, opacity = 1;
  bool markers = false;
  bool outline = false;
};

struct Layout {
  double W, H, left, top, pw, ph;
  bool legendOutside;
};

/// The legend box at (x, y) [px], w × h, one row of height `row` per entry with a swatch of
/// width `swatch`.
std::string legendSvg(const std::vector<LegendEntry>& legend, double x, double y, double w,
                      double h, double row, double swatch);

}  // namespace sinsim::report::plot_detail
