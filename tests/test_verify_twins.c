/* Issue 43: a tracked window confirms only the id its prediction names,
 * so a prediction that names a landmark's zone twin (a wrong pose, or a
 * wrong place on a map whose ids repeat) must not be confirmed there.
 *
 *   test_verify_twins DIR SET...   the renderer's SET_NNN frames in DIR:
 *       every whole landmark, at its true centre and radius (the
 *       renderer's truth), about whole (0.97 in view, as tracking
 *       verifies), verified as each zone twin of its id (each code
 *       one zone from it: rl_verify_read, and rl_verify_read_border for
 *       one near the border): none taken. Its own id from the same place
 *       is read on most of them (the rest go to the costly reads), so
 *       nothing is passed by reading nothing. Degraded frames gave a
 *       whole 2 verified as 18 (0.883 against 0.813) before the twins
 *       were held against the id at every radius tried (rl_verify.c).
 *       Then the same verified as known (rl_verify_read's `known`: the
 *       id judged against its rivals alone, rl_rivals) as every other id
 *       of the family, not its twins only: none taken, its own read as
 *       known where it is read with every id matched (brute force over
 *       the pairs the frames hold; docs/tracking.md, eleventh session).
 *       Then at a radius 10-15% off the renderer's (a prediction that
 *       far off: a map's height, a pose or a place wrong), every whole
 *       landmark verified as every other id, as known and with every id
 *       matched: none taken (400 of 316,332 before the read was held
 *       against the outer ring's edge, rl_verify.c: zone twins mostly, a
 *       19 as 3, a 25 as 17, read 5-10% off their radius); its own id
 *       still read from its true radius and from 5% off (1.4 times as
 *       many reads over the two as from the true radius: an edge check
 *       that refused most near predictions would fall under it; the
 *       sanitizer build's 12-frame sets read 439 from 5% off against 294
 *       at the true radius, 1.49). */
#include "rl_test.h"
#include <math.h>
#include "fixture_eval.h"
#include "rl_family.h"
#include "rl_heap_recog.h"
#include "rl_png.h"
#include "rl_verify.h"

static fixture_sets fs;

typedef struct {
    int whole, near_border, own, twins, wrong;
    int own_known, others, others_taken; /* verified as known */
} twin_counts;

/* The verification of id at landmark l: the border read where the
 * centre step cannot run (room under 1.2 radii), else the usual one. */
static int verify(const rl_recog *rec, const rl_image *img, const rl_result *res, const truth_landmark *l, int id,
                  int known)
{
    rl_detection d;
    int away;
    return rl_verify_read(rec, img, res, id, known, l->u, l->v, l->radius, &d, &away) ||
           rl_verify_read_border(rec, img, res, id, known, l->u, l->v, l->radius, &d);
}

static void frame_twins(rl_heap_recog *hr, const char *set, const truth *t, void *counts)
{
    twin_counts *c = counts;
    static rl_result res;
    char png[1200], err[512];
    rl_image img;
    int j, z, k, own;
    snprintf(png, sizeof png, "%s/%s", fs.dir, t->image);
    if (rl_png_read_gray(png, &img, err, sizeof err) != RL_OK)
        fail_msg("%s", err);
    assert_int_equal(rl_heap_recog_run(hr, &img, &res), RL_OK);
    for (j = 0; j < t->n; j++) {
        const truth_landmark *l = &t->lm[j];
        const rl_family *fam = &hr->rec->templates.fam;
        /* about whole: what tracking verifies (rl_track's CUT_VISIBLE) */
        if (l->visible < 0.97)
            continue;
        c->whole++;
        c->near_border += fmin(fmin(l->u, l->v), fmin(img.width - 1 - l->u, img.height - 1 - l->v)) < 1.2 * l->radius;
        own = verify(hr->rec, &img, &res, l, l->id, 0);
        c->own += own;
        c->own_known += own && verify(hr->rec, &img, &res, l, l->id, 1);
        for (k = 0; k < hr->rec->templates.n; k++) {
            int other = hr->rec->templates.ids[k];
            if (other == l->id)
                continue;
            c->others++;
            if (verify(hr->rec, &img, &res, l, other, 1)) {
                c->others_taken++;
                printf("%s: a whole %d at (%.1f, %.1f), radius %.1f, verified as known %d\n", set, l->id, l->u, l->v,
                       l->radius, other);
            }
        }
        for (z = 0; z < fam->bits; z++) {
            int twin = l->id ^ (1 << z);
            if (!rl_family_valid(fam, twin))
                continue;
            c->twins++;
            if (verify(hr->rec, &img, &res, l, twin, 0)) {
                c->wrong++;
                printf("%s: a whole %d at (%.1f, %.1f), radius %.1f, verified as its twin %d\n", set, l->id, l->u,
                       l->v, l->radius, twin);
            }
        }
    }
    rl_png_free(&img);
}

