// Self-contained HTML reports with inline SVG plots: no JavaScript, no fonts or styles fetched
// from the network, one file that any browser opens offline. Used by the Monte Carlo report
// (drift envelopes of several models over time, tables of differences) and the diagnosis report
// (Allan deviation / PSD / ACF of a measurement against a model on log-log axes, with the model's
// confidence band and the failing τ-ranges shaded).
//
// Output is deterministic: the same input gives the same bytes (numbers are formatted with
// std::to_chars, never through the C locale; nothing depends on time, addresses or hashing).
// Values are plotted as given: the caller converts SI to display units (deg/h, µg, …) and says
// the unit in the axis label, e.g. "τ [s]".
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sinsim::report {

/// A polyline y(x). Points with a non-finite coordinate (or ≤ 0 on a log axis) are gaps: the
/// line is broken there, not joined across.
struct Series {
  std::string label;            ///< legend text; empty = not in the legend
  std::vector<double> x, y;     ///< same length
  std::string color;            ///< CSS colour ("#1f77b4"); empty = next colour of the palette
  bool dashed = false;
  double width = 1.8;           ///< stroke width [px]
  bool markers = false;         ///< draw a dot at every point

  Series() = default;
  Series(std::string label_, std::vector<double> x_, std::vector<double> y_,
         std::string color_ = "", bool dashed_ = false, double width_ = 1.8, bool markers_ = false)
      : label(std::move(label_)), x(std::move(x_)), y(std::move(y_)), color(std::move(color_)),
        dashed(dashed_), width(width_), markers(markers_) {}
};

/// A filled region between lo(x) and hi(x), e.g. a confidence band or a ±3σ envelope.
/// Points where x, lo or hi is unusable split the band into separate pieces.
struct Band {
  std::string label;
  std::vector<double> x, lo, hi;  ///< same length
  std::string color;              ///< empty = next colour of the palette
  double opacity = 0.22;          ///< fill opacity in [0, 1]
  bool edges = true;              ///< thin lines along lo and hi (tells overlapping bands apart)

  Band() = default;
  Band(std::string label_, std::vector<double> x_, std::vector<double> lo_,
       std::vector<double> hi_, std::string color_ = "", double opacity_ = 0.22,
       bool edges_ = true)
      : label(std::move(label_)), x(std::move(x_)), lo(std::move(lo_)), hi(std::move(hi_)),
        color(std::move(color_)), opacity(opacity_), edges(edges_) {}
};

/// A vertical shaded x-range over the whole plot height, e.g. a τ-range where a test fails.
struct Shade {
  double x0 = 0, x1 = 0;
  std::string color = "#d62728";
  std::string label;
  double opacity = 0.12;

  Shade() = default;
  Shade(double x0_, double x1_, std::string color_ = "#d62728", std::string label_ = "",
        double opacity_ = 0.12)
      : x0(x0_), x1(x1_), color(std::move(color_)), label(std::move(label_)), opacity(opacity_) {}
};

/// Axis ticks: positions (in data units) and the label of each major tick.
struct Ticks {
  std::vector<double> major;
  std::vector<std::string> labels;  ///< one per major tick ("" = tick without label)
  std::vector<double> minor;
};

/// 1-2-5 ticks covering [lo, hi] (lo < hi, both finite) with about `target` intervals; only ticks
/// inside [lo, hi] are returned. Labels share one number of decimals.
Ticks linearTicks(double lo, double hi, int target = 6);

/// Decade ticks 10^k inside [lo, hi] (0 < lo < hi) labelled "10⁻³" with minor ticks at 2..9·10^k.
/// Over many decades only every 2nd/3rd/... decade is labelled; over less than about one decade
/// the 1..9·10^k ticks become the labelled ones.
Ticks logTicks(double lo, double hi);

/// Escapes & < > " ' for HTML/XML text and attribute values.
std::string escape(const std::string& text);

/// Shortest round-trip-free fixed formatting used everywhere in the output: `decimals` digits
/// after the point, trailing zeros removed, "-0" printed as "0", no locale.
std::string formatFixed(double value, int decimals);

/// A display unit for values up to maxAbs (SI): the factor to multiply by and its name.
struct DisplayUnit {
  double factor;
  const char* name;
};

/// mm, m or km for lengths up to maxAbs [m], so that axis labels read 0.1 to 1000 (not
/// micrometres as 10^-4 km).
DisplayUnit lengthUnit(double maxAbs);

/// Colour number i of the default palette (Tableau 10, cycles).
const std::string& paletteColor(std::size_t i);

/// One 2-D chart rendered as SVG.
class Plot {
 public:
  std::string title;
  std::string xLabel, yLabel;  ///< with units, e.g. "time [s]", "σ(τ) [deg/h]"
  bool xLog = false, yLog = false;
  /// Fixed axis ranges; unset = from all finite data (and shades) with a small margin.
  std::optional<std::pair<double, double>> xRange, yRange;

  Plot() = default;
  Plot(std::string title_, std::string xLabel_, std::string yLabel_)
      : title(std::move(title_)), xLabel(std::move(xLabel_)), yLabel(std::move(yLabel_)) {}

  /// Drawing order: all shades, then all bands, then all series (each kind in the order added);
  /// the legend lists labelled items in the order added (shades with equal label and colour once).
  Plot& add(Series s);
  Plot& add(Band b);
  Plot& add(Shade s);

  const std::vector<Series>& series() const { return series_; }
  const std::vector<Band>& bands() const { return bands_; }
  const std::vector<Shade>& shades() const { return shades_; }

  /// A standalone <svg> element of width × height pixels. Throws InputError when a series or band
  /// has mismatched vector lengths, or a fixed range is not usable (lo ≥ hi, ≤ 0 on a log axis).
  std::string svg(int width = 760, int height = 440) const;

 private:
  std::vector<Series> series_;
  std::vector<Band> bands_;
  std::vector<Shade> shades_;
  std::vector<std::string> seriesColor_, bandColor_;  // resolved at add() time
  std::size_t nextColor_ = 0;
  enum class Kind { Series, Band, Shade };
  std::vector<std::pair<Kind, std::size_t>> order_;  // legend order
};

/// One bar of a BarChart: its label, value (sets the length; ≤ 0 or NaN: no bar) and the text
/// shown after it (e.g. "41 % ± 2").
struct Bar {
  std::string label;
  double value = 0.0;
  std::string text;
  std::string color;  ///< empty = the first palette colour
};

/// Horizontal bars in the order given (sort them first for a ranking, e.g. an error budget),
/// the longest one spanning the width.
struct BarChart {
  std::string title;
  std::string xLabel;
  std::vector<Bar> bars;
  /// A standalone <svg> element `width` px wide, as tall as the bars need.
  std::string svg(int width = 760) const;
};

/// A table cell: text plus an optional CSS class. Built-in classes: "pass" (green), "fail" (red),
/// "warn" (amber), "num" (right-aligned, tabular digits), "muted" (grey). Several may be given
/// separated by spaces ("num fail").
struct Cell {
  std::string text;
  std::string cls;
  Cell() = default;
  Cell(const char* t) : text(t) {}                       // NOLINT: implicit on purpose
  Cell(std::string t, std::string c = "") : text(std::move(t)), cls(std::move(c)) {}  // NOLINT
};

struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<Cell>> rows;
  std::string caption;  ///< optional, shown above the table
};

