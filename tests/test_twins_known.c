/* rl_twins_check_known: the frame's zone twins' check (rl_twins_check),
 * but a landmark the caller marks known keeps its id unjudged (tracking's
 * window reads of a landmark the check kept before), and kept[] says, in
 * the order the landmarks came in, which kept their ids.
 *
 *   test_twins_known DIR SET CUT   frame 0 of SET and of CUT in DIR
 *       (SET_000.png and the renderer's truth SET_000.yaml; tests/frames
 *       band_twin: the frame where rl_twins once kept a 24 read as its
 *       twin 16 at gamma 1; twins_cut: a frame with a cut 19 in its
 *       corner, where the local search once climbed to a circle 1.2 times
 *       its radius, a third of a radius out of the frame)
 *
 * At gamma 1 and 2.2 the frame's whole landmarks are read by hand at
 * their true places and radii (the truth's), each as its own id or as a
 * zone twin of it (the landmark contract, docs/landmark-spec.md: an id
 * differing only in c_1 or c_2, the code's two highest bits), scored
 * through the frame's curve, their lead over the runner-up under
 * RL_TWINS_CLEAR (a read the check judges). Which reads are wrong is the
 * truth's; the plain check must refuse the twins and keep the right reads
 * there (the precondition, asserted). Then rl_twins_check_known:
 *   - known NULL or all 0: the plain check's result, kept[] 1 on the
 *     truth's right reads alone;
 *   - a twin read marked known keeps its id and its runner-up (unjudged),
 *     kept[] 1 at its input index, while the unknown twins before and
 *     after it are refused (kept[] in input order: a refused read at 0,
 *     the known one at 1);
 *   - a known read under the size floor (rl_twins_min_radius) gets no id;
 *   - a known cut local read whose circle passes outside the landmark's
 *     outer edge by more than RL_TWINS_CUT_BULGE of its radius gets no id
 *     (CUT's 19 read from 1.2 times its true circle, its centre a third of
 *     a radius further out of the frame: by hand it passes outside the
 *     true edge by R / 3 + 0.2 R = 0.53 R, over 0.4 x 1.2 R = 0.48 R),
 *     while the same landmark read from its true circle keeps its id.
 */
#include "rl_test.h"
#include <math.h>
#include "fixture_eval.h"
#include "rl_geom.h"
#include "rl_heap_recog.h"
#include "rl_match.h"
#include "rl_png.h"
#include "rl_twins.h"

static const char *dir, *set, *cut_set;

/* The reads, in input order: a true landmark's id (looked up in the
 * truth) read as itself (twin -1) or as its zone twin in code bit
 * bits - 1 - twin (0: c_1, 1: c_2). Index 0 and 3 are twins left
 * unknown, index 1 the twin marked known; 2 and 4 right reads. */
static const struct {
    int id, twin;
} plan[] = {{28, 0}, {24, 1}, {23, -1}, {29, 0}, {17, -1}};
#define N_READS (int)(sizeof plan / sizeof plan[0])
#define KNOWN_AT 1

typedef struct {
    rl_heap_recog hr;
    rl_image img;
    rl_result empty;  /* the frame's result (levels, size), no landmarks */
    rl_detection reads[N_READS];
    int truth_id[N_READS];
} frame;

/* Zone twins from the landmark contract, not from the recognizer's list
 * (as test_search_twins.c's is_twin). */
static int is_twin(int bits, int id, int other)
{
    return other == (id ^ (1 << (bits - 1))) || other == (id ^ (1 << (bits - 2)));
}

/* A global read of a whole landmark of id at (u, v), radius r: scored
 * through the frame's curve as the global pass scores it, its lead over
 * the runner-up 0.01 (under RL_TWINS_CLEAR: not clear, so judged). */
static rl_detection read_at(const rl_recog *rec, const rl_image *img, int id, double u, double v, double r)
{
    rl_detection d;
    rl_profile p;
    rl_match m;
    memset(&d, 0, sizeof d);
    rl_profile_gather_rows(img, rec->tone, u, v, r, 1, &p);
    rl_match_ids(&rec->templates, &p, &id, 1, -1, &m);
    assert_int_equal(m.id, id); /* a valid code of the table */
    d.id = d.best_id = id;
    d.u = u;
    d.v = v;
    d.radius = r;
    d.score = m.score;
    d.runner_up = m.score - 0.01;
    assert_true(d.score - d.runner_up < RL_TWINS_CLEAR);
    d.pass = RL_PASS_GLOBAL;
    d.complete = 1;
    d.visible = 1.0;
    d.box.x0 = (int)floor(u - r);
    d.box.y0 = (int)floor(v - r);
    d.box.x1 = (int)ceil(u + r);
    d.box.y1 = (int)ceil(v + r);
    return d;
}

