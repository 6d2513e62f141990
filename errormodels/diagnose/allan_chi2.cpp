// Least squares of the Allan chi-square over the level and the candidates' sizes (allan_chi2.hpp):
// grid start for new terms, Gauss-Newton on the level, then Levenberg-Marquardt with the sizes
// projected onto >= 0.
#include "errormodels/diagnose/allan_chi2.hpp"

#include <algorithm>
#include <cmath>

namespace sinsim::errormodels::diagnose::detail {

std::vector<double> modelAvarOf(const AllanProblem& p, const std::vector<const Candidate*>& set,
                                const AllanSolution& sol) {
  std::vector<double> M(p.mu.size());
  for (std::size_t k = 0; k < M.size(); ++k) {
    M[k] = sol.s * p.mu[k];
    for (std::size_t j = 0; j < set.size(); ++j) M[k] += (set[j]->freeSize ? sol.theta[j] : 1.0) * set[j]->g[k];
  }
  return M;
}

namespace {

/// chi2(x) = r' W r + (x0 / kLevelLnSd)^2, r_k = L_k - bias_k - ln M_k, M = e^x0 mu + fixed +
/// sum_i x_i scale_i g_i over the free candidates i. The scale_i is the theta that alone explains
/// the largest share of the measurement at some tau, so that every x_i is of order 1.
class AllanObjective {
 public:
  AllanObjective(const AllanProblem& p, const std::vector<const Candidate*>& set, bool fixLevel)
      : p_(p), set_(set), fixLevel_(fixLevel), K_(p.L.size()) {
    for (std::size_t j = 0; j < set.size(); ++j)
      if (set[j]->freeSize) freeIdx_.push_back(j);
    scale_.assign(freeIdx_.size(), 1.0);
    for (std::size_t i = 0; i < freeIdx_.size(); ++i) {
      double mx = 0;
      for (std::size_t k = 0; k < K_; ++k) {
        const double g = set[freeIdx_[i]]->g[k];
        if (g > 0) mx = std::max(mx, std::exp(p.L[k]) / g);
      }
      scale_[i] = mx > 0 ? mx : 1.0;
    }
    fixedSum_.assign(K_, 0.0);
    for (const auto* c : set)
      if (!c->freeSize)
        for (std::size_t k = 0; k < K_; ++k) fixedSum_[k] += c->g[k];
  }

  std::size_t parameters() const { return 1 + freeIdx_.size(); }

  double evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* J) const {
    const double s = std::exp(x[0]);
    r.resize(Eigen::Index(K_));
    if (J) J->resize(Eigen::Index(K_), Eigen::Index(parameters()));
    for (std::size_t k = 0; k < K_; ++k) {
      double M = s * p_.mu[k] + fixedSum_[k];
      for (std::size_t i = 0; i < freeIdx_.size(); ++i) M += x[1 + i] * scale_[i] * set_[freeIdx_[i]]->g[k];
      M = std::max(M, 1e-300);
      r[k] = p_.L[k] - p_.bias[k] - std::log(M);
      if (J) {
        (*J)(k, 0) = fixLevel_ ? 0.0 : -s * p_.mu[k] / M;
        for (std::size_t i = 0; i < freeIdx_.size(); ++i)
          (*J)(k, 1 + i) = -scale_[i] * set_[freeIdx_[i]]->g[k] / M;
      }
    }
    return r.dot(p_.W * r) + priorW_ * x[0] * x[0];
  }

  /// Level alone (a few Gauss-Newton steps on ln s, step halving) for the given sizes.
  double optimiseLevel(Eigen::VectorXd& x) const {
    Eigen::VectorXd r;
    Eigen::MatrixXd J;
    double chi = evaluate(x, r, &J);
    for (int it = 0; it < 30; ++it) {
      const Eigen::VectorXd j0 = J.col(0);
      const double h = j0.dot(p_.W * j0) + priorW_, g = j0.dot(p_.W * r) + priorW_ * x[0];
      if (fixLevel_ || !(h > 0)) break;
      Eigen::VectorXd xn = x;
      double step = -g / h;
      for (int half = 0; half < 30; ++half, step *= 0.5) {
        xn[0] = x[0] + step;
        Eigen::VectorXd rn;
        Eigen::MatrixXd Jn;
        const double cn = evaluate(xn, rn, &Jn);
        if (cn <= chi) {
          const bool done = chi - cn < 1e-12 * (1 + chi);
          x = xn, chi = cn, r = rn, J = Jn;
          if (done) return chi;
          break;
        }
      }
    }
    return chi;
  }

