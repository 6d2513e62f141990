// The ziggurat's tables and its fast path, in plain C++ and in AVX2 / AVX-512 (see ziggurat.hpp).
// The vector kernels do per lane what the scalar one does per word — an integer mantissa, one
// subtraction, one multiplication, one comparison, a sign flip — so every kernel gives the same
// bits; the CPU only decides how many words go at once.
#include "errormodels/ziggurat.hpp"

#include <cmath>
#include <stdexcept>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define SINSIM_ZIGGURAT_X86 1
#endif

namespace sinsim::errormodels {
namespace {

ZigguratTables buildTables() {
  constexpr int L = ZigguratTables::kLayers;
  constexpr double r = ZigguratTables::kR;
  ZigguratTables t;
  const double fr = std::exp(-0.5 * r * r);
  const double v = r * fr + std::sqrt(M_PI / 2) * std::erfc(r / std::sqrt(2.0));
  t.x[0] = v / fr;
  t.x[1] = r;
  t.f[0] = fr;  // the base layer's top is f(r)
  t.f[1] = fr;
  for (int i = 1; i < L - 1; ++i) {
    t.f[i + 1] = t.f[i] + v / t.x[i];
    t.x[i + 1] = std::sqrt(-2.0 * std::log(t.f[i + 1]));
  }
  t.x[L] = 0.0;
  t.f[L] = 1.0;
  // The last layer [0, x_255] × [f(x_255), 1] must have area v too.
  const double top = t.x[L - 1] * (1.0 - t.f[L - 1]);
  if (!(std::abs(top - v) < 1e-9 * v)) throw std::logic_error("ziggurat tables inconsistent");
  return t;
}

std::uint64_t candidatesScalar(const std::uint64_t* w, double* cand) {
  const ZigguratTables& T = zigguratTables();
  std::uint64_t ok = 0;
  for (int k = 0; k < kZigguratBlockWords; ++k) {
    const std::uint64_t u = w[k];
    const unsigned i = unsigned(u & 0xff);
    const double x = zigguratUniform(u) * T.x[i];
    cand[k] = zigguratSign(x, u);
    ok |= std::uint64_t(x < T.x[i + 1]) << k;
  }
  return ok;
}

#ifdef SINSIM_ZIGGURAT_X86
__attribute__((target("avx2"))) std::uint64_t candidatesAvx2(const std::uint64_t* w, double* cand) {
  const double* x = zigguratTables().x;
  const __m256i layer = _mm256_set1_epi64x(0xff), sign = _mm256_set1_epi64x(0x100);
  const __m256i exponent = _mm256_set1_epi64x(0x3ff0000000000000ll);
  const __m256d one = _mm256_set1_pd(1.0);
  std::uint64_t ok = 0;
  for (int k = 0; k < kZigguratBlockWords; k += 4) {
    const __m256i u = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(w + k));
    const __m256i i = _mm256_and_si256(u, layer);
    const __m256d U = _mm256_sub_pd(
        _mm256_castsi256_pd(_mm256_or_si256(_mm256_srli_epi64(u, 12), exponent)), one);
    const __m256d v = _mm256_mul_pd(U, _mm256_i64gather_pd(x, i, 8));
    const __m256d next = _mm256_i64gather_pd(x + 1, i, 8);
    const unsigned m = unsigned(_mm256_movemask_pd(_mm256_cmp_pd(v, next, _CMP_LT_OQ)));
    const __m256i s = _mm256_slli_epi64(_mm256_and_si256(u, sign), 55);
    _mm256_storeu_pd(cand + k, _mm256_castsi256_pd(_mm256_xor_si256(_mm256_castpd_si256(v), s)));
    ok |= std::uint64_t(m) << k;
  }
  return ok;
}

// GCC 12's avx512fintrin.h builds its set1/cast results from an "undefined" vector, which
// -W(maybe-)uninitialized reports at every use; nothing here reads an undefined lane.
#if !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
#endif
__attribute__((target("avx512f"))) std::uint64_t candidatesAvx512(const std::uint64_t* w,
                                                                  double* cand) {
  const double* x = zigguratTables().x;
  const __m512i layer = _mm512_set1_epi64(0xff), sign = _mm512_set1_epi64(0x100);
  const __m512i exponent = _mm512_set1_epi64(0x3ff0000000000000ll);
  const __m512d one = _mm512_set1_pd(1.0);
  std::uint64_t ok = 0;
  for (int k = 0; k < kZigguratBlockWords; k += 8) {
    const __m512i u = _mm512_loadu_si512(w + k);
    const __m512i i = _mm512_and_si512(u, layer);
    const __m512d U = _mm512_sub_pd(
        _mm512_castsi512_pd(_mm512_or_si512(_mm512_srli_epi64(u, 12), exponent)), one);
    const __m512d v = _mm512_mul_pd(U, _mm512_i64gather_pd(i, x, 8));
    const __m512d next = _mm512_i64gather_pd(i, x + 1, 8);
    const __mmask8 m = _mm512_cmp_pd_mask(v, next, _CMP_LT_OQ);
    const __m512i s = _mm512_slli_epi64(_mm512_and_si512(u, sign), 55);
    _mm512_storeu_pd(cand + k, _mm512_castsi512_pd(_mm512_xor_si512(_mm512_castpd_si512(v), s)));
    ok |= std::uint64_t(m) << k;
  }
  return ok;
}
#if !defined(__clang__)
#pragma GCC diagnostic pop
#endif
#endif

using Kernel = std::uint64_t (*)(const std::uint64_t*, double*);

Kernel kernelOf(ZigguratKernel k) {
#ifdef SINSIM_ZIGGURAT_X86
  if (k == ZigguratKernel::avx512) return candidatesAvx512;
  if (k == ZigguratKernel::avx2) return candidatesAvx2;
#endif
  (void)k;
  return candidatesScalar;
}

Kernel bestKernel() {
  if (zigguratKernelAvailable(ZigguratKernel::avx512)) return kernelOf(ZigguratKernel::avx512);
  if (zigguratKernelAvailable(ZigguratKernel::avx2)) return kernelOf(ZigguratKernel::avx2);
  return candidatesScalar;
}

}  // namespace

const ZigguratTables& zigguratTables() {
  static const ZigguratTables t = buildTables();
  return t;
}

bool zigguratKernelAvailable(ZigguratKernel k) {
  switch (k) {
    case ZigguratKernel::scalar:
      return true;
#ifdef SINSIM_ZIGGURAT_X86
    case ZigguratKernel::avx2:
      return __builtin_cpu_supports("avx2");
    case ZigguratKernel::avx512:
      return __builtin_cpu_supports("avx512f");
#endif
    default:
      return false;
  }
}

std::uint64_t zigguratCandidates(const std::uint64_t* w, double* cand) {
  static const Kernel best = bestKernel();
  return best(w, cand);
}

std::uint64_t zigguratCandidates(const std::uint64_t* w, double* cand, ZigguratKernel kernel) {
  if (!zigguratKernelAvailable(kernel))
    throw std::logic_error("ziggurat: this CPU lacks the requested kernel");
  return kernelOf(kernel)(w, cand);
}

}  // namespace sinsim::errormodels
