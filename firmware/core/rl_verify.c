/* rl_verify: a predicted landmark's id verified in its window (rl_verify.h). */
#include "rl_verify.h"

#include <math.h>
#include <string.h>
#include <stdio.h>
#include <stdlib.h>
#ifdef VERIFY_DEBUG
#define DBG(...) do { if (getenv("TRK_DBG")) fprintf(stderr, __VA_ARGS__); } while (0)
#else
#define DBG(...) ((void)0)
#endif
#include "rl_accept.h"
#include "rl_geom.h"
#include "rl_inner.h"
#include "rl_match.h"
#include "rl_refine.h"
#include "rl_result.h"

/* The centre is drawn to the landmark's dark mass at most this many times,
 * until a step moves it less than CENTRE_SETTLED px; a centre that still
 * moves CENTRE_UNSETTLED px or more, or lies farther than CENTRE_REACH
 * radii from the prediction, is no clear read. */
#define CENTRE_STEPS 6
#define WIDE_MOVE 0.15
#define WIDE_DISK 2.5
#define CENTRE_SETTLED 1.0
#define CENTRE_REACH 1.5
/* The disk that must be in the frame, in radii: the quiet zone the
 * profile reads, and the inner-ring check's rays. */
#define VERIFY_WHOLE 1.3
/* The profile from every GATHER_ROWS-th row (a landmark's 2,000 pixels and
 * more are plenty to tell its id). */
#define GATHER_ROWS 2

/* The centre drawn from the prediction to the landmark's dark mass (as
 * the global pass centres a box, rl_refine_centre), a step at a time;
 * 0 when it does not settle near the prediction. A first step that moves
 * it more than WIDE_MOVE radii (a prediction a radius off sees part of
 * the landmark) is followed by one over WIDE_DISK radii counting only
 * what is darker than midway to the ink: all of the landmark, none of
 * the ceiling around it, whose light would hold the centre back. */
static int settle_centre(const rl_image *img, const rl_levels *local, double r, double *cx, double *cy)
{
    double u0 = *cx, v0 = *cy, moved = HUGE_VAL, before = HUGE_VAL;
    int k, wide = 0;
    for (k = 0; k < CENTRE_STEPS && moved >= CENTRE_SETTLED; k++) {
        double u = *cx, v = *cy;
        if (k > 0 && !wide && (moved > WIDE_MOVE * r || moved > 0.5 * before)) {
            wide = 1;
            rl_levels ink = *local;
            ink.bg = 0.5 * (local->bg + local->fg);
            rl_refine_centre(img, &ink, cx, cy, WIDE_DISK * r);
        } else {
            rl_refine_centre(img, local, cx, cy, r);
        }
        before = moved;
        moved = hypot(*cx - u, *cy - v);
        DBG("  step %d -> %.1f %.1f moved %.2f\n", k, *cx, *cy, moved);
    }
    return moved < CENTRE_SETTLED && hypot(*cx - u0, *cy - v0) <= CENTRE_REACH * r;
}

int rl_verify_read(const rl_recog *rec, const rl_image *img, const rl_result *res, int id, double u,
                   double v, double r, rl_detection *d)
{
    rl_accept_rule rule = rl_accept_rule_of(&rec->cfg, RL_PASS_GLOBAL);
    rl_levels local;
    rl_profile p;
    rl_match m;
    memset(d, 0, sizeof *d);
    d->id = d->best_id = -1;
    if (!(r > 0) || !rl_geom_disk_complete(img->width, img->height, u, v, VERIFY_WHOLE * r))
        return 0;
    rl_accept_levels_at(&rec->illum, &res->levels, u, v, &local);
    d->u = u;
    d->v = v;
    if (!settle_centre(img, &local, r, &d->u, &d->v) ||
        !rl_geom_disk_complete(img->width, img->height, d->u, d->v, VERIFY_WHOLE * r)) {
        DBG("VER id %d settle-fail at %.1f %.1f -> %.1f %.1f\n", id, u, v, d->u, d->v);
        return 0; }
    d->radius = r;
    d->box.x0 = (int)floor(d->u - r);
    d->box.y0 = (int)floor(d->v - r);
    d->box.x1 = (int)ceil(d->u + r);
    d->box.y1 = (int)ceil(d->v + r);
    if (rl_result_light_gap(res, &d->box) <= rec->cfg.near_light * r)
        rule.max_blur = RL_BLUR_LEVELS - 2; /* beside a lamp, as the global pass */
    rl_profile_gather_rows(img, rec->tone, d->u, d->v, r, GATHER_ROWS, &p);
    rl_match_all(&rec->templates, &p, &m);
    d->best_id = m.id;
    d->score = m.score;
    d->runner_up = m.second;
    if (m.id != id || !rl_accept(&rule, &m, rl_accept_span(&local, rec->tone, &p))) {
        DBG("VER id %d match-fail best %d sc %.3f sec %.3f blur %d move %.1f\n", id, m.id, m.score, m.second, m.blur, hypot(d->u-u,d->v-v));
        return 0; }
    DBG("VER id %d ok sc %.3f sec %.3f move %.1f\n", id, m.score, m.second, hypot(d->u-u,d->v-v));
    d->id = id;
    d->pass = RL_PASS_GLOBAL;
    d->complete = 1;
    d->visible = 1.0;
    return 1;
}
