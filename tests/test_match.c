/* The matcher: its kernels (plain C, 4-lane vectors, 8 on x86 with AVX) give the same
 * bits on arbitrary data, and the block-wise Pearson scores agree with a
 * direct double-precision correlation over the bins (an oracle written
 * here from the formula, not from the matcher). */
#include "rl_test.h"
#include <math.h>
#include "rl_family.h"
#include "rl_match.h"
#include "rl_match_kernel.h"

static uint64_t rng = 12345;
static double uniform(void)
{
    rng = rng * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(rng >> 11) / 9007199254740992.0;
}

static void test_kernels_agree_bit_for_bit(void **state)
{
#ifdef RL_HAVE_MATCH_KERNEL_V4
    static float t[RL_PROFILE_BINS * 24];
    float fn[RL_PROFILE_BINS], fs[RL_PROFILE_BINS];
    int trial, k, c;
    (void)state;
    for (trial = 0; trial < 200; trial++) {
        float a[3][RL_MATCH_BLOCK], b[3][RL_MATCH_BLOCK];
        for (k = 0; k < RL_PROFILE_BINS * 24; k++)
            t[k] = (float)uniform();
        for (k = 0; k < RL_PROFILE_BINS; k++) {
            fn[k] = uniform() < 0.2 ? 0.0f : (float)(uniform() * 300); /* empty bins too */
            fs[k] = fn[k] * (float)(uniform() * 255);
        }
        rl_match_kernel_plain(t + 8, 24, fn, fs, a[0], a[1], a[2]);
        rl_match_kernel_v4(t + 8, 24, fn, fs, b[0], b[1], b[2]);
        for (k = 0; k < 3; k++)
            for (c = 0; c < RL_MATCH_BLOCK; c++)
                assert_memory_equal(&a[k][c], &b[k][c], sizeof(float));
#ifdef RL_HAVE_MATCH_KERNEL_V8
        if (__builtin_cpu_supports("avx")) {
            rl_match_kernel_v8(t + 8, 24, fn, fs, b[0], b[1], b[2]);
            for (k = 0; k < 3; k++)
                for (c = 0; c < RL_MATCH_BLOCK; c++)
                    assert_memory_equal(&a[k][c], &b[k][c], sizeof(float));
        }
#endif
    }
#else
    (void)state;
    skip(); /* no vector extension in this compiler: only the plain kernel exists */
#endif
}

/* Pearson's r over bins in double precision: n_k pixels of mean darkness
 * sx_k / n_k against template value t_k, with the profile's own sxx. */
static double direct_r(const rl_profile *p, const rl_templates *tt, int i, int b)
{
    double n = 0, sx = 0, st = 0, stt = 0, sxt = 0;
    int k;
    for (k = 0; k < RL_PROFILE_BINS; k++) {
        double tv = rl_templates_bin(tt, i, b, k);
        n += p->n[k];
        sx += p->sx[k];
        st += p->n[k] * tv;
        stt += p->n[k] * tv * tv;
        sxt += p->sx[k] * tv;
    }
    return (n * sxt - sx * st) / sqrt((n * p->sxx - sx * sx) * (n * stt - st * st));
}

static void test_scores_match_a_direct_correlation(void **state)
{
    static unsigned char mem[1 << 16];
    rl_family fam = {5};
    rl_templates tt;
    rl_ws ws;
    int trial;
    (void)state;
    rl_ws_init(&ws, mem, sizeof mem);
    assert_int_equal(rl_templates_init(&tt, &ws, &fam, NULL, 0), RL_OK);
    for (trial = 0; trial < 100; trial++) {
        /* a noisy profile of a random id at a random blur */
        int i = (int)(uniform() * tt.n), b = (int)(uniform() * RL_BLUR_LEVELS), k, j;
        double best = -2, second = -2;
        int best_id = -1;
        rl_profile p;
        rl_match m, ml;
        memset(&p, 0, sizeof p);
        for (k = 0; k < RL_PROFILE_BINS; k++) {
            double n = 20 + 10 * k, v = 40 + 180 * rl_templates_bin(&tt, i, b, k) + 30 * (uniform() - 0.5);
            p.n[k] = n;
            p.sx[k] = n * v;
            p.sxx += n * v * v + n * 25.0; /* some spread within the bin */
            p.total += n;
        }
        rl_match_all(&tt, &p, &m);
        for (j = 0; j < tt.n; j++)
            for (k = 0; k < RL_BLUR_LEVELS; k++) {
                double r = direct_r(&p, &tt, j, k);
                if (r > best) {
                    if (tt.ids[j] != best_id)
                        second = best;
                    best = r;
                    best_id = tt.ids[j];
                } else if (r > second && tt.ids[j] != best_id) {
                    second = r;
                }
            }
        assert_int_equal(m.id, best_id);
        assert_true(fabs(m.score - best) < 1e-4);
        assert_true(fabs(m.second - second) < 1e-4);
        /* a short list of the true id and two others scores the same */
        {
            int ids[3] = {tt.ids[i], tt.ids[(i + 1) % tt.n], tt.ids[(i + 7) % tt.n]};
            rl_match_list ls;
            rl_match_list_make(&tt, ids, 3, m.blur, &ls);
            rl_match_list_score(&ls, &p, &ml);
            if (m.id == ids[0])
                assert_true(fabs(ml.score - m.score) < 1e-6);
            assert_true(fabs(ml.score - direct_r(&p, &tt, rl_templates_find(&tt, ml.id), m.blur)) < 1e-4);
        }
    }
}

