#include "rl_match_kernel.h"

#include <string.h>

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

void rl_match_kernel_wide_blocks(const float *const *t, size_t stride, const float *fn, const float *fs,
                                 float *st, float *stt, float *sxt)
{
    int b;
    for (b = 0; b < RL_MATCH_WIDE; b++) {
        size_t at = (size_t)b * RL_MATCH_BLOCK, was = at - RL_MATCH_BLOCK;
        if (b > 0 && t[b] == t[b - 1]) {
            /* a block given again (sum_in_place pads two ids to three):
             * its sums are the ones before, not walked again (a block a
             * walk here: no walk of the others to share) */
            memcpy(st + at, st + was, RL_MATCH_BLOCK * sizeof *st);
            memcpy(stt + at, stt + was, RL_MATCH_BLOCK * sizeof *stt);
            memcpy(sxt + at, sxt + was, RL_MATCH_BLOCK * sizeof *sxt);
            continue;
        }
        rl_match_kernel(t[b], stride, fn, fs, st + at, stt + at, sxt + at);
    }
}
