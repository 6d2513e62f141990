// Whiteness of an AR model's one-step prediction residuals on the record (Ljung & Box 1978).
#pragma once

#include <cstddef>
#include <vector>

#include "errormodels/diagnose/diagnose.hpp"

namespace sinsim::errormodels::diagnose::detail {

/// Q = N (N+2) sum_{k=1..h} r_k^2 / (N - k) of the residuals e_n = sum_i a_i (y_{n-i} - mean),
/// a = [1, a1..ap]; chi-square with h - p dof.
LjungBox ljungBox(const std::vector<double>& y, const std::vector<double>& a, std::size_t h);

}  // namespace sinsim::errormodels::diagnose::detail
