// The ziggurat normals the Monte Carlo engine lives on (errormodels/random.cpp): the distribution
// against Φ, including the wedges and the tail beyond r = 3.654 that the fast path never produces.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "errormodels/random.hpp"
#include "errormodels/stats/special.hpp"

using sinsim::errormodels::NormalStream;

TEST_CASE("ziggurat normals: chi2 goodness of fit against the normal law, moments, tails") {
  const long n = 10'000'000;
  // Bins: edges every 0.25 from −4.5 to 4.5 plus the two open tails (38 bins); probabilities from
  // Φ(x) = erfc(−x/√2)/2. Fine bins near 3.654 = r check the seam between wedge and tail.
  std::vector<double> edges;
  for (int k = -18; k <= 18; ++k) edges.push_back(0.25 * k);
  std::vector<long> count(edges.size() + 1, 0);
  double s1 = 0, s2 = 0, s4 = 0;
  long beyondR = 0;
  NormalStream s(11, 22, 33);
  for (long i = 0; i < n; ++i) {
    const double x = s.next();
    s1 += x;
    s2 += x * x;
    s4 += x * x * x * x;
    beyondR += std::abs(x) > 3.6541528853610088 ? 1 : 0;
    const auto b = std::upper_bound(edges.begin(), edges.end(), x) - edges.begin();
    ++count[std::size_t(b)];
  }
  auto Phi = [](double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); };
  double chi2 = 0;
  for (std::size_t b = 0; b < count.size(); ++b) {
    const double lo = b == 0 ? 0.0 : Phi(edges[b - 1]);
    const double hi = b == edges.size() ? 1.0 : Phi(edges[b]);
    const double e = double(n) * (hi - lo);
    chi2 += (double(count[b]) - e) * (double(count[b]) - e) / e;
  }
  const double dof = double(count.size() - 1);
  const double bound = sinsim::errormodels::chiSquareQuantile(0.999, dof);  // 0.1 % false alarm
  INFO("chi2 = " << chi2 << " with " << dof << " dof, 99.9 % bound " << bound);
  CHECK(chi2 < bound);
  // Moments: sd of the mean 1/√n, of the variance √(2/n), of the 4th moment √(96/n) (E x⁸ − 9 = 96).
  const double m = s1 / n, var = s2 / n - m * m, k4 = s4 / n;
  CHECK(std::abs(m) < 5 / std::sqrt(double(n)));
  CHECK(std::abs(var - 1) < 5 * std::sqrt(2.0 / n));
  CHECK(std::abs(k4 - 3) < 5 * std::sqrt(96.0 / n));
  // The tail beyond r: P = erfc(r/√2) = 2.58e-4; binomial count within 5 sd.
  const double p = std::erfc(3.6541528853610088 / std::sqrt(2.0));
  CHECK(std::abs(double(beyondR) - n * p) < 5 * std::sqrt(n * p));
}