/* A profile rescaled to a smaller radius: each bin's pixels move to the
 * bin its middle falls in at the new scale, those past the end to the
 * last; by hand: at s = 0.5 bin 3 (middle 3.5) goes to 7, bin 40 (40.5)
 * past 63 to the last; the other sums as they were. */
static void test_rescaled_profile_moves_bins(void **state)
{
    rl_profile p, q;
    (void)state;
    memset(&p, 0, sizeof p);
    p.n[3] = 10;
    p.sx[3] = 500;
    p.n[40] = 4;
    p.sx[40] = 100;
    p.sxx = 123;
    p.plane = 7;
    p.total = 14;
    rl_profile_rescale(&p, 0.5, &q);
    assert_true(q.n[7] == 10 && q.sx[7] == 500);
    assert_true(q.n[RL_PROFILE_BINS - 1] == 4 && q.sx[RL_PROFILE_BINS - 1] == 100);
    assert_true(q.n[3] == 0 && q.n[40] == 0);
    assert_true(q.sxx == 123 && q.plane == 7 && q.total == 14);
    rl_profile_rescale(&p, 1.0, &q); /* unchanged */
    assert_true(q.n[3] == 10 && q.n[40] == 4);
}

/* The oracle of the rescale, from its definition (rl_profile.h): bin k's
 * sums added, in k's order, into the bin its middle (k + 0.5) / s falls
 * in, those past the end into the last. */
static void rescaled_by_division(const rl_profile *src, double s, rl_profile *dst)
{
    int k;
    memset(dst, 0, sizeof *dst);
    dst->sxx = src->sxx;
    dst->plane = src->plane;
    dst->total = src->total;
    for (k = 0; k < RL_PROFILE_BINS; k++) {
        double at = floor((k + 0.5) / s);
        int j = at >= RL_PROFILE_BINS - 1 ? RL_PROFILE_BINS - 1 : (int)at;
        dst->n[j] += src->n[k];
        dst->sx[j] += src->sx[k];
    }
}

/* At a tiny scale (a radius measured near 0) every bin's middle is past
 * the end: all in the last bin (before the twelfth session's edge round
 * the quotient was cast to int first, past int's range: undefined, a
 * write far outside the profile on x86). */
static void test_rescale_tiny_scale_to_last_bin(void **state)
{
    rl_profile p, q;
    rl_profile_scale sc;
    double tiny[] = {1e-300, 1e-12, 4e-9};
    int i, k;
    (void)state;
    memset(&p, 0, sizeof p);
    for (k = 0; k < RL_PROFILE_BINS; k++) {
        p.n[k] = 1;
        p.sx[k] = k;
    }
    for (i = 0; i < 3; i++) {
        rl_profile_rescale(&p, tiny[i], &q);
        for (k = 0; k < RL_PROFILE_BINS - 1; k++)
            assert_true(q.n[k] == 0 && q.sx[k] == 0);
        assert_true(q.n[RL_PROFILE_BINS - 1] == RL_PROFILE_BINS);
        assert_true(q.sx[RL_PROFILE_BINS - 1] == 0.5 * RL_PROFILE_BINS * (RL_PROFILE_BINS - 1));
        rl_profile_scale_make(tiny[i], &sc);
        for (k = 0; k < RL_PROFILE_BINS; k++)
            assert_int_equal(sc.to[k], RL_PROFILE_BINS - 1);
    }
    /* no caller's (the header: 0 < s <= 1), but a table built at s <= 0
     * must still index the profile: every move to bin 0 (before the
     * guard, -0.5 gave moves to 255 and 129) */
    for (i = 0; i < 2; i++) {
        rl_profile_scale_make(i == 0 ? -0.5 : -0.0, &sc);
        for (k = 0; k < RL_PROFILE_BINS; k++)
            assert_int_equal(sc.to[k], 0);
    }
}

/* A profile rescaled by the bins' moves worked out once for its scale
 * (rl_profile_scale_make) is the one rl_profile_rescale gives, and the
 * one the division gives (rescaled_by_division), bit for
 * bit, at the verification's radii and at random ones (half of them
 * decimals, where a bin's middle falls on a bin's edge: 26.5 / 0.53), on
 * random profiles with empty bins; a scale table made for another scale
 * gives another profile (the test tells them apart). */
