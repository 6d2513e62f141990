// Ljung-Box test of AR prediction residuals (whiteness.hpp).
#include "errormodels/diagnose/whiteness.hpp"

#include "errormodels/stats/special.hpp"

namespace sinsim::errormodels::diagnose::detail {

namespace {

/// Prediction residuals of the AR a on y with the mean removed, themselves centred.
std::vector<double> centredResiduals(const std::vector<double>& y, const std::vector<double>& a) {
  const std::size_t p = a.size() - 1, N = y.size();
  double mean = 0;
  for (double v : y) mean += v;
  mean /= double(N);
  std::vector<double> e(N - p);
  for (std::size_t n = p; n < N; ++n) {
    double v = 0;
    for (std::size_t i = 0; i <= p; ++i) v += a[i] * (y[n - i] - mean);
    e[n - p] = v;
  }
  double em = 0;
  for (double v : e) em += v;
  em /= double(e.size());
  for (double& v : e) v -= em;
  return e;
}

}  // namespace

LjungBox ljungBox(const std::vector<double>& y, const std::vector<double>& a, std::size_t h) {
  const std::size_t p = a.size() - 1;
  const std::vector<double> e = centredResiduals(y, a);
  const std::size_t M = e.size();
  double r0 = 0;
  for (double v : e) r0 += v * v;
  LjungBox lb;
  lb.lags = h;
  lb.dof = h > p ? h - p : 1;
  double Q = 0;
  for (std::size_t k = 1; k <= h; ++k) {
    double rk = 0;
    for (std::size_t n = k; n < M; ++n) rk += e[n] * e[n - k];
    rk /= r0;
    Q += rk * rk / double(M - k);
  }
  lb.Q = double(M) * double(M + 2) * Q;
  lb.pValue = regularizedGammaQ(double(lb.dof) / 2, lb.Q / 2);
  return lb;
}

}  // namespace sinsim::errormodels::diagnose::detail
