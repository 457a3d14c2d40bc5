#include "rl_match_kernel.h"

#ifdef RL_HAVE_MATCH_KERNEL_V4
#include <string.h>

typedef float rl_v4 __attribute__((vector_size(16)));

/* The plain kernel's loop with each sum in two 4-lane vectors. */
void rl_match_kernel_v4(const float *t, size_t stride, const float *fn, const float *fs,
                        float *st, float *stt, float *sxt)
{
    rl_v4 s0 = {0, 0, 0, 0}, s1 = s0, ss0 = s0, ss1 = s0, sx0 = s0, sx1 = s0;
    int k;
    for (k = 0; k < RL_PROFILE_BINS; k++) {
        const float *tk = t + (size_t)k * stride;
        float nk = fn[k], sk = fs[k];
        rl_v4 t0, t1, nv = {nk, nk, nk, nk}, sv = {sk, sk, sk, sk};
        if (nk == 0)
            continue; /* bins outside the image or in light */
        memcpy(&t0, tk, sizeof t0);
        memcpy(&t1, tk + 4, sizeof t1);
        s0 += nv * t0;
        s1 += nv * t1;
        ss0 += nv * t0 * t0;
        ss1 += nv * t1 * t1;
        sx0 += sv * t0;
        sx1 += sv * t1;
    }
    memcpy(st, &s0, sizeof s0);
    memcpy(st + 4, &s1, sizeof s1);
    memcpy(stt, &ss0, sizeof ss0);
    memcpy(stt + 4, &ss1, sizeof ss1);
    memcpy(sxt, &sx0, sizeof sx0);
    memcpy(sxt + 4, &sx1, sizeof sx1);
}

#ifdef RL_HAVE_MATCH_KERNEL_V8
#include <immintrin.h>
typedef float rl_v8 __attribute__((vector_size(32)));

/* The plain kernel's loop with each sum in one 8-lane vector (AVX), for
 * nb (1 .. 3) blocks (columns t[0] .. t[0] + 7, t[1] .., t[2] ..) in one
 * walk over the bins: each bin's count and sum straight from memory into
 * every lane, once for them all; each lane the same products added in the
 * same order as one block alone. Inlined with nb a constant: the blocks
 * past it fold away and the sums stay in registers.
 *
 * Every bin is added, an empty one (fn[k] 0) too, with no test: its
 * products are zeros (fs[k] is 0 where fn[k] is, rl_match_kernel.h), and
 * a zero added leaves each sum's bits as the plain kernel's skip does
 * (a sum starts at +0 and never becomes -0: x + -x is +0). The empty bins
 * lie where the rescaled profile's bins skip one, at no pattern a branch
 * predicts: the test cost the windows' matches more than the bins' adds
 * (issue 43: ids and twins 3-4 us less a moving window frame). */
static inline __attribute__((always_inline, target("avx"))) void walk_v8w(const float *const *t, int nb,
                                                                          size_t stride, const float *fn,
                                                                          const float *fs, float *st,
                                                                          float *stt, float *sxt)
{
    rl_v8 s0 = {0, 0, 0, 0, 0, 0, 0, 0}, s1 = s0, s2 = s0, ss0 = s0, ss1 = s0, ss2 = s0, sx0 = s0, sx1 = s0,
          sx2 = s0;
    const float *t0 = t[0], *t1 = nb > 1 ? t[1] : t0, *t2 = nb > 2 ? t[2] : t0;
    int k;
    for (k = 0; k < RL_PROFILE_BINS; k++) {
        size_t at = (size_t)k * stride;
        rl_v8 v0, v1, v2, nv, sv;
        nv = (rl_v8)_mm256_broadcast_ss(fn + k);
        sv = (rl_v8)_mm256_broadcast_ss(fs + k);
        memcpy(&v0, t0 + at, sizeof v0);
        s0 += nv * v0;
        ss0 += nv * v0 * v0;
        sx0 += sv * v0;
        if (nb > 1) {
            memcpy(&v1, t1 + at, sizeof v1);
            s1 += nv * v1;
            ss1 += nv * v1 * v1;
            sx1 += sv * v1;
        }
        if (nb > 2) {
            memcpy(&v2, t2 + at, sizeof v2);
            s2 += nv * v2;
            ss2 += nv * v2 * v2;
            sx2 += sv * v2;
        }
    }
    memcpy(st, &s0, sizeof s0);
    memcpy(stt, &ss0, sizeof ss0);
    memcpy(sxt, &sx0, sizeof sx0);
    if (nb > 1) {
        memcpy(st + 8, &s1, sizeof s1);
        memcpy(stt + 8, &ss1, sizeof ss1);
        memcpy(sxt + 8, &sx1, sizeof sx1);
    }
    if (nb > 2) {
        memcpy(st + 16, &s2, sizeof s2);
        memcpy(stt + 16, &ss2, sizeof ss2);
        memcpy(sxt + 16, &sx2, sizeof sx2);
    }
}

__attribute__((target("avx"))) void rl_match_kernel_v8(const float *t, size_t stride, const float *fn,
                                                       const float *fs, float *st, float *stt, float *sxt)
{
    walk_v8w(&t, 1, stride, fn, fs, st, stt, sxt);
}

/* nb 3, 2 or 1: walked with it a constant */
typedef char rl_match_wide_is_3[RL_MATCH_WIDE == 3 ? 1 : -1];

__attribute__((target("avx"))) void rl_match_kernel_v8w(const float *const *t, int nb, size_t stride,
                                                        const float *fn, const float *fs, float *st, float *stt,
                                                        float *sxt)
{
    if (nb == 3)
        walk_v8w(t, 3, stride, fn, fs, st, stt, sxt);
    else if (nb == 2)
        walk_v8w(t, 2, stride, fn, fs, st, stt, sxt);
    else
        walk_v8w(t, 1, stride, fn, fs, st, stt, sxt);
}

void rl_match_kernel_wide_x86(const float *const *t, int nb, size_t stride, const float *fn, const float *fs,
                              float *st, float *stt, float *sxt)
{
    if (__builtin_cpu_supports("avx"))
        rl_match_kernel_v8w(t, nb, stride, fn, fs, st, stt, sxt);
    else
        rl_match_kernel_wide_blocks(t, nb, stride, fn, fs, st, stt, sxt); /* v4 a block */
}

void rl_match_kernel_x86(const float *t, size_t stride, const float *fn, const float *fs, float *st,
                         float *stt, float *sxt)
{
    if (__builtin_cpu_supports("avx"))
        rl_match_kernel_v8(t, stride, fn, fs, st, stt, sxt);
    else
        rl_match_kernel_v4(t, stride, fn, fs, st, stt, sxt);
}
#endif
#else
typedef int rl_match_kernel_v4_not_built; /* ISO C: no empty translation unit */
#endif
