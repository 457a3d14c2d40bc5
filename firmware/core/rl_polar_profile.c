/* A polar gather's profile (rl_polar.h): its sectors shifted to a centre
 * moved by (dx, dy) and summed into mid bins, then rescaled to a radius
 * `scale` times the gather's. */
#include "rl_polar.h"

#include <string.h>
#include "rl_clones.h"

/* On x86 the shift is also built for AVX2 (rl_clones.h), as the gather's
 * loops are (rl_polar.c): the same float operations, the same numbers. */
#define POLAR_CLONES RL_CLONES_AVX2

/* Guard bins either side of the shifted profile: a shift of up to
 * SHIFT_GUARD - 1 bins (1.5 px at the smallest landmarks) stays inside. */
#define SHIFT_GUARD RL_POLAR_SHIFT_GUARD
#define SHIFT_SPAN (RL_POLAR_BINS + RL_POLAR_PAD) /* cells written per sector */
#define MID_BINS RL_POLAR_MID_BINS

/* The first step of a profile: every sector moved by its own fraction of
 * a bin (the shift, the same for all its cells: a two-tap filter), the
 * sectors summed into mid bins mn, ms, mq (MID_BINS, zeroed here). */
POLAR_CLONES
static void shift_sectors(const rl_polar *pol, double dx, double dy, unsigned octants, float *mn,
                          float *ms, float *mq)
{
    double bw = RL_PROFILE_EXTENT * pol->r / RL_PROFILE_BINS;
    int sct, k;
    memset(mn, 0, MID_BINS * sizeof *mn);
    memset(ms, 0, MID_BINS * sizeof *ms);
    memset(mq, 0, MID_BINS * sizeof *mq);
    for (sct = 0; sct < RL_SECTORS / 2; sct++) {
        /* c[k] is bin k; c[-1] and c[RL_POLAR_BINS] are pads */
        const float *cn = pol->n[sct] + RL_POLAR_PAD, *cs = pol->s[sct] + RL_POLAR_PAD;
        const float *cq = pol->q[sct] + RL_POLAR_PAD;
        float u, w, *on, *os, *oq;
        double sh;
        int j0;
        if (!pol->merged_usable[sct] || !(octants >> sct & 1u))
            continue;
        /* cell k moves to k + sh: (1 - w) of it to k + j0, w to k + j0 + 1 */
        sh = -(dx * pol->ux[sct] + dy * pol->uy[sct]) / bw;
        if (sh > SHIFT_GUARD - 1) sh = SHIFT_GUARD - 1;
        if (sh < 1 - SHIFT_GUARD) sh = 1 - SHIFT_GUARD;
        j0 = (int)(sh + SHIFT_GUARD) - SHIFT_GUARD; /* floor: sh + SHIFT_GUARD > 0 */
        w = (float)(sh - j0);
        u = 1.0f - w;
        on = mn + SHIFT_GUARD + j0;
        os = ms + SHIFT_GUARD + j0;
        oq = mq + SHIFT_GUARD + j0;
        /* bin k + j0 from cells k and k - 1, over whole vectors */
        for (k = 0; k < SHIFT_SPAN; k++) {
            on[k] += u * cn[k] + w * cn[k - 1];
            os[k] += u * cs[k] + w * cs[k - 1];
            oq[k] += u * cq[k] + w * cq[k - 1];
        }
    }
}

/* The rescale's three sums side by side (GCC's vectors: lane by lane the
 * same float operations as three scalars, so the same bits). Whether
 * `b += w * x` is one fused multiply-add is the compiler's choice, taken
 * alike for vectors and scalars: GCC in ISO C mode (the build's -std=c99)
 * never fuses; clang fuses within an expression by default where the
 * target has one (aarch64; x86 with FMA), in both forms. RL_NO_VECTOR_EXT
 * (the sanitizer build) runs the scalar loop, under test_polar_scan's
 * oracle. */
#if defined(__GNUC__) && !defined(RL_NO_VECTOR_EXT)
#define RESCALE_VECTORS 1
typedef float rescale_v4 __attribute__((vector_size(16)));
#endif

/* Scale 1: mid bin SHIFT_GUARD + j is bin j, as gathered. */
static void bins_as_gathered(const float *mn, const float *ms, const float *mq, rl_profile *p)
{
    float tn = 0, tq = 0;
    int k;
    for (k = 0; k < RL_PROFILE_BINS; k++) {
        p->n[k] = mn[SHIFT_GUARD + k];
        p->sx[k] = ms[SHIFT_GUARD + k];
        tn += mn[SHIFT_GUARD + k];
        tq += mq[SHIFT_GUARD + k];
    }
    p->total = tn;
    p->sxx = tq;
    p->plane = 0;
}

/* The mid bins from m on rescaled, mid bin m landing at output bin
 * t = a m + b (below). */
