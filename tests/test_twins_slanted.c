/* rl_twins' read across a motion (docs/design.md, rule 5) is for
 * landmarks that moved. A still landmark seen slanted measures as moved
 * (its edges are smoothed along its major axis: rl_motion_measure's
 * ratio under RL_TWINS_MOVED, test_motion), so the read across that
 * "motion" must refuse it however its id reads there: its outer edge is
 * an ellipse flatter than RL_TWINS_MOVED_ASPECT (the guard in rl_twins.c's
 * moved_keeps, included here to call it).
 *
 * Drawn here still (the truth by construction: no motion) from the
 * family's zone radii (rl_templates_value_at), its x axis shrunk to
 * 0.75-0.85 of its 16-24 px radius, a whole global read of its own id at its true centre,
 * read through the 2.2 curve (the frame's, the moved read's condition).
 * Preconditions asserted: the measure calls it moved, and along the
 * sharpest axis its id passes keeps through both formations, so that
 * without the guard moved_keeps would keep it (the guard alone refuses
 * it). */
#include "rl_test.h"
#include <math.h>
#include "draw_slanted.h"
#include "rl_heap_recog.h"
#include "rl_match.h"
#include "rl_profile.h"
#include "rl_templates.h"
/* the statics called */
#include "rl_twins.c"

#define W 120
#define H 120

static uint8_t pix[W * H];

static void slanted_still_is_not_read_across_a_motion(void **state)
{
    /* radius (px) and slant (minor over major): each measures as moved */
    static const struct {
        double r, sx;
    } cases[] = {{16, 0.85}, {16, 0.8}, {18, 0.8}, {20, 0.75}, {24, 0.75}};
    static rl_result res;
    rl_recog_config cfg;
    rl_heap_recog hr;
    size_t i;
    (void)state;
    rl_recog_defaults(&cfg);
    cfg.gamma = 2.2;
    rl_heap_recog_init(&hr, &cfg);
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        double r = cases[i].r, cx = 60.3, cy = 59.6, aspect, fit, least = 0;
        rl_image img = draw_slanted(pix, W, H, 23, cx, cy, r, 0.03, cases[i].sx);
        const rl_recog *rec;
        const rl_tone *other;
        rl_detection d;
        rl_profile p;
        rl_match m;
        rl_motion mo;
        landmark_reads mr;
        int rv[RL_MAX_IDS], n, small;
        double tol, mg;
        /* the frame's curve and levels */
        assert_int_equal(rl_heap_recog_run(&hr, &img, &res), RL_OK);
        rec = hr.rec;
        other = rl_tones_other(&rec->tones, rec->tone);
        assert_true(rec->tones.gamma[rec->tone - rec->tones.tone] > 1.0);
        /* its own id, read as the global pass reads a whole landmark */
        memset(&d, 0, sizeof d);
        rl_profile_gather_rows(&img, rec->tone, cx, cy, r, 1, &p);
        d.id = d.best_id = 23;
        rl_match_ids(&rec->templates, &p, &d.id, 1, -1, &m);
        assert_int_equal(m.id, 23);
        d.u = cx;
        d.v = cy;
        d.radius = r;
        d.score = m.score;
        d.runner_up = m.score - 0.01;
        d.pass = RL_PASS_GLOBAL;
        d.complete = 1;
        d.visible = 1.0;
        n = rl_twins_rivals(rec, &d, rv);
        assert_true(n > 0);
        small = r < RL_TWINS_FAR_ZONE_PX / RL_TWINS_MIN_ZONE_PX * rl_twins_min_radius(&rec->templates.fam);
        tol = tolerance(&d, 1, small);
        mg = margin(&d, small);
        /* preconditions: it measures as moved, its edge is flat, and
         * along the sharpest axis its id passes (the guard alone
         * refuses it) */
        assert_true(rl_motion_measure(&img, cx, cy, r, &mo));
        assert_true(mo.ratio < RL_TWINS_MOVED);
        minor_radius(rec, &img, res.levels.light, &d, &aspect);
        assert_true(aspect < RL_TWINS_MOVED_ASPECT);
        assert_true(keeps(tol, mg, rl_twins_lead(rec, &img, other, &d, rv, n, 0, mo.axis, &fit),
                          rl_twins_lead(rec, &img, rec->tone, &d, rv, n, 0, mo.axis, &fit)));
        /* still: not read across a motion */
        memset(&mr, 0, sizeof mr);
        assert_false(moved_keeps(rec, &img, &res.levels, &d, rv, n, tol, mg, &mr, &least));
    }
    rl_heap_recog_free(&hr);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(slanted_still_is_not_read_across_a_motion),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
