/* rl_verify: a predicted landmark's id verified in its window (rl_verify.h). */
#include "rl_verify.h"

#include <math.h>
#include <string.h>
#include "rl_accept.h"
#include "rl_edge.h"
#include "rl_family.h"
#include "rl_geom.h"
#include "rl_inner.h"
#include "rl_match.h"
#include "rl_refine.h"
#include "rl_result.h"

/* The centre: at most CENTRE_STEPS steps (settle_centre), each over a
 * disk of INK_DISK radii from every INK_ROWS-th row, or once over
 * WIDE_DISK radii from every WIDE_ROWS-th row; settled when a step's disk
 * held the whole landmark (HELD_MARGIN px for its blurred edge to spare)
 * or it moved less than CENTRE_SETTLED px; no read when that is farther
 * than CENTRE_REACH radii from the prediction. */
#define CENTRE_STEPS 6
#define INK_DISK 1.2
#define INK_ROWS 2
#define WIDE_DISK 2.5
#define WIDE_ROWS 3
#define HELD_MARGIN 1.0
#define CENTRE_SETTLED 0.3
#define CENTRE_REACH 1.5
/* Next to the border, the centre is drawn over a disk down to this many
 * radii (all of the landmark but its outer ring's rim). */
#define MIN_ROOM 0.85
/* rl_refine_centre's disk stays this far inside the frame (px): its
 * pixels reach a pixel past the disk. The profile's quiet zone may be
 * cut, as the global pass reads one. */
#define WHOLE_MARGIN 1.5
/* The profile from every GATHER_ROWS-th row: a landmark's 700 pixels and
 * more tell its id (a doubtful one is read as before). */
#define GATHER_ROWS 3

/* The largest disk about (cx, cy) that rl_refine_centre reads (it stays
 * a pixel and a half inside the frame), px. */
static double room_at(const rl_image *img, double cx, double cy)
{
    return fmin(fmin(cx, cy), fmin(img->width - 1 - cx, img->height - 1 - cy)) - WHOLE_MARGIN;
}

/* The centre drawn from the prediction to the landmark's ink, a step at a
 * time (rl_refine_centre, counting only what is darker than midway from
 * the ceiling's light to the ink: the ceiling around the landmark, which
 * would hold the centre back, counts nothing). A step over a disk that
 * held all of the landmark (it moved the centre less than the disk's
 * margin over the landmark) lands on its ink's centre: settled. A step
 * that did not settle is followed by one over WIDE_DISK radii (a
 * prediction a radius off sees part of the landmark), then by the usual
 * ones; a step whose disk held no ink settles nothing (the wide one
 * follows). 0 when it does not settle within CENTRE_REACH radii of the
 * prediction, or the border cuts the disk it needs; *away 1 when the ink
 * drew it farther than that, or the wide disk held no ink. */
static int settle_centre(const rl_image *img, const rl_levels *local, double r, double *cx, double *cy,
                         int *away)
{
    double u0 = *cx, v0 = *cy;
    int k, wide = 0, widened = 0;
    rl_levels ink = *local;
    ink.bg = 0.5 * (local->bg + local->fg);
    if (!(ink.bg - ink.fg >= 1))
        return 0; /* no ink to draw to (rl_refine_centre would not move) */
    for (k = 0; k < CENTRE_STEPS; k++) {
        double u = *cx, v = *cy, room = room_at(img, u, v), disk, moved;
        *away = hypot(u - u0, v - v0) > CENTRE_REACH * r;
        if (room < MIN_ROOM * r || *away)
            return 0; /* the border cuts it, or it is not where predicted */
        wide = k > 0 && !widened && room >= WIDE_DISK * r;
        widened |= wide;
        disk = wide ? WIDE_DISK * r : fmin(INK_DISK * r, room);
        if (!(rl_refine_centre_rows(img, &ink, cx, cy, disk, wide ? WIDE_ROWS : INK_ROWS) > 0)) {
            /* no ink in the disk: not a centre that did not move; looked
             * for over the wide disk once, else not near */
            *away = wide;
            if (wide || widened || room < WIDE_DISK * r)
                return 0;
            continue;
        }
        moved = hypot(*cx - u, *cy - v);
        if (!wide && (moved + r + HELD_MARGIN <= disk || moved < CENTRE_SETTLED)) {
            *away = hypot(*cx - u0, *cy - v0) > CENTRE_REACH * r;
            return !*away && room_at(img, *cx, *cy) >= MIN_ROOM * r;
        }
    }
    return 0;
}

