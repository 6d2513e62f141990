// Tests of sim/report: escaping, number formatting, ticks against hand-computed values, gaps for
// unusable points, well-formed SVG, deterministic output, atomic writing.
#include <catch2/catch.hpp>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "common/error.hpp"
#include "sim/report/report.hpp"
#include "tests/report/sample_report.hpp"
#include "tests/report/xml_check.hpp"

using namespace sinsim::report;
using sinsim::report::testing::xmlProblem;
namespace fs = std::filesystem;

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

// The d attributes of the line paths stroked with `color` (series are drawn as one path each).
std::vector<std::string> linePaths(const std::string& svg, const std::string& color) {
  std::vector<std::string> out;
  const std::string tail = "\" fill=\"none\" stroke=\"" + color + "\"";
  std::size_t pos = 0;
  while ((pos = svg.find("<path d=\"", pos)) != std::string::npos) {
    pos += 9;
    const std::size_t end = svg.find('"', pos);
    if (svg.compare(end, tail.size(), tail) == 0) out.push_back(svg.substr(pos, end - pos));
  }
  return out;
}

std::size_t countChar(const std::string& s, char c) {
  return static_cast<std::size_t>(std::count(s.begin(), s.end(), c));
}

// Value of attribute `name` in the first element that starts with `prefix`.
double attrOf(const std::string& svg, const std::string& prefix, const std::string& name) {
  const std::size_t at = svg.find(prefix);
  REQUIRE(at != std::string::npos);
  const std::size_t end = svg.find('>', at);
  const std::string key = " " + name + "=\"";
  const std::size_t a = svg.find(key, at);
  REQUIRE(a < end);
  return std::stod(svg.substr(a + key.size()));
}