/* Every frame of the sets through frame(hr, set, truth, counts), one
 * recognizer with the defaults for them all. */
static void each_frame(void (*frame)(rl_heap_recog *, const char *, const truth *, void *), void *counts)
{
    rl_recog_config cfg;
    rl_heap_recog hr;
    int s = 0, k = 0, got;
    truth t;
    rl_recog_defaults(&cfg);
    rl_heap_recog_init(&hr, &cfg);
    while ((got = fixture_sets_next(&fs, &s, &k, &t)) == 1)
        frame(&hr, fs.sets[s], &t, counts);
    assert_int_equal(got, 0);
    rl_heap_recog_free(&hr);
}

static void no_twin_confirmed(void **state)
{
    twin_counts c;
    (void)state;
    memset(&c, 0, sizeof c);
    each_frame(frame_twins, &c);
    printf("%d about whole landmarks (%d near the border: read from their edge): %d verified as their own id, "
           "%d of %d zone twins taken\n",
           c.whole, c.near_border, c.own, c.wrong, c.twins);
    assert_true(c.whole >= 100 && c.near_border >= 30);
    assert_true(c.own >= 0.6 * c.whole);
    assert_int_equal(c.wrong, 0);
    printf("verified as known: %d of the %d read as their own id; %d of %d other ids taken\n", c.own_known, c.own,
           c.others_taken, c.others);
    assert_int_equal(c.others_taken, 0);
    assert_true(c.own_known >= c.own - c.own / 50);
}

/* The renderer's radius times these: a prediction 10-15% off, and 3-7%
 * off (twelfth session's review: a whole 2 of the moving set taken as 18
 * from 5% long, read at the smallest radius tried). */
static const double off_scales[] = {0.85, 0.88, 0.90, 0.93, 0.95, 0.97, 1.03, 1.05, 1.07, 1.10, 1.12, 1.15};
#define N_OFF (int)(sizeof off_scales / sizeof off_scales[0])

typedef struct {
    int whole, own, own_near, tries, taken;
} off_counts;

static void frame_off_radius(rl_heap_recog *hr, const char *set, const truth *t, void *counts)
{
    off_counts *c = counts;
    static rl_result res;
    char png[1200], err[512];
    rl_image img;
    int j, k, q, known;
    snprintf(png, sizeof png, "%s/%s", fs.dir, t->image);
    if (rl_png_read_gray(png, &img, err, sizeof err) != RL_OK)
        fail_msg("%s", err);
    assert_int_equal(rl_heap_recog_run(hr, &img, &res), RL_OK);
    for (j = 0; j < t->n; j++) {
        truth_landmark l = t->lm[j];
        const double r = l.radius;
        if (l.visible < 0.97)
            continue;
        c->whole++;
        c->own += verify(hr->rec, &img, &res, &l, l.id, 1);
        for (q = -1; q <= 1; q += 2) { /* its own id from 5% off */
            l.radius = r * (1 + 0.05 * q);
            c->own_near += verify(hr->rec, &img, &res, &l, l.id, 1);
        }
        for (q = 0; q < N_OFF; q++) {
            l.radius = r * off_scales[q];
            for (k = 0; k < hr->rec->templates.n; k++) {
                int other = hr->rec->templates.ids[k];
                if (other == l.id)
                    continue;
                for (known = 0; known <= 1; known++) {
                    c->tries++;
                    if (verify(hr->rec, &img, &res, &l, other, known)) {
                        c->taken++;
                        printf("%s: a whole %d at (%.1f, %.1f), radius %.1f, verified as %s%d at %.2f of it\n", set,
                               l.id, l.u, l.v, r, known ? "known " : "", other, off_scales[q]);
                    }
                }
            }
        }
    }
    rl_png_free(&img);
}

static void off_radius_not_taken(void **state)
{
    off_counts c;
    (void)state;
    memset(&c, 0, sizeof c);
    each_frame(frame_off_radius, &c);
    printf("%d about whole landmarks: %d verified as their own id (known), %d of %d from 5%% off; predicted "
           "3-15%% off: %d of %d other ids taken\n",
           c.whole, c.own, c.own_near, 2 * c.whole, c.taken, c.tries);
    assert_true(c.whole >= 100);
    assert_true(c.own >= 0.6 * c.whole);
    assert_true(5 * c.own_near >= 7 * c.own);
    assert_int_equal(c.taken, 0);
}

int main(int argc, char **argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(no_twin_confirmed),
        cmocka_unit_test(off_radius_not_taken),
    };
    if (!fixture_sets_args(argc, argv, "test_verify_twins", &fs))
        return 2;
    return cmocka_run_group_tests(tests, NULL, NULL);
}