/* Next to the border (the centre step's disk would leave the frame within
 * EDGE_NEAR radii of the prediction) the centre is the circle through the
 * outer edge's visible part (rl_edge_fit_rays, the local pass's fit: rays
 * that leave the frame give no point), fitted twice (the second from the
 * first's centre), taken when its radius is within EDGE_RADIUS of the
 * predicted one and it is within CENTRE_REACH radii of the prediction
 * (rl_twins.c's edge_centre, on a whole read's circle, is another rule). */
#define EDGE_NEAR 1.2
#define EDGE_FITS 2
#define EDGE_RADIUS 0.1

static int edge_centre(const rl_image *img, const rl_tone *tone, int light, double r, double *cx, double *cy)
{
    double u = *cx, v = *cy, fr = r;
    int k;
    for (k = 0; k < EDGE_FITS; k++)
        if (!rl_edge_fit_rays(img, tone, light, &u, &v, &fr) || !(fabs(fr - r) <= EDGE_RADIUS * r))
            return 0;
    if (!(hypot(u - *cx, v - *cy) <= CENTRE_REACH * r))
        return 0;
    *cx = u;
    *cy = v;
    return 1;
}

/* The profile is gathered once, RADIUS_WIDEST times the predicted radius
 * r, and read as gathered at smaller radii (rl_profile_rescale): at r
 * first; when that is not clear, at the one of RADIUS_SCALES radii a few
 * percent either side where id's templates match best. */
#define RADIUS_WIDEST 1.05
#define RADIUS_SCALES 5
#define RADIUS_STEP 0.025
/* rl_recog holds one bin-move table a radius (rl_verify_init) */
typedef char rl_verify_scales_fit[sizeof(((rl_recog *)0)->verify_scales) ==
                                          RADIUS_SCALES * sizeof(rl_profile_scale) ? 1 : -1];

/* Scale k (0 .. RADIUS_SCALES - 1) of the gathered radius: k 2 is the
 * predicted radius, each next k RADIUS_STEP of it smaller. */
static double radius_scale(int k)
{
    return (1.0 - (k - RADIUS_SCALES / 2) * RADIUS_STEP) / RADIUS_WIDEST;
}

void rl_verify_init(rl_recog *rec)
{
    int k;
    for (k = 0; k < RADIUS_SCALES; k++)
        rl_profile_scale_make(radius_scale(k), &rec->verify_scales[k]);
}

/* The gathered profile read at scale s (rl_profile_rescale): by the
 * moves worked out at init when s is one of the radii, the same bits. */
static void rescale(const rl_recog *rec, const rl_profile *wide, double s, rl_profile *q)
{
    int k;
    for (k = 0; k < RADIUS_SCALES; k++)
        if (rec->verify_scales[k].made && rec->verify_scales[k].s == s) {
            rl_profile_rescale_by(wide, &rec->verify_scales[k], q);
            return;
        }
    rl_profile_rescale(wide, s, q);
}

/* id's best score over the RADIUS_SCALES radii (its templates alone),
 * and the scale (of the gathered radius) where it is reached (*at). */
static double best_of(const rl_recog *rec, const rl_profile *wide, int id, double *at)
{
    double best = -2;
    int k;
    *at = 1.0 / RADIUS_WIDEST;
    for (k = 0; k < RADIUS_SCALES; k++) {
        double s = radius_scale(k);
        rl_profile q;
        rl_match m;
        if (s > 1.0)
            continue;
        rescale(rec, wide, s, &q);
        rl_match_ids(&rec->templates, &q, &id, 1, -1, &m);
        if (m.id >= 0 && m.score > best) {
            best = m.score;
            *at = s;
        }
    }
    return best;
}

/* A taken id that leads every other id at its scale by less than this is
 * held against its zone twins at every scale (twin_fits_as_well). */
#define TWIN_CLEAR 0.1

/* Past rounding: a twin under the runner-up by less than this is scored. */
#define KNOWN_MARGIN 1e-9

/* Whether a code one zone from id (a zone twin) matches the profile at
 * its own best radius as well as id at id's: only the predicted id is
 * judged at the predicted radius, and a twin whose zone edge the blur or
 * the radius moved can lead there (a whole 2 of a degraded frame verified
 * as 18, 0.883 against 0.813, where a full frame reads 2). The profile is
 * rescaled once a radius, each code's own columns scored there; not at
 * s_read, where the id was taken (read: its match of every id): no twin
 * scored more than the runner-up there, under the id. The id's own best
 * is at least its score at s_read: the twins are scored first, and the id
 * at the other radii only when a twin reaches that (the same answer as
 * every code at every radius: test_verify_scales). */
