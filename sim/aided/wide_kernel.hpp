// SINSIM_WIDE_KERNEL: a loop kernel compiled twice on x86-64 with GCC, for AVX2 and for the
// baseline, the loader picking one for the CPU (target_clones; other compilers build the baseline
// alone). A kernel so marked must do the same IEEE additions and multiplications in the same
// order in either version (AVX2 without FMA: nothing is contracted), so that its results are
// bit-identical on every machine; AVX2 only does four of them per instruction instead of two.
#pragma once

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define SINSIM_WIDE_KERNEL __attribute__((target_clones("avx2", "default")))
#else
#define SINSIM_WIDE_KERNEL
#endif
