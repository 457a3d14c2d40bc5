/* Issue 44: the local pass reads a candidate from the circle fitted to
 * its outer edge, and that fit errs: glare or the border leaves it an arc,
 * and a circle through an arc sits 5-12% short and up to a tenth of a
 * radius off (rl_search.c). Whatever the circle, the read must not take a
 * landmark's zone twin (the codes one zone from it next to the outer ring,
 * which a radius error confuses most), and no other id may pass the
 * frame's zone twins' check: the search holds the id against every id one
 * zone away (twin_check), each at every blur, and rl_twins meets a local
 * read's rivals where they fit.
 *
 *   test_search_twins DIR SET...   the renderer's SET_NNN frames in DIR
 *       (rendered through the 2.2 curve), each recognized at gamma 2.2
 *       (the frame read through the camera's curve, where the local
 *       read's lead is the gate) and at gamma 1 (read as linear, where
 *       the zone twins' check rl_twins is the gate): every landmark at
 *       least 0.4 in view (what the local pass tries, CUT_MIN_VISIBLE),
 *       read by the local pass's reads (rl_local_read_circle) from
 *       circles placed as an edge fit errs round its true one (the
 *       renderer's truth): radius 0.88 to 1.06 of the true, centre moved
 *       up to a tenth of the radius. No read that the frame's zone twins'
 *       check (rl_twins) keeps may name another id than the truth, at
 *       either gamma. The reads it does not keep (a miss, not a wrong
 *       id) are printed and counted, not judged (docs/results.md, "The
 *       search's twin check at every blur", "Every id one zone away",
 *       "Frames nobody tuned on"): at gamma 2.2 the sanitizer build's
 *       frames have one zone twin's, a whole 4 of moving 016 tied with
 *       its twin 20 from its true centre at 1.03 r. DIR may hold any
 *       frames the renderer made (other seeds: ringloc-render --set
 *       moving --seed S --rock 0.03 [--isp blur:1.0]). Its own id is read from at least one
 *       circle of most landmarks, so nothing passes by reading nothing.
 *       Every read's box is the circle it reports (box_fits), not the
 *       one it was read from (681 of twins_cut's 712 reads before).
 *       The one-block twin check read 54 zone twins on isp_blur_s21 and
 *       199 on moving and border (19 of them kept); with the twins at
 *       every blur, the read across the motion still took the moving
 *       set's cut 22 of frame 008 as 30 from 3 circles where the search
 *       had its twin ahead (rl_local.c, read_across_axes); with the two
 *       zone twins alone checked, whole 25s of isp_blur_s21 were read as
 *       29 (zone 3) from circles 0.1 r off and 3-6% large and kept (4
 *       reads); read as linear, rl_twins kept a whole 25 of its frame 011
 *       read as 17 from a circle 12% short, and 3 whole landmarks of
 *       moving 036 read as their twins (5 reads), its rivals scored
 *       within 3% of the radius read; on the sanitizer build's frames
 *       (another renderer's floating point) its rank read kept a whole 11
 *       of isp_blur_s21 007 read as 3 from a circle 1.3 px off at 0.94 r,
 *       read about the read's centre, not its outer edge's; read as
 *       linear, the search climbed from the arc of seed 42's border 018
 *       cut 19 to a circle 1.2 times its radius, a third of a radius out
 *       of the frame, where both formations read 7 (rl_twins.c,
 *       rl_twins_cut_on_edge). */
#include "rl_test.h"
#include <math.h>
#include "fixture_eval.h"
#include "rl_geom.h"
#include "rl_heap_recog.h"
#include "rl_local.h"
#include "rl_match.h"
#include "rl_png.h"
#include "rl_twins.h"

/* The circles: radius scales, and centre steps of a twentieth of the
 * radius out to a tenth (within a disk of that). */
static const double scales[] = {0.88, 0.91, 0.94, 0.97, 1.0, 1.03, 1.06};
#define N_SCALES (int)(sizeof scales / sizeof scales[0])
#define SHIFT_STEP 0.05
#define SHIFT_STEPS 2

static fixture_sets fs;

typedef struct {
    int landmarks, cut, reads, own_reads, own, twin_reads, twin_landmarks, other_reads, twin_kept, other_kept;
    int box_off; /* reads whose box is not their circle's (box_fits) */
} twin_counts;

/* A candidate as the global pass leaves one: its box's circle the fitted
 * one (a box that errs as the fit). */
