/* rl_match_kernel: the sums of one block of template columns against a
 * profile, the inner loop of identification (internal).
 *
 * For the RL_MATCH_BLOCK columns starting at t (bin k's values at
 * t + k * stride) and a profile's per-bin counts fn and darkness sums fs,
 * each column c gets st[c] = sum_k fn[k] t[k][c], stt[c] = sum_k fn[k]
 * t[k][c]^2 and sxt[c] = sum_k fs[k] t[k][c],
 * added bin by bin in order, in single precision (64 bins lose no more than
 * 1e-5 of a correlation). Two builds of the same loop: plain C, and 4-lane
 * vectors kept in registers (the GCC/Clang vector extension: SSE, NEON).
 * Both add the same products in the same order, so they give the same
 * bits (and so does an 8-lane build on x86 with AVX); RL_NO_VECTOR_EXT selects the plain one, and CI runs the test
 * suite with each. A bin with no pixel (fn[k] 0) adds nothing: the
 * plain and 4-lane kernels pass over it, the 8-lane one adds its zero
 * products (the same bits), so fs[k] must be 0 there too and the
 * templates finite (rl_match's terms are: a bin with no pixel has no
 * darkness).
 *
 *   float fn[RL_PROFILE_BINS] = {0}, fs[RL_PROFILE_BINS] = {0};
 *   float st[RL_MATCH_BLOCK], stt[RL_MATCH_BLOCK], sxt[RL_MATCH_BLOCK];
 *   rl_match_kernel(tt.table, (size_t)tt.stride, fn, fs, st, stt, sxt);
 */
#ifndef RL_MATCH_KERNEL_H
#define RL_MATCH_KERNEL_H

#include <stddef.h>
#include "rl_templates.h"

typedef void (*rl_match_kernel_fn)(const float *t, size_t stride, const float *fn,
                                   const float *fs, float *st, float *stt, float *sxt);

void rl_match_kernel_plain(const float *t, size_t stride, const float *fn, const float *fs,
                           float *st, float *stt, float *sxt);

#if defined(__GNUC__) && RL_MATCH_BLOCK == 8
#define RL_HAVE_MATCH_KERNEL_V4 1
void rl_match_kernel_v4(const float *t, size_t stride, const float *fn, const float *fs,
                        float *st, float *stt, float *sxt);
#endif

/* On x86, one 8-lane vector a sum where the processor has AVX (the same
 * bits again), chosen at each call (rl_match_kernel_x86). */
#if defined(RL_HAVE_MATCH_KERNEL_V4) && (defined(__x86_64__) || defined(__i386__))
#define RL_HAVE_MATCH_KERNEL_V8 1
void rl_match_kernel_v8(const float *t, size_t stride, const float *fn, const float *fs,
                        float *st, float *stt, float *sxt);
void rl_match_kernel_x86(const float *t, size_t stride, const float *fn, const float *fs,
                         float *st, float *stt, float *sxt);
#endif

/* nb blocks (1 .. RL_MATCH_WIDE), block b's columns from t[b] (anywhere
 * in the table: side by side for every id, or one id's own columns each),
 * their sums at st + b * RL_MATCH_BLOCK ..: each column's sums the bits of
 * rl_match_kernel's. On x86 with AVX one walk over the bins for all of
 * them (each bin's count and sum loaded once, two or three chains of adds
 * in flight instead of one), else a block at a time. */
#define RL_MATCH_WIDE 3
void rl_match_kernel_wide_blocks(const float *const *t, int nb, size_t stride, const float *fn, const float *fs,
                                 float *st, float *stt, float *sxt);
#if defined(RL_HAVE_MATCH_KERNEL_V8)
void rl_match_kernel_v8w(const float *const *t, int nb, size_t stride, const float *fn, const float *fs,
                         float *st, float *stt, float *sxt);
void rl_match_kernel_wide_x86(const float *const *t, int nb, size_t stride, const float *fn, const float *fs,
                              float *st, float *stt, float *sxt);
#endif

/* The kernel identification uses. */
#if defined(RL_HAVE_MATCH_KERNEL_V8) && !defined(RL_NO_VECTOR_EXT)
#define rl_match_kernel rl_match_kernel_x86
#define rl_match_kernel_wide rl_match_kernel_wide_x86
#elif defined(RL_HAVE_MATCH_KERNEL_V4) && !defined(RL_NO_VECTOR_EXT)
#define rl_match_kernel rl_match_kernel_v4
#define rl_match_kernel_wide rl_match_kernel_wide_blocks
#else
#define rl_match_kernel rl_match_kernel_plain
#define rl_match_kernel_wide rl_match_kernel_wide_blocks
#endif

#endif
