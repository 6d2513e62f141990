#include "errormodels/fit/nnls.hpp"

#include <limits>
#include <vector>

#include "common/error.hpp"

namespace sinsim::errormodels::fit {

namespace {

// Least squares on the columns flagged in `passive`; other entries 0. The fits call this tens of
// thousands of times on matrices of ~20 x 6: the column block and its QR are kept per thread, so
// that only a change of shape allocates (the same arithmetic as a fresh decomposition).
Eigen::VectorXd solvePassive(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                             const Eigen::Array<bool, Eigen::Dynamic, 1>& passive) {
  const Eigen::Index n = A.cols();
  thread_local std::vector<Eigen::Index> idx;
  thread_local Eigen::MatrixXd Ap;
  thread_local Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr;
  idx.clear();
  for (Eigen::Index j = 0; j < n; ++j)
    if (passive(j)) idx.push_back(j);
  Ap.resize(A.rows(), static_cast<Eigen::Index>(idx.size()));
  for (std::size_t k = 0; k < idx.size(); ++k) Ap.col(static_cast<Eigen::Index>(k)) = A.col(idx[k]);
  qr.compute(Ap);
  const Eigen::VectorXd zp = qr.solve(b);
  Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
  for (std::size_t k = 0; k < idx.size(); ++k) z(idx[k]) = zp(static_cast<Eigen::Index>(k));
  return z;
}

}  // namespace

NnlsResult nnls(const Eigen::MatrixXd& Ain, const Eigen::VectorXd& b) {
  const Eigen::Index n = Ain.cols();
  if (Ain.rows() != b.size()) throw InputError("nnls: A and b sizes differ");
  // Column scaling (x_j >= 0 is invariant under positive scaling).
  Eigen::VectorXd scale(n);
  Eigen::MatrixXd A = Ain;
  for (Eigen::Index j = 0; j < n; ++j) {
    const double c = A.col(j).norm();
    scale(j) = c > 0.0 ? c : 1.0;
    A.col(j) /= scale(j);
  }
  const double tol = 10.0 * std::numeric_limits<double>::epsilon() *
                     static_cast<double>(std::max(A.rows(), n)) * std::max(1.0, b.norm());
  NnlsResult out;
  out.x = Eigen::VectorXd::Zero(n);
  out.free = Eigen::Array<bool, Eigen::Dynamic, 1>::Constant(n, false);
  Eigen::VectorXd w = A.transpose() * (b - A * out.x);
  const int maxOuter = 3 * static_cast<int>(n) + 30;
  while (true) {
    Eigen::Index t = -1;
    double wmax = tol;
    for (Eigen::Index j = 0; j < n; ++j)
      if (!out.free(j) && w(j) > wmax) {
        wmax = w(j);
        t = j;
      }
    if (t < 0) break;
    if (++out.iterations > maxOuter) throw NumericalError("nnls: iteration limit exceeded");
    out.free(t) = true;
    while (true) {
      const Eigen::VectorXd z = solvePassive(A, b, out.free);
      bool allPositive = true;
      for (Eigen::Index j = 0; j < n; ++j)
        if (out.free(j) && z(j) <= 0.0) allPositive = false;
      if (allPositive) {
        out.x = z;
        break;
      }
      // Step from x towards z as far as feasibility allows, then drop the zeroed variables.
      double alpha = std::numeric_limits<double>::infinity();
      Eigen::Index blocking = -1;
      for (Eigen::Index j = 0; j < n; ++j)
        if (out.free(j) && z(j) <= 0.0) {
          const double aj = out.x(j) / (out.x(j) - z(j));
          if (aj < alpha) {
            alpha = aj;
            blocking = j;
          }
        }
      out.x += alpha * (z - out.x);
      out.x(blocking) = 0.0;  // the variable that hit its bound, exactly
      for (Eigen::Index j = 0; j < n; ++j)
        if (out.free(j) && out.x(j) <= 0.0) {
          out.free(j) = false;
          out.x(j) = 0.0;
        }
      if (!out.free.any()) break;
    }
    w = A.transpose() * (b - A * out.x);
  }
  for (Eigen::Index j = 0; j < n; ++j) out.x(j) /= scale(j);
  return out;
}

}  // namespace sinsim::errormodels::fit