#ifdef RESCALE_VECTORS
static void rescale_from(const float *mn, const float *ms, const float *mq, double a, double b, int m,
                         rl_profile *p)
{
    /* lanes n, s, q (and an idle fourth): each lane the scalar loop's
     * float operations in its order (below), one vector op for three */
    const rescale_v4 zero = {0, 0, 0, 0};
    rescale_v4 b0 = zero, b1 = zero, tot = zero; /* bins cur, cur + 1; the sums of n and q */
    int cur = -1;
    for (;; m++) {
        double t = m < MID_BINS ? a * m + b : RL_PROFILE_BINS;
        int last = t >= RL_PROFILE_BINS, j;
        float w, v;
        rescale_v4 x, wv, vv;
        if (t < -1.0)
            continue;
        j = last ? RL_PROFILE_BINS : (int)(t + 1.0) - 1; /* floor: t >= -1 */
        while (cur < j) {
            if (cur >= 0) {
                p->n[cur] = b0[0];
                p->sx[cur] = b0[1];
                tot += b0;
            }
            cur++;
            b0 = b1;
            b1 = zero;
        }
        if (last)
            break;
        w = (float)(t - j);
        v = 1.0f - w;
        x = (rescale_v4){mn[m], ms[m], mq[m], 0.0f};
        wv = (rescale_v4){w, w, w, w};
        vv = (rescale_v4){v, v, v, v};
        b0 += vv * x;
        b1 += wv * x;
    }
    p->sxx = tot[2];
    p->plane = 0;
    p->total = tot[0];
}
#else
static void rescale_from(const float *mn, const float *ms, const float *mq, double a, double b, int m,
                         rl_profile *p)
{
    float n0 = 0, n1 = 0, s0 = 0, s1 = 0, q0 = 0, q1 = 0, tq = 0, tn = 0;
    int cur = -1; /* the bin n0, s0, q0 hold; n1, s1, q1 hold cur + 1 */
    for (;; m++) {
        /* past the last mid bin or the last output bin, every bin
         * still open is written */
        double t = m < MID_BINS ? a * m + b : RL_PROFILE_BINS;
        int last = t >= RL_PROFILE_BINS, j;
        float w, v;
        if (t < -1.0)
            continue;
        j = last ? RL_PROFILE_BINS : (int)(t + 1.0) - 1; /* floor: t >= -1 */
        while (cur < j) {
            /* bin cur is complete */
            if (cur >= 0) {
                p->n[cur] = n0;
                p->sx[cur] = s0;
                tn += n0;
                tq += q0;
            }
            cur++;
            n0 = n1;
            s0 = s1;
            q0 = q1;
            n1 = s1 = q1 = 0;
        }
        if (last)
            break;
        w = (float)(t - j);
        v = 1.0f - w;
        n0 += v * mn[m];
        s0 += v * ms[m];
        q0 += v * mq[m];
        n1 += w * mn[m];
        s1 += w * ms[m];
        q1 += w * mq[m];
    }
    p->sxx = tq;
    p->plane = 0;
    p->total = tn;
}
#endif

/* The second step: the mid bins rescaled by `scale`, each shared between
 * the two output bins around where its centre lands. Mid bin m (centre
 * m - SHIFT_GUARD + 0.5 bins out) lands at output t = a (m - SHIFT_GUARD
 * + 0.5) - 0.5, (1 - w) of it in bin j = floor(t) and w in j + 1. t grows
 * with m, so bins j and j + 1 are summed in registers and bin j is
 * written once t has moved past it. */
static void rescale_bins(const float *mn, const float *ms, const float *mq, double scale,
                         rl_profile *p)
{
    double a = 1.0 / scale, b;
    int m;
    if (scale == 1.0) {
        bins_as_gathered(mn, ms, mq, p);
        return;
    }
    b = a * (0.5 - SHIFT_GUARD) - 0.5;
    m = (int)((-1.0 - b) / a); /* the first m with t >= -1, or one before */
    rescale_from(mn, ms, mq, a, b, m < 0 ? 0 : m, p);
}

void rl_polar_profile(const rl_polar *pol, double dx, double dy, double scale, rl_profile *p)
{
    rl_polar_profile_octants(pol, dx, dy, scale, RL_POLAR_ALL, p);
}

void rl_polar_profile_octants(const rl_polar *pol, double dx, double dy, double scale,
                              unsigned octants, rl_profile *p)
{
    rl_polar_shift sh;
    rl_polar_shift_make(pol, dx, dy, octants, &sh);
    rl_polar_shift_profile(&sh, scale, p);
}

void rl_polar_shift_make(const rl_polar *pol, double dx, double dy, unsigned octants, rl_polar_shift *sh)
{
    shift_sectors(pol, dx, dy, octants, sh->n, sh->s, sh->q);
}

void rl_polar_shift_profile(const rl_polar_shift *sh, double scale, rl_profile *p)
{
    rescale_bins(sh->n, sh->s, sh->q, scale, p);
}
