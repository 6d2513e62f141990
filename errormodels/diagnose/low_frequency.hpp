// The record's longest scales, beyond the Allan grid's T/10, as evidence in the selection.
//
// A random walk the model lacks lifts the Allan variance most at the longest tau, where the
// octave curve (up to ~T/10) has few points and little weight; at T/2-T/4 its share over a white
// base is 10-25x larger than at T/10. The record is projected on a few slow cosines made
// orthogonal to what a slow deterministic effect would put there (a constant, a line, settling
// exponentials, the temperature and its square); each coefficient is Gaussian with the variance
// the current model predicts for it (the Monte Carlo realisations' mean square, plus each
// accepted noise's from its Allan term), and a candidate is credited with the likelihood gain of
// the coefficients when its variance is added: a walk (variance ~ 1/k^2 over the cosines) and a
// slow Gauss-Markov or telegraph (flat below its corner) are told apart by the same data.
#pragma once

#include <cstddef>
#include <vector>

namespace sinsim::errormodels::diagnose::detail {

/// Slow cosines on a grid of block sums, orthonormal (in the samples' inner product) and
/// orthogonal to the nuisance shapes. Empty when the record is too short.
struct LowFrequencyBasis {
  std::size_t block = 0;                // samples per block (the last block may be shorter)
  std::vector<double> count;            // samples in each block
  std::vector<std::vector<double>> u;   // per direction, its value in each block
  std::vector<double> k;                // the cosine index each direction stems from
};

/// The basis for n samples; the temperature per sample (empty: none) adds T and T^2 to the
/// nuisance shapes.
LowFrequencyBasis lowFrequencyBasis(std::size_t n, const std::vector<double>& temperature);

/// The coefficients of y on the basis (sum over samples of u(t) y(t)) [SI].
std::vector<double> lowFrequencyCoefficients(const std::vector<double>& y, const LowFrequencyBasis& b);

/// An Allan term g on the tau grid [s] at t [s]: log-log between the grid points around t, carried
/// beyond the grid along its last two points' slope (clamped to [-1, 2], white to ramp-like;
/// slope 1 where a point is not positive); 0 when the last point is not positive.
double allanTermAt(const std::vector<double>& g, const std::vector<double>& tau, double t);

/// The variance of the coefficient on direction k (cosine index, half-period T/k) that a noise of
/// AVAR g on the tau grid [s] makes [SI^2]: (12/pi^2) (tau_k/dt) g(tau_k) at tau_k = T/(2k)
/// (allanTermAt). Exact for a random
/// walk's plain cosine, 12/pi^2 = 1.22x for white noise; the projection on the nuisance shapes
/// only lowers the true value: on the high side.
double lowFrequencyVarianceOf(const std::vector<double>& g, const std::vector<double>& tau, double T,
                              double dt, double k);

/// A shape x on the record's cosines u_k(t) = sqrt(2/N) cos(pi k (t + 1/2) / N), k = 1..K
/// (orthonormal in the samples' inner product): a2[k-1] = (u_k . x)^2 for x without its mean,
/// computed on block sums (the cosines vary little within one of at least 8 blocks per period),
/// its squared norm x'x, and the part of x'x beyond the K cosines (tail).
struct CosineSpectrum {
  std::vector<double> a, a2;  // u_k . x and its square
  double norm2 = 0, tail = 0;
};
CosineSpectrum cosineSpectrum(const std::vector<double>& x, std::size_t maxCosines = 512);

/// Variance [SI^2 / x^2] of the least-squares coefficient of a series on x (x'y / x'x, x without
/// its mean) under a noise of AVAR g on the tau grid [s] [SI^2]: sum_k a2_k v_k + tail v_K over
/// (x'x)^2, v_k = lowFrequencyVarianceOf(g, tau, T, dt, k) (a noise's v_k do not rise with k).
/// Exact for a random walk (its cosine coefficients are uncorrelated: the sines on dW are
/// orthogonal, and v_k is its exact cosine variance), 12/pi^2 = 1.22x for white noise; the cross
/// terms of a stationary noise's cosine coefficients are neglected.
double coefficientVarianceOf(const CosineSpectrum& s, const std::vector<double>& g, const std::vector<double>& tau,
                             double T, double dt);

/// (12/pi^2) (tau_k/dt) AVAR(tau_k) over the true cosine variance S(f_k)/(2 dt), f_k = 1/(4 tau_k),
/// for a power-law noise of AVAR ~ tau^mu: 12/pi^2 for white noise (mu = -1), 12 ln 2 / pi^2 =
/// 0.84 for flicker (mu = 0), 1 for a walk (mu = 1); mu clamped to [-1, 1] (beyond, the ratio
/// grows: held at the ends, the variance it gives is on the high side).
double powerLawCosineRatio(double mu);

/// The variance of the cosine of index k under a noise of AVAR g on the tau grid [SI^2]:
/// lowFrequencyVarianceOf over powerLawCosineRatio at g's log-log slope around tau_k (exact for a
/// power law, where lowFrequencyVarianceOf is 0.84-1.22x of it).
double cosineVarianceOf(const std::vector<double>& g, const std::vector<double>& tau, double T, double dt, double k);

/// The generalised least-squares test of a series y on a shape x under the current model, on
/// their cosines k = 1..K (cosineSpectrum of both): the cosine coefficients of a noise are nearly
/// uncorrelated (exactly for a walk) with variance v_k (cosineVarianceOf), so the coefficient
/// sum_k x_k y_k / v_k over sum_k x_k^2 / v_k has variance 1 / sum_k x_k^2 / v_k, and
/// t = |sum_k x_k y_k / v_k| / sqrt(sum_k x_k^2 / v_k). Against a red noise it weighs the cosines
/// where the noise is small: a settling of T/20 on a walk is seen ~3x better than by least
/// squares. The part of x beyond K cosines is left out (on the safe side). The model's AVAR on the
/// tau grid [s] [SI^2] is in two parts: one estimated (the base from `realisations` Monte Carlo
/// realisations, a noise fitted to the record) and one known in closed form. An Allan variance at
/// tau_k = T/(2k) stands for the cosines of its octave, 2^j <= k < 2^(j+1), with ~2^j degrees of
/// freedom per series; so t's dof is Satterthwaite's (1946) over the octaves' shares of the
/// coefficient's variance, the estimated part's with realisations x 2^j dof each, the known
/// part's exact (a line's information, at k = 1, gets the realisations' dof: the trend test's).
/// t = 0 when the model's AVAR is not positive.
struct GlsTest {
  double t = 0, dof = 0;
};
GlsTest glsTestOf(const CosineSpectrum& x, const CosineSpectrum& y, const std::vector<double>& estimated,
                  const std::vector<double>& known, double realisations, const std::vector<double>& tau, double T,
                  double dt);

/// -2 ln L of the coefficients c under variances var [SI^2] (up to a constant), each variance the
/// mean square of `dof` realisations: the scaled Student t's, sum over directions of
/// (dof + 1) ln(1 + c^2 / (dof var)) + ln var (Gaussian, c^2/var + ln var, for dof -> infinity).
/// Its decrease when a candidate's variance is added is what the longest scales say for it.
double lowFrequencyNll(const std::vector<double>& c, const std::vector<double>& var, double dof);

}  // namespace sinsim::errormodels::diagnose::detail
