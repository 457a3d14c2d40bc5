/* rl_clones: a function also built for AVX2 on x86, the version chosen
 * when the program loads (GCC target_clones, through the C library's
 * ifunc: glibc's). Elsewhere (ARM, clang, musl, RL_NO_VECTOR_EXT) only the
 * plain build. The clones do the same float operations in the same order:
 * the build's -std=c99 turns GCC's contraction into fused multiply-adds
 * off, and AVX2 does not include FMA.
 *
 *   // at file scope, before the function's definition:
 *   //   RL_CLONES_AVX2
 *   //   static void gather(const float *in, float *out, int n) { ... }
 */
#ifndef RL_CLONES_H
#define RL_CLONES_H

#include <limits.h> /* the C library's own macros (__GLIBC__) */

#if defined(__GNUC__) && !defined(__clang__) && !defined(RL_NO_VECTOR_EXT) && defined(__x86_64__) && \
    defined(__GLIBC__)
#define RL_CLONES_AVX2 __attribute__((target_clones("avx2", "default")))
#else
#define RL_CLONES_AVX2
#endif

/* A helper a clone calls in its loops, compiled into each clone (the
 * clone's own instructions, the same operations): out of line it is the
 * plain build's, and switching between a clone's AVX code and plain SSE
 * code costs time on some machines (issue 43: gather's plane_row). */
#if defined(__GNUC__)
#define RL_CLONE_INLINE __attribute__((always_inline)) inline
#else
#define RL_CLONE_INLINE
#endif

#endif
