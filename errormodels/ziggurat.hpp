// The ziggurat normal method's layers and its fast path (Marsaglia & Tsang, "The ziggurat method
// for generating random variables", J. Stat. Softw. 5(8), 2000), used by NormalStream (random.hpp).
//
// 256 layers of equal area v under f(x) = exp(−x²/2), x ≥ 0: x_1 = r = 3.6541528853610088 (the
// 256-layer solution), v = r f(r) + ∫_r^∞ f = r f(r) + sqrt(π/2) erfc(r/√2), x_0 = v/f(r) (the
// base layer including the tail), and f(x_{i+1}) = f(x_i) + v/x_i up to x_256 = 0 (the top layer's
// area comes out v within 1e-13 relative; the tables are checked when built).
//
// One 64-bit word per normal on the fast path: bits 0-7 the layer i, bit 8 the sign, bits 12-63 a
// 52-bit uniform U (disjoint bits, so the layer and the value are independent — the flaw Doornik
// 2005 found in implementations that reuse bits). x = U x_i is accepted at once when x < x_{i+1}
// (98.5 % of words).
#pragma once

#include <cstdint>
#include <cstring>

namespace sinsim::errormodels {

struct ZigguratTables {
  static constexpr int kLayers = 256;
  static constexpr double kR = 3.6541528853610088;
  double x[kLayers + 1];  // layer edges x_0 > x_1 = r > ... > x_256 = 0
  double f[kLayers + 1];  // f(x_i)
};

/// The tables, built once.
const ZigguratTables& zigguratTables();

/// U ∈ [0, 1) from the top 52 bits of u: they become the mantissa of a double in [1, 2), minus 1.
inline double zigguratUniform(std::uint64_t u) {
  const std::uint64_t b = (u >> 12) | 0x3ff0000000000000ull;
  double d;
  std::memcpy(&d, &b, sizeof d);
  return d - 1.0;
}

/// x with its sign bit flipped when bit 8 of u is set.
inline double zigguratSign(double x, std::uint64_t u) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  b ^= (u & 0x100) << 55;
  std::memcpy(&x, &b, sizeof b);
  return x;
}

/// The instruction sets the fast path has a kernel for (the same IEEE operations in each, so the
/// same bits).
enum class ZigguratKernel { scalar, avx2, avx512 };

/// The words the fast path takes at once: one per normal, one bit each in the acceptance mask.
constexpr int kZigguratBlockWords = 64;

/// Whether this CPU runs the kernel.
bool zigguratKernelAvailable(ZigguratKernel k);

/// The fast path of a block's 64 words taken as if each were a draw's first word: cand[k] = ±U x_i
/// of w[k]; returns the mask whose bit k is set when w[k] is accepted at once. The best available
/// kernel unless one is named.
std::uint64_t zigguratCandidates(const std::uint64_t* w, double* cand);
std::uint64_t zigguratCandidates(const std::uint64_t* w, double* cand, ZigguratKernel kernel);

}  // namespace sinsim::errormodels
