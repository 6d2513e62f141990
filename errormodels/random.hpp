// Counter-based Gaussian streams (Random123 Philox4x64-10; Salmon et al., "Parallel random
// numbers: as easy as 1, 2, 3", SC'11) turned into normals by the ziggurat method (Marsaglia &
// Tsang, "The ziggurat method for generating random variables", J. Stat. Softw. 5(8), 2000).
// There is no global generator and nothing is seeded from time: a stream is a pure function of
// (seed, run, stream id) and the position in it, so run k of a Monte Carlo batch can be
// regenerated alone, and results do not depend on thread count.
//
// Key   = {seed, run}                        (128 bits)
// Count = {block, stream id, j, 0}           (block = index of the kBlock-normal block in the
//                                             stream, j = 0, 1, ... the Philox calls of that block)
// Each block of normals has its own counter space, so block b is a pure function of (key, stream,
// b) however many 64-bit words its rejections consumed: random access (at()) stays cheap.
// stream id packs (sensor, axis, effect index, sub-stream) — see streamId().
#pragma once

#include <Random123/philox.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace sinsim::errormodels {

/// Packs the identity of one random stream: sensor (0 gyro, 1 accel), axis (0..2, 3 = triad),
/// effect index in its list, and a sub-stream for effects that need several (e.g. one per GM
/// component of bias_instability, or the turn-on draw of a bias).
constexpr std::uint64_t streamId(unsigned sensor, unsigned axis, unsigned effect, unsigned sub = 0) {
  return (std::uint64_t(sensor & 0xffu) << 56) | (std::uint64_t(axis & 0xffu) << 48) |
         (std::uint64_t(effect & 0xffffu) << 32) | std::uint64_t(sub);
}

/// A stream of independent N(0, 1) draws, produced in blocks of kBlock.
class NormalStream {
 public:
  static constexpr int kBlock = 64;  // normals per refill (16 Philox calls)

  NormalStream() = default;
  NormalStream(std::uint64_t seed, std::uint64_t run, std::uint64_t stream) {
    key_ = {{seed, run}};
    stream_ = stream;
  }

  double next() {
    if (pos_ == kBlock) refill();
    return buf_[pos_++];
  }

  /// The next n draws into out, as n calls of next() would give them.
  void fill(double* out, std::size_t n) {
    while (n > 0) {
      if (pos_ == kBlock) refill();
      const std::size_t m = std::min(n, std::size_t(kBlock - pos_));
      std::memcpy(out, buf_.data() + pos_, m * sizeof(double));
      out += m;
      n -= m;
      pos_ += int(m);
    }
  }

  /// The n-th normal of the stream (random access: regenerates only the block holding it).
  static double at(std::uint64_t seed, std::uint64_t run, std::uint64_t stream, std::uint64_t n);

 private:
  using Philox = r123::Philox4x64;

  /// Fills buf_ with the next kBlock normals (random.cpp). The result depends only on (key,
  /// stream, block), never on the caller.
  void refill();

  Philox::key_type key_ = {{0, 0}};
  std::uint64_t stream_ = 0;
  std::uint64_t block_ = 0;
  int pos_ = kBlock;
  std::array<double, kBlock> buf_{};
};

}  // namespace sinsim::errormodels
