#include "sim/aided/block_series.hpp"

#include <algorithm>
#include <cmath>

namespace sinsim::sim::aided {
namespace {

// The non-zeros of A T by rows, each row's in ascending column order.
struct RowNonZeros {
  int start[10] = {};  // row i's entries are [start[i], start[i + 1])
  int col[81];
  double v[81];
};

// out.col(i) = Σ_j (A T)_ij in.col(j) over the rows of `in` (transposed rows, see below), each
// entry's sum taken from 0 in ascending j: the same additions, in the same order, as adding the
// non-zeros' columns one after another, with four entries at a time kept in registers instead of
// a pass over the output per non-zero.
void multiplyRows(const RowNonZeros& a, const Eigen::MatrixXd& in, Eigen::MatrixXd& out) {
  const Eigen::Index n = in.rows();
  const double* src = in.data();
  for (int i = 0; i < 9; ++i) {
    double* o = out.data() + i * n;
    const int t0 = a.start[i], t1 = a.start[i + 1];
    Eigen::Index r = 0;
    for (; r + 4 <= n; r += 4) {
      double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
      for (int t = t0; t < t1; ++t) {
        const double v = a.v[t];
        const double* c = src + a.col[t] * n + r;
        s0 += v * c[0];
        s1 += v * c[1];
        s2 += v * c[2];
        s3 += v * c[3];
      }
      o[r] = s0;
      o[r + 1] = s1;
      o[r + 2] = s2;
      o[r + 3] = s3;
    }
    for (; r < n; ++r) {
      double s0 = 0.0;
      for (int t = t0; t < t1; ++t) s0 += a.v[t] * src[a.col[t] * n + r];
      o[r] = s0;
    }
  }
}

// term ← tmp · scale, sum += term; returns max |term|, NaN if a term is NaN (one pass instead
// of three).
double scaleAndAdd(const Eigen::MatrixXd& tmp, double scale, Eigen::MatrixXd& term,
                   Eigen::MatrixXd& sum) {
  const Eigen::Index size = tmp.size();
  const double* t = tmp.data();
  double* d = term.data();
  double* s = sum.data();
  double largest = 0.0;
  bool nan = false;
  for (Eigen::Index i = 0; i < size; ++i) {
    d[i] = t[i] * scale;
    s[i] += d[i];
    largest = std::max(largest, std::abs(d[i]));
    nan = nan || std::isnan(d[i]);
  }
  return nan ? NAN : largest;
}

}  // namespace

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
  // The rows are kept transposed (rows × 9), so that row i of A T X is the contiguous column
  // out.col(i) = Σ_j A_ij T · X.col(j).
  RowNonZeros nz;
  int nnz = 0;
  for (int i = 0; i < 9; ++i) {
    nz.start[i] = nnz;
    for (int j = 0; j < 9; ++j)
      if (A(i, j) != 0.0) {
        nz.col[nnz] = j;
        nz.v[nnz++] = A(i, j) * T;
      }
  }
  nz.start[9] = nnz;

