#include "sim/aided/block_series.hpp"

#include <cmath>

namespace sinsim::sim::aided {

bool navigationRowSeries(const Eigen::Matrix<double, 9, 9>& A, const Eigen::Matrix<double, 9, 9>& Qn,
                         const std::vector<InputBlock>& blocks, int n, double T,
                         Eigen::Matrix<double, 9, Eigen::Dynamic>& PhiN,
                         Eigen::Matrix<double, 9, Eigen::Dynamic>& QdN) {
  // The series without cancellation needs every |F_ii| T <= 1 (discretize's halving case).
  for (int i = 0; i < 9; ++i)
    if (!(std::abs(A(i, i)) * T <= 1.0)) return false;
  for (const InputBlock& b : blocks)
    for (Eigen::Index i = 0; i < b.F.rows(); ++i)
      if (!(std::abs(b.F(i, i)) * T <= 1.0)) return false;
  // The rows are kept transposed (n × 9), so that each non-zero A_ij T adds a contiguous column:
  // out.col(i) += A_ij T · X.col(j) is row i of A T X.
  struct NonZero {
    int i, j;
    double v;
  };
  NonZero nz[81];
  int nnz = 0;
  for (int j = 0; j < 9; ++j)
    for (int i = 0; i < 9; ++i)
      if (A(i, j) != 0.0) nz[nnz++] = {i, j, A(i, j) * T};
  // One-state blocks (bias, random walk, Gauss-Markov: all of today's continuous ones) are summed
  // with scalars; blocks of several states with small matrices. Blocks with the same input column
  // (one sensor axis) share it in X's Σ g_b (c_b M_bn).
  struct Scalar {
    int column, input;
    double c, f, p, m;  // c_b, F_b T, the Φ and M terms of the block's own series
  };
  std::vector<Scalar> scalars;
  std::vector<const InputBlock*> general;
  std::vector<Eigen::Matrix<double, 9, 1>> inputs;  // distinct T g_b
  auto inputOf = [&inputs, T](const Eigen::Matrix<double, 9, 1>& g) {
    for (std::size_t i = 0; i < inputs.size(); ++i)
      if (inputs[i] == T * g) return int(i);
    inputs.push_back(T * g);
    return int(inputs.size()) - 1;
  };
  for (const InputBlock& B : blocks) {
    if (B.c.size() == 1)
      scalars.push_back({B.column, inputOf(B.g), B.c[0], B.F(0, 0) * T, 1.0, B.Qc(0, 0) * T});
    else
      general.push_back(&B);
  }
  const std::size_t nb = general.size();
  // Per general block: F_b T and the block's current Φ and M terms, with scratch of the same size
  // (the loop allocates nothing).
  std::vector<Eigen::MatrixXd> FT(nb), Pb(nb), Mb(nb), Sb(nb);
  std::vector<Eigen::RowVectorXd> v(nb);
  std::vector<int> generalInput(nb);
  for (std::size_t b = 0; b < nb; ++b) {
    generalInput[b] = inputOf(general[b]->g);
    FT[b] = general[b]->F * T;
    Pb[b] = Eigen::MatrixXd::Identity(FT[b].rows(), FT[b].cols());
    Mb[b] = general[b]->Qc * T;
    Sb[b].resize(FT[b].rows(), FT[b].cols());
    v[b].resize(FT[b].cols());
  }
  Eigen::Matrix<double, 9, Eigen::Dynamic> Wc(9, inputs.size());  // Σ over an input's blocks of c_b M_bn
  Eigen::MatrixXd PhiT = Eigen::MatrixXd::Zero(n, 9);
  PhiT.topRows<9>().setIdentity();
  Eigen::MatrixXd QdT = Eigen::MatrixXd::Zero(n, 9);
  QdT.topRows<9>() = Qn * T;
  Eigen::MatrixXd Pt = PhiT, Mt = QdT, tmp(n, 9);
  // tmp rows of block b += rᵀ (T g_b)ᵀ for a row r of the block's size.
  auto addOuter = [&tmp, T](const InputBlock& B, const Eigen::RowVectorXd& r) {
    for (int j = 0; j < 9; ++j) {
      const double gj = T * B.g[j];
      for (Eigen::Index q = 0; q < r.size(); ++q) tmp(B.column + q, j) += r[q] * gj;
    }
  };
  constexpr int kMaxTerms = 40;
  constexpr double kTol = 0x1p-53;  // as discretize: a term below half an ulp of the largest entry
  double boundPhi = 1.0, boundQ = QdT.lpNorm<Eigen::Infinity>();
  for (int k = 1; k <= kMaxTerms; ++k) {
    // Φ: [n] A T Φ_n, [b] A T Φ_b + T g_b c_b (F_b T)^(k−1)/(k−1)!, over k.
    tmp.setZero();
    for (int z = 0; z < nnz; ++z) tmp.col(nz[z].i) += nz[z].v * Pt.col(nz[z].j);
    for (Scalar& b : scalars) {
      const double cp = b.c * b.p;
      for (int j = 0; j < 9; ++j) tmp(b.column, j) += cp * inputs[b.input][j];
      b.p *= b.f / double(k);
    }
    for (std::size_t b = 0; b < nb; ++b) {
      v[b].noalias() = general[b]->c * Pb[b];
      addOuter(*general[b], v[b]);
      Sb[b].noalias() = FT[b] * Pb[b];
      Pb[b] = Sb[b] * (1.0 / double(k));
    }
    Pt = tmp * (1.0 / double(k));
    // M: [nn] X + Xᵀ, X = A T M_nn + Σ T g_b c_b M_bn; [nb] A T M_nb + T g_b c_b M_bb + M_nb (F_b T)ᵀ.
    tmp.setZero();
    for (int z = 0; z < nnz; ++z) tmp.col(nz[z].i) += nz[z].v * Mt.col(nz[z].j);
    Wc.setZero();
    for (Scalar& b : scalars) {
      const double cm = b.c * b.m;
      for (int j = 0; j < 9; ++j) {
        Wc(j, b.input) += b.c * Mt(b.column, j);
        tmp(b.column, j) += cm * inputs[b.input][j] + b.f * Mt(b.column, j);
      }
      b.m *= 2.0 * b.f / double(k + 1);
    }
    for (std::size_t b = 0; b < nb; ++b) {
      const InputBlock& B = *general[b];
      const Eigen::Index s = B.c.size();
      for (int j = 0; j < 9; ++j)
        for (Eigen::Index q = 0; q < s; ++q) Wc(j, generalInput[b]) += B.c[q] * Mt(B.column + q, j);
      v[b].noalias() = B.c * Mb[b];
      addOuter(B, v[b]);
      tmp.middleRows(B.column, s).noalias() += FT[b] * Mt.middleRows(B.column, s);
      Sb[b].noalias() = FT[b] * Mb[b];
      Mb[b] = (Sb[b] + Sb[b].transpose()) * (1.0 / double(k + 1));
    }
    for (std::size_t i = 0; i < inputs.size(); ++i)  // Σ_b (c_b M_bn)ᵀ (T g_b)ᵀ
      tmp.topRows<9>().noalias() += Wc.col(i) * inputs[i].transpose();
    const Eigen::Matrix<double, 9, 9> X = tmp.topRows<9>();
    tmp.topRows<9>() = X + X.transpose();
    Mt = tmp * (1.0 / double(k + 1));
    PhiT += Pt;
    QdT += Mt;
    const double termPhi = Pt.lpNorm<Eigen::Infinity>(), termQ = Mt.lpNorm<Eigen::Infinity>();
    boundPhi += termPhi;
    boundQ += termQ;
    if (termPhi > kTol * boundPhi || termQ > kTol * boundQ) continue;
    if (termPhi <= kTol * PhiT.lpNorm<Eigen::Infinity>() &&
        termQ <= kTol * QdT.lpNorm<Eigen::Infinity>()) {
      PhiN = PhiT.transpose();
      QdN = QdT.transpose();
      return true;
    }
  }
  return false;
}

}  // namespace sinsim::sim::aided