static int twin_fits_as_well(const rl_recog *rec, const rl_profile *wide, int id, double s_read,
                             const rl_match *read)
{
    int codes[RL_MAX_BITS + 1], n, k, i, pass;
    double best[RL_MAX_BITS + 1], top = -2;
    codes[0] = id;
    n = 1 + rl_family_zone_twins(&rec->templates.fam, id, codes + 1);
    for (i = 0; i < n; i++)
        best[i] = -2;
    /* pass 0: the twins at every radius, the id at s_read; pass 1 (only
     * when a twin reached the id's score so far): the id at the others */
    for (pass = 0; pass < 2 && n > 1; pass++) {
        for (k = 0; k < RADIUS_SCALES; k++) {
            double s = radius_scale(k), sc[RL_MAX_BITS + 1];
            int at_read = s == s_read, from = pass == 0 && !at_read, to = pass == 0 ? n : 1;
            rl_profile q;
            if (s > 1.0 || (pass == 1 && at_read))
                continue;
            if (at_read && read->score - read->second > KNOWN_MARGIN) {
                /* the scale the id was taken at: every id was matched there,
                 * so id scored read->score and no twin more than read->second */
                best[0] = fmax(best[0], read->score);
                continue;
            }
            rescale(rec, wide, s, &q);
            /* each code's own columns, the profile's terms worked out once */
            rl_match_ids_each(&rec->templates, &q, codes + from, to - from, sc + from);
            for (i = from; i < to; i++)
                if (sc[i] > best[i])
                    best[i] = sc[i];
        }
        if (pass == 0) {
            for (i = 1; i < n; i++)
                top = fmax(top, best[i]);
            if (top < best[0])
                return 0; /* no twin reaches the id's score at s_read */
        }
    }
    for (i = 1; i < n; i++)
        if (best[i] >= best[0])
            return 1;
    return 0;
}

/* A known landmark's id (rl_verify.h: `known`) against its rivals alone
 * (rl_rivals) when its templates score RL_RIVALS_TAKEN or more at q: into
 * m->second their best, which the rule's lead and the zone twins' check
 * (twin_fits_as_well: the twins are rivals) take as the runner-up. 0 when
 * the rivals were not worked out, the map holds none of them, or the id
 * scores under that: every id is matched instead. */
static int rivals_only(const rl_recog *rec, const rl_profile *q, int id, rl_match *m)
{
    int rv[RL_MAX_IDS], n;
    rl_match r;
    /* no rivals in the map (n 0): every id matched, which is cheap on a
     * short list, gives the rule its runner-up */
    if (!(m->score >= RL_RIVALS_TAKEN) || (n = rl_rivals_of(&rec->rivals, &rec->templates, id, rv)) <= 0)
        return 0;
    rl_match_ids(&rec->templates, q, rv, n, -1, &r);
    if (r.id >= 0 && r.score > m->score) {
        /* a rival leads: not id (every id matched would say the same) */
        double own = m->score;
        *m = r;
        m->second = fmax(own, r.second);
    } else if (r.id >= 0) {
        m->second = fmax(m->second, r.score);
    }
    return 1;
}

/* The match of every id at every blur against the profile read at scale
 * s of the gathered one (into *m), as the global pass matches; 1 when the
 * rule takes it as id. A known landmark's id is matched against its
 * rivals alone when it scores high enough (rivals_only). */
static int judged(const rl_recog *rec, const rl_accept_rule *rule, const rl_levels *local,
                  const rl_profile *wide, double s, int id, int known, rl_match *m)
{
    rl_profile q;
    rescale(rec, wide, s, &q);
    /* the id's own columns first: below the rule's score at its best blur
     * it is not taken whatever the others score (the match of every id
     * would find the same score for it) */
    rl_match_ids(&rec->templates, &q, &id, 1, -1, m);
    if (!(m->id == id && m->score >= rule->min_score))
        return 0;
    if (!(known && rivals_only(rec, &q, id, m)))
        rl_match_all(&rec->templates, &q, m);
    return m->id == id && rl_accept(rule, m, rl_accept_span(local, rec->tone, &q));
}

