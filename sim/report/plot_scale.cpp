// Text metrics and the data -> pixel mapping of a plot (plot_detail.hpp).
#include <algorithm>
#include <cmath>

#include "common/error.hpp"
#include "sim/report/plot_detail.hpp"
#include "sim/report/report.hpp"
#include "sim/report/report_detail.hpp"

namespace sinsim::report::plot_detail {

double textWidth(const std::string& s, double size) {
  return static_cast<double>(detail::displayLength(s)) * size * kCharWidth;
}

std::string num(double v) {
  return formatFixed(std::clamp(v, -kCoordLimit, kCoordLimit), kCoordDecimals);
}

std::pair<double, double> autoRange(std::vector<double> v, bool log) {
  if (v.empty()) return log ? std::make_pair(1.0, 10.0) : std::make_pair(0.0, 1.0);
  const auto [mn, mx] = std::minmax_element(v.begin(), v.end());
  double lo = log ? std::log10(*mn) : *mn, hi = log ? std::log10(*mx) : *mx;
  if (hi - lo <= 1e-12 * std::max(std::abs(lo), std::abs(hi)) || hi == lo) {
    const double half = log ? 0.5 : (lo == 0 ? 1.0 : 0.1 * std::abs(lo));
    lo -= half;
    hi += half;
  } else {
    const double pad = 0.04 * (hi - lo);
    lo -= pad;
    hi += pad;
  }
  return log ? std::make_pair(std::pow(10.0, lo), std::pow(10.0, hi)) : std::make_pair(lo, hi);
}

void checkRange(const std::optional<std::pair<double, double>>& r, bool log, const char* name) {
  if (!r) return;
  const auto [lo, hi] = *r;
  if (!(std::isfinite(lo) && std::isfinite(hi) && lo < hi && (!log || lo > 0)))
    throw InputError(std::string("plot ") + name + " range [" + formatFixed(lo, 6) + ", " +
                     formatFixed(hi, 6) + "] is not usable" + (log ? " on a log axis" : ""));
}

Run decimate(const Run& in, double width) {
  if (in.size() <= static_cast<std::size_t>(2 * width)) return in;
  Run out;
  std::size_t i = 0;
  while (i < in.size()) {
    const double col = std::floor(in[i].first);
    std::size_t j = i, lo = i, hi = i;
    while (j < in.size() && std::floor(in[j].first) == col) {
      if (in[j].second < in[lo].second) lo = j;
      if (in[j].second > in[hi].second) hi = j;
      ++j;
    }
    std::size_t keep[] = {i, std::min(lo, hi), std::max(lo, hi), j - 1};
    for (std::size_t n = 0; n < 4; ++n)
      if (n == 0 || keep[n] != keep[n - 1]) out.push_back(in[keep[n]]);
    i = j;
  }
  return out;
}

}  // namespace sinsim::report::plot_detail