static void test_rescale_by_moves_is_rescale(void **state)
{
    rl_profile p, a, b;
    rl_profile_scale sc;
    int trial, k, differ = 0;
    (void)state;
    for (trial = 0; trial < 400; trial++) {
        double s = trial < 5 ? (1.0 - (trial - 2) * 0.025) / 1.05
                   : trial % 2 ? 0.5 + 0.5 * uniform() : (double)(500 + (int)(uniform() * 500)) / 1000.0;
        for (k = 0; k < RL_PROFILE_BINS; k++) {
            p.n[k] = uniform() < 0.1 ? 0.0 : floor(uniform() * 300);
            p.sx[k] = p.n[k] * floor(uniform() * 1023) + uniform();
        }
        p.sxx = uniform();
        p.plane = uniform();
        p.total = uniform();
        rl_profile_scale_make(s, &sc);
        assert_true(sc.made && sc.s == s);
        rl_profile_rescale_by(&p, &sc, &a);
        rl_profile_rescale(&p, s, &b);
        assert_memory_equal(&a, &b, sizeof a);
        rescaled_by_division(&p, s, &b);
        assert_memory_equal(&a, &b, sizeof a);
        rl_profile_rescale(&p, s * 0.97, &b);
        differ += memcmp(&a, &b, sizeof a) != 0;
    }
    assert_true(differ > 300);
}

/* The wide kernel (1 .. RL_MATCH_WIDE blocks in one walk) gives each
 * column the bits of one block at a time, with empty bins and on a table
 * whose rows are longer than the blocks (the table's stride): blocks side
 * by side (rl_match_all) and blocks anywhere in the row, out of order and
 * overlapping (a list of ids' own columns, rl_match_ids); given fewer
 * blocks than RL_MATCH_WIDE (two ids of a list), it writes theirs and no
 * other sums. */
/* The three sums of RL_MATCH_WIDE blocks in s, each value v. */
static void fill(float s[3][RL_MATCH_WIDE * RL_MATCH_BLOCK], float v)
{
    int j, k;
    for (j = 0; j < 3; j++)
        for (k = 0; k < RL_MATCH_WIDE * RL_MATCH_BLOCK; k++)
            s[j][k] = v;
}

static void test_wide_kernel_is_blocks_bit_for_bit(void **state)
{
    enum { STRIDE = RL_MATCH_WIDE * RL_MATCH_BLOCK + 16 };
    static float t[RL_PROFILE_BINS * STRIDE];
    float fn[RL_PROFILE_BINS], fs[RL_PROFILE_BINS];
    float a[3][RL_MATCH_WIDE * RL_MATCH_BLOCK], b[3][RL_MATCH_WIDE * RL_MATCH_BLOCK];
    const float *blocks[RL_MATCH_WIDE];
    int trial, k, blk, nb;
    (void)state;
    for (trial = 0; trial < 200; trial++) {
        for (k = 0; k < RL_PROFILE_BINS * STRIDE; k++)
            t[k] = (float)uniform();
        for (k = 0; k < RL_PROFILE_BINS; k++) {
            fn[k] = uniform() < 0.2 ? 0.0f : (float)(uniform() * 300);
            fs[k] = fn[k] * (float)(uniform() * 255);
        }
        /* side by side from column 8; then three columns drawn anywhere
         * in the row's first STRIDE - RL_MATCH_BLOCK */
        for (blk = 0; blk < RL_MATCH_WIDE; blk++)
            blocks[blk] = t + (trial % 2 == 0 ? 8 + blk * RL_MATCH_BLOCK
                                              : (int)(uniform() * (STRIDE - RL_MATCH_BLOCK + 1)));
        for (nb = 1; nb <= RL_MATCH_WIDE; nb++) {
            /* -1, which no sum gives: what the kernels must write, and
             * past nb what they must leave */
            fill(a, -1.0f);
            for (blk = 0; blk < nb; blk++)
                rl_match_kernel_plain(blocks[blk], STRIDE, fn, fs, a[0] + blk * RL_MATCH_BLOCK,
                                      a[1] + blk * RL_MATCH_BLOCK, a[2] + blk * RL_MATCH_BLOCK);
            fill(b, -1.0f);
            rl_match_kernel_wide(blocks, nb, STRIDE, fn, fs, b[0], b[1], b[2]);
            assert_memory_equal(a, b, sizeof a);
            fill(b, -1.0f);
            rl_match_kernel_wide_blocks(blocks, nb, STRIDE, fn, fs, b[0], b[1], b[2]);
            assert_memory_equal(a, b, sizeof a);
#ifdef RL_HAVE_MATCH_KERNEL_V8
            if (__builtin_cpu_supports("avx")) {
                fill(b, -1.0f);
                rl_match_kernel_v8w(blocks, nb, STRIDE, fn, fs, b[0], b[1], b[2]);
                assert_memory_equal(a, b, sizeof a);
            }
#endif
        }
    }
}

/* Empty bins (fn 0, fs 0) add nothing: the 8-lane kernels add their zero
 * products where the plain kernel passes over them, and the sums must be
 * its bits. Templates of either sign and exact zeros (a zero product of
 * a negative value is -0), sums that cancel to 0 before an empty bin, a
 * profile empty but for one bin, and one with every bin empty (a column
 * below 0 throughout: a sum started at -0 would stay -0); the oracle is
 * the plain kernel's skip. */