/* The read radius held against the outer ring's edge (read_at). The
 * verification reads at the predicted radius, or the best of 0.95-1.05
 * of it, and trusted it: a prediction 10-15% off the landmark's radius (a
 * map's height, a pose or a place wrong) read another landmark there as
 * the predicted id, at a radius 5-10% off its own (docs/tracking.md,
 * twelfth session; test_verify_twins). Now where the ring's edge, measured
 * on the profile gathered (profile_edge), is more than EDGE_TRUSTED off
 * the predicted radius, the id must also lead every id (its rivals, when
 * known) at the edge: a veto, the read stays the one taken (taken at the
 * edge instead, the moving drive's poses moved and a whole landmark went
 * unread); no edge (no contrast from EDGE_FROM out) refuses it. A read at
 * the predicted radius must lead there at all; one best_of moved off it
 * by the rule's lead (an edge within a quarter of the outermost code
 * zone of such a read was taken as confirming it until the twelfth
 * session's review: on smeared moving landmarks predicted 15% short or 5%
 * long the edge measured 3-12% short sat on the read's own radius, a 19
 * read as 3, a 25 as 17, a 2 as 18). EDGE_TRUSTED is how far
 * the edge's measure strays on the bench's smeared, tone-mismatched
 * landmarks (within 0.04 of the renderer's radius on most, up to 0.07 on
 * the moving drive's): a prediction that close is trusted as before, and
 * the drives' reads judged again are few (2 of 587 on the demo's drive).
 * EDGE_FROM: the ring's levels are looked for from this many read radii
 * out (the outer ring of a landmark 15% larger or smaller lies beyond). */
#define EDGE_TRUSTED 0.04
#define EDGE_FROM 0.6

/* The outer ring's edge in profile p, as a scale of its gathered radius:
 * from the outside in, the first bin darker than midway between the
 * darkest and the lightest bins from `from` radii out (the profile's own
 * levels: a blurred ring's peak is under the ink's), then the steepest
 * fall of darkness within two bins of it (a symmetric blur leaves the
 * printed edge at its inflection, where midway of a lowered peak lies
 * outside), placed between bins by a parabola through the falls. -1 when
 * there is no contrast. */
static double profile_edge(const rl_profile *p, double from)
{
    double d[RL_PROFILE_BINS], hi = -1, lo = RL_TONE_MAX + 1.0, mid, g0, g1 = 0, g2, c;
    int k, k0 = (int)(from / RL_PROFILE_EXTENT * RL_PROFILE_BINS), kc = -1, kb = -1;
    k0 = k0 < 2 ? 2 : k0;
    for (k = k0 - 2; k < RL_PROFILE_BINS; k++) {
        d[k] = p->n[k] > 0 ? p->sx[k] / p->n[k] : -1; /* -1: no pixel */
        if (k >= k0 && d[k] >= 0) {
            if (d[k] > hi)
                hi = d[k];
            if (d[k] < lo)
                lo = d[k];
        }
    }
    if (!(hi > lo))
        return -1;
    mid = 0.5 * (hi + lo);
    for (k = RL_PROFILE_BINS - 1; k >= k0 && kc < 0; k--)
        if (d[k] >= mid)
            kc = k;
    if (kc < 0)
        return -1;
    for (k = kc - 2; k <= kc + 1 && k + 1 < RL_PROFILE_BINS; k++)
        if (d[k] >= 0 && d[k + 1] >= 0 && d[k] - d[k + 1] > g1) {
            g1 = d[k] - d[k + 1];
            kb = k;
        }
    if (kb < 0)
        return (kc + 1.0) / RL_PROFILE_BINS * RL_PROFILE_EXTENT;
    g0 = kb > k0 - 2 && d[kb - 1] >= 0 ? d[kb - 1] - d[kb] : 0;
    g2 = kb + 2 < RL_PROFILE_BINS && d[kb + 2] >= 0 ? d[kb + 1] - d[kb + 2] : 0;
    c = g0 - 2 * g1 + g2;
    /* between bins only where kb's fall is at least both neighbours' (the
     * window's steepest may sit beside a steeper one outside it): the
     * parabola's top is then within half a bin of kb's */
    return (kb + 1 + (c < 0 && g1 >= g0 && g1 >= g2 ? 0.5 * (g0 - g2) / c : 0)) / RL_PROFILE_BINS *
           RL_PROFILE_EXTENT;
}

/* The read at d's centre (settled): the profile gathered there, judged
 * as id (judged, best_of; local: the levels at the prediction), not a
 * code ring; into *d. */