/* Frame 0 of set_name read at gamma (its recognizer's curve and levels)
 * into *f, its truth into *t. */
static void frame_load(const char *set_name, double gamma, frame *f, truth *t)
{
    static rl_result res;
    rl_recog_config cfg;
    char png[1200], err[512];
    assert_int_equal(truth_load_frame(dir, set_name, 0, t), 1);
    snprintf(png, sizeof png, "%s/%s", dir, t->image);
    if (rl_png_read_gray(png, &f->img, err, sizeof err) != RL_OK)
        fail_msg("%s", err);
    rl_recog_defaults(&cfg);
    cfg.gamma = gamma;
    rl_heap_recog_init(&f->hr, &cfg);
    assert_int_equal(rl_heap_recog_run(&f->hr, &f->img, &res), RL_OK);
    f->empty = res;
    f->empty.n_landmarks = 0;
    f->empty.n_unidentified = 0;
}

/* The truth's landmark of id (one in the frame). */
static const truth_landmark *truth_of(const truth *t, int id)
{
    const truth_landmark *l = NULL;
    int j;
    for (j = 0; j < t->n; j++)
        if (t->lm[j].id == id) {
            assert_null(l);
            l = &t->lm[j];
        }
    assert_non_null(l);
    return l;
}

/* SET's frame read at gamma and the plan's reads at the truth's places. */
static void frame_at(double gamma, frame *f)
{
    truth t;
    int i, bits;
    frame_load(set, gamma, f, &t);
    bits = f->hr.rec->templates.fam.bits;
    for (i = 0; i < N_READS; i++) {
        const truth_landmark *l = truth_of(&t, plan[i].id);
        int id;
        assert_true(l->visible >= 1.0); /* whole: a global read */
        id = plan[i].twin < 0 ? l->id : l->id ^ (1 << (bits - 1 - plan[i].twin));
        assert_true(plan[i].twin < 0 ? id == l->id : is_twin(bits, l->id, id));
        f->truth_id[i] = l->id;
        f->reads[i] = read_at(f->hr.rec, &f->img, id, l->u, l->v, l->radius);
    }
}

static void frame_free(frame *f)
{
    rl_heap_recog_free(&f->hr);
    rl_png_free(&f->img);
}

/* The frame's result holding reads 0 .. N_READS - 1, in order. */
static void with_reads(const frame *f, const rl_detection *reads, rl_result *res)
{
    int i;
    *res = f->empty;
    for (i = 0; i < N_READS; i++)
        res->landmarks[res->n_landmarks++] = reads[i];
}

static const rl_tone *other(const frame *f)
{
    return rl_tones_other(&f->hr.rec->tones, f->hr.rec->tone);
}

/* The same landmark (place, radius) with the same id. */
static int same_read(const rl_detection *a, const rl_detection *b)
{
    return a->u == b->u && a->v == b->v && a->radius == b->radius && a->id == b->id;
}

/* res, from the reads, holds exactly those with want[i] among its
 * landmarks, in input order, and the others among its unidentified (id
 * -1), in input order. */
static void assert_split(const rl_detection *reads, const int *want, const rl_result *res)
{
    int i, k = 0, u = 0;
    for (i = 0; i < N_READS; i++) {
        if (want[i]) {
            assert_true(k < res->n_landmarks);
            assert_true(same_read(&res->landmarks[k], &reads[i]));
            k++;
        } else {
            assert_true(u < res->n_unidentified);
            assert_int_equal(res->unidentified[u].id, -1);
            assert_true(res->unidentified[u].u == reads[i].u && res->unidentified[u].v == reads[i].v);
            u++;
        }
    }
    assert_int_equal(res->n_landmarks, k);
    assert_int_equal(res->n_unidentified, u);
}

/* The check with known[] over reads (in order), into res: kept[] must be
 * want[], and the result split as want says. */
