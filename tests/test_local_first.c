/* Issue 43: the local pass reads a whole candidate no further when its
 * first match scores under RL_LOCAL_MIN_FIRST (rl_local.h); that must
 * cost no landmark the reads after it would take.
 *
 *   test_local_first DIR SET...   the renderer's SET_NNN frames in DIR:
 *       every whole landmark (the renderer's truth), from a candidate at
 *       its true centre at the frame's landmark size, is read as the
 *       tracker reads it (rl_local_read: every read, no early stop); of
 *       those read with their own id, each one's first match (the located
 *       circle's, rl_search_identify_over stopping there) scores at least
 *       RL_LOCAL_MIN_FIRST, and the smallest is printed. */
#include "rl_test.h"
#include <math.h>
#include "fixture_eval.h"
#include "rl_heap_recog.h"
#include "rl_local.h"
#include "rl_locate.h"
#include "rl_png.h"
#include "rl_result.h"
#include "rl_search.h"

static const char *dir;
static const char *const *sets;
static int n_sets;

typedef struct {
    int read, under;
    double lowest;
} first_counts;

/* The first match of u as the local pass reads it; -1 if not located. */
static double first_score(rl_recog *rec, const rl_image *img, const rl_result *res, const rl_detection *u)
{
    rl_box box;
    rl_match m;
    double cx, cy, r;
    if (!rl_locate_outer_ring(rec, img, res, u, u->radius, &box, &cx, &cy, &r))
        return -1.0;
    rl_search_identify_over(&rec->templates, rec->polar, img, rec->tone, res->levels.light, INFINITY, 0.0, &cx,
                            &cy, &r, &m);
    return m.id < 0 ? 0.0 : m.score;
}

static void frame_firsts(rl_heap_recog *hr, const truth *t, first_counts *c)
{
    static rl_result res;
    char png[1200], err[512];
    rl_image img;
    double R;
    int j;
    snprintf(png, sizeof png, "%s/%s", dir, t->image);
    if (rl_png_read_gray(png, &img, err, sizeof err) != RL_OK)
        fail_msg("%s", err);
    assert_int_equal(rl_heap_recog_run(hr, &img, &res), RL_OK);
    R = rl_result_median_radius(&res);
    for (j = 0; j < t->n; j++) {
        const truth_landmark *l = &t->lm[j];
        rl_detection u, d;
        double s;
        if (l->visible < 1.0)
            continue;
        memset(&u, 0, sizeof u);
        u.u = l->u;
        u.v = l->v;
        u.radius = R > 0 ? R : l->radius;
        u.complete = 1;
        u.visible = 1.0;
        if (!rl_local_read(hr->rec, &img, &res, &u, u.radius, &d) || d.id != l->id)
            continue;
        c->read++;
        s = first_score(hr->rec, &img, &res, &u);
        if (s < c->lowest)
            c->lowest = s;
        if (s < RL_LOCAL_MIN_FIRST) {
            c->under++;
            printf("%s: a whole %d at (%.1f, %.1f) read, its first match %.3f\n", t->image, l->id, l->u, l->v, s);
        }
    }
    rl_png_free(&img);
}

static void no_read_lost(void **state)
{
    rl_recog_config cfg;
    rl_heap_recog hr;
    first_counts c = {0, 0, INFINITY};
    int s, k;
    (void)state;
    rl_recog_defaults(&cfg);
    rl_heap_recog_init(&hr, &cfg);
    for (s = 0; s < n_sets; s++)
        for (k = 0;; k++) {
            char yaml[1200];
            truth t;
            FILE *f;
            snprintf(yaml, sizeof yaml, "%s/%s_%03d.yaml", dir, sets[s], k);
            if ((f = fopen(yaml, "r")) == NULL)
                break;
            fclose(f);
            assert_int_equal(truth_load(yaml, &t), 0);
            frame_firsts(&hr, &t, &c);
        }
    rl_heap_recog_free(&hr);
    printf("%d whole landmarks read with their id; lowest first match %.3f (stop under %.2f): %d under\n", c.read,
           c.lowest, RL_LOCAL_MIN_FIRST, c.under);
    assert_true(c.read >= 100);
    assert_int_equal(c.under, 0);
}

int main(int argc, char **argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(no_read_lost),
    };
    if (argc < 3) {
        fprintf(stderr, "usage: test_local_first DIR SET...\n");
        return 2;
    }
    dir = argv[1];
    sets = (const char *const *)(argv + 2);
    n_sets = argc - 2;
    return cmocka_run_group_tests(tests, NULL, NULL);
}
