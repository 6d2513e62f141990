#include "sim/aided/block_series.hpp"

#include <algorithm>
#include <cmath>

#include "sim/aided/wide_kernel.hpp"

namespace sinsim::sim::aided {
namespace {

// The non-zeros of A T by rows, each row's in ascending column order.
struct RowNonZeros {
  int start[10] = {};  // row i's entries are [start[i], start[i + 1])
  int col[81];
  double v[81];
};

// W entries of out.col(i) from row r on (the caller keeps r + W <= rows), see multiplyRows.
template <int W>
inline void multiplyRowBlock(const RowNonZeros& a, const double* src, Eigen::Index n, int i,
                             Eigen::Index r, double* o) {
  double s[W];
  for (int q = 0; q < W; ++q) s[q] = 0.0;
  for (int t = a.start[i]; t < a.start[i + 1]; ++t) {
    const double v = a.v[t];
    const double* c = src + a.col[t] * n + r;
    for (int q = 0; q < W; ++q) s[q] += v * c[q];
  }
  for (int q = 0; q < W; ++q) o[r + q] = s[q];
}

// out.col(i) = Σ_j (A T)_ij in.col(j) over the rows of `in` (transposed rows, see below), each
// entry's sum taken from +0 in ascending j: the same additions, in the same order, as adding the
// non-zeros' columns one after another, with up to eight entries at a time kept in registers
// instead of a pass over the output per non-zero.
SINSIM_WIDE_KERNEL
void multiplyRows(const RowNonZeros& a, const Eigen::MatrixXd& in, Eigen::MatrixXd& out) {
  const Eigen::Index n = in.rows();
  const double* src = in.data();
  for (int i = 0; i < 9; ++i) {
    double* o = out.data() + i * n;
    Eigen::Index r = 0;
    for (; r + 8 <= n; r += 8) multiplyRowBlock<8>(a, src, n, i, r, o);
    for (; r + 4 <= n; r += 4) multiplyRowBlock<4>(a, src, n, i, r, o);
    for (; r < n; ++r) multiplyRowBlock<1>(a, src, n, i, r, o);
  }
}

// term ← tmp · scale, sum += term; returns max |term| (one pass instead of three; four running
// maxima, so that the comparisons do not wait on each other).
SINSIM_WIDE_KERNEL
double scaleAndAdd(const Eigen::MatrixXd& tmp, double scale, Eigen::MatrixXd& term,
                   Eigen::MatrixXd& sum) {
  const Eigen::Index size = tmp.size();
  const double* t = tmp.data();
  double* d = term.data();
  double* s = sum.data();
  for (Eigen::Index i = 0; i < size; ++i) {
    d[i] = t[i] * scale;
    s[i] += d[i];
  }
  double m[4] = {0.0, 0.0, 0.0, 0.0};
  Eigen::Index i = 0;
  for (; i + 4 <= size; i += 4)
    for (int q = 0; q < 4; ++q) m[q] = std::max(m[q], std::abs(d[i + q]));
  for (; i < size; ++i) m[0] = std::max(m[0], std::abs(d[i]));
  return std::max(std::max(m[0], m[1]), std::max(m[2], m[3]));
}

// The non-zero entries of an input column T g (a gyro or accelerometer axis drives three of the
// nine INS errors).
struct Support {
  int count = 0;
  int index[9];
};

Support supportOf(const Eigen::Matrix<double, 9, 1>& g) {
  Support s;
  for (int c = 0; c < 9; ++c)
    if (g[c] != 0.0) s.index[s.count++] = c;
  return s;
}

// The navigation block of M's next term: X = tmp[nn] + Σ_i Wc_i (T g_i)ᵀ (in i order), then
// tmp[nn] = X + Xᵀ — by plain loops over the 9 × 9 block of the (rows × 9) work matrix, entry by
// entry the same operations as Eigen's outer products and transpose sum. The entries of a zero
// g_ic are skipped: they would add ±0 to a sum that started from +0 (multiplyRows), which leaves
// it bit for bit unchanged.
void addInputsAndSymmetrize(const Eigen::Matrix<double, 9, Eigen::Dynamic>& Wc,
                            const std::vector<Eigen::Matrix<double, 9, 1>>& inputs,
                            const std::vector<Support>& support, Eigen::MatrixXd& tmp) {
  const Eigen::Index n = tmp.rows();
  double* t = tmp.data();
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const double* w = Wc.data() + 9 * i;
    for (int k = 0; k < support[i].count; ++k) {
      const int c = support[i].index[k];
      const double g = inputs[i][c];
      for (int r = 0; r < 9; ++r) t[c * n + r] += g * w[r];
    }
  }
  double X[9][9];  // X[c][r] = tmp(r, c)
  for (int c = 0; c < 9; ++c)
    for (int r = 0; r < 9; ++r) X[c][r] = t[c * n + r];
  for (int c = 0; c < 9; ++c)
    for (int r = 0; r < 9; ++r) t[c * n + r] = X[c][r] + X[r][c];
}

}  // namespace

