#include "rl_global.h"

#include <string.h>
#include "rl_accept.h"
#include "rl_clr.h"
#include "rl_inner.h"
#include "rl_match.h"
#include "rl_refine.h"
#include "rl_result.h"

/* Border landmarks with at most this much missing are identified in the
 * global pass (their outer ring is closed but for a sliver); the rest wait
 * for the local pass. */
#define GLOBAL_MIN_VISIBLE 0.95

/* Radius, profile and match of candidate d as an ellipse of the given
 * shape, from the radius of its box; 1 (and d's radius, p, m replaced)
 * when that matches better than what they hold. An ellipse from a region's moments is perspective or the
 * lens's distortion, or a circle smeared by motion (its rings are not
 * ellipses then): the match tells which. */
static int try_ellipse(const rl_image *img, const rl_templates *tt, const rl_shape *shape,
                       double box_r, rl_detection *d, rl_profile *p, rl_match *m)
{
    rl_profile pe;
    rl_match me;
    double r = box_r; /* the radius search starts from the CLR box's */
    if (rl_shape_is_circle(shape))
        return 0;
    rl_refine_radius_shaped(img, d->u, d->v, shape, &r);
    rl_profile_gather_shaped(img, d->u, d->v, r, shape, &pe);
    rl_match_all(tt, &pe, &me);
    if (!(me.score > m->score))
        return 0;
    d->radius = r;
    *p = pe;
    *m = me;
    return 1;
}

void rl_global_identify(const rl_recog *rec, const rl_image *img, const rl_clr *c, rl_result *res)
{
    rl_accept_rule rule = rl_accept_rule_of(&rec->cfg, RL_PASS_GLOBAL);
    rl_detection d;
    rl_levels local;
    rl_profile p;
    rl_match m;
    double box_r;
    int taken;
    memset(&d, 0, sizeof d);
    d.id = -1;
    d.pass = RL_PASS_GLOBAL;
    if (!rl_clr_geometry(&c->box, rec->width, rec->height, &d))
        return;
    res->n_candidates++;
    /* the frame's levels as the light falls here */
    rl_accept_levels_at(&rec->illum, &res->levels, d.u, d.v, &local);
    if (d.complete)
        rl_refine_centre(img, &local, &d.u, &d.v, d.radius);
    if (d.visible < GLOBAL_MIN_VISIBLE) {
        rl_refine_radius(img, d.u, d.v, &d.radius);
        rl_result_add_unidentified(res, &d);
        return;
    }
    /* as a circle first; an ellipse only when the circle is not taken */
    box_r = d.radius;
    rl_refine_radius(img, d.u, d.v, &d.radius);
    rl_profile_gather(img, d.u, d.v, d.radius, &p);
    rl_match_all(&rec->templates, &p, &m);
    taken = rl_accept(&rule, &m, rl_accept_span(&local, &p));
    if (!taken && try_ellipse(img, &rec->templates, &c->shape, box_r, &d, &p, &m))
        taken = rl_accept(&rule, &m, rl_accept_span(&local, &p));
    d.score = m.score;
    if (taken &&
        !rl_inner_enclosed(img, res->levels.light, d.u, d.v, d.radius)) {
        d.id = m.id;
        if (rec->cfg.band_radius && d.complete && rl_shape_is_circle(&c->shape))
            rl_refine_radius_band(img, &rec->cfg.family, d.id, d.u, d.v, &d.radius);
        rl_result_add_landmark(res, &d);
    } else {
        rl_result_add_unidentified(res, &d);
    }
}
