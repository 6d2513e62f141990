// Ziggurat normals over Philox output (see random.hpp and ziggurat.hpp).
//
// A block's words are those of Philox calls 0, 1, 2, ... on the counter {block, stream, j, 0},
// taken in order. Each normal takes the next word; a word rejected by the fast path is followed by
// a wedge test y < f(x) with a fresh uniform (the next word) or, for layer 0, by the tail x > r by
// Marsaglia's (1964) method (x = −ln(U1)/r, y = −ln(U2) until 2y > x², return r + x, two words a
// try), and a rejected wedge starts over with the next word. The first kCalls calls' words are
// made at once and their fast-path candidates worked out in one vector pass (ziggurat.cpp); the
// normals are then runs of accepted candidates copied as they are, with the sequential algorithm
// taking over at each rejected word — the same words for the same normals as one at a time.
// Speed: bench_errormodels BM_NormalStream (docs/monte-carlo.md).
#include "errormodels/random.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "errormodels/ziggurat.hpp"

namespace sinsim::errormodels {

namespace {

constexpr int kWords = kZigguratBlockWords;  // made at once, one per normal
constexpr int kCalls = kWords / 4;

}  // namespace

void NormalStream::refill() {
  static_assert(kWords == NormalStream::kBlock, "a block's normals come from the fast path's words");
  const ZigguratTables& T = zigguratTables();
  Philox gen;
  alignas(64) std::uint64_t w[kWords];
  for (int j = 0; j < kCalls; ++j) {
    const Philox::ctr_type c = {{block_, stream_, std::uint64_t(j), 0}};
    const Philox::ctr_type r = gen(c, key_);
    for (int q = 0; q < 4; ++q) w[4 * j + q] = r.v[q];
  }
  alignas(64) double cand[kWords];
  const std::uint64_t ok = zigguratCandidates(w, cand);
  // Word k of the block: made at once, or by call k / 4 (kept while its words are used).
  std::uint64_t extra[4];
  std::uint64_t extraCall = ~std::uint64_t(0);
  auto word = [&](std::uint64_t k) -> std::uint64_t {
    if (k < std::uint64_t(kWords)) return w[k];
    if (k / 4 != extraCall) {
      extraCall = k / 4;
      const Philox::ctr_type r = gen({{block_, stream_, extraCall, 0}}, key_);
      for (int q = 0; q < 4; ++q) extra[q] = r.v[q];
    }
    return extra[k % 4];
  };
  std::uint64_t used = 0;
  int n = 0;
  for (;;) {
    if (used < std::uint64_t(kWords)) {  // the run of accepted candidates from word `used`
      const std::uint64_t rejected = ~ok >> used;
      const int run = std::min(rejected ? int(__builtin_ctzll(rejected)) : kWords - int(used),
                               kBlock - n);
      std::memcpy(buf_.data() + n, cand + used, sizeof(double) * std::size_t(run));
      n += run;
      used += std::uint64_t(run);
      if (n == kBlock) break;
    }
    // Word `used` was rejected (or lies beyond the candidates): the sequential algorithm.
    for (;;) {
      const std::uint64_t u = word(used++);
      const unsigned i = unsigned(u & 0xff);
      const double x = zigguratUniform(u) * T.x[i];
      if (x < T.x[i + 1]) {  // inside the layer's rectangle under the curve
        buf_[n] = zigguratSign(x, u);
        break;
      }
      if (i == 0) {  // tail beyond r; 1 − U ∈ (0, 1] keeps the logarithms finite
        double xt, yt;
        do {
          xt = -std::log(1.0 - zigguratUniform(word(used++))) / ZigguratTables::kR;
          yt = -std::log(1.0 - zigguratUniform(word(used++)));
        } while (yt + yt < xt * xt);
        buf_[n] = zigguratSign(ZigguratTables::kR + xt, u);
        break;
      }
      const double y = T.f[i] + zigguratUniform(word(used++)) * (T.f[i + 1] - T.f[i]);  // wedge
      if (y < std::exp(-0.5 * x * x)) {
        buf_[n] = zigguratSign(x, u);
        break;
      }
    }
    if (++n == kBlock) break;
  }
  ++block_;
  pos_ = 0;
}

double NormalStream::at(std::uint64_t seed, std::uint64_t run, std::uint64_t stream,
                        std::uint64_t n) {
  NormalStream s(seed, run, stream);
  s.block_ = n / kBlock;
  s.refill();
  return s.buf_[n % kBlock];
}

}  // namespace sinsim::errormodels