static void assert_known_check(const frame *f, const rl_detection *reads, const unsigned char *known,
                               const int *want, rl_result *res)
{
    unsigned char kept[N_READS];
    int i;
    memset(kept, 0xAA, sizeof kept);
    with_reads(f, reads, res);
    rl_twins_check_known(f->hr.rec, &f->img, other(f), res, known, kept);
    for (i = 0; i < N_READS; i++)
        assert_int_equal(kept[i], want[i]);
    assert_split(reads, want, res);
}

/* Two results alike in what the check decides and writes. */
static void assert_same_result(const rl_result *a, const rl_result *b)
{
    int i;
    assert_int_equal(a->n_landmarks, b->n_landmarks);
    assert_int_equal(a->n_unidentified, b->n_unidentified);
    for (i = 0; i < a->n_landmarks; i++) {
        assert_true(same_read(&a->landmarks[i], &b->landmarks[i]));
        assert_true(a->landmarks[i].runner_up == b->landmarks[i].runner_up);
    }
    for (i = 0; i < a->n_unidentified; i++)
        assert_true(same_read(&a->unidentified[i], &b->unidentified[i]));
}

static const double gammas[] = {1.0, 2.2};
#define N_GAMMAS 2

/* The precondition: the plain check refuses every twin read at its true
 * place and keeps every right one, alone and all together. */
static void plain_check_refuses_the_twins(void **state)
{
    static rl_result res;
    frame f;
    int g, i, right[N_READS];
    (void)state;
    for (g = 0; g < N_GAMMAS; g++) {
        frame_at(gammas[g], &f);
        for (i = 0; i < N_READS; i++) {
            right[i] = f.reads[i].id == f.truth_id[i];
            res = f.empty;
            res.landmarks[res.n_landmarks++] = f.reads[i];
            rl_twins_check(f.hr.rec, &f.img, other(&f), &res);
            printf("gamma %g: a %d read as %d: %s\n", gammas[g], f.truth_id[i], f.reads[i].id,
                   res.n_landmarks ? "kept" : "refused");
            assert_int_equal(res.n_landmarks, right[i]);
        }
        assert_false(right[0]); /* a refused read first */
        assert_false(right[KNOWN_AT]);
        with_reads(&f, f.reads, &res);
        rl_twins_check(f.hr.rec, &f.img, other(&f), &res);
        assert_split(f.reads, right, &res);
        frame_free(&f);
    }
}

/* Nothing known (all 0, or NULL): the plain check, kept[] 1 on the right
 * reads alone. */
static void nothing_known_is_the_plain_check(void **state)
{
    static rl_result plain, res;
    unsigned char known[N_READS] = {0}, kept[N_READS];
    frame f;
    int g, i, pass;
    (void)state;
    for (g = 0; g < N_GAMMAS; g++) {
        frame_at(gammas[g], &f);
        with_reads(&f, f.reads, &plain);
        rl_twins_check(f.hr.rec, &f.img, other(&f), &plain);
        for (pass = 0; pass < 3; pass++) {
            /* known all 0 with kept; NULL with kept; all 0 without */
            memset(kept, 0xAA, sizeof kept);
            with_reads(&f, f.reads, &res);
            rl_twins_check_known(f.hr.rec, &f.img, other(&f), &res, pass == 1 ? NULL : known,
                                 pass == 2 ? NULL : kept);
            assert_same_result(&plain, &res);
            for (i = 0; i < N_READS; i++)
                assert_int_equal(kept[i], pass == 2 ? 0xAA : f.reads[i].id == f.truth_id[i]);
        }
        frame_free(&f);
    }
}

/* A twin read marked known keeps its id unjudged (its runner-up as it
 * came), kept[] 1 at its input index; the unknown twins before and after
 * it are refused, the right reads kept. */
static void a_known_read_keeps_its_id(void **state)
{
    static rl_result res;
    unsigned char known[N_READS] = {0};
    int want[N_READS];
    frame f;
    int g, i, k = 0;
    (void)state;
    known[KNOWN_AT] = 1;
    for (g = 0; g < N_GAMMAS; g++) {
        frame_at(gammas[g], &f);
        for (i = 0; i < N_READS; i++)
            want[i] = f.reads[i].id == f.truth_id[i] || known[i];
        assert_known_check(&f, f.reads, known, want, &res);
        for (i = 0, k = 0; i < KNOWN_AT; i++)
            k += want[i];
        assert_true(res.landmarks[k].runner_up == f.reads[KNOWN_AT].runner_up);
        frame_free(&f);
    }
}

