// The HTML page: escaped text blocks, tables and inline SVG, one inline style sheet, written
// atomically (common/atomic_file.hpp).
#include <string>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "sim/report/report.hpp"

namespace sinsim::report {
namespace {

constexpr const char* kStyle = R"(
body { font-family: "DejaVu Sans", Helvetica, Arial, sans-serif; color: #222; background: #fff;
       max-width: 1120px; margin: 24px auto; padding: 0 16px; line-height: 1.45; font-size: 15px; }
h1 { font-size: 26px; border-bottom: 2px solid #1f77b4; padding-bottom: 6px; }
h2 { font-size: 20px; margin-top: 32px; border-bottom: 1px solid #ddd; padding-bottom: 4px; }
h3 { font-size: 17px; margin-top: 24px; }
h4 { font-size: 15px; }
table { border-collapse: collapse; margin: 12px 0 20px; font-size: 14px; }
caption { text-align: left; font-weight: bold; padding: 4px 0; }
th, td { border: 1px solid #d0d0d0; padding: 4px 10px; text-align: left; vertical-align: top; }
th { background: #f0f3f7; }
tbody tr:nth-child(even) td { background: #fafafa; }
td.num, th.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
td.pass { background: #e6f4ea !important; color: #11632b; }
td.fail { background: #fde8e6 !important; color: #a3150a; font-weight: bold; }
td.warn { background: #fff3dc !important; color: #7a4b00; }
td.muted { color: #888; }
pre { background: #f6f8fa; border: 1px solid #e1e4e8; padding: 10px; overflow-x: auto;
      font-size: 13px; line-height: 1.35; }
figure { margin: 12px 0 24px; }
figcaption { font-size: 13px; color: #555; margin-top: 4px; max-width: 760px; }
.row { display: flex; flex-wrap: wrap; gap: 12px; margin: 12px 0 24px; }
svg { max-width: 100%; height: auto; }
)";

}  // namespace

HtmlPage::HtmlPage(std::string title) : title_(std::move(title)) {
  body_ += "<h1>" + escape(title_) + "</h1>\n";
}

HtmlPage& HtmlPage::heading(const std::string& text, int level) {
  if (level < 1 || level > 4) throw InputError("heading level must be 1..4");
  const std::string tag = "h" + std::to_string(level);
  body_ += "<" + tag + ">" + escape(text) + "</" + tag + ">\n";
  return *this;
}

HtmlPage& HtmlPage::paragraph(const std::string& text) {
  body_ += "<p>" + escape(text) + "</p>\n";
  return *this;
}

HtmlPage& HtmlPage::table(const Table& t) {
  auto cls = [](const std::string& c) {
    return c.empty() ? std::string() : " class=\"" + escape(c) + "\"";
  };
  std::string s = "<table>\n";
  if (!t.caption.empty()) s += "<caption>" + escape(t.caption) + "</caption>\n";
  if (!t.header.empty()) {
    s += "<thead><tr>";
    for (const auto& h : t.header) s += "<th>" + escape(h) + "</th>";
    s += "</tr></thead>\n";
  }
  s += "<tbody>\n";
  for (const auto& row : t.rows) {
    s += "<tr>";
    for (const auto& c : row) s += "<td" + cls(c.cls) + ">" + escape(c.text) + "</td>";
    s += "</tr>\n";
  }
  s += "</tbody>\n</table>\n";
  body_ += s;
  return *this;
}

HtmlPage& HtmlPage::plot(const Plot& p, const std::string& caption, int width, int height) {
  body_ += "<figure>\n" + p.svg(width, height);
  if (!caption.empty()) body_ += "<figcaption>" + escape(caption) + "</figcaption>\n";
  body_ += "</figure>\n";
  return *this;
}

HtmlPage& HtmlPage::plotRow(const std::vector<Plot>& plots, int width, int height) {
  body_ += "<div class=\"row\">\n";
  for (const Plot& p : plots) body_ += p.svg(width, height);
  body_ += "</div>\n";
  return *this;
}

HtmlPage& HtmlPage::bars(const BarChart& chart, const std::string& caption, int width) {
  body_ += "<figure>\n" + chart.svg(width);
  if (!caption.empty()) body_ += "<figcaption>" + escape(caption) + "</figcaption>\n";
  body_ += "</figure>\n";
  return *this;
}

HtmlPage& HtmlPage::preformatted(const std::string& text) {
  body_ += "<pre>" + escape(text) + "</pre>\n";
  return *this;
}

std::string HtmlPage::html() const {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
         "<title>" +
         escape(title_) + "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n" + body_ +
         "</body>\n</html>\n";
}

void HtmlPage::write(const std::string& path) const { writeFileAtomic(path, html()); }

}  // namespace sinsim::report
