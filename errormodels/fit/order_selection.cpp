#include "errormodels/fit/order_selection.hpp"

#include <cmath>
#include <sstream>

#include "common/error.hpp"

namespace sinsim::errormodels::fit {

std::string toString(OrderCriterion c) {
  switch (c) {
    case OrderCriterion::AIC: return "aic";
    case OrderCriterion::MDL: return "mdl";
    case OrderCriterion::FPE: return "fpe";
    case OrderCriterion::PaperRule: return "paper-rule";
    case OrderCriterion::Forced: return "forced";
  }
  return "?";
}

std::vector<OrderCriteriaRow> orderCriteria(const std::vector<double>& path, std::size_t n,
                                            bool demeaned) {
  if (path.empty()) throw InputError("order criteria: empty driving-variance path");
  if (path.size() + 1 >= n) throw InputError("order criteria: maximum order must be < N - 2");
  const double N = static_cast<double>(n);
  std::vector<OrderCriteriaRow> rows;
  for (std::size_t p = 0; p < path.size(); ++p) {
    const double E = path[p], P = static_cast<double>(p);
    if (!(E > 0.0 && std::isfinite(E)))
      throw InputError("order criteria: driving variance of order " + std::to_string(p) +
                       " is not positive (a perfectly predictable series?)");
    OrderCriteriaRow r;
    r.order = p;
    r.drivingVariance = E;
    r.aic = N * std::log(E) + 2.0 * P;
    r.mdl = N * std::log(E) + P * std::log(N);
    r.fpe = demeaned ? E * (N + P + 1.0) / (N - P - 1.0) : E * (N + P) / (N - P);
    rows.push_back(r);
  }
  return rows;
}

double correlationTime(const std::vector<double>& acf, double lagStep, double level) {
  if (acf.size() < 2 || !(acf[0] > 0.0))
    throw InputError("correlation time: need acf[0] > 0 and at least two lags");
  if (!(std::isfinite(lagStep) && lagStep > 0.0))
    throw InputError("correlation time: lag step must be a positive time");
  if (!(level > 0.0 && level < 1.0)) throw InputError("correlation time: level must be in (0, 1)");
  for (std::size_t k = 1; k < acf.size(); ++k) {
    const double r1 = acf[k] / acf[0];
    if (r1 <= level) {
      const double r0 = acf[k - 1] / acf[0];
      const double frac = (r0 - level) / (r0 - r1);
      return (static_cast<double>(k - 1) + frac) * lagStep;
    }
  }
  std::ostringstream s;
  s << "correlation time: the autocorrelation does not fall to " << level << " within "
    << acf.size() - 1 << " lags";
  throw InputError(s.str());
}

double arCorrelationTime(const std::vector<double>& a, double dt) {
  // Grow the lag window until the 1/e crossing is inside it.
  for (std::size_t lags = 64;; lags *= 4) {
    const auto g = arAutocovariance(a, 1.0, lags);
    for (std::size_t k = 1; k <= lags; ++k)
      if (g[k] / g[0] <= std::exp(-1.0)) return correlationTime(g, dt);
    if (lags > (1u << 26))
      throw InputError("AR correlation time: no 1/e crossing within 2^26 lags");
  }
}

std::size_t paperRuleOrder(double tc, double navigationStep) {
  if (!(std::isfinite(tc) && tc > 0.0) || !(std::isfinite(navigationStep) && navigationStep > 0.0))
    throw InputError("paper's order rule: correlation time and navigation step must be positive");
  return static_cast<std::size_t>(std::floor(tc / navigationStep)) + 1;
}

OrderSelection selectArOrder(const std::vector<double>& x, const OrderSelectionOptions& options) {
  if (options.maxOrder < 1) throw InputError("order selection: maxOrder must be >= 1");
  const ArFit full = options.method == ArMethod::Burg ? burg(x, options.maxOrder, options.ar)
                                                      : yuleWalker(x, options.maxOrder, options.ar);
  OrderSelection out;
  out.table = orderCriteria(full.drivingVariancePath, x.size(), options.ar.demean);
  auto argmin = [&](auto field) {
    std::size_t best = 0;
    for (const auto& r : out.table)
      if (field(r) < field(out.table[best])) best = r.order;
    return best;
  };
  out.aicOrder = argmin([](const OrderCriteriaRow& r) { return r.aic; });
  out.mdlOrder = argmin([](const OrderCriteriaRow& r) { return r.mdl; });
  out.fpeOrder = argmin([](const OrderCriteriaRow& r) { return r.fpe; });

  if (options.navigationStep) {
    if (options.correlationTime) {
      out.correlationTime = *options.correlationTime;
    } else {
      if (!(options.sampleInterval > 0.0))
        throw InputError("paper's order rule: sampleInterval is needed to take the correlation "
                         "time from the AR model");
      const std::size_t p = std::max<std::size_t>(out.mdlOrder, 1);
      // the nested order-p model of the same run, rebuilt from its reflection coefficients
      std::vector<double> a{1.0};
      for (std::size_t m = 0; m < p; ++m) {
        const double k = full.reflection[m];
        std::vector<double> next(a.size() + 1, 0.0);
        next[0] = 1.0;
        for (std::size_t i = 1; i < a.size(); ++i) next[i] = a[i] + k * a[a.size() - i];
        next[a.size()] = k;
        a.swap(next);
      }
      out.correlationTime = arCorrelationTime(a, options.sampleInterval);
    }
    out.paperOrder = paperRuleOrder(*out.correlationTime, *options.navigationStep);
  }

  if (options.forcedOrder) {
    out.selectedOrder = *options.forcedOrder;
    out.selectedBy = OrderCriterion::Forced;
  } else {
    out.selectedBy = options.criterion;
    switch (options.criterion) {
      case OrderCriterion::AIC: out.selectedOrder = out.aicOrder; break;
      case OrderCriterion::MDL: out.selectedOrder = out.mdlOrder; break;
      case OrderCriterion::FPE: out.selectedOrder = out.fpeOrder; break;
      case OrderCriterion::PaperRule:
        if (!out.paperOrder)
          throw InputError("order selection: the paper's rule needs a navigation step");
        out.paperCapped = *out.paperOrder > options.maxOrder;
        out.selectedOrder = std::min(*out.paperOrder, options.maxOrder);
        break;
      case OrderCriterion::Forced:
        throw InputError("order selection: criterion 'forced' needs forcedOrder");
    }
  }
  // Order 0 (white noise) is reported but an AR model needs p >= 1.
  const std::size_t p = std::max<std::size_t>(out.selectedOrder, 1);
  out.fit = options.method == ArMethod::Burg ? burg(x, p, options.ar) : yuleWalker(x, p, options.ar);
  return out;
}

}  // namespace sinsim::errormodels::fit