static void test_empty_bins_add_nothing(void **state)
{
    enum { STRIDE = RL_MATCH_WIDE * RL_MATCH_BLOCK + 16 };
    static float t[RL_PROFILE_BINS * STRIDE];
    float fn[RL_PROFILE_BINS], fs[RL_PROFILE_BINS];
    float a[3][RL_MATCH_WIDE * RL_MATCH_BLOCK], b[3][RL_MATCH_WIDE * RL_MATCH_BLOCK];
    const float *blocks[RL_MATCH_WIDE];
    int trial, k, blk, nb;
    (void)state;
    for (trial = 0; trial < 300; trial++) {
        int kind = trial % 4;
        for (k = 0; k < RL_PROFILE_BINS * STRIDE; k++) {
            double u = uniform();
            t[k] = u < 0.1 ? 0.0f : (float)(2 * uniform() - 1);
        }
        for (k = 0; k < RL_PROFILE_BINS; k++) {
            fn[k] = kind == 3 || uniform() < 0.4 ? 0.0f : (float)(1 + (int)(uniform() * 30));
            fs[k] = fn[k] * (float)(uniform() * 255);
        }
        if (kind == 1) {
            /* bins 0 and 1 cancel in every column of the first block
             * (t and -t, one pixel each), then bin 2 is empty */
            for (k = 0; k < RL_MATCH_WIDE * RL_MATCH_BLOCK; k++)
                t[STRIDE + 8 + k] = -t[8 + k];
            fn[0] = fn[1] = 1;
            fs[0] = fs[1] = 7;
            fn[2] = fs[2] = 0;
        } else if (kind == 2) {
            for (k = 0; k < RL_PROFILE_BINS; k++)
                fn[k] = fs[k] = 0;
            fn[33] = 5;
            fs[33] = 600;
        } else if (kind == 3) {
            /* every bin empty and a column below 0 in every bin: each
             * product is -0, and the sum must stay the +0 it starts at */
            for (k = 0; k < RL_PROFILE_BINS; k++)
                t[k * STRIDE + 8 + 3] = -(float)(0.5 + uniform());
        }
        for (blk = 0; blk < RL_MATCH_WIDE; blk++)
            blocks[blk] = t + 8 + blk * RL_MATCH_BLOCK;
        for (nb = 1; nb <= RL_MATCH_WIDE; nb++) {
            fill(a, -1.0f);
            for (blk = 0; blk < nb; blk++)
                rl_match_kernel_plain(blocks[blk], STRIDE, fn, fs, a[0] + blk * RL_MATCH_BLOCK,
                                      a[1] + blk * RL_MATCH_BLOCK, a[2] + blk * RL_MATCH_BLOCK);
            fill(b, -1.0f);
            rl_match_kernel_wide(blocks, nb, STRIDE, fn, fs, b[0], b[1], b[2]);
            assert_memory_equal(a, b, sizeof a);
            fill(b, -1.0f);
            for (blk = 0; blk < nb; blk++)
                rl_match_kernel(blocks[blk], STRIDE, fn, fs, b[0] + blk * RL_MATCH_BLOCK,
                                b[1] + blk * RL_MATCH_BLOCK, b[2] + blk * RL_MATCH_BLOCK);
            assert_memory_equal(a, b, sizeof a);
        }
    }
}

/* A profile with empty bins (a gather's rows miss the innermost bins, a
 * rescale skips one) scores as a direct double-precision correlation
 * over its bins says (direct_r, written from the formula), every id at
 * every blur: the best, its score and the runner-up's. */
static void test_scores_with_empty_bins_match_a_direct_correlation(void **state)
{
    static unsigned char mem[1 << 16];
    rl_family fam = {5};
    rl_templates tt;
    rl_ws ws;
    int trial;
    (void)state;
    rl_ws_init(&ws, mem, sizeof mem);
    assert_int_equal(rl_templates_init(&tt, &ws, &fam, NULL, 0), RL_OK);
    for (trial = 0; trial < 100; trial++) {
        int i = (int)(uniform() * tt.n), b = (int)(uniform() * RL_BLUR_LEVELS), k, j, best_id = -1;
        double best = -2, second = -2;
        rl_profile p;
        rl_match m;
        memset(&p, 0, sizeof p);
        for (k = 0; k < RL_PROFILE_BINS; k++) {
            double n = uniform() < 0.15 || (k < 6 && uniform() < 0.6) ? 0 : 3 + (int)(uniform() * 40),
                   v = 40 + 180 * rl_templates_bin(&tt, i, b, k) + 30 * (uniform() - 0.5);
            p.n[k] = n;
            p.sx[k] = n * v;
            p.sxx += n * v * v + n * 25.0;
            p.total += n;
        }
        rl_match_all(&tt, &p, &m);
        for (j = 0; j < tt.n; j++)
            for (k = 0; k < RL_BLUR_LEVELS; k++) {
                double r = direct_r(&p, &tt, j, k);
                if (r > best) {
                    if (tt.ids[j] != best_id)
                        second = best;
                    best = r;
                    best_id = tt.ids[j];
                } else if (r > second && tt.ids[j] != best_id) {
                    second = r;
                }
            }
        assert_int_equal(m.id, best_id);
        assert_true(fabs(m.score - best) < 1e-4);
        assert_true(fabs(m.second - second) < 1e-4);
    }
}