/* A known read under the size floor gets no id (RL_TWINS_MIN_ZONE_PX):
 * the known twin read, and a right read, at 0.9 of rl_twins_min_radius. */
static void a_known_read_too_small_has_no_id(void **state)
{
    static rl_result res;
    unsigned char known[N_READS];
    rl_detection small[N_READS];
    int want[N_READS];
    frame f;
    int g, i;
    double floor_r;
    (void)state;
    memset(known, 1, sizeof known);
    for (g = 0; g < N_GAMMAS; g++) {
        frame_at(gammas[g], &f);
        floor_r = rl_twins_min_radius(&f.hr.rec->templates.fam);
        /* code zone 1 of ring5 (N = 5) spans 0.8 R sqrt(4/5) .. 0.8 R
         * (docs/landmark-spec.md): RL_TWINS_MIN_ZONE_PX of it at 14.2 px */
        assert_int_equal(f.hr.rec->templates.fam.bits, 5);
        assert_true(fabs(floor_r - RL_TWINS_MIN_ZONE_PX / (0.8 * (1.0 - sqrt(0.8)))) < 1e-9);
        for (i = 0; i < N_READS; i++) {
            small[i] = f.reads[i];
            want[i] = i != KNOWN_AT && i != 2;
            if (!want[i])
                small[i].radius = 0.9 * floor_r;
        }
        assert_known_check(&f, small, known, want, &res);
        frame_free(&f);
    }
}

/* A local read of a landmark the border cuts, as the search leaves one:
 * id at (u, v), radius r, scored there through the frame's curve. */
static rl_detection cut_read_at(const frame *f, int id, double u, double v, double r)
{
    rl_detection d = read_at(f->hr.rec, &f->img, id, u, v, r);
    d.pass = RL_PASS_LOCAL;
    d.complete = rl_geom_disk_complete(f->img.width, f->img.height, u, v, r);
    d.visible = rl_geom_visible_in(f->img.width, f->img.height, u, v, r);
    assert_false(d.complete);
    return d;
}

/* CUT's cut 19 marked known: read from a circle off its outer edge
 * (1.2 R, its centre R / 3 further from the frame's centre), no id; from
 * its true circle, its id; the frame's whole landmarks (right global
 * reads, the frame's size for the rule) kept. kept[] in input order. */
static void a_known_cut_read_off_its_edge_has_no_id(void **state)
{
    static rl_result res;
    unsigned char known[N_READS];
    rl_detection reads[N_READS];
    int want[N_READS] = {0, 1, 1, 1, 1};
    const int whole[] = {30, 24, 22};
    frame f;
    truth t;
    int g, i;
    (void)state;
    memset(known, 1, sizeof known);
    for (g = 0; g < N_GAMMAS; g++) {
        const truth_landmark *l;
        double out_u, out_v, len;
        frame_load(cut_set, gammas[g], &f, &t);
        l = truth_of(&t, 19);
        assert_true(l->visible < 1.0);
        out_u = l->u - 0.5 * f.img.width;
        out_v = l->v - 0.5 * f.img.height;
        len = hypot(out_u, out_v);
        reads[0] = cut_read_at(&f, l->id, l->u + out_u / len * l->radius / 3, l->v + out_v / len * l->radius / 3,
                               1.2 * l->radius);
        reads[1] = cut_read_at(&f, l->id, l->u, l->v, l->radius);
        for (i = 2; i < N_READS; i++) {
            const truth_landmark *w = truth_of(&t, whole[i - 2]);
            assert_true(w->visible >= 1.0);
            reads[i] = read_at(f.hr.rec, &f.img, w->id, w->u, w->v, w->radius);
        }
        assert_known_check(&f, reads, known, want, &res);
        frame_free(&f);
    }
}

int main(int argc, char **argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(plain_check_refuses_the_twins),
        cmocka_unit_test(nothing_known_is_the_plain_check),
        cmocka_unit_test(a_known_read_keeps_its_id),
        cmocka_unit_test(a_known_read_too_small_has_no_id),
        cmocka_unit_test(a_known_cut_read_off_its_edge_has_no_id),
    };
    if (argc != 4) {
        fprintf(stderr, "usage: test_twins_known DIR SET CUT\n");
        return 2;
    }
    dir = argv[1];
    set = argv[2];
    cut_set = argv[3];
    return cmocka_run_group_tests(tests, NULL, NULL);
}
