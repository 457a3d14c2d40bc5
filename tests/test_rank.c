/* rl_rank: the score of a template through any monotone curve. By hand on
 * three bins (the isotonic fit pools the bins whose order disagrees with
 * the template's and the score is what is left of the template's spread),
 * and on whole profiles: a landmark's profile bent by any increasing curve
 * scores 1 for its own id, and its zone twin less. The early exits
 * (rl_rank_score_over, rl_rank_any_over) against an isotonic regression
 * written out here from its min-max formula, on noisy profiles. */
#include "rl_test.h"
#include <math.h>
#include <string.h>
#include "rl_rank.h"

static unsigned char mem[1 << 16];

static void templates(rl_templates *tt)
{
    rl_family fam = {5};
    rl_ws ws;
    rl_ws_init(&ws, mem, sizeof mem);
    assert_int_equal(rl_templates_init(tt, &ws, &fam, NULL, 0), RL_OK);
}

/* Three bins of id 23 at blur 0 whose template values differ, in rising
 * order of the value: (k[0], k[1], k[2]). */
static void three_bins(const rl_templates *tt, int i, int *k)
{
    int a, b, c;
    for (a = 0; a < RL_PROFILE_BINS; a++)
        for (b = 0; b < RL_PROFILE_BINS; b++)
            for (c = 0; c < RL_PROFILE_BINS; c++) {
                double ta = rl_templates_bin(tt, i, 0, a), tb = rl_templates_bin(tt, i, 0, b),
                       tc = rl_templates_bin(tt, i, 0, c);
                if (tb > ta + 0.2 && tc > tb + 0.2) {
                    k[0] = a, k[1] = b, k[2] = c;
                    return;
                }
            }
    fail_msg("no three distinct template values");
}

static double by_order(const rl_templates *tt, int i, const int *k, const double *dark)
{
    rl_profile p;
    rl_rank_order o;
    int j;
    memset(&p, 0, sizeof p);
    for (j = 0; j < 3; j++) {
        p.n[k[j]] = 10;
        p.sx[k[j]] = 10 * dark[j];
    }
    rl_rank_sort(&p, &o);
    assert_int_equal(o.n, 3);
    return rl_rank_score(tt, &o, i, 0);
}

static void test_three_bins_by_hand(void **state)
{
    rl_templates tt;
    int k[3] = {0, 0, 0}, i;
    double t1, t2, t3, m, sst, sse;
    static const double rising[3] = {10, 20, 30}, falling[3] = {30, 20, 10}, swap[3] = {20, 10, 30};
    (void)state;
    templates(&tt);
    i = rl_templates_find(&tt, 23);
    three_bins(&tt, i, k);
    t1 = rl_templates_bin(&tt, i, 0, k[0]);
    t2 = rl_templates_bin(&tt, i, 0, k[1]);
    t3 = rl_templates_bin(&tt, i, 0, k[2]);
    m = (t1 + t2 + t3) / 3;
    sst = (t1 - m) * (t1 - m) + (t2 - m) * (t2 - m) + (t3 - m) * (t3 - m);
    /* darkness rising with the template: an increasing curve fits exactly */
    assert_true(fabs(by_order(&tt, i, k, rising) - 1.0) < 1e-9);
    /* falling: the fit pools all three into their mean, nothing explained */
    assert_true(fabs(by_order(&tt, i, k, falling)) < 1e-9);
    /* the first two swapped: they pool at (t1 + t2) / 2, the third stays */
    sse = (t1 - t2) * (t1 - t2) / 2;
    assert_true(fabs(by_order(&tt, i, k, swap) - (1.0 - sse / sst)) < 1e-6);
}

/* Id 23's profile at blur b with its darkness through curve f (the pixels
 * each bin holds: as many as its ring of radii), its rank score for id. */
static double bent(const rl_templates *tt, int b, double (*f)(double), int id)
{
    rl_profile p;
    rl_rank_order o;
    int k, i = rl_templates_find(tt, 23);
    memset(&p, 0, sizeof p);
    for (k = 0; k < RL_PROFILE_BINS; k++) {
        p.n[k] = 2 * k + 1;
        p.sx[k] = p.n[k] * f(rl_templates_bin(tt, i, b, k));
    }
    rl_rank_sort(&p, &o);
    return rl_rank_score(tt, &o, rl_templates_find(tt, id), b);
}

static double cube(double t) { return 255 * t * t * t; }
static double root(double t) { return 255 * pow(t, 1 / 2.2); }

