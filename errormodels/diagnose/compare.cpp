// Curves with Monte Carlo bands, misfit and Allan chi-square of one channel (compare.hpp).
#include "errormodels/diagnose/compare.hpp"

#include <algorithm>
#include <cmath>

#include "errormodels/diagnose/series_tools.hpp"
#include "errormodels/fit/allan_fit.hpp"
#include "errormodels/stats/special.hpp"

namespace sinsim::errormodels::diagnose::detail {

namespace {

/// Central interval of a variance estimate with nu EDF around its mean: mean chi2_q(nu) / nu.
double chi2Factor(double p, double nu) {
  if (!(nu < 1e6)) {  // the chi-square law is normal to 1e-3 here: mean (1 + z sqrt(2/nu))
    const double z = normalQuantileTwoSided(std::fabs(2 * p - 1)) * (p < 0.5 ? -1 : 1);
    return std::max(0.0, 1 + z * std::sqrt(2 / nu));
  }
  return chiSquareQuantile(p, nu) / nu;
}

/// Band of a variance-like statistic from its realisations (chi-square with nu = 2 mean^2/var).
void chiBand(const std::vector<double>& real, double level, double& model, double& lo, double& hi) {
  const auto m = moments(real);
  model = m.mean;
  const double nu = m.var > 0 ? 2 * m.mean * m.mean / m.var : INFINITY;
  lo = m.mean * chi2Factor((1 - level) / 2, nu);
  hi = m.mean * chi2Factor((1 + level) / 2, nu);
}

/// ADEV curve and band per tau, the raw misfit (its square: meanSquare), the fraction outside,
/// and the Allan problem's L, mu, bias. Returns ln AVAR of every realisation (R x K).
Eigen::MatrixXd compareAdev(const SeriesStats& meas, const std::vector<SeriesStats>& real,
                            double level, AxisDiagnosis& d, AllanProblem& prob, double& meanSquare) {
  const std::size_t R = real.size(), K = meas.avar.size();
  Eigen::MatrixXd logs(static_cast<Eigen::Index>(R), static_cast<Eigen::Index>(K));
  prob.L.resize(K), prob.mu.resize(K), prob.bias.resize(K);
  double sumsq = 0;
  std::size_t out = 0;
  for (std::size_t k = 0; k < K; ++k) {
    std::vector<double> a(R);
    for (std::size_t r = 0; r < R; ++r) a[r] = real[r].avar[k];
    double mu, lo, hi;
    chiBand(a, level, mu, lo, hi);
    mu = std::max(mu, 1e-300);
    const double mv = std::max(meas.avar[k], 1e-300);
    d.adev.meas.push_back(std::sqrt(mv));
    d.adev.model.push_back(std::sqrt(mu));
    d.adev.lo.push_back(std::sqrt(std::max(lo, 0.0)));
    d.adev.hi.push_back(std::sqrt(hi));
    const int side = mv > hi ? 1 : (mv < lo ? -1 : 0);
    d.adev.outside.push_back(side);
    out += side != 0;
    const double l10 = std::log10(std::sqrt(mv / mu));
    sumsq += l10 * l10;
    double lm = 0;
    for (std::size_t r = 0; r < R; ++r) {
      logs(Eigen::Index(r), Eigen::Index(k)) = std::log(std::max(a[r], 1e-300));
      lm += logs(Eigen::Index(r), Eigen::Index(k));
    }
    lm /= double(R);
    prob.L[k] = std::log(mv);
    prob.mu[k] = mu;
    prob.bias[k] = lm - std::log(mu);
  }
  meanSquare = sumsq / double(K);
  d.misfitRaw = std::sqrt(meanSquare);
  d.fractionOutside = double(out) / double(K);
  return logs;
}

/// The RMS of log10(ADEV_realisation / ADEV_model) over realisations and tau (the misfit a
/// perfect model shows), and the misfit beyond it (meanSquare: the measurement's mean square).
void misfitBeyondFloor(const Eigen::MatrixXd& logs, const std::vector<double>& mu, double meanSquare,
                       AxisDiagnosis& d) {
  const std::size_t R = std::size_t(logs.rows()), K = std::size_t(logs.cols());
  double fl = 0;
  for (std::size_t r = 0; r < R; ++r)
    for (std::size_t k = 0; k < K; ++k) {
      const double l10 = (logs(Eigen::Index(r), Eigen::Index(k)) - std::log(mu[k])) / (2 * std::log(10.0));
      fl += l10 * l10;
    }
  d.misfitFloor = std::sqrt(fl / double(R * K));
  d.misfit = std::sqrt(std::max(0.0, meanSquare - d.misfitFloor * d.misfitFloor));
}

/// Inverse covariance of ln AVAR: per-tau variances, correlation averaged along the octave
/// diagonals (the estimates at tau_i, tau_j depend mostly on tau_j / tau_i), eigenvalues floored,
/// times 1 + 1/R for the Monte Carlo mean's own error.
Eigen::MatrixXd lnAvarWeight(const Eigen::MatrixXd& logs) {
  const std::size_t R = std::size_t(logs.rows()), K = std::size_t(logs.cols());
  Eigen::MatrixXd X = logs.rowwise() - logs.colwise().mean();
  Eigen::MatrixXd C = X.transpose() * X / double(R - 1);
  Eigen::VectorXd sd = C.diagonal().cwiseMax(1e-12).cwiseSqrt();
  std::vector<double> rho(K, 0.0);
  for (std::size_t lag = 0; lag < K; ++lag) {
    double s = 0;
    for (std::size_t i = 0; i + lag < K; ++i)
      s += C(Eigen::Index(i), Eigen::Index(i + lag)) / (sd[Eigen::Index(i)] * sd[Eigen::Index(i + lag)]);
    rho[lag] = s / double(K - lag);
  }
  rho[0] = 1;
  Eigen::MatrixXd Cs(static_cast<Eigen::Index>(K), static_cast<Eigen::Index>(K));
  for (std::size_t i = 0; i < K; ++i)
    for (std::size_t j = 0; j < K; ++j)
      Cs(Eigen::Index(i), Eigen::Index(j)) =
          sd[Eigen::Index(i)] * sd[Eigen::Index(j)] * rho[i > j ? i - j : j - i] * (1 + 1.0 / double(R));
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(Cs);
  Eigen::VectorXd ev = es.eigenvalues();
  const double floor = 1e-3 * ev.maxCoeff();
  Eigen::VectorXd inv = ev.cwiseMax(floor).cwiseInverse();
  return es.eigenvectors() * inv.asDiagonal() * es.eigenvectors().transpose();
}

/// r' W r with r = L - bias - ln mu: the Allan chi-square of the model as it is.
double chi2Of(const AllanProblem& p) {
  const std::size_t K = p.L.size();
  Eigen::VectorXd r(static_cast<Eigen::Index>(K));
  for (std::size_t k = 0; k < K; ++k) r[Eigen::Index(k)] = p.L[k] - p.bias[k] - std::log(p.mu[k]);
  return r.dot(p.W * r);
}

void comparePsd(const SeriesStats& meas, const std::vector<SeriesStats>& real, const Setup& setup,
                double level, Comparison& c) {
  for (std::size_t b = 0; b < setup.psdBandFreq.size(); ++b) {
    std::vector<double> v(real.size());
    for (std::size_t r = 0; r < real.size(); ++r) v[r] = real[r].psd[b];
    double mu, lo, hi;
    chiBand(v, level, mu, lo, hi);
    c.x.push_back(setup.psdBandFreq[b]);
    c.meas.push_back(meas.psd[b]);
    c.model.push_back(mu);
    c.lo.push_back(lo);
    c.hi.push_back(hi);
    c.outside.push_back(meas.psd[b] > hi ? 1 : (meas.psd[b] < lo ? -1 : 0));
  }
}

/// ACF band: mean +- z sqrt(var (1 + 1/R)) over the realisations, z the two-sided normal quantile.
void compareAcf(const SeriesStats& meas, const std::vector<SeriesStats>& real, const Setup& setup,
                double level, Comparison& c) {
  const std::size_t R = real.size();
  const double zAcf = normalQuantileTwoSided(level);
  for (std::size_t l = 0; l <= setup.acfLags; ++l) {
    std::vector<double> v(R);
    for (std::size_t r = 0; r < R; ++r) v[r] = real[r].acf[l];
    const auto mm = moments(v);
    const double half = zAcf * std::sqrt(mm.var * (1 + 1.0 / double(R)));
    c.x.push_back(double(l) / setup.rate);
    c.meas.push_back(meas.acf[l]);
    c.model.push_back(mm.mean);
    c.lo.push_back(mm.mean - half);
    c.hi.push_back(mm.mean + half);
    c.outside.push_back(meas.acf[l] > mm.mean + half ? 1 : (meas.acf[l] < mm.mean - half ? -1 : 0));
  }
}

}  // namespace

RoundedScatter roundedScatter(const std::vector<SeriesStats>& real) {
  RoundedScatter out;
  const std::size_t R = real.size();
  if (R < 2) return out;
  const std::size_t K = real.front().roundedAvar.size();
  if (K == 0) return out;
  Eigen::MatrixXd logs(static_cast<Eigen::Index>(R), static_cast<Eigen::Index>(K));
  out.bias.resize(K);
  for (std::size_t k = 0; k < K; ++k) {
    double mean = 0, lm = 0;
    for (std::size_t r = 0; r < R; ++r) {
      if (real[r].roundedAvar.size() != K || !(real[r].roundedAvar[k] > 0)) return {};
      mean += real[r].roundedAvar[k] / double(R);
      logs(Eigen::Index(r), Eigen::Index(k)) = std::log(real[r].roundedAvar[k]);
      lm += logs(Eigen::Index(r), Eigen::Index(k)) / double(R);
    }
    out.bias[k] = lm - std::log(mean);
  }
  out.W = lnAvarWeight(logs);
  return out;
}

std::vector<FailRange> failRanges(const Comparison& c, const std::string& stat) {
  std::vector<FailRange> out;
  for (std::size_t i = 0; i < c.x.size();) {
    if (c.outside[i] == 0) {
      ++i;
      continue;
    }
    FailRange f;
    f.statistic = stat;
    f.direction = c.outside[i];
    f.from = c.x[i];
    double worst = 0;
    std::size_t j = i;
    for (; j < c.x.size() && c.outside[j] == f.direction; ++j) {
      const double r = c.meas[j] / c.model[j];
      const double far = std::fabs(std::log(r));
      if (far > worst) worst = far, f.worstRatio = r;
      f.to = c.x[j];
      ++f.points;
    }
    out.push_back(f);
    i = j;
  }
  return out;
}

void compareChannel(const SeriesStats& meas, const std::vector<SeriesStats>& real,
                    const Setup& setup, double bandLevel, AxisDiagnosis& d, AllanProblem& prob) {
  for (auto m : setup.factors) d.adev.x.push_back(double(m) / setup.rate);
  double meanSquare = 0;
  const Eigen::MatrixXd logs = compareAdev(meas, real, bandLevel, d, prob, meanSquare);
  misfitBeyondFloor(logs, prob.mu, meanSquare, d);
  prob.W = lnAvarWeight(logs);
  d.chi2 = chi2Of(prob);
  d.chi2Points = prob.L.size();
  comparePsd(meas, real, setup, bandLevel, d.psd);
  compareAcf(meas, real, setup, bandLevel, d.acf);
  d.fails = failRanges(d.adev, "adev");
  for (auto& f : failRanges(d.psd, "psd")) d.fails.push_back(f);
}

}  // namespace sinsim::errormodels::diagnose::detail
