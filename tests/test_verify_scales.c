/* Verification's zone twins' check (rl_verify.c, twin_fits_as_well): a
 * taken id is refused when one of its zone twins, at its own best of the
 * radii tried, matches as well as the id at the id's best. The check does
 * not score the radius the id was taken at again (every id was matched
 * there, so no twin scored over the runner-up); this test holds its
 * decision against the rule worked out in full, here: every code one zone
 * from the id and the id itself, a direct double-precision Pearson
 * correlation (an oracle written from the formula) at every blur and every
 * radius tried, nothing skipped.
 *
 * The profiles are drawn here: a landmark that is a blend of an id's and a
 * zone twin's templates, at a true radius 0.92-1.04 of the predicted one,
 * gathered 1.05 radii wide as verification gathers it; the check is asked
 * for every radius it could have taken the id at (the match of every id
 * there names the id). The cases where the answer is a twin, where it is
 * the id, and where the id's best is at another radius than the one it
 * was taken at are counted and must be there in numbers: skipping another
 * radius than the read's (either neighbour), skipping every radius, or
 * taking another score than the read's for the id there gives other
 * answers on some of them. */
#include "rl_test.h"
#include <math.h>
#include "rl_verify.c"

static uint64_t rng = 4242;
static double uniform(void)
{
    rng = rng * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(rng >> 11) / 9007199254740992.0;
}

/* The radii tried, as scales of the gathered profile: the prediction's
 * radius and 2.5% and 5% either side, gathered 1.05 radii wide. */
#define N_SCALES 5
static double scale_at(int k)
{
    return (1.0 - (k - 2) * 0.025) / 1.05;
}

/* Pearson's r over the bins in double precision (n_k pixels of summed
 * darkness sx_k against template value t_k, the profile's own sxx less
 * the plane), -2 where the profile is too small or flat to correlate. */
static double direct_r(const rl_profile *p, const rl_templates *tt, int i, int b)
{
    double n = 0, sx = 0, st = 0, stt = 0, sxt = 0, vx;
    int k;
    for (k = 0; k < RL_PROFILE_BINS; k++) {
        double tv = rl_templates_bin(tt, i, b, k);
        n += p->n[k];
        sx += p->sx[k];
        st += p->n[k] * tv;
        stt += p->n[k] * tv * tv;
        sxt += p->sx[k] * tv;
    }
    vx = n * (p->sxx - p->plane) - sx * sx;
    if (p->total < 16 || !(vx > 0))
        return -2;
    return (n * sxt - sx * st) / sqrt(vx * (n * stt - st * st));
}

/* code's best over every blur and every radius tried (*at: the radius) */
static double best_everywhere(const rl_templates *tt, const rl_profile *wide, int code, int *at)
{
    double best = -2;
    int k, b, i = rl_templates_find(tt, code);
    for (k = 0; k < N_SCALES; k++) {
        rl_profile q;
        rl_profile_rescale(wide, scale_at(k), &q);
        for (b = 0; b < RL_BLUR_LEVELS; b++) {
            double r = direct_r(&q, tt, i, b);
            if (r > best) {
                best = r;
                *at = k;
            }
        }
    }
    return best;
}

/* Template i at blur b read at radius rho (in radii of the landmark),
 * linear between the bins' middles; past the profile's extent the last
 * bin's (the quiet zone). */
static double template_at(const rl_templates *tt, int i, int b, double rho)
{
    double x = rho / RL_PROFILE_EXTENT * RL_PROFILE_BINS - 0.5, f;
    int k;
    if (x <= 0)
        return rl_templates_bin(tt, i, b, 0);
    if (x >= RL_PROFILE_BINS - 1)
        return rl_templates_bin(tt, i, b, RL_PROFILE_BINS - 1);
    k = (int)x;
    f = x - k;
    return (1 - f) * rl_templates_bin(tt, i, b, k) + f * rl_templates_bin(tt, i, b, k + 1);
}

/* A profile gathered 1.05 predicted radii wide of a landmark of true
 * radius f (in predicted radii) that is the blend a * template ia + (1 - a)
 * * template ib at blur b, a third of the rows (uneven counts), noisy. */
static void draw_profile(const rl_templates *tt, int ia, int ib, double a, int b, double f, rl_profile *p)
{
    int k;
    memset(p, 0, sizeof *p);
    for (k = 0; k < RL_PROFILE_BINS; k++) {
        double rho = (k + 0.5) / RL_PROFILE_BINS * RL_PROFILE_EXTENT * 1.05 / f;
        double t = a * template_at(tt, ia, b, rho) + (1 - a) * template_at(tt, ib, b, rho);
        double n = floor((2 * k + 1) * (0.3 + 0.4 * uniform())) + 1;
        double v = 40 + 180 * t + 12 * (uniform() - 0.5);
        p->n[k] = n;
        p->sx[k] = n * v;
        p->sxx += n * v * v + n * 20.0; /* some spread within the bin */
        p->total += n;
    }
}