  // Rows. A block's navigation-row columns evolve on their own (A acts on each column; the block
  // adds its own term), so only distinct blocks need rows: one-state blocks (bias, random walk,
  // Gauss-Markov) are grouped by (input, c, F) for Φ — a bias and a random walk of one axis have
  // the same Φ column — and by (input, c, F, Qc) for M, where a block without noise (a bias) has
  // no M column at all (M_nb stays 0). Blocks of several states get rows of their own. Columns of
  // no block (the sampled ones, spliced by the filter) get no rows. The groups' M rows enter
  // M_nn through X's Σ g_b c_b M_bn, once per block of the group (mult).
  std::vector<Eigen::Matrix<double, 9, 1>> inputs;  // distinct T g_b
  auto inputOf = [&inputs, T](const Eigen::Matrix<double, 9, 1>& g) {
    for (std::size_t i = 0; i < inputs.size(); ++i)
      if (inputs[i] == T * g) return int(i);
    inputs.push_back(T * g);
    return int(inputs.size()) - 1;
  };
  struct Scalar {
    int input, row, mult;
    double c, f, q, term;  // c_b, F_b T, Qc_b T; the block's own Φ or M term
  };
  struct General {
    const InputBlock* block;
    int input, rowP, rowM;
    Eigen::MatrixXd FT, P, M, S;  // F_b T, its own Φ and M terms, scratch
    Eigen::RowVectorXd v;
  };
  std::vector<Scalar> phiScalars, mScalars;
  std::vector<General> general;
  std::vector<int> rowP(blocks.size()), rowM(blocks.size());  // per block; −1: no M row
  int nP = 9, nM = 9;
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const InputBlock& B = blocks[b];
    const int input = inputOf(B.g);
    if (B.c.size() != 1) continue;
    const double c = B.c[0], f = B.F(0, 0) * T, q = B.Qc(0, 0) * T;
    auto find = [&](std::vector<Scalar>& list, bool withQ) -> Scalar* {
      for (Scalar& s : list)
        if (s.input == input && s.c == c && s.f == f && (!withQ || s.q == q)) return &s;
      return nullptr;
    };
    Scalar* sp = find(phiScalars, false);
    if (!sp) {
      phiScalars.push_back({input, nP++, 1, c, f, q, 1.0});
      sp = &phiScalars.back();
    }
    rowP[b] = sp->row;
    rowM[b] = -1;
    if (q == 0.0) continue;
    Scalar* sm = find(mScalars, true);
    if (sm) {
      ++sm->mult;
    } else {
      mScalars.push_back({input, nM++, 1, c, f, q, q});
      sm = &mScalars.back();
    }
    rowM[b] = sm->row;
  }
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const InputBlock& B = blocks[b];
    const int s = int(B.c.size());
    if (s == 1) continue;
    General g{&B, inputOf(B.g), nP, nM, B.F * T, Eigen::MatrixXd::Identity(s, s), B.Qc * T,
              Eigen::MatrixXd(s, s), Eigen::RowVectorXd(s)};
    rowP[b] = nP;
    rowM[b] = nM;
    nP += s;
    nM += s;
    general.push_back(std::move(g));
  }

  Eigen::MatrixXd PhiT = Eigen::MatrixXd::Zero(nP, 9);
  PhiT.topRows<9>().setIdentity();
  Eigen::MatrixXd QdT = Eigen::MatrixXd::Zero(nM, 9);
  QdT.topRows<9>() = Qn * T;
  Eigen::MatrixXd Pt = PhiT, Mt = QdT, tmpP(nP, 9), tmpM(nM, 9);
  Eigen::Matrix<double, 9, Eigen::Dynamic> Wc(9, inputs.size());  // Σ over an input's blocks of c_b M_bn
  // out rows [row, row + s) += rᵀ (T g)ᵀ.
  auto addOuter = [](Eigen::MatrixXd& out, int row, const Eigen::Matrix<double, 9, 1>& Tg,
                     const Eigen::RowVectorXd& r) {
    for (int j = 0; j < 9; ++j)
      for (Eigen::Index q = 0; q < r.size(); ++q) out(row + q, j) += r[q] * Tg[j];
  };
  constexpr int kMaxTerms = 40;
  constexpr double kTol = 0x1p-53;  // as discretize: a term below half an ulp of the largest entry
  double boundPhi = 1.0, boundQ = QdT.lpNorm<Eigen::Infinity>();
  for (int k = 1; k <= kMaxTerms; ++k) {
    // Φ: [n] A T Φ_n, [b] A T Φ_b + T g_b c_b (F_b T)^(k−1)/(k−1)!, over k.
    multiplyRows(nz, Pt, tmpP);
    for (Scalar& b : phiScalars) {
      const double cp = b.c * b.term;
      for (int j = 0; j < 9; ++j) tmpP(b.row, j) += cp * inputs[b.input][j];
      b.term *= b.f / double(k);
    }
    for (General& g : general) {
      g.v.noalias() = g.block->c * g.P;
      addOuter(tmpP, g.rowP, inputs[g.input], g.v);
      g.S.noalias() = g.FT * g.P;
      g.P = g.S * (1.0 / double(k));
    }
    // M: [nn] X + Xᵀ, X = A T M_nn + Σ T g_b c_b M_bn; [nb] A T M_nb + T g_b c_b M_bb + M_nb (F_b T)ᵀ.
    multiplyRows(nz, Mt, tmpM);
    Wc.setZero();
    for (Scalar& b : mScalars) {
      const double cm = b.c * b.term, mc = double(b.mult) * b.c;
      for (int j = 0; j < 9; ++j) {
        Wc(j, b.input) += mc * Mt(b.row, j);
        tmpM(b.row, j) += cm * inputs[b.input][j] + b.f * Mt(b.row, j);
      }
      b.term *= 2.0 * b.f / double(k + 1);
    }
    for (General& g : general) {
      const Eigen::Index s = g.v.size();
      for (int j = 0; j < 9; ++j)
        for (Eigen::Index q = 0; q < s; ++q) Wc(j, g.input) += g.block->c[q] * Mt(g.rowM + q, j);
      g.v.noalias() = g.block->c * g.M;
      addOuter(tmpM, g.rowM, inputs[g.input], g.v);
      tmpM.middleRows(g.rowM, s).noalias() += g.FT * Mt.middleRows(g.rowM, s);
      g.S.noalias() = g.FT * g.M;
      g.M = (g.S + g.S.transpose()) * (1.0 / double(k + 1));
    }
    for (std::size_t i = 0; i < inputs.size(); ++i)  // Σ_b (c_b M_bn)ᵀ (T g_b)ᵀ
      tmpM.topRows<9>().noalias() += Wc.col(i) * inputs[i].transpose();
    const Eigen::Matrix<double, 9, 9> X = tmpM.topRows<9>();
    tmpM.topRows<9>() = X + X.transpose();
    const double termPhi = scaleAndAdd(tmpP, 1.0 / double(k), Pt, PhiT);
    const double termQ = scaleAndAdd(tmpM, 1.0 / double(k + 1), Mt, QdT);
    boundPhi += termPhi;
    boundQ += termQ;
    if (termPhi > kTol * boundPhi || termQ > kTol * boundQ) continue;
    if (termPhi <= kTol * PhiT.lpNorm<Eigen::Infinity>() &&
        termQ <= kTol * QdT.lpNorm<Eigen::Infinity>()) {
      PhiN.setZero(9, n);
      QdN.setZero(9, n);
      PhiN.leftCols<9>() = PhiT.topRows<9>().transpose();
      QdN.leftCols<9>() = QdT.topRows<9>().transpose();
      for (std::size_t b = 0; b < blocks.size(); ++b) {
        const int o = blocks[b].column, s = int(blocks[b].c.size());
        PhiN.middleCols(o, s) = PhiT.middleRows(rowP[b], s).transpose();
        if (rowM[b] >= 0) QdN.middleCols(o, s) = QdT.middleRows(rowM[b], s).transpose();
      }
      return true;
    }
  }
  return false;
}

}  // namespace sinsim::sim::aided
