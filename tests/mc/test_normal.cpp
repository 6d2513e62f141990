// The ziggurat normals the Monte Carlo engine lives on (errormodels/random.cpp): the distribution
// against Φ, including the wedges and the tail beyond r = 3.654 that the fast path never produces;
// the vector fast path against the algorithm taken one word at a time.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include <Random123/philox.h>

#include <cstdint>
#include <cstring>

#include "errormodels/random.hpp"
#include "errormodels/ziggurat.hpp"
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

namespace {

// The ziggurat as the documentation states it, one word at a time (random.hpp, ziggurat.hpp):
// block b of stream (seed, run, id) reads the words of Philox4x64-10 calls j = 0, 1, ... on
// counter {b, id, j, 0} with key {seed, run}, in order. The vector fast path must give these bits.
std::vector<double> referenceBlock(std::uint64_t seed, std::uint64_t run, std::uint64_t id,
                                   std::uint64_t block, long* wordsUsed) {
  const auto& T = sinsim::errormodels::zigguratTables();
  r123::Philox4x64 gen;
  const r123::Philox4x64::key_type key = {{seed, run}};
  std::uint64_t k = 0;
  auto word = [&]() {
    const r123::Philox4x64::ctr_type r = gen({{block, id, k / 4, 0}}, key);
    return r.v[k++ % 4];
  };
  auto uniform = [](std::uint64_t u) { return double(u >> 12) * 0x1p-52; };  // exact: 52 bits
  auto sign = [](double x, std::uint64_t u) { return (u & 0x100) ? -x : x; };
  std::vector<double> out;
  while (out.size() < std::size_t(NormalStream::kBlock)) {
    const std::uint64_t u = word();
    const unsigned i = unsigned(u & 0xff);
    const double x = uniform(u) * T.x[i];
    if (x < T.x[i + 1]) {
      out.push_back(sign(x, u));
    } else if (i == 0) {
      double xt, yt;
      do {
        xt = -std::log(1.0 - uniform(word())) / 3.6541528853610088;
        yt = -std::log(1.0 - uniform(word()));
      } while (yt + yt < xt * xt);
      out.push_back(sign(3.6541528853610088 + xt, u));
    } else if (T.f[i] + uniform(word()) * (T.f[i + 1] - T.f[i]) < std::exp(-0.5 * x * x)) {
      out.push_back(sign(x, u));
    }
  }
  *wordsUsed = long(k);
  return out;
}

}  // namespace

TEST_CASE("ziggurat normals: the vector fast path gives the one-word-at-a-time algorithm's bits") {
  using sinsim::errormodels::ZigguratKernel;
  // Every kernel this CPU has gives the scalar kernel's candidates, on Philox words and on words
  // that sweep every layer with both signs and the extreme mantissas.
  r123::Philox4x64 gen;
  std::vector<std::uint64_t> w(64);
  int kernelsChecked = 0;
  for (ZigguratKernel k : {ZigguratKernel::avx2, ZigguratKernel::avx512}) {
    if (!sinsim::errormodels::zigguratKernelAvailable(k)) continue;
    ++kernelsChecked;
    for (int b = 0; b < 20000; ++b) {
      for (int j = 0; j < 16; ++j) {
        const auto r = gen({{std::uint64_t(b), 7, std::uint64_t(j), 0}}, {{3, 4}});
        for (int q = 0; q < 4; ++q) w[4 * j + q] = r.v[q];
      }
      if (b < 16)  // layer 16 b .. 16 b + 15 four times: sign and mantissa all zero / all one
        for (int q = 0; q < 64; ++q)
          w[q] = std::uint64_t(16 * b + q % 16) | (q & 16 ? 0x100u : 0u) |
                 (q & 32 ? ~std::uint64_t(0) << 12 : 0u);
      double c0[64], c1[64];
      const std::uint64_t ok0 =
          sinsim::errormodels::zigguratCandidates(w.data(), c0, ZigguratKernel::scalar);
      const std::uint64_t ok1 = sinsim::errormodels::zigguratCandidates(w.data(), c1, k);
      REQUIRE(std::memcmp(c0, c1, sizeof c0) == 0);
      REQUIRE(ok0 == ok1);
    }
  }
  INFO("vector kernels on this CPU: " << kernelsChecked);
  // The stream against the reference, block by block, over many streams: the blocks whose
  // rejections need words beyond the 64 made at once, and the tail, must be among them.
  long beyond = 0, tails = 0, blocks = 0;
  for (std::uint64_t id = 0; id < 40; ++id) {
    NormalStream s(9, 2, id * 0x10001);
    for (std::uint64_t b = 0; b < 400; ++b, ++blocks) {
      long used = 0;
      const std::vector<double> ref = referenceBlock(9, 2, id * 0x10001, b, &used);
      beyond += used > 64;
      for (double x : ref) {
        tails += std::abs(x) > 3.6541528853610088;
        const double y = s.next();
        REQUIRE(std::memcmp(&x, &y, sizeof x) == 0);
      }
    }
  }
  INFO(blocks << " blocks, " << beyond << " needing more than 64 words, " << tails << " tail draws");
  CHECK(beyond > 1000);  // a block needs more than 64 words whenever it rejects (~60 %)
  CHECK(tails > 0);      // P(tail) = 2.6e-4 per draw: ~270 expected in 1.02 M
}
