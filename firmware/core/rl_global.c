#include "rl_global.h"

#include <math.h>
#include <string.h>
#include "rl_accept.h"
#include "rl_clr.h"
#include "rl_ellipse.h"
#include "rl_inner.h"
#include "rl_match.h"
#include "rl_refine.h"
#include "rl_result.h"
#include "rl_twins.h"

/* Border landmarks with at most this much missing are identified in the
 * global pass (their outer ring is closed but for a sliver); the rest wait
 * for the local pass. */
#define GLOBAL_MIN_VISIBLE 0.95

/* Radius, profile and match of candidate d as an ellipse of the given
 * shape, from the radius of its box; 1 (and d's radius, p, m replaced)
 * when that matches better than what they hold. An ellipse from a region's moments is perspective or the
 * lens's distortion, or a circle smeared by motion (its rings are not
 * ellipses then): the match tells which. */
static int try_ellipse(const rl_image *img, const rl_tone *tone, const rl_templates *tt,
                       const rl_shape *shape, double box_r, rl_detection *d, rl_profile *p,
                       rl_match *m)
{
    rl_profile pe;
    rl_match me;
    double r = box_r; /* the radius search starts from the CLR box's */
    if (rl_shape_is_circle(shape))
        return 0;
    rl_refine_radius_shaped(img, tone, d->u, d->v, shape, &r);
    rl_profile_gather_shaped(img, tone, d->u, d->v, r, shape, &pe);
    rl_match_all(tt, &pe, &me);
    if (!(me.score > m->score))
        return 0;
    d->radius = r;
    *p = pe;
    *m = me;
    return 1;
}

/* Whether d, read as a circle or as c's ellipse, is under the size floor
 * (rl_twins_min_radius) along its narrowest extent: the ellipse's minor
 * semi-axis, its area's radius (d's) times the root of its aspect. The
 * floor is on code zone 1's width, and a landmark seen at a slant has it
 * narrowest along the minor axis, where the circle's radius read (or the
 * ellipse's, its area's) says it is wider: a whole 1 of a 15 px grey-mixed
 * sheet at aspect 0.88 read as its twin 17, its radius read 14.30 px over
 * the 14.2 px floor, its minor semi-axis 12.8 px (zone 1 1.08 px there,
 * under the 1.14 px every wrong read under the floor had; docs/results.md). */
static int under_floor(const rl_recog *rec, const rl_clr *c, const rl_detection *d)
{
    return d->radius * sqrt(rl_ellipse_aspect(&c->shape)) < rl_twins_min_radius(&rec->templates.fam);
}

/* The circle (then the ellipse) at d's place through tone: d's radius and
 * the match into *m; 1 when the rule takes it. */
static int identify_through(const rl_recog *rec, const rl_image *img, const rl_tone *tone,
                            const rl_clr *c, const rl_levels *local, int near_light, rl_detection *d,
                            rl_match *m)
{
    rl_accept_rule rule = rl_accept_rule_at(&rec->cfg, RL_PASS_GLOBAL, near_light);
    rl_profile p;
    double box_r = d->radius;
    int taken;
    rl_refine_radius(img, tone, d->u, d->v, &d->radius);
    rl_profile_gather(img, tone, d->u, d->v, d->radius, &p);
    rl_match_all(&rec->templates, &p, m);
    taken = rl_accept(&rule, m, rl_accept_span(local, tone, &p));
    if (!taken && try_ellipse(img, tone, &rec->templates, &c->shape, box_r, d, &p, m))
        taken = rl_accept(&rule, m, rl_accept_span(local, tone, &p));
    return taken;
}

void rl_global_read(const rl_recog *rec, const rl_image *img, const rl_clr *c, const rl_tone *tone,
                   const rl_result *res, rl_detection *d)
{
    const rl_levels *frame = &res->levels;
    rl_levels local;
    rl_match m;
    memset(d, 0, sizeof *d);
    d->id = -1;
    d->best_id = -1;
    d->pass = RL_PASS_GLOBAL;
    rl_clr_geometry(&c->box, rec->width, rec->height, d);
    /* the frame's levels as the light falls here */
    rl_accept_levels_at(&rec->illum, frame, d->u, d->v, &local);
    if (d->complete)
        rl_refine_centre(img, &local, &d->u, &d->v, d->radius);
    if (d->visible < GLOBAL_MIN_VISIBLE) {
        rl_refine_radius(img, tone, d->u, d->v, &d->radius);
        return;
    }
    /* as a circle first; an ellipse only when the circle is not taken */
    if (identify_through(rec, img, tone, c, &local,
                         rl_result_light_gap(res, &c->box) <= rec->cfg.near_light * d->radius, d, &m) &&
        !rl_inner_enclosed(img, frame->light, d->u, d->v, d->radius, 0.0) && !under_floor(rec, c, d)) {
        d->id = m.id;
        if (rec->cfg.band_radius && d->complete && rl_shape_is_circle(&c->shape))
            rl_refine_radius_band(img, tone, &rec->cfg.family, d->id, d->u, d->v, &d->radius);
    }
    d->best_id = m.id; /* taken or not: an unread candidate's nearest id */
    d->score = m.score;
    d->runner_up = m.second;
}
