// Box-Muller over blocks of Philox output, written so that the compiler vectorises the
// transcendental functions (this file is built with -ffast-math, see CMakeLists.txt,
// so glibc's libmvec provides SIMD log/sin/cos). Nothing else in sinsim is built that way.
//
// Box & Muller 1958: with u0 uniform on (-1, 1] and u1 uniform on (0, 1],
//   z0 = sqrt(-2 ln u1) sin(π u0),  z1 = sqrt(-2 ln u1) cos(π u0)  are independent N(0, 1).
// The uniforms are the 53-bit conversions of Random123's u01 / uneg11 (uniform.hpp), which never
// return 0 for u1, so the logarithm is finite (|z| ≤ 8.6 for 64-bit inputs).
#include "errormodels/random.hpp"

#include <Random123/uniform.hpp>

#include <cmath>

namespace sinsim::errormodels {

void NormalStream::refill() {
  constexpr int kPairs = kBlock / 2;
  alignas(64) double u0[kPairs];
  alignas(64) double u1[kPairs];
  Philox gen;
  for (int b = 0; b < kBlock / 4; ++b) {
    Philox::ctr_type c = {{block_++, stream_, 0, 0}};
    Philox::ctr_type r = gen(c, key_);
    u0[2 * b] = r123::uneg11<double>(r.v[0]);
    u1[2 * b] = r123::u01<double>(r.v[1]);
    u0[2 * b + 1] = r123::uneg11<double>(r.v[2]);
    u1[2 * b + 1] = r123::u01<double>(r.v[3]);
  }
  constexpr double kPi = 3.14159265358979323846;
  alignas(64) double rad[kPairs];
  alignas(64) double zs[kPairs];
  alignas(64) double zc[kPairs];
  // Three separate loops: in one loop GCC fuses sin and cos into sincos, which has no SIMD clone.
  for (int i = 0; i < kPairs; ++i) rad[i] = std::sqrt(-2.0 * std::log(u1[i]));
  for (int i = 0; i < kPairs; ++i) zs[i] = rad[i] * std::sin(kPi * u0[i]);
  for (int i = 0; i < kPairs; ++i) zc[i] = rad[i] * std::cos(kPi * u0[i]);
  for (int i = 0; i < kPairs; ++i) {
    buf_[2 * i] = zs[i];
    buf_[2 * i + 1] = zc[i];
  }
  pos_ = 0;
}

double NormalStream::at(std::uint64_t seed, std::uint64_t run, std::uint64_t stream,
                        std::uint64_t n) {
  NormalStream s(seed, run, stream);
  s.block_ = (n / kBlock) * (kBlock / 4);
  s.refill();
  return s.buf_[n % kBlock];
}

}  // namespace sinsim::errormodels
