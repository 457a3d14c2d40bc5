#include "rl_global.h"

#include <string.h>
#include "rl_accept.h"
#include "rl_clr.h"
#include "rl_inner.h"
#include "rl_match.h"
#include "rl_refine.h"
#include "rl_result.h"
#include "rl_twins_lead.h"

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

/* The circle (then the ellipse) at d's place through tone: d's radius and
 * the match into *m, the profile matched into *pp; 1 when the rule takes
 * it. */
static int identify_through(const rl_recog *rec, const rl_image *img, const rl_tone *tone,
                            const rl_clr *c, const rl_levels *local, int near_light, rl_detection *d,
                            rl_match *m, rl_profile *pp)
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
    *pp = p;
    return taken;
}

/* d's place before any refinement (the CLR box's circle: rl_clr_geometry),
 * the frame's levels there into *local; d otherwise a read of no id. */
static void place(const rl_recog *rec, const rl_clr *c, const rl_result *res, rl_detection *d,
                  rl_levels *local)
{
    memset(d, 0, sizeof *d);
    d->id = -1;
    d->best_id = -1;
    d->pass = RL_PASS_GLOBAL;
    rl_clr_geometry(&c->box, rec->width, rec->height, d);
    /* the frame's levels as the light falls here */
    rl_accept_levels_at(&rec->illum, &res->levels, d->u, d->v, local);
}

/* The read of d (placed: its centre refined) through tone, local the
 * frame's levels at its unrefined centre; with kept (a read the frame
 * keeps, not the tone reads' count), whether a clear one leads its zone
 * twins beside its radius too, from these pixels (d->twins_led:
 * rl_twins' shortcut asks). */
static void read_placed(const rl_recog *rec, const rl_image *img, const rl_clr *c, const rl_tone *tone,
                        const rl_result *res, const rl_levels *local, int kept, rl_detection *d)
{
    rl_match m;
    rl_profile p;
    if (d->visible < GLOBAL_MIN_VISIBLE) {
        rl_refine_radius(img, tone, d->u, d->v, &d->radius);
        return;
    }
    /* as a circle first; an ellipse only when the circle is not taken */
    if (identify_through(rec, img, tone, c, local,
                         rl_result_light_gap(res, &c->box) <= rec->cfg.near_light * d->radius, d, &m, &p) &&
        !rl_inner_enclosed(img, res->levels.light, d->u, d->v, d->radius, 0.0)) {
        d->id = m.id;
        d->twins_led = kept && rl_twins_led_read(rec, &p, &m, d);
        d->band_ready = rec->cfg.band_radius && d->complete && rl_shape_is_circle(&c->shape);
    }
    d->best_id = m.id; /* taken or not: an unread candidate's nearest id */
    d->score = m.score;
    d->runner_up = m.second;
}

void rl_global_read(const rl_recog *rec, const rl_image *img, const rl_clr *c, const rl_tone *tone,
                   const rl_result *res, rl_detection *d)
{
    rl_levels local;
    place(rec, c, res, d, &local);
    if (d->complete)
        rl_refine_centre(img, &local, &d->u, &d->v, d->radius);
    read_placed(rec, img, c, tone, res, &local, 1, d);
}

void rl_global_read_placed(const rl_recog *rec, const rl_image *img, const rl_clr *c, const rl_tone *tone,
                           const rl_result *res, double u, double v, rl_detection *d)
{
    rl_levels local;
    place(rec, c, res, d, &local);
    d->u = u;
    d->v = v;
    read_placed(rec, img, c, tone, res, &local, 0, d);
}

int rl_global_readable(const rl_clr *c, int W, int H)
{
    rl_detection d;
    rl_clr_geometry(&c->box, W, H, &d); /* rl_global_read's d->visible, before any read */
    return !(d.visible < GLOBAL_MIN_VISIBLE);
}