/* Every id matched (rl_match_all: wide blocks over the table) and every id
 * listed (rl_match_ids: each id's own columns) give the same match, bit for
 * bit, on noisy profiles of random ids and on profiles of noise, for
 * families whose column count leaves the last wide block short. */
static void test_match_all_is_every_id_listed(void **state)
{
    static unsigned char mem[1 << 18];
    int bits, trial, k, j;
    (void)state;
    for (bits = 3; bits <= 6; bits++) {
        rl_family fam;
        rl_templates tt;
        rl_ws ws;
        int ids[64];
        fam.bits = bits;
        rl_ws_init(&ws, mem, sizeof mem);
        assert_int_equal(rl_templates_init(&tt, &ws, &fam, NULL, 0), RL_OK);
        for (j = 0; j < tt.n; j++)
            ids[j] = tt.ids[j];
        for (trial = 0; trial < 60; trial++) {
            int i = (int)(uniform() * tt.n), b = (int)(uniform() * RL_BLUR_LEVELS), noise = trial % 3 == 0;
            rl_profile p;
            rl_match m, ml;
            memset(&p, 0, sizeof p);
            for (k = 0; k < RL_PROFILE_BINS; k++) {
                double n = uniform() < 0.1 ? 0 : (double)(int)(uniform() * 40 * (k + 1) / 8);
                double v = noise ? 255 * uniform() : 40 + 180 * rl_templates_bin(&tt, i, b, k) + 40 * (uniform() - 0.5);
                p.n[k] = n;
                p.sx[k] = (double)(int)(n * v);
                p.sxx += n * v * v + n * 30.0;
                p.total += n;
            }
            rl_match_all(&tt, &p, &m);
            rl_match_ids(&tt, &p, ids, tt.n, -1, &ml);
            assert_int_equal(m.id, ml.id);
            assert_int_equal(m.blur, ml.blur);
            assert_memory_equal(&m.score, &ml.score, sizeof m.score);
            assert_memory_equal(&m.second, &ml.second, sizeof m.second);
            assert_memory_equal(&m.contrast, &ml.contrast, sizeof m.contrast);
            if (!noise)
                assert_int_equal(m.id, tt.ids[i]);
        }
    }
}

/* Each id's own best (rl_match_ids_each, the zone twins' check's scores):
 * the direct correlation's best over the id's blurs, computed here from
 * the template bins; bit for bit what rl_match_ids gives the id alone;
 * -2 for an id the table does not hold and for a profile too small to
 * correlate. */

/* A profile drawn from template i at blur b, grey 40 .. 220, each bin
 * (10 + 8 k pixels) off by up to amp / 2 and its spread 30 a pixel. */
static void noisy_profile(const rl_templates *tt, int i, int b, double amp, rl_profile *p)
{
    int k;
    memset(p, 0, sizeof *p);
    for (k = 0; k < RL_PROFILE_BINS; k++) {
        double cnt = 10 + 8 * k, v = 40 + 180 * rl_templates_bin(tt, i, b, k) + amp * (uniform() - 0.5);
        p->n[k] = cnt;
        p->sx[k] = cnt * v;
        p->sxx += cnt * v * v + cnt * 30.0;
        p->total += cnt;
    }
}

static void test_each_id_is_its_own_best(void **state)
{
    static unsigned char mem[1 << 18];
    int bits, trial, k, j;
    (void)state;
    for (bits = 5; bits <= 6; bits++) {
        rl_family fam;
        rl_templates tt;
        rl_ws ws;
        fam.bits = bits;
        rl_ws_init(&ws, mem, sizeof mem);
        assert_int_equal(rl_templates_init(&tt, &ws, &fam, NULL, 0), RL_OK);
        for (trial = 0; trial < 40; trial++) {
            int i = (int)(uniform() * tt.n), b = (int)(uniform() * RL_BLUR_LEVELS), codes[RL_MAX_BITS + 2], n, nonid;
            double best[RL_MAX_BITS + 2];
            rl_profile p;
            noisy_profile(&tt, i, b, 40, &p);
            codes[0] = tt.ids[i];
            n = 1 + rl_family_zone_twins(&fam, codes[0], codes + 1);
            /* not an id, anywhere in the list (the ids are scored three
             * a walk: one passed over must not shift the rest) */
            nonid = trial % (n + 1);
            for (j = n; j > nonid; j--)
                codes[j] = codes[j - 1];
            codes[nonid] = -5;
            n++;
            rl_match_ids_each(&tt, &p, codes, n, best);
            for (j = 0; j < n; j++) {
                int t = rl_templates_find(&tt, codes[j]);
                double want = -2;
                rl_match m;
                if (j == nonid)
                    continue;
                for (k = 0; k < RL_BLUR_LEVELS; k++)
                    want = fmax(want, direct_r(&p, &tt, t, k));
                assert_true(fabs(best[j] - want) < 1e-4);
                rl_match_ids(&tt, &p, &codes[j], 1, -1, &m);
                assert_memory_equal(&best[j], &m.score, sizeof m.score);
            }
            assert_true(best[nonid] == -2);
            p.total = 10; /* too few pixels */
            rl_match_ids_each(&tt, &p, codes, n, best);
            for (j = 0; j < n; j++)
                assert_true(best[j] == -2);
        }
    }
}

