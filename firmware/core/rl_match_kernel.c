#include "rl_match_kernel.h"

void rl_match_kernel_plain(const float *t, size_t stride, const float *fn, const float *fs,
                           float *st, float *stt, float *sxt)
{
    int k, c;
    for (c = 0; c < RL_MATCH_BLOCK; c++)
        st[c] = stt[c] = sxt[c] = 0;
    for (k = 0; k < RL_PROFILE_BINS; k++) {
        const float *tk = t + (size_t)k * stride;
        float nk = fn[k], sk = fs[k];
        if (nk == 0)
            continue; /* bins outside the image or in light */
        for (c = 0; c < RL_MATCH_BLOCK; c++) {
            st[c] += nk * tk[c];
            stt[c] += nk * tk[c] * tk[c];
            sxt[c] += sk * tk[c];
        }
    }
}

void rl_match_kernel_wide_blocks(const float *const *t, int nb, size_t stride, const float *fn, const float *fs,
                                 float *st, float *stt, float *sxt)
{
    int b;
    for (b = 0; b < nb; b++) {
        size_t at = (size_t)b * RL_MATCH_BLOCK;
        rl_match_kernel(t[b], stride, fn, fs, st + at, stt + at, sxt + at);
    }
}