static rl_detection candidate_at(int W, int H, double cx, double cy, double r)
{
    rl_detection u;
    memset(&u, 0, sizeof u);
    u.id = u.best_id = -1;
    u.u = cx;
    u.v = cy;
    u.radius = r;
    u.complete = rl_geom_disk_complete(W, H, cx, cy, r);
    u.visible = rl_geom_visible_in(W, H, cx, cy, r);
    u.box.x0 = (int)floor(fmax(0, cx - r));
    u.box.y0 = (int)floor(fmax(0, cy - r));
    u.box.x1 = (int)ceil(fmin(W - 1, cx + r));
    u.box.y1 = (int)ceil(fmin(H - 1, cy + r));
    return u;
}

/* Whether a read's box is its outer ring's bounding box (rl_recog.h),
 * the circle it reports (not the one it was read from): each side within
 * a pixel of the circle's, the frame's edge where the circle passes it. */
static int box_fits(int W, int H, const rl_detection *d)
{
    double x0 = fmax(0, d->u - d->radius), y0 = fmax(0, d->v - d->radius);
    double x1 = fmin(W - 1, d->u + d->radius), y1 = fmin(H - 1, d->v + d->radius);
    return fabs(d->box.x0 - x0) <= 1 && fabs(d->box.y0 - y0) <= 1 && fabs(d->box.x1 - x1) <= 1 &&
           fabs(d->box.y1 - y1) <= 1;
}

/* Zone twins from the landmark contract (docs/landmark-spec.md), not from
 * the recognizer's own list: ids that differ only in c_1 or c_2, the
 * code's two highest bits. */
static int is_twin(const rl_recog *rec, int id, int other)
{
    int bits = rec->cfg.family.bits;
    return other == (id ^ (1 << (bits - 1))) || other == (id ^ (1 << (bits - 2)));
}

/* Whether the frame's zone twins' check (rl_twins, after both passes)
 * keeps the local read d among the frame's landmarks res. */
static int reported(const rl_recog *rec, const rl_image *img, const rl_result *res, const rl_detection *d)
{
    static rl_result r2;
    int i;
    r2 = *res;
    if (r2.n_landmarks == RL_MAX_LANDMARKS)
        r2.n_landmarks--;
    r2.landmarks[r2.n_landmarks++] = *d;
    rl_twins_check(rec, img, rl_tones_other(&rec->tones, rec->tone), &r2);
    for (i = 0; i < r2.n_landmarks; i++)
        if (r2.landmarks[i].u == d->u && r2.landmarks[i].v == d->v && r2.landmarks[i].radius == d->radius &&
            r2.landmarks[i].id == d->id)
            return 1;
    return 0;
}

static void landmark_reads(rl_recog *rec, const rl_image *img, const rl_result *res, const char *what,
                           const truth_landmark *l, twin_counts *c)
{
    int k, i, j, own = 0, twins = 0;
    c->landmarks++;
    c->cut += l->visible < 0.97;
    for (k = 0; k < N_SCALES; k++)
        for (i = -SHIFT_STEPS; i <= SHIFT_STEPS; i++)
            for (j = -SHIFT_STEPS; j <= SHIFT_STEPS; j++) {
                double r = l->radius * scales[k], cx = l->u + i * SHIFT_STEP * l->radius,
                       cy = l->v + j * SHIFT_STEP * l->radius;
                rl_detection u, d;
                int twin, kept;
                if (i * i + j * j > SHIFT_STEPS * SHIFT_STEPS)
                    continue;
                u = candidate_at(img->width, img->height, cx, cy, r);
                c->reads++;
                if (!rl_local_read_circle(rec, img, res, &u, l->radius, cx, cy, r, &d))
                    continue;
                c->box_off += !box_fits(img->width, img->height, &d);
                if (d.id == l->id) {
                    own++;
                    continue;
                }
                twin = is_twin(rec, l->id, d.id);
                kept = reported(rec, img, res, &d);
                c->twin_reads += twin;
                twins += twin;
                c->other_reads += !twin;
                c->twin_kept += twin && kept;
                c->other_kept += !twin && kept;
                printf("%s: a %s %d at (%.1f, %.1f), radius %.1f, %.2f in view, read as %s%d (%.3f, runner-up "
                       "%.3f) from (%+.1f, %+.1f) px, radius x%.2f%s\n",
                       what, l->visible < 0.97 ? "cut" : "whole", l->id, l->u, l->v, l->radius, l->visible,
                       twin ? "its twin " : "", d.id, d.score, d.runner_up, cx - l->u, cy - l->v, scales[k],
                       kept ? ", REPORTED" : "");
            }
    c->own_reads += own;
    c->own += own > 0;
    c->twin_landmarks += twins > 0;
}