  /// The start x: ln s = 0, the given starts, and for each new term (start < 0) the best of 0 and
  /// 10^(-e/4), e = 0..40, each with the level refitted.
  Eigen::VectorXd start(const std::vector<double>& thetaStart) const {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(Eigen::Index(parameters()));
    for (std::size_t i = 0; i < freeIdx_.size(); ++i) {
      const std::size_t j = freeIdx_[i];
      x[1 + i] = j < thetaStart.size() && thetaStart[j] >= 0 ? thetaStart[j] / scale_[i] : -1.0;
    }
    for (std::size_t i = 0; i < freeIdx_.size(); ++i) {
      if (x[1 + i] >= 0) continue;
      double best = INFINITY, bestV = 0;
      for (int e = -1; e <= 40; ++e) {
        Eigen::VectorXd xt = x;
        for (std::size_t q = 0; q < freeIdx_.size(); ++q) xt[1 + q] = std::max(0.0, xt[1 + q]);
        xt[1 + i] = e < 0 ? 0.0 : std::pow(10.0, -e / 4.0);
        const double c = optimiseLevel(xt);
        if (c < best) best = c, bestV = xt[1 + i];
      }
      x[1 + i] = bestV;
    }
    return x;
  }

  /// Levenberg-Marquardt from x with the free sizes projected onto >= 0; returns chi2.
  double levenbergMarquardt(Eigen::VectorXd& x) const {
    Eigen::VectorXd r;
    Eigen::MatrixXd J;
    double chi = evaluate(x, r, &J);
    double lambda = 1e-3;
    for (int it = 0; it < 300; ++it) {
      Eigen::MatrixXd H = J.transpose() * p_.W * J;
      Eigen::VectorXd g = J.transpose() * p_.W * r;
      H(0, 0) += priorW_, g[0] += priorW_ * x[0];  // the level's prior: one more residual ln s / sd
      bool improved = false;
      for (int tries = 0; tries < 12; ++tries) {
        Eigen::MatrixXd A = H;
        for (Eigen::Index d = 0; d < A.rows(); ++d) A(d, d) += lambda * std::max(H(d, d), 1e-12);
        if (fixLevel_) A(0, 0) = 1.0, A.row(0).tail(A.cols() - 1).setZero(), A.col(0).tail(A.rows() - 1).setZero();
        Eigen::VectorXd xn = x - A.ldlt().solve(g);
        for (Eigen::Index d = 1; d < xn.size(); ++d) xn[d] = std::max(0.0, xn[d]);
        Eigen::VectorXd rn;
        Eigen::MatrixXd Jn;
        const double cn = evaluate(xn, rn, &Jn);
        if (std::isfinite(cn) && cn < chi) {
          const bool done = chi - cn < 1e-11 * (1 + chi);
          x = xn, r = rn, J = Jn, chi = cn;
          lambda = std::max(lambda / 4, 1e-12);
          improved = !done;
          break;
        }
        lambda *= 8;
      }
      if (!improved) break;
    }
    return chi;
  }

  AllanSolution solution(const Eigen::VectorXd& x, double chi) const {
    AllanSolution sol;
    sol.s = std::exp(x[0]);
    sol.chi2 = chi;
    sol.theta.assign(set_.size(), 1.0);
    for (std::size_t i = 0; i < freeIdx_.size(); ++i) sol.theta[freeIdx_[i]] = x[1 + i] * scale_[i];
    return sol;
  }

 private:
  const AllanProblem& p_;
  const std::vector<const Candidate*>& set_;
  bool fixLevel_;
  std::size_t K_;
  std::vector<std::size_t> freeIdx_;
  std::vector<double> scale_;     // theta_i = x_i scale_i
  std::vector<double> fixedSum_;  // AVAR of the fixed-size candidates [SI^2]
  static constexpr double priorW_ = 1.0 / (kLevelLnSd * kLevelLnSd);  // the level's prior weight
};

}  // namespace

AllanSolution solveAllan(const AllanProblem& p, const std::vector<const Candidate*>& set,
                         const std::vector<double>& thetaStart, bool fixLevel) {
  const AllanObjective objective(p, set, fixLevel);
  Eigen::VectorXd x = objective.start(thetaStart);
  objective.optimiseLevel(x);
  const double chi = objective.levenbergMarquardt(x);
  return objective.solution(x, chi);
}

}  // namespace sinsim::errormodels::diagnose::detail
