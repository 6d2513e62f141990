// Axis ticks. Linear axes step by 1, 2 or 5 × 10^k (the "nice numbers" of Heckbert, Graphics
// Gems I, 1990, "Nice numbers for graph labels"); log axes tick every decade with minor ticks at
// 2..9 × 10^k, the convention of log-log Allan deviation plots (IEEE Std 952-1997, Fig. C.2).
#include <algorithm>
#include <cmath>
#include <string>

#include "common/error.hpp"
#include "sim/report/report.hpp"
#include "sim/report/report_detail.hpp"

namespace sinsim::report {
namespace {

// 10^k, correctly rounded for |k| ≤ 22 (exact powers, one correctly rounded division).
double pow10(int k) {
  if (k >= 0 && k <= 22) {
    double p = 1;
    for (int i = 0; i < k; ++i) p *= 10;
    return p;
  }
  if (k < 0 && k >= -22) return 1.0 / pow10(-k);
  return std::pow(10.0, k);
}

// m·10^k with a plain label where it stays short, "m×10ᵏ" otherwise.
std::string mantissaLabel(double m, int k, int mantissaDecimals) {
  return detail::typographicMinus(formatFixed(m, mantissaDecimals)) + "×10" +
         detail::superscript(k);
}

// Largest k with 10^k ≤ v (v > 0), robust to log10 rounding at exact powers.
int floorLog10(double v) {
  int k = static_cast<int>(std::floor(std::log10(v)));
  if (pow10(k) > v) --k;
  if (pow10(k + 1) <= v) ++k;
  return k;
}

}  // namespace

Ticks linearTicks(double lo, double hi, int target) {
  if (!(std::isfinite(lo) && std::isfinite(hi) && lo < hi))
    throw InputError("linearTicks: need finite lo < hi, got [" + formatFixed(lo, 6) + ", " +
                     formatFixed(hi, 6) + "]");
  target = std::max(target, 1);
  const double raw = (hi - lo) / target;
  const int k = floorLog10(raw);
  // Of the candidate steps 1, 2, 5, 10 × 10^k take the one whose interval count is nearest the
  // target; ties go to the coarser step (fewer labels to crowd).
  const int nice[] = {1, 2, 5, 10};
  int best = 1;
  double bestErr = 1e300;
  for (int m : nice) {
    const double step = m * pow10(k);
    const double err = std::abs((hi - lo) / step - target);
    if (err <= bestErr) {
      bestErr = err;
      best = m;
    }
  }
  int stepExp = k;
  if (best == 10) {
    best = 1;
    ++stepExp;
  }
  const double base = pow10(stepExp);
  const double step = best * base;
  // Tick i sits at i·step; compute it as i·best·10^e or i·best/10^-e so decimals come out exact.
  auto at = [&](long long i) {
    return stepExp >= 0 ? static_cast<double>(i * best) * base
                        : static_cast<double>(i * best) / pow10(-stepExp);
  };
  const double tol = 1e-9;  // relative to a step: keeps ticks that sit on lo or hi up to rounding
  const long long i0 = static_cast<long long>(std::ceil(lo / step - tol));
  const long long i1 = static_cast<long long>(std::floor(hi / step + tol));

  Ticks t;
  double maxAbs = 0;
  for (long long i = i0; i <= i1; ++i) {
    t.major.push_back(at(i));
    maxAbs = std::max(maxAbs, std::abs(t.major.back()));
  }
  // Plain decimals while labels stay short (≤ 6 integer digits, ≤ 4 decimals), else m×10ᵏ with
  // the mantissa precise enough to tell neighbouring ticks apart.
  const bool scientific = maxAbs >= 1e6 || stepExp < -4;
  for (double v : t.major) {
    if (v == 0 || !scientific) {
      t.labels.push_back(detail::typographicMinus(formatFixed(v, std::max(0, -stepExp))));
    } else {
      const int e = floorLog10(std::abs(v));
      t.labels.push_back(mantissaLabel(v / pow10(e), e, std::max(0, e - stepExp)));
    }
  }
  return t;
}

Ticks logTicks(double lo, double hi) {
  if (!(std::isfinite(lo) && std::isfinite(hi) && lo > 0 && lo < hi))
    throw InputError("logTicks: need finite 0 < lo < hi, got [" + formatFixed(lo, 6) + ", " +
                     formatFixed(hi, 6) + "]");
  const double relTol = 1e-12;  // a decade equal to lo or hi up to rounding still counts as inside
  auto inside = [&](double v) { return v >= lo * (1 - relTol) && v <= hi * (1 + relTol); };
  const int kLo = floorLog10(lo), kHi = floorLog10(hi);

  Ticks t;
  std::vector<int> decades;
  for (int k = kLo; k <= kHi + 1; ++k)
    if (inside(pow10(k))) decades.push_back(k);

  if (decades.size() >= 2) {
    // At most ~8 decade labels: label every n-th decade, on exponents divisible by n.
    const int n = static_cast<int>((decades.size() + 7) / 8);
    for (int k : decades) {
      t.major.push_back(pow10(k));
      t.labels.push_back(k % n == 0 ? "10" + detail::superscript(k) : "");
    }
    if (decades.size() <= 12)  // beyond that the minor ticks merge into a grey smear
      for (int k = kLo; k <= kHi; ++k)
        for (int m = 2; m <= 9; ++m)
          if (inside(m * pow10(k))) t.minor.push_back(m * pow10(k));
    return t;
  }

  // Less than about a decade: label the 1..9·10^k ticks themselves.
  std::vector<std::pair<int, int>> mk;  // (m, k)
  for (int k = kLo; k <= kHi; ++k)
    for (int m = 1; m <= 9; ++m)
      if (inside(m * pow10(k))) mk.emplace_back(m, k);
  if (mk.size() >= 2) {
    const bool thin = mk.size() > 6;  // then label only 1, 2, 5 and keep the rest as minor ticks
    for (auto [m, k] : mk) {
      const double v = m * pow10(k);
      if (thin && m != 1 && m != 2 && m != 5) {
        t.minor.push_back(v);
        continue;
      }
      t.major.push_back(v);
      t.labels.push_back(k >= -4 && k < 6 ? formatFixed(v, std::max(0, -k))
                                          : mantissaLabel(m, k, 0));
    }
    return t;
  }
  // A narrow range inside one 1..9 step: linear ticks are the honest ones.
  return linearTicks(lo, hi, 4);
}

}  // namespace sinsim::report