/// An HTML page assembled from blocks in order. All text is escaped; nothing is interpreted as
/// markup.
class HtmlPage {
 public:
  explicit HtmlPage(std::string title);

  HtmlPage& heading(const std::string& text, int level = 2);  ///< level 1..4
  HtmlPage& paragraph(const std::string& text);
  HtmlPage& table(const Table& t);
  /// A plot with an optional caption below it.
  HtmlPage& plot(const Plot& p, const std::string& caption = "", int width = 760, int height = 440);
  /// Several plots side by side (wrapping onto new rows when the window is narrow).
  HtmlPage& plotRow(const std::vector<Plot>& plots, int width = 520, int height = 360);
  HtmlPage& preformatted(const std::string& text);
  /// A bar chart with an optional caption below it.
  HtmlPage& bars(const BarChart& chart, const std::string& caption = "", int width = 760);

  /// The whole document (UTF-8, inline CSS).
  std::string html() const;

  /// Writes html() to `path` atomically: a temporary file in the same folder is renamed over
  /// `path`. On any failure nothing is left behind and an exception is thrown (InputError when the
  /// folder does not exist or is not writable, Error on an I/O failure).
  void write(const std::string& path) const;

 private:
  std::string title_;
  std::string body_;
};

}  // namespace sinsim::report