/* An id's index: the first place of it in the table's ids (a linear
 * search here), -1 for any other number. */
static int first_place(const rl_templates *tt, int id)
{
    int i;
    for (i = 0; i < tt->n; i++)
        if (tt->ids[i] == id)
            return i;
    return -1;
}

/* Every field the same, bit for bit. */
static int same_match(const rl_match *a, const rl_match *b)
{
    return a->id == b->id && a->blur == b->blur && memcmp(&a->score, &b->score, sizeof a->score) == 0 &&
           memcmp(&a->second, &b->second, sizeof a->second) == 0 &&
           memcmp(&a->contrast, &b->contrast, sizeof a->contrast) == 0;
}

/* rl_match_id_and_ids (the zone twins' check: an id and its rivals on one
 * profile) gives what rl_match_ids gives for the id alone and for the
 * rivals, and the id's score is the direct correlation's best over its
 * blurs; rl_templates_find is the first place of an id, on the whole
 * family and on a table of ids out of order with one repeated. */
static void test_id_and_rivals_at_once(void **state)
{
    static unsigned char mem[1 << 18];
    static const int some[] = {9, 3, 30, 3, 17, 1, 22, 9};
    int table, trial, k, j;
    (void)state;
    for (table = 0; table < 3; table++) {
        rl_family fam;
        rl_templates tt;
        rl_ws ws;
        fam.bits = table == 1 ? 6 : 5;
        rl_ws_init(&ws, mem, sizeof mem);
        assert_int_equal(rl_templates_init(&tt, &ws, &fam, table == 2 ? some : NULL, table == 2 ? 8 : 0), RL_OK);
        for (k = -3; k < 300; k++)
            assert_int_equal(rl_templates_find(&tt, k), first_place(&tt, k));
        for (trial = 0; trial < 40; trial++) {
            int i = (int)(uniform() * tt.n), b = (int)(uniform() * RL_BLUR_LEVELS), rv[RL_MAX_IDS + 1], n = 0, flat;
            rl_profile p;
            noisy_profile(&tt, i, b, 60, &p);
            for (j = 0; j < tt.n; j++)
                if (tt.ids[j] != tt.ids[i] && uniform() < 0.7)
                    rv[n++] = tt.ids[j];
            rv[n++] = 255 - table; /* not in the table (no family here reaches 254) */
            for (flat = 0; flat < 2; flat++) {
                rl_match own, them, want_own, want_them;
                double direct = -2;
                if (flat)
                    p.total = 10; /* too few pixels: nothing matched */
                rl_match_id_and_ids(&tt, &p, tt.ids[i], rv, n, -1, &own, &them);
                rl_match_ids(&tt, &p, &tt.ids[i], 1, -1, &want_own);
                rl_match_ids(&tt, &p, rv, n, -1, &want_them);
                assert_true(same_match(&own, &want_own));
                assert_true(same_match(&them, &want_them));
                for (k = 0; k < RL_BLUR_LEVELS; k++)
                    direct = fmax(direct, direct_r(&p, &tt, first_place(&tt, tt.ids[i]), k));
                if (!flat) {
                    assert_int_equal(own.id, tt.ids[i]);
                    assert_true(fabs(own.score - direct) < 1e-4);
                } else {
                    assert_int_equal(own.id, -1);
                    assert_int_equal(them.id, -1);
                }
            }
        }
    }
}

/* rl_match_id_and_rest (a local read's zone twins' check: its id and
 * every other id of the table, rl_twins) gives, bit for bit, what
 * rl_match_id_and_ids gives for the id and the list of every other id in
 * table order (the old computation, the oracle here): whole families of
 * 5 to 8 bits (each id's block of columns in the table, which the old
 * call scores in place) and 8 ids out of order (the last id's block runs
 * past the table: the old call copies it into a list); profiles
 * drawn from the id, from another id, and noise; too few pixels. */
