#include "sim/aided/kalman.hpp"

#include <Eigen/Cholesky>

#include "common/error.hpp"
#include "sim/aided/wide_kernel.hpp"

namespace sinsim::sim::aided {

namespace {

// P ← ½ (P + Pᵀ), in place.
void symmetrize(Eigen::MatrixXd& P) {
  const Eigen::Index n = P.rows();
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index i = j + 1; i < n; ++i) P(i, j) = P(j, i) = 0.5 * (P(i, j) + P(j, i));
}

// W entries of out.col(j) from row r on: each sum over c in ascending order, from +0 (or from the
// entry itself when accumulating), kept in registers across the inner dimension.
template <int W>
inline void transposedBlock(const double* __restrict U, Eigen::Index rows, const double* v,
                            Eigen::Index vStride, Eigen::Index inner, Eigen::Index r,
                            double* __restrict o, bool accumulate) {
  double s[W];
  for (int q = 0; q < W; ++q) s[q] = accumulate ? o[r + q] : 0.0;
  for (Eigen::Index c = 0; c < inner; ++c) {
    const double vc = v[c * vStride];
    const double* __restrict u = U + c * rows + r;
    for (int q = 0; q < W; ++q) s[q] += u[q] * vc;
  }
  for (int q = 0; q < W; ++q) o[r + q] = s[q];
}

// out ← Σ_c U.col(c) V(j, c) per column j of out (out = U Vᵀ, or += with accumulate): the
// update's products are thin (m columns of U against a few dozen rows), so each output column is
// summed down U's contiguous columns — no packing, no blocking — eight, four or two entries at a time
// in registers (the same additions in the same order as one axpy per column of U, without storing
// and reloading the column of out between them).
SINSIM_WIDE_KERNEL
void multiplyTransposed(const double* __restrict U, Eigen::Index rows,
                        const Eigen::Ref<const Eigen::MatrixXd>& V,
                        Eigen::Index cols, double* __restrict out, Eigen::Index ld,
                        bool accumulate) {
  const Eigen::Index inner = V.cols(), vStride = V.outerStride();
  for (Eigen::Index j = 0; j < cols; ++j) {
    double* __restrict o = out + j * ld;
    const double* v = V.data() + j;
    Eigen::Index r = 0;
    for (; r + 8 <= rows; r += 8) transposedBlock<8>(U, rows, v, vStride, inner, r, o, accumulate);
    for (; r + 4 <= rows; r += 4) transposedBlock<4>(U, rows, v, vStride, inner, r, o, accumulate);
    for (; r + 2 <= rows; r += 2) transposedBlock<2>(U, rows, v, vStride, inner, r, o, accumulate);
    for (; r < rows; ++r) transposedBlock<1>(U, rows, v, vStride, inner, r, o, accumulate);
  }
}

}  // namespace

void kalmanPredict(Eigen::VectorXd& x, Eigen::MatrixXd& P, const Eigen::MatrixXd& Phi,
                   const Eigen::MatrixXd& Qd) {
  x = Phi * x;
  P = Phi * P * Phi.transpose() + Qd;
  symmetrize(P);
}


void kalmanPredict(Eigen::VectorXd& x, Eigen::MatrixXd& P, const BlockTransition& Phi,
                   const Eigen::MatrixXd& Qd) {
  // P is symmetric, so Φ P Φᵀ follows from YT = P Φ_navᵀ (n × 9, thin products down P's
  // columns): [nn] Φ_nav YT, [sn] Φ_s YT_s, [ss] Φ_s P_ss Φ_sᵀ with Φ_s block diagonal — 9 n² + 81 n
  // multiplications instead of the 18 n² of Φ_nav P and (Φ P) Φ_navᵀ.
  const Eigen::Index n = P.rows(), ns = n - 9;
  Eigen::MatrixXd YT(n, 9);
  multiplyTransposed(P.data(), n, Phi.nav, 9, YT.data(), n, false);
  const Eigen::MatrixXd YTt = YT.transpose();
  Eigen::Matrix<double, 9, 9> Pnn;  // Φ_nav YT
  multiplyTransposed(Phi.nav.data(), 9, YTt, 9, Pnn.data(), 9, false);
  Eigen::VectorXd xn(n);
  xn.head<9>().noalias() = Phi.nav * x;
  for (std::size_t b = 0; b < Phi.block.size(); ++b) {
    const Eigen::Index o = Phi.offset[b], s = Phi.block[b].rows();
    if (s == 1) {  // one-state blocks (most): a scale, without a product's dispatch
      const double f = Phi.block[b](0, 0);
      xn[o] = f * x[o];
      YT.row(o) *= f;
      P.row(o).tail(ns) *= f;
      P.col(o).tail(ns) *= f;
      continue;
    }
    const Eigen::MatrixXd& F = Phi.block[b];
    xn.segment(o, s).noalias() = F * x.segment(o, s);
    YT.middleRows(o, s) = (F * YT.middleRows(o, s)).eval();
    P.block(o, 9, s, ns) = (F * P.block(o, 9, s, ns)).eval();
    P.block(9, o, ns, s) = (P.block(9, o, ns, s) * F.transpose()).eval();
  }
  x = xn;
  P.topLeftCorner<9, 9>() = Pnn;
  P.bottomLeftCorner(ns, 9) = YT.bottomRows(ns);
  P.topRightCorner(9, ns) = YT.bottomRows(ns).transpose();
  P += Qd;
  symmetrize(P);
}

Innovation kalmanUpdate(Eigen::VectorXd& x, Eigen::MatrixXd& P, const Eigen::VectorXd& z,
                        const Eigen::MatrixXd& H, const Eigen::MatrixXd& R) {
  // H's columns after its last non-zero one add nothing: P Hᵀ runs over the first k states (a
  // GNSS fix sees the 9 navigation errors only); the rank-m corrections by thin products.
  const Eigen::Index n = P.rows(), m = H.rows();
  Eigen::Index k = H.cols();
  while (k > 0 && H.col(k - 1).isZero(0.0)) --k;
  const Eigen::MatrixXd Hk = H.leftCols(k);
  Innovation in;
  in.nu = z - Hk * x.head(k);
  Eigen::MatrixXd PHt(n, m);  // P Hᵀ = Σ_c P.col(c) H(:, c)ᵀ over c < k
  multiplyTransposed(P.data(), n, Hk, m, PHt.data(), n, false);
  in.S = Hk * PHt.topRows(k) + R;  // H P Hᵀ + R
  const Eigen::LLT<Eigen::MatrixXd> llt(in.S);
  if (llt.info() != Eigen::Success)
    throw InputError("Kalman update: innovation covariance is not positive definite");
  const Eigen::MatrixXd K = llt.solve(PHt.transpose()).transpose();  // P Hᵀ S⁻¹
  in.nis = in.nu.dot(llt.solve(in.nu));
  x += K * in.nu;
  // A = (I − K H) P = P − K (P Hᵀ)ᵀ; then A (I − K H)ᵀ + K R Kᵀ = A + (K R − A Hᵀ) Kᵀ.
  const Eigen::MatrixXd minusPHt = -PHt;
  multiplyTransposed(K.data(), n, minusPHt, n, P.data(), n, true);
  Eigen::MatrixXd W = K * R;  // K R − A Hᵀ
  Eigen::MatrixXd AHt(n, m);
  multiplyTransposed(P.data(), n, Hk, m, AHt.data(), n, false);
  W -= AHt;
  multiplyTransposed(W.data(), n, K, n, P.data(), n, true);
  symmetrize(P);
  return in;
}

}  // namespace sinsim::sim::aided
