// The value lattice of a recorded series: the step its values move by when an output register's
// LSB (or a CSV's printing precision) rounds them. The diagnosis' quantization candidates and the
// fit's choice of how a quantization term is realised both read it.
#pragma once

#include <vector>

namespace sinsim::errormodels {

/// Lattice of values: step q [SI] when the record's increments are integer multiples of one
/// step (>= 99 % of >= 10 non-zero differences within 1 % of a multiple); 0 otherwise.
double latticeStep(const std::vector<double>& y);

}  // namespace sinsim::errormodels