static void test_id_and_rest_is_every_other_listed(void **state)
{
    static unsigned char mem[1 << 19];
    static const int some[] = {9, 3, 30, 17, 1, 22, 12, 5}; /* 56 columns: the last id's block runs past them */
    int table, trial, j;
    (void)state;
    for (table = 0; table < 5; table++) {
        rl_family fam;
        rl_templates tt;
        rl_ws ws;
        fam.bits = table < 4 ? 5 + table : 5;
        rl_ws_init(&ws, mem, sizeof mem);
        assert_int_equal(rl_templates_init(&tt, &ws, &fam, table == 4 ? some : NULL, table == 4 ? 8 : 0), RL_OK);
        /* the whole families' last ids have a whole block after them (the
         * old call scores each id in place); the 8 ids' last has not (it
         * is copied into a list) */
        assert_int_equal((tt.n - 1) * RL_BLUR_LEVELS + RL_MATCH_BLOCK <= tt.stride, table < 4);
        for (trial = 0; trial < 60; trial++) {
            int i = (int)(uniform() * tt.n), src = trial % 3 == 0 ? (int)(uniform() * tt.n) : i;
            int b = (int)(uniform() * RL_BLUR_LEVELS), rv[RL_MAX_IDS], n = 0, flat;
            rl_profile p;
            noisy_profile(&tt, src, b, trial % 3 == 2 ? 400 : 60, &p);
            for (j = 0; j < tt.n; j++)
                if (tt.ids[j] != tt.ids[i])
                    rv[n++] = tt.ids[j];
            for (flat = 0; flat < 2; flat++) {
                rl_match own, rest, want_own, want_rest;
                if (flat)
                    p.total = 10; /* too few pixels: nothing matched */
                rl_match_id_and_rest(&tt, &p, tt.ids[i], &own, &rest);
                rl_match_id_and_ids(&tt, &p, tt.ids[i], rv, n, -1, &want_own, &want_rest);
                assert_true(same_match(&own, &want_own));
                assert_true(same_match(&rest, &want_rest));
                if (!flat && src == i && trial % 3 != 2)
                    assert_int_equal(own.id, tt.ids[i]);
            }
        }
    }
}

/* rl_match_all_kept is rl_match_all, and rl_match_kept_ids from its sums
 * (in the caller's block, as rl_match_kept_init carves them; or none kept
 * where the room is short of the table) is rl_match_ids at every blur
 * (the old calls, the oracle), on one id and on lists of ids (the same id
 * twice in some),
 * every field the same bits: whole families of 5 to 8 bits (each id's
 * last block in place) and 8 ids out of order (the last id's block runs
 * past the table: the old call copies it into a list), every id of the
 * table and ids it does not hold, profiles drawn from an id, from another
 * id and from noise, and a profile of too few pixels. */
static void test_kept_sums_are_the_ids_read_again(void **state)
{
    static unsigned char mem[1 << 19];
    static const int some[] = {9, 3, 30, 17, 1, 22, 12, 5};
    int table, trial, j;
    (void)state;
    for (table = 0; table < 5; table++) {
        rl_family fam;
        rl_templates tt;
        rl_match_kept *kp, *none;
        rl_ws ws, sizing;
        size_t before;
        fam.bits = table < 4 ? 5 + table : 5;
        rl_ws_init(&ws, mem, sizeof mem);
        assert_int_equal(rl_templates_init(&tt, &ws, &fam, table == 4 ? some : NULL, table == 4 ? 8 : 0), RL_OK);
        /* the room is the table's columns, 3 floats each, in the caller's
         * block, and sizing counts what init takes */
        rl_ws_init_sizing(&sizing);
        assert_int_equal(rl_match_kept_init(&none, &sizing, &tt), RL_OK);
        assert_null(none);
        assert_int_equal(sizing.peak, rl_match_kept_bytes(tt.stride));
        before = rl_ws_mark(&ws);
        assert_int_equal(rl_match_kept_init(&kp, &ws, &tt), RL_OK);
        assert_true(rl_ws_mark(&ws) - before <= rl_match_kept_bytes(tt.stride));
        assert_true(rl_ws_mark(&ws) - before >= sizeof *kp + (size_t)tt.stride * 3 * sizeof(float));
        assert_int_equal(kp->columns, tt.stride);
        assert_true((unsigned char *)kp >= mem && (unsigned char *)(kp->sxt + tt.stride) <= mem + sizeof mem);
        for (trial = 0; trial < 40; trial++) {
            rl_match_kept keep = *kp;
            int i = (int)(uniform() * tt.n), src = trial % 3 == 0 ? (int)(uniform() * tt.n) : i;
            int b = (int)(uniform() * RL_BLUR_LEVELS), flat;
            rl_profile p;
            noisy_profile(&tt, src, b, trial % 3 == 2 ? 400 : 60, &p);
            for (flat = 0; flat < 2; flat++) {
                rl_match m, want;
                if (flat)
                    p.total = 10; /* too few pixels: nothing matched */
                if (trial % 10 == 9)
                    keep.columns = tt.stride - RL_MATCH_BLOCK; /* too little room: none kept */
                rl_match_all_kept(&tt, &p, &m, &keep);
                rl_match_all(&tt, &p, &want);
                assert_true(same_match(&m, &want));
                assert_int_equal(keep.state, flat              ? RL_MATCH_KEPT_FLAT
                                             : trial % 10 == 9 ? RL_MATCH_KEPT_NONE
                                                               : RL_MATCH_KEPT_SUMS);
                for (j = -1; j <= tt.n; j++) {
                    /* the table's ids, one under them and one past them */
                    int id = j < 0 ? 0 : j < tt.n ? tt.ids[j] : (1 << fam.bits) - 1;
                    rl_match got, old;
                    if (j == tt.n && table < 4)
                        id = 1 << fam.bits; /* no id of a whole family */
                    rl_match_kept_ids(&tt, &p, &keep, &id, 1, &got);
                    rl_match_ids(&tt, &p, &id, 1, -1, &old);
                    assert_true(same_match(&got, &old));
                    if (!flat && j >= 0 && j < tt.n)
                        assert_true(got.id == id);
                }
                for (j = 0; j < 6; j++) {
                    /* lists of 1 to 9 ids in any order, with ids the
                     * table does not hold among them */
                    int list[9], nl = 1 + (int)(uniform() * 9), q;
                    rl_match got, old;
                    for (q = 0; q < nl; q++)
                        list[q] = uniform() < 0.15 ? 0 : tt.ids[(int)(uniform() * tt.n)];
                    rl_match_kept_ids(&tt, &p, &keep, list, nl, &got);
                    rl_match_ids(&tt, &p, list, nl, -1, &old);
                    assert_true(same_match(&got, &old));
                }
            }
        }
    }
}