static void check_is_the_rule_in_full(void **state)
{
    static unsigned char mem[1 << 18];
    static rl_recog rec;
    const rl_templates *tt = &rec.templates;
    int trial, agree = 0, twin = 0, own = 0, elsewhere = 0, ties = 0, bits;
    rl_ws ws;
    (void)state;
    for (bits = 5; bits <= 6; bits++) {
        rl_family fam;
        fam.bits = bits;
        rl_ws_init(&ws, mem, sizeof mem);
        assert_int_equal(rl_templates_init(&rec.templates, &ws, &fam, NULL, 0), RL_OK);
        rl_verify_init(&rec); /* the radii's moves, as rl_recog_init makes them */
        for (trial = 0; trial < 150; trial++) {
            int ia = (int)(uniform() * tt->n), z = 1 + (int)(uniform() * 2), b = (int)(uniform() * RL_BLUR_LEVELS);
            int idb = tt->ids[ia] ^ (1 << (bits - z)), k;
            rl_profile wide;
            if (!rl_family_valid(&fam, idb))
                continue;
            draw_profile(tt, ia, rl_templates_find(tt, idb), 0.35 + 0.3 * uniform(), b, 0.92 + 0.12 * uniform(),
                         &wide);
            for (k = 0; k < N_SCALES; k++) {
                /* the id as taken at radius k: the match of every id there */
                double s = scale_at(k), own_best, twin_best = -2;
                int at_own = -1, c, want;
                rl_profile q;
                rl_match m;
                rl_profile_rescale(&wide, s, &q);
                rl_match_all(tt, &q, &m);
                if (m.id < 0)
                    continue;
                own_best = best_everywhere(tt, &wide, m.id, &at_own);
                for (c = 0; c < bits; c++) {
                    int t = m.id ^ (1 << c), at = -1;
                    double r;
                    if (!rl_family_valid(&fam, t))
                        continue;
                    r = best_everywhere(tt, &wide, t, &at);
                    twin_best = fmax(twin_best, r);
                }
                if (fabs(twin_best - own_best) < 1e-4) {
                    ties++; /* single against double precision could go either way */
                    continue;
                }
                want = twin_best >= own_best;
                agree += twin_fits_as_well(&rec, &wide, m.id, s, &m) == want;
                twin += want;
                own += !want;
                elsewhere += at_own != k;
            }
        }
    }
    printf("%d of %d decisions as the rule in full (%d a twin, %d the id; the id's best at another radius than "
           "the read's in %d; %d ties left out)\n",
           agree, twin + own, twin, own, elsewhere, ties);
    assert_int_equal(agree, twin + own);
    /* the cases that tell a skip of the wrong radius, or of every radius */
    assert_true(twin >= 100 && own >= 100 && elsewhere >= 100);
}

/* A profile of darkness levels d (one pixel a bin) for profile_edge. */
static void levels_profile(const double *d, rl_profile *p)
{
    int k;
    memset(p, 0, sizeof *p);
    for (k = 0; k < RL_PROFILE_BINS; k++) {
        p->n[k] = 1;
        p->sx[k] = d[k];
        p->total += 1;
    }
}

/* profile_edge's place between bins (twelfth session's edge round), by
 * hand. The falls of darkness are written g(k) = d[k] - d[k + 1], at the
 * boundary k + 1 (in bins; the edge is returned as boundary / BINS *
 * EXTENT). Two profiles, bins 0..A at 100:
 * - the ring's levels' midway (70, the lightest 40) first met from the
 *   outside at bin A + 3, so the falls looked at are g(A + 1 .. A + 4):
 *   10, 8.9, 1.1, 1; the steepest there is g(A + 1) (boundary A + 2) but
 *   g(A) = 11, outside, is steeper: the edge is between the boundaries of
 *   the two steepest falls, A + 1 .. A + 2 (a parabola through 11, 10,
 *   8.9 has its top 10.5 bins off: the old code's answer);
 * - midway 79.75 (the lightest 59.5) first met at A + 3, falls g(A .. A +
 *   4) 4, 10, 6, 0.5, 0.5: the steepest g(A + 1) at least both
 *   neighbours', its parabola through (-1, 4), (0, 10), (1, 6) tops at
 *   (4 - 6) / (2 (4 - 20 + 6)) = 0.1: boundary A + 2.1. */
static void edge_within_the_steepest_falls(void **state)
{
    enum { A = 20 };
    const double w = RL_PROFILE_EXTENT / RL_PROFILE_BINS;
    double d[RL_PROFILE_BINS], e;
    rl_profile p;
    int k;
    (void)state;
    for (k = 0; k < RL_PROFILE_BINS; k++)
        d[k] = k <= A ? 100 : 40;
    d[A + 1] = 89;
    d[A + 2] = 79;
    d[A + 3] = 70.1;
    d[A + 4] = 69;
    d[A + 5] = 68;
    levels_profile(d, &p);
    e = profile_edge(&p, 0.0);
    printf("edge beside a steeper fall: %.3f bins (between %d and %d)\n", e / w, A + 1, A + 2);
    assert_true(e >= (A + 1) * w - 1e-9 && e <= (A + 2) * w + 1e-9);
    for (k = 0; k < RL_PROFILE_BINS; k++)
        d[k] = k <= A ? 100 : 59.5;
    d[A + 1] = 96;
    d[A + 2] = 86;
    d[A + 3] = 80;
    d[A + 4] = 79.5;
    d[A + 5] = 79;
    levels_profile(d, &p);
    e = profile_edge(&p, 0.0);
    printf("edge at a peaked fall: %.4f bins (%.1f)\n", e / w, A + 2.1);
    assert_true(fabs(e - (A + 2.1) * w) < 1e-9);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(check_is_the_rule_in_full),
        cmocka_unit_test(edge_within_the_steepest_falls),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
