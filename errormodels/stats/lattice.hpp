// The value lattice of a recorded series: the step its values move by when an output register's
// LSB (or a CSV's printing precision) rounds them. The diagnosis' quantization candidates and the
// fit's choice of how a quantization term is realised both read it.
#pragma once

#include <vector>

namespace sinsim::errormodels {

/// Lattice of values: step q [SI] when the record's increments are integer multiples of one
/// step (>= 99 % of >= 10 non-zero differences within 1 % of a multiple); 0 otherwise.
double latticeStep(const std::vector<double>& y);

/// The scatter of y's overlapping Allan variance at one sample, sqrt(3 / N) AVAR(1) as for white
/// noise [SI^2]: a rounding whose nominal variance there is below it is no effect any statistic of
/// the record can see.
double oneSampleAvarScatter(const std::vector<double>& y);

/// Whether the rounding onto a value lattice of step q [SI] (latticeStep) could be seen in y at
/// all: its nominal Allan variance at one sample -- q^2 / 12 with each sample rounded, q^2 / 4 with
/// the remainder carried (an increment output) -- above oneSampleAvarScatter(y). A CSV's printing
/// precision is no quantization; a lattice the diagnosis can see is one the fit writes.
bool latticeVisible(const std::vector<double>& y, double q, bool carried = false);

}  // namespace sinsim::errormodels
