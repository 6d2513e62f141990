// The Gauss-Markov Allan variance (errormodels/gm_process.hpp, the one home) against published
// properties: the deviation peaks at 0.618 sigma at tau = 1.89 T (the values quoted with the
// IEEE Std 952-1997 Annex C form), tends to 2 s2 T / tau for tau >> T and to 2 s2 tau / (3 T)
// for tau << T (Taylor series of the closed form, which it uses below tau = 0.1 T), continuously
// across that switch.
#include <catch2/catch.hpp>

#include <cmath>

#include "errormodels/gm_process.hpp"

using sinsim::errormodels::gaussMarkovAllanVariance;

TEST_CASE("Gauss-Markov Allan variance: peak, both asymptotes, series seam", "[gm][allan]") {
  const double s2 = 4.0, T = 50.0;  // sigma = 2, T = 50 s
  // Peak: scan tau on a fine log grid; published to 3 digits, so 2e-3 relative.
  double best = 0, tauBest = 0;
  for (int i = 0; i <= 4000; ++i) {
    const double tau = T * std::pow(10.0, -1.0 + 2.0 * i / 4000.0);
    const double adev = std::sqrt(gaussMarkovAllanVariance(s2, T, tau));
    if (adev > best) best = adev, tauBest = tau;
  }
  CHECK(best / std::sqrt(s2) == Approx(0.618).epsilon(2e-3));
  CHECK(tauBest / T == Approx(1.89).epsilon(3e-3));
  // tau >> T: 2 s2 T / tau (1 - 3 T / (2 tau)) to first order; at tau = 1e4 T the relative
  // correction is 1.5e-4, so 2e-4 separates it from a wrong factor.
  CHECK(gaussMarkovAllanVariance(s2, T, 1e4 * T) == Approx(2 * s2 / 1e4).epsilon(2e-4));
  // tau << T: AVAR / s2 = 2x/3 - x^2/2 + 7x^3/30 - x^4/12 + ... (the closed form's Taylor series;
  // the function switches to it below x = 0.1, where the closed form loses ~1e-16 / x^3). At
  // x = 1e-4 three terms leave x^4/12 / (2x/3) = 1.3e-13 relative; across the switch the two forms
  // meet to the closed form's rounding there (~1e-13).
  const double x = 1e-4;
  CHECK(gaussMarkovAllanVariance(s2, T, x * T) == Approx(s2 * (2 * x / 3 - x * x / 2 + 7 * x * x * x / 30)).epsilon(1e-12));
  const double below = gaussMarkovAllanVariance(s2, T, 0.1 * (1 - 1e-15) * T);
  const double above = gaussMarkovAllanVariance(s2, T, 0.1 * T);
  CHECK(above == Approx(below).epsilon(1e-12));
  CHECK(gaussMarkovAllanVariance(s2, T, 1e-3 * T) == Approx(2 * s2 * 1e-3 / 3).epsilon(1e-3));
}