bool navigationRowSeries(const Eigen::Matrix<double, 9, 9>& A, const Eigen::Matrix<double, 9, 9>& Qn,
                         const std::vector<InputBlock>& blocks, int n, double T,
                         Eigen::Matrix<double, 9, Eigen::Dynamic>& PhiN,
                         Eigen::Matrix<double, 9, Eigen::Dynamic>& QdN) {
  // Non-finite input: the whole-system path (which reports it).
  if (!(A.allFinite() && Qn.allFinite() && std::isfinite(T))) return false;
  for (const InputBlock& b : blocks)
    if (!(b.g.allFinite() && b.c.allFinite() && b.F.allFinite() && b.Qc.allFinite())) return false;
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

  // The row counts rounded up to a multiple of 4 with zero rows (which stay zero): multiplyRows
  // then works in blocks of 8 and 4 rows without a one-row tail, which costs as much per non-zero
  // of A as a block of 8 (the real rows' sums are the same operations either way).
  const int rowsP = (nP + 3) / 4 * 4, rowsM = (nM + 3) / 4 * 4;
  Eigen::MatrixXd PhiT = Eigen::MatrixXd::Zero(rowsP, 9);
  PhiT.topRows<9>().setIdentity();
  Eigen::MatrixXd QdT = Eigen::MatrixXd::Zero(rowsM, 9);
  QdT.topRows<9>() = Qn * T;
  Eigen::MatrixXd Pt = PhiT, Mt = QdT, tmpP(rowsP, 9), tmpM(rowsM, 9);
  Eigen::Matrix<double, 9, Eigen::Dynamic> Wc(9, inputs.size());  // Σ over an input's blocks of c_b M_bn
  std::vector<Support> support;
  for (const Eigen::Matrix<double, 9, 1>& g : inputs) support.push_back(supportOf(g));
  // out rows [row, row + s) += rᵀ (T g)ᵀ.
  auto addOuter = [](Eigen::MatrixXd& out, int row, const Eigen::Matrix<double, 9, 1>& Tg,
                     const Eigen::RowVectorXd& r) {
    for (int j = 0; j < 9; ++j)
      for (Eigen::Index q = 0; q < r.size(); ++q) out(row + q, j) += r[q] * Tg[j];
  };
  constexpr int kMaxTerms = 40;
  // A term below 2^-40 (9e-13) of the largest entry ends the series. The terms fall by two to
  // three decades each by then (car.yaml, T = 1 s: Qd's 8th, 9th, 10th terms 5e-11, 2e-13, 4e-16
  // of the largest entry), so what is left out is ~1e-15 relative; even a slow fall (ratio 1/2)
  // leaves 2e-12 — six decades below the error of the filter's own linearisation. Half an ulp
  // (discretize's 2^-53) took 11 terms instead of 9 here: 18 % of the filter's series.
  constexpr double kTol = 0x1p-40;
  double boundPhi = 1.0, boundQ = QdT.lpNorm<Eigen::Infinity>();
  for (int k = 1; k <= kMaxTerms; ++k) {
    // Φ: [n] A T Φ_n, [b] A T Φ_b + T g_b c_b (F_b T)^(k−1)/(k−1)!, over k.
    multiplyRows(nz, Pt, tmpP);
    for (Scalar& b : phiScalars) {
      const double cp = b.c * b.term;
      for (int k = 0; k < support[b.input].count; ++k) {  // (zero entries add ±0 to +0 sums)
        const int j = support[b.input].index[k];
        tmpP(b.row, j) += cp * inputs[b.input][j];
      }
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
    addInputsAndSymmetrize(Wc, inputs, support, tmpM);
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
