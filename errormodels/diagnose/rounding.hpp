// What rounding to a value lattice does to a Gaussian signal's variance when the lattice is not
// fine: the exact moments of q round(x / q) for x ~ N(mu, sigma^2), and the white variance the
// rounding adds to a record's short scales given its local levels (the quantization candidate).
#pragma once

#include <vector>

namespace sinsim::errormodels::diagnose::detail {

/// Mean and variance of q round((mu + sigma Z) / q), Z standard normal [SI], [SI^2]; sigma > 0,
/// q > 0. The variance tends to sigma^2 + q^2/12 (Sheppard) once sigma >> q, the deviation
/// falling as exp(-2 pi^2 sigma^2 / q^2) (Widrow & Kollar 2008, ch. 4); for sigma < q/2 it
/// depends on where mu sits in its cell and may be far below either.
struct RoundedMoments {
  double mean = 0, var = 0;
};
RoundedMoments roundedMoments(double mu, double sigma, double q);

/// The level mu [SI] within a cell of `mean` whose rounded mean (roundedMoments, lattice points at
/// integers x q) is `mean`, for input sd sigma: where a Gaussian input must sit for its rounding to
/// average what a record rounded on that lattice averages.
double levelOfRoundedMean(double mean, double sigma, double q);

/// The white variance [SI^2] that rounding to the lattice q (a point of it: y[0]) adds to the
/// short scales of the record y (samples on that lattice): v - sigma^2, v the mean variance of y
/// within blocks of `block` samples, sigma the one-sample sd of the Gaussian input (one for the
/// record) whose rounded variance, at each block's level mu_b (the mu whose rounded mean is the
/// block's mean), averages v. q^2/12 when v >= 1.1 q^2 (then sigma >= q, where the exact value
/// differs from q^2/12 by < 1e-8 of it); negative where rounding hides the noise (sigma < q/2,
/// the levels near the cells' centres).
double roundingAddedVariance(const std::vector<double>& y, double q, std::size_t block = 32);

}  // namespace sinsim::errormodels::diagnose::detail