static void frame_reads(rl_heap_recog *hr, double gamma, const truth *t, twin_counts *c)
{
    static rl_result res;
    char png[1200], err[512], what[600];
    rl_image img;
    int j;
    snprintf(png, sizeof png, "%s/%s", fs.dir, t->image);
    if (rl_png_read_gray(png, &img, err, sizeof err) != RL_OK)
        fail_msg("%s", err);
    assert_int_equal(rl_heap_recog_run(hr, &img, &res), RL_OK);
    snprintf(what, sizeof what, "%s at gamma %g", t->image, gamma);
    for (j = 0; j < t->n; j++)
        if (t->lm[j].visible >= 0.4)
            landmark_reads(hr->rec, &img, &res, what, &t->lm[j], c);
    rl_png_free(&img);
}

/* the least a run must read (RL_SEARCH_MIN=LANDMARKS,CUT) */
static int min_landmarks = 50, min_cut = 8;

/* Every frame of the sets read at gamma (its own recognizer), into *c. */
static void sets_reads(double gamma, twin_counts *c)
{
    rl_recog_config cfg;
    rl_heap_recog hr;
    int s = 0, k = 0, got;
    truth t;
    memset(c, 0, sizeof *c);
    rl_recog_defaults(&cfg);
    cfg.gamma = gamma;
    rl_heap_recog_init(&hr, &cfg);
    while ((got = fixture_sets_next(&fs, &s, &k, &t)) == 1)
        frame_reads(&hr, cfg.gamma, &t, c);
    assert_int_equal(got, 0);
    rl_heap_recog_free(&hr);
    printf("gamma %g: %d landmarks read (%d cut), %d circles: %d landmarks read as their own id (%d reads); %d "
           "reads as a zone twin (%d reported), %d as another id (%d reported); %d boxes not their circle's\n",
           gamma, c->landmarks, c->cut, c->reads, c->own, c->own_reads, c->twin_reads, c->twin_kept,
           c->other_reads, c->other_kept, c->box_off);
    assert_int_equal(c->box_off, 0);
    /* frames were read: at least RL_SEARCH_MIN's "landmarks,cut" (a
     * rendered set, 50 and 8: isp_blur_s21 82, 10 cut, 9 in the sanitizer
     * build; the committed frame 6 and 0) */
    assert_true(c->landmarks >= min_landmarks);
    assert_true(c->cut >= min_cut);
}

static void through_the_curve(void **state)
{
    twin_counts c;
    (void)state;
    sets_reads(2.2, &c);
    assert_int_equal(c.twin_kept, 0);
    assert_int_equal(c.other_kept, 0);
    /* through the camera's curve the local read's lead is the gate: every
     * landmark of every CI set of both builds is read as its own id from
     * some circle (82 of 82, 661 of 661; the sanitizer build's 81, 301)
     * and at most one in 200 as its twin from any (none; the sanitizer
     * build's moving 016's 4 tied with its 20); one in 100 unread leaves
     * room for other seeds (173 of 177 and up) */
    assert_true(c.landmarks - c.own <= c.landmarks / 100);
    assert_true(c.twin_landmarks * 200 <= c.landmarks);
}

/* The 2.2 camera read as linear: the local reads' leads are weaker (a
 * zone twin is read from some circles), rl_twins keeps none. */
static void read_as_linear(void **state)
{
    twin_counts c;
    (void)state;
    sets_reads(1.0, &c);
    assert_int_equal(c.twin_kept, 0);
    assert_int_equal(c.other_kept, 0);
    assert_true(c.own >= 0.93 * c.landmarks); /* 81 of 82, 631 of 661 */
}

int main(int argc, char **argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(through_the_curve),
        cmocka_unit_test(read_as_linear),
    };
    const char *min = getenv("RL_SEARCH_MIN");
    if (!fixture_sets_args(argc, argv, "test_search_twins", &fs))
        return 2;
    if (min != NULL && sscanf(min, "%d,%d", &min_landmarks, &min_cut) != 2) {
        fprintf(stderr, "test_search_twins: RL_SEARCH_MIN is not LANDMARKS,CUT: '%s'\n", min);
        return 2;
    }
    return cmocka_run_group_tests(tests, NULL, NULL);
}
