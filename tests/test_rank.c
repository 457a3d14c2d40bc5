/* rl_rank: the score of a template through any monotone curve. By hand on
 * three bins (the isotonic fit pools the bins whose order disagrees with
 * the template's and the score is what is left of the template's spread),
 * and on whole profiles: a landmark's profile bent by any increasing curve
 * scores 1 for its own id, and its zone twin less. */
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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_three_bins_by_hand),
        cmocka_unit_test(test_any_increasing_curve_reads_the_id),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
