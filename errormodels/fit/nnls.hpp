// Non-negative least squares: min ||A x - b||_2 subject to x >= 0, by the active-set method of
// Lawson & Hanson (Solving Least Squares Problems, 1974, ch. 23, algorithm NNLS). Meant for the
// small, badly scaled problems of Allan-term fitting: columns are scaled to unit norm inside.
#pragma once

#include <Eigen/Dense>

namespace sinsim::errormodels::fit {

struct NnlsResult {
  Eigen::VectorXd x;
  Eigen::Array<bool, Eigen::Dynamic, 1> free;  ///< x_j > 0 (passive set)
  int iterations = 0;
};

/// Throws NumericalError if the iteration limit (3 n + 30 outer steps) is exceeded.
NnlsResult nnls(const Eigen::MatrixXd& A, const Eigen::VectorXd& b);

}  // namespace sinsim::errormodels::fit