static int read_at(const rl_recog *rec, const rl_image *img, const rl_result *res, const rl_levels *local,
                   int id, int known, double r, rl_detection *d)
{
    rl_accept_rule rule;
    rl_profile wide;
    rl_match m;
    double s = 1.0 / RADIUS_WIDEST;
    int taken;
    d->box.x0 = (int)floor(d->u - r);
    d->box.y0 = (int)floor(d->v - r);
    d->box.x1 = (int)ceil(d->u + r);
    d->box.y1 = (int)ceil(d->v + r);
    rule = rl_accept_rule_at(&rec->cfg, RL_PASS_GLOBAL,
                             rl_result_light_gap(res, &d->box) <= rec->cfg.near_light * r);
    rl_stage_enter(&rec->cfg.stage_hook, RL_STAGE_WIN_PROFILE);
    rl_profile_gather_rows(img, rec->tone, d->u, d->v, RADIUS_WIDEST * r, GATHER_ROWS, &wide);
    rl_stage_enter(&rec->cfg.stage_hook, RL_STAGE_WIN_ID);
    taken = judged(rec, &rule, local, &wide, s, id, known, &m);
    if (!taken) {
        double bs;
        best_of(rec, &wide, id, &bs);
        if (bs != s)
            taken = judged(rec, &rule, local, &wide, s = bs, id, known, &m);
    }
    if (taken) {
        /* a veto: where the ring's edge is off the prediction
         * (EDGE_TRUSTED), the id must lead every id there too (the rule's
         * score, contrast and blur): by the rule's lead for a read off
         * the prediction's radius (best_of's; an edge agreeing with it
         * confirmed nothing: twelfth session's review), by any lead for
         * one at it (its lead was met there); the read stays the one
         * taken at s */
        double e = profile_edge(&wide, EDGE_FROM * s);
        if (!(fabs(1.0 / RADIUS_WIDEST - e) <= EDGE_TRUSTED * e)) {
            rl_accept_rule leads = rule;
            rl_match at_edge;
            if (s == 1.0 / RADIUS_WIDEST)
                leads.min_lead = 1.0;
            taken = e > 0 && e <= 1.0 && judged(rec, &leads, local, &wide, e, id, known, &at_edge);
        }
    }
    if (taken && m.score - m.second < TWIN_CLEAR) {
        rl_stage_enter(&rec->cfg.stage_hook, RL_STAGE_WIN_TWINS);
        if (twin_fits_as_well(rec, &wide, id, s, &m))
            taken = 0;
    }
    d->radius = RADIUS_WIDEST * r * s;
    d->best_id = m.id;
    d->score = m.score;
    d->runner_up = m.second;
    /* not a code ring of a larger landmark read as its own (as the global
     * pass drops one); around a known landmark, no larger than the map's
     * landmarks, r as predicted (the local pass bounds it by the frame's
     * size alike): its rays stop past the quiet zone */
    if (taken)
        rl_stage_enter(&rec->cfg.stage_hook, RL_STAGE_WIN_RING);
    if (!taken ||
        rl_inner_enclosed(img, res->levels.light, d->u, d->v, d->radius,
                          known ? RL_INNER_REACH * r + RL_INNER_REACH_PX : 0.0))
        return 0;
    d->id = id;
    d->pass = RL_PASS_GLOBAL;
    /* no twin fit as well at 0.95 .. 1.05 (twin_fits_as_well), or the id
     * led every id by TWIN_CLEAR */
    d->twins_led = 1;
    d->complete = rl_geom_disk_complete(img->width, img->height, d->u, d->v, d->radius);
    d->visible = rl_geom_visible_in(img->width, img->height, d->u, d->v, d->radius);
    return 1;
}

int rl_verify_read(const rl_recog *rec, const rl_image *img, const rl_result *res, int id, int known,
                   double u, double v, double r, rl_detection *d, int *away)
{
    rl_levels local;
    int far = 0;
    memset(d, 0, sizeof *d);
    d->id = d->best_id = -1;
    if (away != NULL)
        *away = 0;
    if (!(r > 0))
        return 0;
    rl_stage_enter(&rec->cfg.stage_hook, RL_STAGE_WIN_CENTRE);
    rl_accept_levels_at(&rec->illum, &res->levels, u, v, &local);
    d->u = u;
    d->v = v;
    if (!settle_centre(img, &local, r, &d->u, &d->v, &far)) {
        if (away != NULL)
            *away = far;
        return 0;
    }
    return read_at(rec, img, res, &local, id, known, r, d);
}

int rl_verify_read_border(const rl_recog *rec, const rl_image *img, const rl_result *res, int id, int known,
                          double u, double v, double r, rl_detection *d)
{
    rl_levels local;
    memset(d, 0, sizeof *d);
    d->id = d->best_id = -1;
    d->u = u;
    d->v = v;
    if (!(r > 0) || room_at(img, u, v) >= EDGE_NEAR * r)
        return 0;
    rl_stage_enter(&rec->cfg.stage_hook, RL_STAGE_WIN_CENTRE);
    if (!edge_centre(img, rec->tone, res->levels.light, r, &d->u, &d->v))
        return 0;
    rl_accept_levels_at(&rec->illum, &res->levels, u, v, &local);
    return read_at(rec, img, res, &local, id, known, r, d);
}
