#include "sim/aided/discretize.hpp"

#include <cmath>
#include <vector>

#include <unsupported/Eigen/MatrixFunctions>

namespace sinsim::sim::aided {

DiscreteSystem vanLoan(const Eigen::MatrixXd& F, const Eigen::MatrixXd& Qc, double T) {
  const Eigen::Index n = F.rows();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  A.topLeftCorner(n, n) = -F * T;
  A.topRightCorner(n, n) = Qc * T;
  A.bottomRightCorner(n, n) = F.transpose() * T;
  const Eigen::MatrixXd B = A.exp();  // Padé with scaling and squaring (Higham 2005)
  DiscreteSystem d;
  d.Phi = B.bottomRightCorner(n, n).transpose();
  d.Qd = d.Phi * B.topRightCorner(n, n);
  d.Qd = 0.5 * (d.Qd + d.Qd.transpose()).eval();
  return d;
}

namespace {

// The series over a step h with every |F_ii| h <= 1; false when it does not converge.
bool seriesStep(const Eigen::MatrixXd& F, const Eigen::MatrixXd& Qc, double T, DiscreteSystem& d) {
  const Eigen::Index n = F.rows();
  // The non-zeros of F T. Products are formed transposed, (F T X)ᵀ = Xᵀ (F T)ᵀ, so that each
  // non-zero F_ij adds a contiguous column: out.col(i) += F_ij T · X.col(j) (X = Pᵀ, or M, which
  // is symmetric).
  struct NonZero {
    Eigen::Index i, j;
    double v;
  };
  std::vector<NonZero> nz;
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index i = 0; i < n; ++i)
      if (F(i, j) != 0.0) nz.push_back({i, j, F(i, j) * T});
  auto productT = [&nz](const Eigen::MatrixXd& X, Eigen::MatrixXd& out) {  // out = (F T Xᵀ)ᵀ
    out.setZero();
    for (const NonZero& z : nz) out.col(z.i) += z.v * X.col(z.j);
  };
  Eigen::MatrixXd PhiT = Eigen::MatrixXd::Identity(n, n);
  Eigen::MatrixXd Qd = Qc * T;
  Eigen::MatrixXd Pt = PhiT;  // ((F T)^k / k!)ᵀ
  Eigen::MatrixXd M = Qd;     // M_k T^(k+1) / (k+1)!, symmetric
  Eigen::MatrixXd tmp(n, n);
  constexpr int kMaxTerms = 40;
  constexpr double kTol = 0x1p-53;  // a term below half an ulp of the sum's largest entry
  // Upper bounds of the sums' largest entries (triangle inequality): while a term is above
  // kTol times the bound, the sum's own norm need not be formed (the stop comes at the same k).
  double boundPhi = 1.0, boundQ = Qd.lpNorm<Eigen::Infinity>();
  for (int k = 1; k <= kMaxTerms; ++k) {
    productT(Pt, tmp);
    Pt = tmp * (1.0 / double(k));
    productT(M, tmp);  // (F T M)ᵀ = M (F T)ᵀ
    M = (tmp + tmp.transpose()) * (1.0 / double(k + 1));
    PhiT += Pt;
    Qd += M;
    // lpNorm<Infinity> is the largest |entry| (the same for a matrix and its transpose).
    const double termPhi = Pt.lpNorm<Eigen::Infinity>(), termQ = M.lpNorm<Eigen::Infinity>();
    boundPhi += termPhi;
    boundQ += termQ;
    if (termPhi > kTol * boundPhi || termQ > kTol * boundQ) continue;
    if (termPhi <= kTol * PhiT.lpNorm<Eigen::Infinity>() &&
        termQ <= kTol * Qd.lpNorm<Eigen::Infinity>()) {
      d.Phi = PhiT.transpose();
      d.Qd = std::move(Qd);
      return true;
    }
  }
  return false;
}

}  // namespace

DiscreteSystem discretize(const Eigen::MatrixXd& F, const Eigen::MatrixXd& Qc, double T) {
  // A fast process (|F_ii| T > 1) is stepped over h = T / 2^s with |F_ii| h <= 1, then doubled:
  // Φ(2h) = Φ(h)², Qd(2h) = Φ(h) Qd(h) Φ(h)ᵀ + Qd(h) (sums of positive terms, no cancellation;
  // Van Loan's exp(−F T) block would overflow for τ of milliseconds).
  const double fastest = (F.diagonal().cwiseAbs() * T).maxCoeff();
  int s = 0;
  if (fastest > 1.0) s = int(std::ceil(std::log2(fastest)));
  if (!(s <= 60)) return vanLoan(F, Qc, T);  // NaN or absurd rates: let Van Loan report it
  DiscreteSystem d;
  if (!seriesStep(F, Qc, std::ldexp(T, -s), d)) return vanLoan(F, Qc, T);
  for (int i = 0; i < s; ++i) {
    d.Qd = (d.Phi * d.Qd * d.Phi.transpose() + d.Qd).eval();
    d.Qd = 0.5 * (d.Qd + d.Qd.transpose()).eval();
    d.Phi = (d.Phi * d.Phi).eval();
  }
  return d;
}

}  // namespace sinsim::sim::aided
