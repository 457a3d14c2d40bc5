/* Issue 43: the local pass reads a whole candidate no further when
 * neither its first match nor the search's step out (radius x1.06)
 * scores RL_LOCAL_MIN_FIRST (rl_local.h). That floor must lose nothing.
 *
 * The same floor holds a cut candidate's read at its box where no other
 * of its reads took it (rl_result.local_box_floored).
 *
 *   test_local_floor DIR SET...   the renderer's SET_NNN frames in DIR,
 *       each read twice by the whole recognizer, the floor on and off (two
 *       recognizers, each over the frames in order): every landmark of the
 *       renderer's truth that the run without the floor reports with its
 *       true id (within half a radius of its true centre) the run with it
 *       reports too, and no reported landmark sits on a true one of another
 *       id. The floor must have stopped candidates on these sets, whole
 *       ones and cut ones' reads at their box (a test of a floor that
 *       never acts would pass whatever it is).
 */
#include "rl_test.h"
#include <math.h>
#include "fixture_eval.h"
#include "rl_heap_recog.h"
#include "rl_png.h"
#include "rl_local.h"
#include "rl_result.h"

static fixture_sets fs;

typedef struct {
    int read_off, read_on, lost, wrong;
    long floored;     /* whole candidates the floor stopped */
    long box_floored; /* cut candidates' reads at their box it stopped */
} floor_counts;

/* The id reported within half a radius of true landmark l, -1 if none. */
static int id_at(const rl_result *res, const truth_landmark *l)
{
    int i;
    for (i = 0; i < res->n_landmarks; i++)
        if (hypot(res->landmarks[i].u - l->u, res->landmarks[i].v - l->v) < 0.5 * l->radius)
            return res->landmarks[i].id;
    return -1;
}

static void frame_both(rl_heap_recog *on, rl_heap_recog *off, const truth *t, floor_counts *c)
{
    static rl_result ron, roff;
    char png[1200], err[512];
    rl_image img;
    int j;
    snprintf(png, sizeof png, "%s/%s", fs.dir, t->image);
    if (rl_png_read_gray(png, &img, err, sizeof err) != RL_OK)
        fail_msg("%s", err);
    assert_int_equal(rl_heap_recog_run(on, &img, &ron), RL_OK);
    assert_int_equal(rl_heap_recog_run(off, &img, &roff), RL_OK);
    c->floored += ron.local_floored; /* per frame */
    assert_int_equal(roff.local_floored, 0);
    c->box_floored += ron.local_box_floored;
    assert_int_equal(roff.local_box_floored, 0);
    for (j = 0; j < t->n; j++) {
        const truth_landmark *l = &t->lm[j];
        int a = id_at(&roff, l), b = id_at(&ron, l);
        c->read_off += a == l->id;
        c->read_on += b == l->id;
        if (a == l->id && b != l->id) {
            c->lost++;
            printf("%s: the %d at (%.1f, %.1f) read without the floor, %d with it\n", t->image, l->id, l->u, l->v, b);
        }
        if (b >= 0 && b != l->id) {
            c->wrong++;
            printf("%s: the %d at (%.1f, %.1f) read as %d with the floor\n", t->image, l->id, l->u, l->v, b);
        }
    }
    rl_png_free(&img);
}

static void floor_loses_nothing(void **state)
{
    rl_recog_config cfg, cfg_off;
    rl_heap_recog on, off;
    floor_counts c;
    int s = 0, k = 0, got;
    truth t;
    (void)state;
    memset(&c, 0, sizeof c);
    rl_recog_defaults(&cfg);
    assert_true(cfg.local_min_first == RL_LOCAL_MIN_FIRST); /* the default is the floor */
    cfg_off = cfg;
    cfg_off.local_min_first = -INFINITY;
    rl_heap_recog_init(&on, &cfg);
    rl_heap_recog_init(&off, &cfg_off);
    while ((got = fixture_sets_next(&fs, &s, &k, &t)) == 1)
        frame_both(&on, &off, &t, &c);
    assert_int_equal(got, 0);
    rl_heap_recog_free(&on);
    rl_heap_recog_free(&off);
    printf("read right: %d without the floor, %d with it (%ld candidates stopped, %ld reads at a cut one's box); "
           "%d lost, %d wrong\n", c.read_off, c.read_on, c.floored, c.box_floored, c.lost, c.wrong);
    assert_true(c.read_off >= 100);
    assert_true(c.floored > 0);
    assert_true(c.box_floored > 0);
    assert_int_equal(c.lost, 0);
    assert_int_equal(c.wrong, 0);
}

int main(int argc, char **argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(floor_loses_nothing),
    };
    if (!fixture_sets_args(argc, argv, "test_local_floor", &fs))
        return 2;
    return cmocka_run_group_tests(tests, NULL, NULL);
}
