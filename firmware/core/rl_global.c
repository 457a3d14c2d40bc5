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

void rl_global_identify(const rl_recog *rec, const rl_image *img, const rl_box *b, rl_result *res)
{
    rl_accept_rule rule = rl_accept_rule_of(&rec->cfg, RL_PASS_GLOBAL);
    rl_detection d;
    rl_levels local;
    rl_profile p;
    rl_match m;
    double scale;
    memset(&d, 0, sizeof d);
    d.id = -1;
    d.pass = RL_PASS_GLOBAL;
    if (!rl_clr_geometry(b, rec->width, rec->height, &d))
        return;
    res->n_candidates++;
    /* the frame's levels as the light falls here */
    scale = rl_illum_scale(&rec->illum, d.u, d.v);
    local = res->levels;
    local.bg *= scale;
    local.fg *= scale;
    if (d.complete)
        rl_refine_centre(img, &local, &d.u, &d.v, d.radius);
    rl_refine_radius(img, d.u, d.v, &d.radius);
    if (d.visible < GLOBAL_MIN_VISIBLE) {
        rl_result_add_unidentified(res, &d);
        return;
    }
    rl_profile_gather(img, d.u, d.v, d.radius, &p);
    rl_match_all(&rec->templates, &p, &m);
    d.score = m.score;
    if (rl_accept(&rule, &m, local.bg - local.fg) &&
        !(rl_inner_possible(res, &d) && rl_inner_enclosed(img, res->levels.light, d.u, d.v, d.radius))) {
        d.id = m.id;
        rl_result_add_landmark(res, &d);
    } else {
        rl_result_add_unidentified(res, &d);
    }
}
