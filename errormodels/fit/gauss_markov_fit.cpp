#include "errormodels/fit/gauss_markov_fit.hpp"

#include <cmath>
#include <sstream>

#include "common/error.hpp"

namespace sinsim::errormodels::fit {

namespace {

// J' C J of the sandwich with C(i, j) = phi^|i-j| (kappa + |i-j|) + phi^(h+k) (kappa + h + k),
// h = first + i, k = first + j (Bartlett's covariance without its sigma^4 / N), in O(m): C is never
// formed (m lags of a 1 kHz record are 10^5, and C would be 80 GB). The Toeplitz part by forward
// and backward recursions, F_i = sum_{j<=i} phi^(i-j) a_j = phi F_{i-1} + a_i and
// G_i = sum_{j<=i} (i-j) phi^(i-j) a_j = phi (G_{i-1} + F_{i-1}) (a_j the j-th row of J), and
// their mirror images; the rest is of rank 3 in u = sum phi^h a and v = sum h phi^h a.
Eigen::Matrix2d bartlettMiddle(const Eigen::MatrixXd& J, std::size_t first, double phi, double kappa) {
  const Eigen::Index m = J.rows();
  Eigen::MatrixXd F(m, 2), G(m, 2), B(m, 2), H(m, 2);
  for (Eigen::Index i = 0; i < m; ++i) {
    F.row(i) = J.row(i) + (i ? Eigen::RowVector2d(phi * F.row(i - 1)) : Eigen::RowVector2d::Zero());
    G.row(i) = i ? Eigen::RowVector2d(phi * (G.row(i - 1) + F.row(i - 1))) : Eigen::RowVector2d::Zero();
  }
  for (Eigen::Index i = m - 1; i >= 0; --i) {
    B.row(i) = J.row(i) + (i + 1 < m ? Eigen::RowVector2d(phi * B.row(i + 1)) : Eigen::RowVector2d::Zero());
    H.row(i) = i + 1 < m ? Eigen::RowVector2d(phi * (H.row(i + 1) + B.row(i + 1))) : Eigen::RowVector2d::Zero();
  }
  const Eigen::MatrixXd toeplitzJ = kappa * (F + B - J) + G + H;  // row i: sum_j C1(i, j) a_j
  Eigen::Vector2d u = Eigen::Vector2d::Zero(), v = Eigen::Vector2d::Zero();
  for (Eigen::Index i = 0; i < m; ++i) {
    const double h = static_cast<double>(first) + static_cast<double>(i);
    const double w = std::pow(phi, h);
    u += w * J.row(i).transpose();
    v += h * w * J.row(i).transpose();
  }
  return J.transpose() * toeplitzJ + kappa * u * u.transpose() + u * v.transpose() + v * u.transpose();
}

}  // namespace

GaussMarkovFit fitGaussMarkov(const std::vector<double>& acf, double lagStep,
                              const GaussMarkovFitOptions& options) {
  if (!(std::isfinite(lagStep) && lagStep > 0.0))
    throw InputError("Gauss-Markov fit: lag step must be a positive time");
  for (std::size_t k = 0; k < acf.size(); ++k)
    if (!std::isfinite(acf[k]))
      throw InputError("Gauss-Markov fit: autocovariance at lag " + std::to_string(k) +
                       " is not finite");
  const std::size_t first = options.skipLagZero ? 1 : 0;
  if (acf.size() < first + 3)
    throw InputError("Gauss-Markov fit: need at least 3 lags of autocovariance");
  const double ref = acf[first];
  if (!(ref > 0.0)) throw InputError("Gauss-Markov fit: autocovariance at the first lag is <= 0");

  std::size_t last = options.maxLag;
  if (last == 0) {
    last = acf.size() - 1;
    for (std::size_t k = first + 1; k < acf.size(); ++k)
      if (acf[k] / ref <= std::exp(-3.0)) {
        last = k;
        break;
      }
    last = std::max(last, first + 2);
  }
  if (last >= acf.size() || last < first + 2) {
    std::ostringstream s;
    s << "Gauss-Markov fit: maxLag " << last << " outside the " << acf.size()
      << " lags given (need >= " << first + 2 << ")";
    throw InputError(s.str());
  }
  const auto m = static_cast<Eigen::Index>(last - first + 1);
  Eigen::VectorXd lag(m), y(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    lag(i) = static_cast<double>(first + static_cast<std::size_t>(i)) * lagStep;
    y(i) = acf[first + static_cast<std::size_t>(i)];
  }

  // Start: log-linear regression ln acf = ln s2 - lag / tau over the positive values.
  double s2 = ref, tau = 0.0;
  {
    double sx = 0, sy = 0, sxx = 0, sxy = 0, cnt = 0;
    for (Eigen::Index i = 0; i < m; ++i) {
      if (y(i) <= 0.0) continue;
      const double ly = std::log(y(i));
      sx += lag(i); sy += ly; sxx += lag(i) * lag(i); sxy += lag(i) * ly; cnt += 1;
    }
    const double slope = (cnt * sxy - sx * sy) / (cnt * sxx - sx * sx);
    if (cnt >= 2 && slope < 0.0) {
      tau = -1.0 / slope;
      s2 = std::exp((sy - slope * sx) / cnt);
    } else {
      throw InputError("Gauss-Markov fit: the autocovariance does not decay over the lags used");
    }
  }

  auto model = [&](double s2v, double tv) {
    return Eigen::VectorXd(s2v * (-lag.array() / tv).exp());
  };
  auto jacobian = [&](double s2v, double tv) {
    Eigen::MatrixXd J(m, 2);
    const Eigen::ArrayXd e = (-lag.array() / tv).exp();
    J.col(0) = e.matrix();
    J.col(1) = (s2v * e * lag.array() / (tv * tv)).matrix();
    return J;
  };
  double rss = (y - model(s2, tau)).squaredNorm();
  for (int it = 0; it < 100; ++it) {
    const Eigen::MatrixXd J = jacobian(s2, tau);
    const Eigen::VectorXd r = y - model(s2, tau);
    const Eigen::Vector2d step = (J.transpose() * J).ldlt().solve(J.transpose() * r);
    double h = 1.0;
    bool improved = false;
    for (int half = 0; half < 40; ++half, h *= 0.5) {
      const double s2n = s2 + h * step(0), taun = tau + h * step(1);
      if (!(s2n > 0.0 && taun > 0.0)) continue;
      const double rssn = (y - model(s2n, taun)).squaredNorm();
      if (rssn <= rss) {
        const bool converged = std::abs(h * step(0)) <= 1e-13 * s2 &&
                               std::abs(h * step(1)) <= 1e-13 * tau;
        s2 = s2n;
        tau = taun;
        improved = rssn < rss && !converged;
        rss = rssn;
        break;
      }
    }
    if (!improved) break;
  }

  GaussMarkovFit fit;
  fit.sigma = std::sqrt(s2);
  fit.tau = tau;
  fit.firstLag = first;
  fit.lastLag = last;
  fit.rmsResidual = std::sqrt(rss / static_cast<double>(m));

  const Eigen::MatrixXd J = jacobian(s2, tau);
  const Eigen::Matrix2d JtJinv = (J.transpose() * J).inverse();
  Eigen::Matrix2d covTheta;  // of (s2, tau)
  if (options.recordLength > 0) {
    const double N = static_cast<double>(options.recordLength);
    const double phi = std::exp(-lagStep / tau);
    const double kappa = (1.0 + phi * phi) / (1.0 - phi * phi);
    covTheta = JtJinv * (s2 * s2 / N * bartlettMiddle(J, first, phi, kappa)) * JtJinv;
    fit.bartlettCovariance = true;
  } else {
    const double dof = std::max<double>(1.0, static_cast<double>(m) - 2.0);
    covTheta = (rss / dof) * JtJinv;
  }
  // (s2, tau) -> (sigma, tau): d sigma / d s2 = 1 / (2 sigma)
  Eigen::Matrix2d G = Eigen::Matrix2d::Identity();
  G(0, 0) = 0.5 / fit.sigma;
  fit.covariance = G * covTheta * G.transpose();
  fit.sigmaStdError = std::sqrt(fit.covariance(0, 0));
  fit.tauStdError = std::sqrt(fit.covariance(1, 1));
  return fit;
}

}  // namespace sinsim::errormodels::fit