std::string slurp(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::ostringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

std::vector<std::string> listDir(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

fs::path freshDir(const std::string& name) {
  const fs::path d = fs::path(SINSIM_BINARY_DIR) / "tests" / "report" /
                     (name + "." + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

}  // namespace

TEST_CASE("escape replaces the five XML-special characters and nothing else") {
  CHECK(escape("a&b<c>d\"e'f") == "a&amp;b&lt;c&gt;d&quot;e&#39;f");
  CHECK(escape("σ(τ) [deg/h] µg") == "σ(τ) [deg/h] µg");  // UTF-8 passes through untouched
  CHECK(escape("&amp;") == "&amp;amp;");                 // no double-unescaping shortcut
  CHECK(escape("") == "");
}

TEST_CASE("formatFixed strips trailing zeros and never prints minus zero") {
  CHECK(formatFixed(1.5, 3) == "1.5");
  CHECK(formatFixed(2.0, 2) == "2");
  CHECK(formatFixed(0.1 + 0.2, 2) == "0.3");  // 0.30000000000000004 rounded to 2 decimals
  CHECK(formatFixed(-0.0001, 2) == "0");
  CHECK(formatFixed(-0.0, 0) == "0");
  CHECK(formatFixed(-12.345, 1) == "-12.3");
  CHECK(formatFixed(1e6, 2) == "1000000");
  CHECK(formatFixed(kNaN, 2) == "nan");
}

TEST_CASE("linear ticks step by 1 or 2 or 5 times a power of ten") {
  SECTION("[0, 7.3] with 6 intervals wanted: step 1 (7.3 intervals) beats step 2 (3.65)") {
    const Ticks t = linearTicks(0, 7.3, 6);
    CHECK(t.major == std::vector<double>{0, 1, 2, 3, 4, 5, 6, 7});
    CHECK(t.labels == std::vector<std::string>{"0", "1", "2", "3", "4", "5", "6", "7"});
  }
  SECTION("[0, 7.3] with 3 intervals wanted: step 2 (|3.65 − 3| < |1.46 − 3|)") {
    CHECK(linearTicks(0, 7.3, 3).major == std::vector<double>{0, 2, 4, 6});
  }
  SECTION("negative decimals come out as the decimal literals, with a typographic minus") {
    const Ticks t = linearTicks(-0.35, 0.12, 5);  // step 0.1: 4.7 intervals
    CHECK(t.major == std::vector<double>{-0.3, -0.2, -0.1, 0, 0.1});  // exact: i/10 rounds once
    CHECK(t.labels == std::vector<std::string>{"−0.3", "−0.2", "−0.1", "0", "0.1"});
  }
  SECTION("ticks on the range ends are kept") {
    CHECK(linearTicks(0, 10, 5).major == std::vector<double>{0, 2, 4, 6, 8, 10});
  }
  SECTION("tiny and huge values get m×10ᵏ labels") {
    const Ticks small = linearTicks(0, 5e-5, 5);
    CHECK(small.labels == std::vector<std::string>{"0", "1×10⁻⁵", "2×10⁻⁵", "3×10⁻⁵", "4×10⁻⁵",
                                                   "5×10⁻⁵"});
    const Ticks big = linearTicks(0, 3e6, 6);  // step 5e5
    CHECK(big.labels ==
          std::vector<std::string>{"0", "5×10⁵", "1×10⁶", "1.5×10⁶", "2×10⁶", "2.5×10⁶", "3×10⁶"});
  }
  SECTION("an empty or non-finite range is an input error") {
    CHECK_THROWS_AS(linearTicks(1, 1), sinsim::InputError);
    CHECK_THROWS_AS(linearTicks(0, kNaN), sinsim::InputError);
  }
}

TEST_CASE("log ticks: decades with 2..9 minor ticks") {
  SECTION("[3e-3, 2e2]: decades 10⁻²..10², minor ticks from 3e-3 to 2e2") {
    const Ticks t = logTicks(3e-3, 2e2);
    CHECK(t.major == std::vector<double>{0.01, 0.1, 1, 10, 100});
    CHECK(t.labels == std::vector<std::string>{"10⁻²", "10⁻¹", "10⁰", "10¹", "10²"});
    // 3..9e-3 (7) + 2..9 × 10^-2..10^1 (4 × 8) + 2e2 (1) = 40
    REQUIRE(t.minor.size() == 40);
    CHECK(t.minor.front() == Approx(3e-3).epsilon(1e-15));  // 3·(1/1000): one rounding
    CHECK(t.minor.back() == 200);
  }
  SECTION("exact decade ends are inside") {
    CHECK(logTicks(1e-3, 1e3).major.size() == 7);
  }
  SECTION("40 decades: every 6th labelled (⌈41/8⌉ = 6), no minor ticks") {
    const Ticks t = logTicks(1e-20, 1e20);
    REQUIRE(t.major.size() == 41);
    std::vector<std::string> shown;
    for (const auto& l : t.labels)
      if (!l.empty()) shown.push_back(l);
    CHECK(shown == std::vector<std::string>{"10⁻¹⁸", "10⁻¹²", "10⁻⁶", "10⁰", "10⁶", "10¹²",
                                            "10¹⁸"});
    CHECK(t.minor.empty());
  }
  SECTION("less than a decade: the 1..9 ticks are labelled") {
    const Ticks t = logTicks(3, 7);
    CHECK(t.major == std::vector<double>{3, 4, 5, 6, 7});
    CHECK(t.labels == std::vector<std::string>{"3", "4", "5", "6", "7"});
    const Ticks s = logTicks(0.0025, 0.0065);
    CHECK(s.labels == std::vector<std::string>{"0.003", "0.004", "0.005", "0.006"});
  }
  SECTION("inside one 1..9 step: linear ticks") {
    CHECK(logTicks(3.1, 3.3).major.size() >= 2);
  }
  SECTION("non-positive ranges are input errors") {
    CHECK_THROWS_AS(logTicks(0, 1), sinsim::InputError);
    CHECK_THROWS_AS(logTicks(-1, 1), sinsim::InputError);
  }
}

TEST_CASE("non-finite points break the line into pieces instead of joining across") {
  Series s{"s", {0, 1, 2, 3, 4, 5, 6, 7, 8, 9}, {0, 1, 2, 3, kNaN, 5, 6, kInf, 8, 9}, "#123456"};
  Plot p("gaps", "x [1]", "y [1]");
  p.add(s);
  const std::string svg = p.svg();
  const auto paths = linePaths(svg, "#123456");
  REQUIRE(paths.size() == 1);
  // pieces 0–3, 5–6, 8–9: three move-to commands, 8 vertices in all (each M or L is one vertex)
  CHECK(countChar(paths[0], 'M') == 3);
  CHECK(countChar(paths[0], 'M') + countChar(paths[0], 'L') == 8);
  CHECK(svg.find("nan") == std::string::npos);
  CHECK(svg.find("inf") == std::string::npos);
  CHECK(xmlProblem(svg) == "");
}

TEST_CASE("a log axis drops non-positive values and they do not set the range") {
  Series s{"s", {1, 2, 3, 4, 5, 6}, {1e-3, 1e-2, 0, -5, 1e-1, 1}, "#123456"};
  Plot p("log", "x", "y");
  p.yLog = true;
  p.add(s);
  const std::string svg = p.svg();
  const auto paths = linePaths(svg, "#123456");
  REQUIRE(paths.size() == 1);
  CHECK(countChar(paths[0], 'M') == 2);  // 1e-3, 1e-2 | 1e-1, 1
  CHECK(countChar(paths[0], 'M') + countChar(paths[0], 'L') == 4);
  // y range from 1e-3..1 plus a 4 % margin in log space: decades 10⁻³..10⁰ all labelled.
  for (const char* label : {">10⁻³<", ">10⁻²<", ">10⁻¹<", ">10⁰<"})
    CHECK(svg.find(label) != std::string::npos);
  CHECK(svg.find(">10⁻⁴<") == std::string::npos);
  CHECK(svg.find(">10¹<") == std::string::npos);
}

TEST_CASE("a band with an unusable point splits into two filled pieces") {
  Band b{"band", {1, 2, 3, 4, 5}, {1, 1, kNaN, 1, 1}, {2, 2, 2, 2, 2}, "#abcdef"};
  Plot p;
  p.add(b);
  const std::string svg = p.svg();
  std::size_t pieces = 0, pos = 0;
  while ((pos = svg.find("fill=\"#abcdef\" fill-opacity=\"0.22\" stroke=\"none\"", pos)) !=
         std::string::npos) {
    ++pieces;
    ++pos;
  }
  CHECK(pieces == 2);
}

TEST_CASE("SVG and HTML text is escaped and the SVG is well-formed XML") {
  const std::string evil = "a & b < c > d \" e ' f </svg>";
  Plot p(evil, evil, evil);
  p.xLog = p.yLog = true;
  p.add(Series{evil, {1, 10, 100}, {3, 2, 1}, "", true, 2, true});
  p.add(Band{evil, {1, 10, 100}, {1, 1, 0.5}, {4, 3, 2}, ""});
  p.add(Shade{5, 50, "#d62728", evil});
  const std::string svg = p.svg(500, 300);
  CHECK(xmlProblem(svg) == "");
  std::size_t closes = 0;
  for (std::size_t at = svg.find("</svg>"); at != std::string::npos; at = svg.find("</svg>", at + 1))
    ++closes;
  CHECK(closes == 2);  // the data viewport and the plot; none from the label
  CHECK(svg.find(evil) == std::string::npos);

  HtmlPage page(evil);
  page.heading(evil).paragraph(evil).preformatted(evil);
  page.table(Table{{evil}, {{Cell(evil, "fail")}}, evil});
  const std::string html = page.html();
  CHECK(html.find(evil) == std::string::npos);
  CHECK(html.find(escape(evil)) != std::string::npos);

  // Every SVG of the sample report (log-log, bands, shades, markers, plot rows) parses.
  const std::string sample = sinsim::report::testing::samplePage().html();
  std::size_t start = 0, n = 0;
  while ((start = sample.find("<svg xmlns", start)) != std::string::npos) {
    std::size_t depth = 0, i = start;
    do {  // find the matching </svg>, nested <svg> included
      const std::size_t open = sample.find("<svg", i + 1), close = sample.find("</svg>", i + 1);
      if (open < close) {
        ++depth;
        i = open;
      } else {
        i = close;
        if (depth == 0) break;
        --depth;
      }
    } while (true);
    const std::string one = sample.substr(start, i + 6 - start);
    INFO("svg #" << n);
    CHECK(xmlProblem(one) == "");
    start = i;
    ++n;
  }
  CHECK(n == 7);
}

TEST_CASE("the XML checker itself rejects broken documents") {
  CHECK(xmlProblem("<a><b></a></b>") != "");
  CHECK(xmlProblem("<a x=1/>") != "");
  CHECK(xmlProblem("<a>x & y</a>") != "");
  CHECK(xmlProblem("<a>x < y</a>") != "");
  CHECK(xmlProblem("<a/><b/>") != "");
  CHECK(xmlProblem("<a x=\"1\" x=\"2\"/>") != "");
  CHECK(xmlProblem("<a>") != "");
  CHECK(xmlProblem("<a x=\"&lt;&#39;&#x3c;\">&amp;</a>") == "");
}

TEST_CASE("output is deterministic: same input gives the same bytes") {
  const std::string a = sinsim::report::testing::samplePage().html();
  const std::string b = sinsim::report::testing::samplePage().html();
  CHECK(a == b);
  CHECK(a.size() > 10000);
}

TEST_CASE("the legend goes to a corner free of data or else beside the plot") {
  SECTION("rising line: top-left and bottom-right are free; top-right is not") {
    Plot p;
    p.add(Series{"rising", {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10}, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10}});
    const std::string svg = p.svg(600, 400);
    const double frameX = attrOf(svg, "<svg x=", "x"), frameW = attrOf(svg, "<svg x=", "width");
    const std::size_t legendAt = svg.find("rx=\"3\"");
    REQUIRE(legendAt != std::string::npos);
    const std::size_t rectStart = svg.rfind("<rect", legendAt);
    const double lx = std::stod(svg.substr(svg.find("x=\"", rectStart) + 3));
    CHECK(lx < frameX + frameW / 2);  // left half: the top-left corner (first free candidate)
  }
  SECTION("noise over the whole frame: the legend moves right of the frame") {
    Series s{"noise", {}, {}};
    for (int i = 0; i < 400; ++i) {
      s.x.push_back(i);
      s.y.push_back(std::sin(i * 1.7) * std::cos(i * 0.31));
    }
    Plot p;
    p.add(s);
    const std::string svg = p.svg(600, 400);
    const double frameX = attrOf(svg, "<svg x=", "x"), frameW = attrOf(svg, "<svg x=", "width");
    const std::size_t legendAt = svg.find("rx=\"3\"");
    const std::size_t rectStart = svg.rfind("<rect", legendAt);
    const double lx = std::stod(svg.substr(svg.find("x=\"", rectStart) + 3));
    CHECK(lx > frameX + frameW);
  }
}

TEST_CASE("x tick labels never overlap even on a narrow plot") {
  for (int width : {160, 300, 760}) {
    Plot p;
    p.add(Series{"", {0, 1.23456e6}, {0, 1}});
    const std::string svg = p.svg(width, 200);
    // Labels below the frame are centred texts in the tick-label group.
    const std::size_t g = svg.find("<g font-size=\"12\" fill=\"#333\">");
    REQUIRE(g != std::string::npos);
    std::vector<std::pair<double, std::string>> labels;
    std::size_t pos = g;
    const std::size_t gEnd = svg.find("</g>", g);
    while ((pos = svg.find("<text x=\"", pos)) < gEnd) {
      const double x = std::stod(svg.substr(pos + 9));
      const std::size_t tagEnd = svg.find('>', pos);
      const bool middle = svg.substr(pos, tagEnd - pos).find("middle") != std::string::npos;
      const std::size_t textEnd = svg.find('<', tagEnd);
      if (middle) labels.emplace_back(x, svg.substr(tagEnd + 1, textEnd - tagEnd - 1));
      pos = textEnd;
    }
    INFO("width " << width);
    REQUIRE(labels.size() >= 2);
    for (std::size_t i = 1; i < labels.size(); ++i) {
      // Code points × 12 px × 0.75: wider than any DejaVu Sans digit (0.636 em) or '×' (0.838 em
      // occurs once per label), so this bounds the real rendered half-widths from above.
      auto half = [](const std::string& s) {
        std::size_t n = 0;
        for (unsigned char c : s) n += (c & 0xC0) != 0x80;
        return static_cast<double>(n) * 12 * 0.75 / 2;
      };
      CHECK(labels[i].first - labels[i - 1].first > half(labels[i].second) +
                                                        half(labels[i - 1].second));
    }
  }
}

TEST_CASE("a million-point series keeps its extremes but not its size") {
  Series s{"big", {}, {}, "#123456"};
  const int n = 1000000;
  for (int i = 0; i < n; ++i) {
    s.x.push_back(i);
    s.y.push_back(i == 500000 ? 50.0 : std::sin(i * 1e-4));  // one spike in the middle
  }
  Plot p;
  p.yRange = std::make_pair(-2.0, 2.0);  // the spike leaves the frame: clipped, not rescaled
  p.add(s);
  const std::string svg = p.svg(760, 440);
  const auto paths = linePaths(svg, "#123456");
  REQUIRE(paths.size() == 1);
  const std::size_t vertices = countChar(paths[0], 'M') + countChar(paths[0], 'L');
  CHECK(vertices <= 4 * 760);  // ≤ first, min, max, last per pixel column
  CHECK(svg.size() < 100000);
  // The spike at y = 50 maps above the frame top: y_px = (1 − (50 + 2)/4)·h < 0 is kept.
  CHECK(paths[0].find(",-") != std::string::npos);
}

TEST_CASE("mismatched lengths and unusable fixed ranges are input errors") {
  Plot a;
  a.add(Series{"s", {1, 2, 3}, {1, 2}});
  CHECK_THROWS_AS(a.svg(), sinsim::InputError);
  Plot b;
  b.add(Band{"b", {1, 2}, {1, 2}, {1}});
  CHECK_THROWS_AS(b.svg(), sinsim::InputError);
  Plot c;
  c.yLog = true;
  c.yRange = std::make_pair(0.0, 1.0);
  CHECK_THROWS_AS(c.svg(), sinsim::InputError);
  Plot d;
  d.xRange = std::make_pair(2.0, 1.0);
  CHECK_THROWS_AS(d.svg(), sinsim::InputError);
}

TEST_CASE("an empty plot still renders a framed and well-formed SVG") {
  Plot p("empty", "x", "y");
  CHECK(xmlProblem(p.svg()) == "");
  p.xLog = p.yLog = true;
  CHECK(xmlProblem(p.svg()) == "");
}

TEST_CASE("write is atomic: the whole file or nothing") {
  HtmlPage page("atomic");
  page.paragraph("content");
  const fs::path dir = freshDir("atomic");

  SECTION("missing folder: InputError and no file anywhere") {
    const fs::path target = dir / "missing" / "r.html";
    CHECK_THROWS_AS(page.write(target.string()), sinsim::InputError);
    CHECK(!fs::exists(dir / "missing"));
    CHECK(listDir(dir).empty());
  }
  SECTION("success: exactly the target file, byte-identical to html(), readable by others") {
    const fs::path target = dir / "r.html";
    page.write(target.string());
    CHECK(listDir(dir) == std::vector<std::string>{"r.html"});
    CHECK(slurp(target.string()) == page.html());
    CHECK((fs::status(target).permissions() & fs::perms::others_read) != fs::perms::none);
    HtmlPage other("replaced");
    other.write(target.string());  // an existing report is replaced whole
    CHECK(slurp(target.string()) == other.html());
    CHECK(listDir(dir) == std::vector<std::string>{"r.html"});
  }
  SECTION("rename fails (target is a folder): Error, temporary removed, folder untouched") {
    fs::create_directory(dir / "taken");
    fs::create_directory(dir / "taken" / "inner");
    CHECK_THROWS_AS(page.write((dir / "taken").string()), sinsim::Error);
    CHECK(listDir(dir) == std::vector<std::string>{"taken"});
  }
  fs::remove_all(dir);
}

TEST_CASE("bar chart: bars in the order given, lengths proportional to the values") {
  BarChart chart{"budget", "share [%]", {{"gyro <x>", 60.0, "60 %", ""}, {"accel", 30.0, "30 %", ""},
                                         {"none", -1.0, "-1 %", ""}}};
  const std::string svg = chart.svg(600);
  CHECK(xmlProblem(svg).empty());  // well-formed, the label escaped
  CHECK(svg.find("gyro &lt;x&gt;") < svg.find(">accel<"));
  // Bar widths from the <rect> elements in order: 60 and 30 give 2:1; a negative value none.
  std::vector<double> widths;
  for (std::size_t at = svg.find("<rect"); at != std::string::npos; at = svg.find("<rect", at + 1)) {
    const std::size_t w = svg.find("width=\"", at) + 7;
    widths.push_back(std::stod(svg.substr(w, svg.find('"', w) - w)));
  }
  REQUIRE(widths.size() == 3);
  CHECK(widths[0] > 100.0);
  CHECK(widths[0] == Approx(2.0 * widths[1]).epsilon(0.01));  // 0.1 px rounding of ~200 px
  CHECK(widths[2] == 0.0);
  CHECK_THROWS_AS(chart.svg(100), sinsim::InputError);
}