/* rl_match_all_kept_as is rl_match_all_kept wherever the latter's winner
 * is the id at a blur up to max_blur (every field and every column's kept
 * sums the same bits), and says 0 only where it is not (the oracle: the
 * full match, rl_match_all): every id of the table at every max_blur, on
 * profiles drawn from that id at each blur (the blurrier ones win past
 * max_blur), from another id and from noise, on whole families and on 8
 * ids out of order (the last id's block runs past the table: the whole
 * match, as rl_match_all_kept), and a profile of too few pixels. */
static void test_kept_as_is_kept_where_the_id_wins(void **state)
{
    static unsigned char mem[1 << 19];
    static const int some[] = {9, 3, 30, 17, 1, 22, 12, 5};
    int table, trial, stops = 0, wins = 0;
    (void)state;
    for (table = 0; table < 3; table++) {
        rl_family fam;
        rl_templates tt;
        rl_match_kept *ka, *kb;
        rl_ws ws;
        fam.bits = table == 1 ? 6 : 5;
        rl_ws_init(&ws, mem, sizeof mem);
        assert_int_equal(rl_templates_init(&tt, &ws, &fam, table == 2 ? some : NULL, table == 2 ? 8 : 0), RL_OK);
        assert_int_equal(rl_match_kept_init(&ka, &ws, &tt), RL_OK);
        assert_int_equal(rl_match_kept_init(&kb, &ws, &tt), RL_OK);
        for (trial = 0; trial < 60; trial++) {
            int i = (int)(uniform() * tt.n), src = trial % 4 == 0 ? (int)(uniform() * tt.n) : i;
            int b = trial % RL_BLUR_LEVELS, mb, flat = trial % 15 == 14;
            rl_profile p;
            noisy_profile(&tt, src, b, trial % 4 == 3 ? 400 : 40, &p);
            if (flat)
                p.total = 10; /* too few pixels: nothing matched */
            for (mb = 0; mb < RL_BLUR_LEVELS; mb++) {
                rl_match got, want;
                int as = rl_match_all_kept_as(&tt, &p, tt.ids[i], mb, &got, ka);
                rl_match_all_kept(&tt, &p, &want, kb);
                if (!as) {
                    stops++;
                    assert_false(want.id == tt.ids[i] && want.blur <= mb);
                    assert_int_equal(ka->state, RL_MATCH_KEPT_NONE);
                    continue;
                }
                wins += want.id == tt.ids[i] && want.blur <= mb;
                assert_true(same_match(&got, &want));
                assert_int_equal(ka->state, kb->state);
                if (kb->state == RL_MATCH_KEPT_SUMS) {
                    assert_memory_equal(ka->st, kb->st, (size_t)tt.stride * sizeof *ka->st);
                    assert_memory_equal(ka->stt, kb->stt, (size_t)tt.stride * sizeof *ka->stt);
                    assert_memory_equal(ka->sxt, kb->sxt, (size_t)tt.stride * sizeof *ka->sxt);
                    assert_memory_equal(&ka->ivx, &kb->ivx, sizeof ka->ivx);
                }
            }
        }
    }
    /* both ways taken many times: stopped, and read to the end with the id winning */
    assert_true(stops > 200);
    assert_true(wins > 200);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_kernels_agree_bit_for_bit),
        cmocka_unit_test(test_rescaled_profile_moves_bins),
        cmocka_unit_test(test_rescale_by_moves_is_rescale),
        cmocka_unit_test(test_rescale_tiny_scale_to_last_bin),
        cmocka_unit_test(test_scores_match_a_direct_correlation),
        cmocka_unit_test(test_wide_kernel_is_blocks_bit_for_bit),
        cmocka_unit_test(test_empty_bins_add_nothing),
        cmocka_unit_test(test_scores_with_empty_bins_match_a_direct_correlation),
        cmocka_unit_test(test_match_all_is_every_id_listed),
        cmocka_unit_test(test_each_id_is_its_own_best),
        cmocka_unit_test(test_id_and_rivals_at_once),
        cmocka_unit_test(test_id_and_rest_is_every_other_listed),
        cmocka_unit_test(test_kept_sums_are_the_ids_read_again),
        cmocka_unit_test(test_kept_as_is_kept_where_the_id_wins),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
