// The noise level over the record (noise_level.hpp).
#include "errormodels/diagnose/noise_level.hpp"
#include "errormodels/diagnose/series_tools.hpp"

#include <algorithm>
#include <cmath>

namespace sinsim::errormodels::diagnose::detail {

NoiseLevelBlocks noiseLevelBlocks(const std::vector<double>& y) {
  NoiseLevelBlocks out;
  if (y.size() < 64 * kNoiseLevelBlocks + 1) return out;
  std::vector<double> d(y.size() - 1);
  for (std::size_t k = 1; k < y.size(); ++k) d[k - 1] = std::abs(y[k] - y[k - 1]);
  const double cap = 8.0 * median(d);
  // On a lattice coarser than the noise most differences are 0: the mean |difference| still
  // counts the flips; a series whose median difference is 0 keeps its largest ones uncapped.
  const double limit = cap > 0 ? cap : INFINITY;
  const std::size_t per = d.size() / kNoiseLevelBlocks;
  for (std::size_t b = 0; b < kNoiseLevelBlocks; ++b) {
    double s = 0;
    for (std::size_t k = b * per; k < (b + 1) * per; ++k) s += std::min(d[k], limit);
    out.level.push_back(s / double(per));
  }
  const double m = median(out.level);
  if (!(m > 0)) return {};
  out.median = m;
  for (double& l : out.level) {
    l /= m;
    out.spread = std::max(out.spread, l > 0 ? std::abs(std::log(l)) : INFINITY);
  }
  return out;
}

std::optional<NoiseLevelChange> noiseLevelChange(const NoiseLevelBlocks& rec, std::size_t n, double rate,
                                                 const std::vector<double>& modelSpreads,
                                                 const std::vector<double>& modelMedians) {
  if (rec.level.empty() || modelSpreads.empty()) return std::nullopt;
  const double most = *std::max_element(modelSpreads.begin(), modelSpreads.end());
  const double threshold = std::max({most, 2.0 * median(modelSpreads), std::log(1.25)});
  if (!(rec.spread > threshold)) return std::nullopt;
  NoiseLevelChange c;
  c.lo = *std::min_element(rec.level.begin(), rec.level.end());
  c.hi = *std::max_element(rec.level.begin(), rec.level.end());
  std::size_t worst = 0;
  for (std::size_t b = 0; b < rec.level.size(); ++b)
    if (std::abs(std::log(rec.level[b])) > std::abs(std::log(rec.level[worst]))) worst = b;
  const double per = double((n - 1) / kNoiseLevelBlocks) / rate;
  c.from = double(worst) * per;
  c.to = double(worst + 1) * per;
  c.worst = rec.level[worst];
  c.modelMost = std::exp(most);
  for (std::size_t b = 0; b < rec.level.size(); ++b) {
    if (!(std::abs(std::log(rec.level[b])) > threshold)) continue;
    if (!c.stretches.empty() && c.stretches.back().second == double(b) * per)
      c.stretches.back().second = double(b + 1) * per;
    else
      c.stretches.emplace_back(double(b) * per, double(b + 1) * per);
  }
  // The quiet stretches: the record's median block against the realisations' medians, in ln
  // (a level's estimate scatters about symmetrically there), mean and sd over the realisations.
  std::vector<double> ln;
  for (double m : modelMedians)
    if (m > 0) ln.push_back(std::log(m));
  if (ln.size() >= 2 && rec.median > 0) {
    const Moments m = moments(ln);
    c.quiet = std::exp(std::log(rec.median) - m.mean);
    c.quietLnSd = std::sqrt(m.var);
    c.quietZ = m.var > 0 ? std::log(c.quiet) / c.quietLnSd : 0.0;
  }
  return c;
}

}  // namespace sinsim::errormodels::diagnose::detail