static void test_any_increasing_curve_reads_the_id(void **state)
{
    rl_templates tt;
    int b;
    (void)state;
    templates(&tt);
    for (b = 0; b < RL_BLUR_LEVELS; b++) {
        assert_true(bent(&tt, b, cube, 23) > 1 - 1e-9);
        assert_true(bent(&tt, b, root, 23) > 1 - 1e-9);
        /* the zone twin (zone 1 white) is explained less through either */
        assert_true(bent(&tt, b, cube, 7) < 1 - 1e-3);
        assert_true(bent(&tt, b, root, 7) < 1 - 1e-3);
    }
}

/* Isotonic regression by its min-max formula (the fit at position k is
 * the largest over a <= k of the least over b >= k of the weighted mean
 * of a .. b), its score 1 - SSE / SST: the oracle, O(n^3). */
static double oracle(const rl_templates *tt, const rl_rank_order *o, int i, int b)
{
    double t[RL_PROFILE_BINS], cw[RL_PROFILE_BINS + 1], cs[RL_PROFILE_BINS + 1], sse = 0, sst = 0, mean;
    int k, a, z;
    cw[0] = cs[0] = 0;
    for (k = 0; k < o->n; k++) {
        t[k] = rl_templates_bin(tt, i, b, o->bin[k]);
        cw[k + 1] = cw[k] + o->w[k];
        cs[k + 1] = cs[k] + o->w[k] * t[k];
    }
    mean = cs[o->n] / cw[o->n];
    for (k = 0; k < o->n; k++) {
        double fit = -1e9;
        for (a = 0; a <= k; a++) {
            double least = 1e9;
            for (z = k; z < o->n; z++) {
                double m = (cs[z + 1] - cs[a]) / (cw[z + 1] - cw[a]);
                least = m < least ? m : least;
            }
            fit = least > fit ? least : fit;
        }
        sse += o->w[k] * (t[k] - fit) * (t[k] - fit);
        sst += o->w[k] * (t[k] - mean) * (t[k] - mean);
    }
    return 1.0 - sse / sst;
}

static unsigned lcg = 12345;
static double uniform(void)
{
    lcg = lcg * 1103515245u + 12345u;
    return (double)((lcg >> 8) & 0xffff) / 65536.0;
}

/* A profile of id at blur b through a curve, with noise (amp, in the
 * darkness's 0 .. 255) and every 7th bin empty. */
static void noisy(const rl_templates *tt, int id, int b, double amp, rl_profile *p)
{
    int k, i = rl_templates_find(tt, id);
    memset(p, 0, sizeof *p);
    for (k = 0; k < RL_PROFILE_BINS; k++) {
        if (k % 7 == 3)
            continue;
        p->n[k] = 2 * k + 1;
        p->sx[k] = p->n[k] * (255 * pow(rl_templates_bin(tt, i, b, k), 0.6) + amp * (uniform() - 0.5));
    }
}

static void test_early_exits_agree_with_the_oracle(void **state)
{
    static const int ids[4] = {23, 7, 21, 12};
    static const double amps[3] = {0, 40, 120};
    rl_templates tt;
    int c = 0, kept = 0;
    (void)state;
    templates(&tt);
    for (c = 0; c < 12; c++) {
        rl_profile p;
        rl_rank_order o;
        int i, b;
        noisy(&tt, ids[c % 4], c % RL_BLUR_LEVELS, amps[c % 3], &p);
        rl_rank_sort(&p, &o);
        for (i = 0; i < tt.n; i++) {
            double best = -1;
            for (b = 0; b < RL_BLUR_LEVELS; b++) {
                double want = oracle(&tt, &o, i, b), bar = want - 0.01 + 0.02 * uniform();
                double got = rl_rank_score_over(&tt, &o, i, b, bar);
                assert_true(fabs(rl_rank_score(&tt, &o, i, b) - want) < 1e-9);
                if (want > bar)
                    assert_true(fabs(got - want) < 1e-9), kept++;
                else
                    assert_true(got <= bar);
                best = want > best ? want : best;
            }
            /* any blur over a bar just under, or just over, the best */
            assert_int_equal(rl_rank_any_over(&tt, &o, i, best - 1e-6), 1);
            assert_int_equal(rl_rank_any_over(&tt, &o, i, best + 1e-6), 0);
            assert_int_equal(rl_rank_any_over(&tt, &o, i, best - 0.05), 1);
        }
    }
    /* bars fell on both sides */
    assert_true(kept > 100 && kept < 12 * 30 * RL_BLUR_LEVELS - 100);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_three_bins_by_hand),
        cmocka_unit_test(test_any_increasing_curve_reads_the_id),
        cmocka_unit_test(test_early_exits_agree_with_the_oracle),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
