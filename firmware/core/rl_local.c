#include "rl_local.h"

#include <math.h>
#include <string.h>
#include "rl_accept.h"
#include "rl_edge.h"
#include "rl_ellipse.h"
#include "rl_geom.h"
#include "rl_inner.h"
#include "rl_locate.h"
#include "rl_result.h"
#include "rl_search.h"

/* Ellipses the local pass tries: flatter than this is not a landmark seen
 * through the lens, rounder is a circle; the fit's centre and radius must
 * stay near the circle's (a circle through a flattened arc sits up to a
 * third of a radius off the ellipse's centre). */
#define ELLIPSE_MIN_ASPECT 0.6
#define ELLIPSE_MAX_ASPECT 0.97
#define ELLIPSE_MAX_MOVE 0.4

/* The zone twins' best score against the ellipse e at radii around its
 * own (at_r: e's profile at its own radius), as m's runner-up when higher (as the search does for circles,
 * which holds them and every other id one zone away: the ellipse's two
 * twins only, its reads not measured with the others). */
static void ellipse_twins(const rl_templates *tt, const rl_image *img, const rl_tone *tone,
                          const rl_ellipse *e, const rl_profile *at_r, rl_match *m)
{
    int twins[2], n = rl_match_twins(tt, m->id, twins), k;
    for (k = 0; n > 0 && k < RL_SEARCH_TWIN_SCALES; k++) {
        rl_profile p;
        const rl_profile *pk = at_r;
        rl_match mm;
        /* at scale 1 (e->r * 1.0 is e->r) the profile local_ellipse
         * gathered, at_r: not gathered again */
        if (rl_search_twin_scale[k] != 1.0) {
            rl_profile_gather_shaped(img, tone, e->cx, e->cy, e->r * rl_search_twin_scale[k], &e->shape, &p);
            pk = &p;
        }
        rl_match_ids(tt, pk, twins, n, -1, &mm);
        if (mm.id >= 0 && mm.score > m->second)
            m->second = mm.score;
    }
}

/* The candidate at (cx, cy, r) as an ellipse fitted to its outer edge
 * (perspective, the lens: a circle's profile smears its zones): its match
 * into *m (its zone twins not yet in m->second: ellipse_twins), the span of light its contrast counts against into *span (not
 * sector-normalized), the ellipse into *e and its profile into *p; 0 when the
 * edge is no such ellipse. */
static int local_ellipse(const rl_recog *rec, const rl_image *img, const rl_result *res,
                         double cx, double cy, double r, rl_ellipse *e, rl_match *m, double *span,
                         rl_profile *p)
{
    const rl_templates *tt = &rec->templates;
    int light = res->levels.light;
    rl_levels local;
    double ex[RL_EDGE_RAYS], ey[RL_EDGE_RAYS], aspect;
    int n = rl_edge_points(img, rec->tone, light, cx, cy, r, ex, ey);
    if (!rl_ellipse_fit(ex, ey, n, cx, cy, r, e))
        return 0;
    aspect = rl_ellipse_aspect(&e->shape);
    if (aspect < ELLIPSE_MIN_ASPECT || aspect > ELLIPSE_MAX_ASPECT ||
        hypot(e->cx - cx, e->cy - cy) > ELLIPSE_MAX_MOVE * r || fabs(e->r - r) > ELLIPSE_MAX_MOVE * r)
        return 0;
    rl_profile_gather_shaped(img, rec->tone, e->cx, e->cy, e->r, &e->shape, p);
    rl_match_all(tt, p, m);
    rl_accept_levels_at(&rec->illum, &res->levels, e->cx, e->cy, &local);
    *span = rl_accept_span(&local, rec->tone, p);
    return 1;
}

/* The rule for a match on a landmark the border cuts: a circle fitted to
 * what is left of it can be a tenth off in size, and at a radius that
 * much off a zone twin comes close, so its lead over the runner-up must
 * be CUT_LEAD; at a moving template MOVING_CUT_LEAD, as the moving
 * templates average every direction of the motion and a cut landmark
 * shows only some of them (a zone twin can fit the directions left). */
#define CUT_LEAD 1.5
#define MOVING_CUT_LEAD 1.6
static rl_accept_rule cut_rule(const rl_accept_rule *rule, const rl_match *m, double visible)
{
    rl_accept_rule r = *rule;
    double lead = rl_templates_moving(m->blur) ? MOVING_CUT_LEAD : CUT_LEAD;
    if (visible < 1.0 && r.min_lead < lead)
        r.min_lead = lead;
    return r;
}

/* How far out an axis must lie in the frame, in radii (the quiet zone). */
#define AXIS_REACH 1.1
/* The lead a read of half an axis needs. */
#define HALF_READ_LEAD 2.0

/* 1 when octant `o` of the landmark at (cx, cy, r) lies wholly in the
 * W x H frame out to its quiet zone. */
static int octant_in_frame(const rl_polar *pol, int o, int W, int H, double cx, double cy, double r)
{
    double t = atan2(pol->uy[o], pol->ux[o]);
    int e, in = 1;
    for (e = -1; e <= 1; e++) {
        double x = cx + AXIS_REACH * r * cos(t + e * M_PI / RL_POLAR_OCTANTS);
        double y = cy + AXIS_REACH * r * sin(t + e * M_PI / RL_POLAR_OCTANTS);
        in &= x >= 0 && y >= 0 && x <= W - 1 && y <= H - 1;
    }
    return in;
}

/* The reads across the motion of the landmark at (cx, cy, r), as octant
 * masks into reads[READS_MAX]: first the whole ones, *whole of them: each
 * axis (an octant and its opposite) and each pair of an octant and its
 * mirror image across the vertical (two octants on one side of the
 * horizontal: a lamp or a shadow on the other side), wholly in the frame;
 * then the half of an axis the border cuts that is in it (the other half
 * reads a zone twin as well as the code). Returns how many in all. */
#define READS_MAX (2 * RL_POLAR_AXES) /* an axis or its half, and a pair */
static int reads_in_frame(const rl_polar *pol, int W, int H, double cx, double cy, double r,
                          unsigned *reads, int *whole)
{
    unsigned half[RL_POLAR_AXES], in = 0;
    int a, n = 0, nh = 0;
    if (rl_geom_disk_complete(W, H, cx, cy, AXIS_REACH * r + 0.5)) /* within 0 .. W - 1 */
        in = RL_POLAR_ALL; /* most candidates: no octant to test */
    else
        for (a = 0; a < RL_POLAR_OCTANTS; a++)
            in |= octant_in_frame(pol, a, W, H, cx, cy, r) ? 1u << a : 0;
    for (a = 0; a < RL_POLAR_AXES; a++) {
        unsigned axis = 1u << a | 1u << rl_polar_opposite(a), side = 1u << a | 1u << rl_polar_mirror(a);
        if ((in & axis) == axis)
            reads[n++] = axis;
        else if (in & axis)
            half[nh++] = in & axis;
        if ((in & side) == side)
            reads[n++] = side;
    }
    *whole = n;
    for (a = 0; a < nh; a++)
        reads[n++] = half[a];
    return n;
}

/* A match taken by the local pass: the rule, with the larger lead of a
 * landmark the border cuts (cut_rule) where the one at (cx, cy, r) is;
 * span as rl_accept's (255 on the polar cells'
 * sector-normalized levels). */
static int local_accept(const rl_accept_rule *rule, const rl_match *m, int W, int H, double cx, double cy,
                        double r, double span)
{
    rl_accept_rule mr = cut_rule(rule, m, rl_geom_visible_in(W, H, cx, cy, r));
    return rl_accept(&mr, m, span);
}

/* A cut landmark's fitted radius this far under the frame's is retried at
 * the frame's (cut_outwards). */
#define CUT_SHRUNK 0.9

/* (x, y) moved by d towards the nearest border. */
static void cut_outwards(int W, int H, double d, double *x, double *y)
{
    double l = *x, rgt = W - 1 - *x, t = *y, b = H - 1 - *y;
    double mx = l < rgt ? l : rgt, my = t < b ? t : b;
    if (mx < my)
        *x += l < rgt ? -d : d;
    else
        *y += t < b ? -d : d;
}

/* A local candidate's read: its match and where it was made. */
typedef struct {
    rl_match m;
    double cx, cy, r;
} local_read;

/* 1 when (x, y) lies in the W x H frame. */
static int in_frame(int W, int H, double x, double y)
{
    return x >= 0 && y >= 0 && x <= W - 1 && y <= H - 1;
}

/* Not as a circle: as the ellipse its edge may be (the cut rule with the
 * ellipse's own template); 1 when taken, into *rd. An ellipse whose centre
 * lies outside the frame was fitted to less than half its edge: where it
 * names another id than the circle's (rd's), the landmark's id depends on
 * the read, and it gets none (-1: no later read either). A cut 7 of a
 * 15 px grey-mixed sheet, its circle reading 23, read as 15 from an
 * ellipse 2.9 px out of the frame and 14% too large; a cut 1 whose
 * ellipse out of the frame read 1 and its circle 17, where refusing only
 * the ellipse let a later read take 17. */
static int read_ellipse(const rl_recog *rec, const rl_image *img, const rl_result *res,
                        const rl_accept_rule *rule, local_read *rd)
{
    rl_ellipse e;
    rl_match me;
    rl_profile pe;
    double span;
    int later;
    if (!local_ellipse(rec, img, res, rd->cx, rd->cy, rd->r, &e, &me, &span, &pe))
        return 0;
    /* a higher runner-up only lowers a lead whose runner-up is >= 0: a
     * match the rule rejects without its twins' scores is rejected with
     * them, and they are gathered only for one it takes; nor for one
     * under the rule's score, which no runner-up makes taken */
    later = me.second >= 0;
    if (me.id >= 0 && !later && me.score >= rule->min_score)
        ellipse_twins(&rec->templates, img, rec->tone, &e, &pe, &me);
    if (!local_accept(rule, &me, rec->width, rec->height, e.cx, e.cy, e.r, span))
        return 0;
    if (!in_frame(rec->width, rec->height, e.cx, e.cy) && me.id != rd->m.id)
        return -1;
    if (me.id >= 0 && later) {
        ellipse_twins(&rec->templates, img, rec->tone, &e, &pe, &me);
        if (!local_accept(rule, &me, rec->width, rec->height, e.cx, e.cy, e.r, span))
            return 0;
    }
    rd->m = me;
    rd->cx = e.cx;
    rd->cy = e.cy;
    rd->r = e.r;
    return 1;
}

/* Read across the motion: the same id as the circle's, and plain there,
 * along each axis in the frame (reads_in_frame); a half axis, half the
 * pixels, must lead by HALF_READ_LEAD. Reads the polar cells of the
 * circle's search. Not from a centre outside the frame (a circle fitted
 * to less than half a ring): no read sees it, and a few octants read
 * from a centre a few pixels off can name another code clearly. Nor for
 * a cut circle whose search found a zone twin (or another id one zone
 * away) reading better over it than the id (m.second over m.score,
 * twin_check): the axes left in the
 * frame then settle nothing between the two (the moving set's cut 22 of
 * frame 008, from a circle 1.3 px off and 3% large, was taken as its
 * twin 30 along an axis; test_search_twins). */
static int read_across_axes(const rl_recog *rec, const rl_accept_rule *rule, const local_read *rd)
{
    int W = rec->width, H = rec->height, n, whole;
    unsigned reads[READS_MAX];
    rl_accept_rule half = *rule;
    rl_match ma;
    if (rd->m.id < 0 || rd->m.score < rule->min_score || !in_frame(W, H, rd->cx, rd->cy) ||
        (rd->m.second > rd->m.score && rl_geom_visible_in(W, H, rd->cx, rd->cy, rd->r) < 1.0))
        return 0;
    n = reads_in_frame(rec->polar, W, H, rd->cx, rd->cy, rd->r, reads, &whole);
    rl_search_across_motion(&rec->templates, rec->polar, rec->kept, rd->cx, rd->cy, rd->r, rd->m.id,
                            rule->max_blur, reads, whole, &ma);
    if (local_accept(rule, &ma, W, H, rd->cx, rd->cy, rd->r, 255.0))
        return 1; /* ma names the circle's id, or none */
    if (half.min_lead < HALF_READ_LEAD)
        half.min_lead = HALF_READ_LEAD;
    rl_search_across_motion(&rec->templates, rec->polar, rec->kept, rd->cx, rd->cy, rd->r, rd->m.id,
                            rule->max_blur, reads + whole, n - whole, &ma);
    return local_accept(&half, &ma, W, H, rd->cx, rd->cy, rd->r, 255.0);
}

/* read_across_axes, timed as the stage of its own it is (rl_stage.h). */
static int read_across(const rl_recog *rec, const rl_accept_rule *rule, const local_read *rd)
{
    int taken;
    rl_stage_enter(&rec->cfg.stage_hook, RL_STAGE_ACROSS);
    taken = read_across_axes(rec, rule, rd);
    rl_stage_enter(&rec->cfg.stage_hook, RL_STAGE_LOCAL);
    return taken;
}

/* A read searched from the circle (cx, cy, r) (its polar cells gathered
 * anew); 1 when taken, into *rd, else 0, or -1 where neither its first
 * match nor the search's step out scored min_first and it was read no
 * further (rl_search_identify_over; -INFINITY: always searched). */
static int read_from_over(rl_recog *rec, const rl_image *img, int light, const rl_accept_rule *rule,
                          double min_first, double cx, double cy, double r, local_read *rd)
{
    local_read s;
    s.cx = cx;
    s.cy = cy;
    s.r = r;
    if (!rl_search_identify_over(&rec->templates, rec->polar, rec->kept, img, rec->tone, light, min_first,
                                 rule->min_score, &s.cx, &s.cy, &s.r, &s.m))
        return -1;
    if (!local_accept(rule, &s.m, rec->width, rec->height, s.cx, s.cy, s.r, 255.0))
        return 0;
    *rd = s;
    return 1;
}

/* read_from_over, always searched: 1 when taken, into *rd. */
static int read_from(rl_recog *rec, const rl_image *img, int light, const rl_accept_rule *rule,
                     double cx, double cy, double r, local_read *rd)
{
    return read_from_over(rec, img, light, rule, -INFINITY, cx, cy, r, rd) > 0;
}

/* A cut landmark whose edge fit came out small (a circle through what is
 * left of a broken ring sits inside the frame): read again at the frame's
 * size R, its centre moved out towards the border by the difference; 1
 * when taken, into *rd. */
static int read_cut_at_size(rl_recog *rec, const rl_image *img, int light, double R,
                            const rl_accept_rule *rule, local_read *rd)
{
    double cx = rd->cx, cy = rd->cy;
    if (!(rl_geom_visible_in(rec->width, rec->height, rd->cx, rd->cy, rd->r) < 1.0 &&
          rd->r < CUT_SHRUNK * R))
        return 0;
    cut_outwards(rec->width, rec->height, R - rd->r, &cx, &cy);
    return read_from(rec, img, light, rule, cx, cy, R, rd);
}

/* A cut landmark read where the global pass put it too (the UCLR u: the
 * centre from its box, a radius in from the far side, and the radius
 * refined from there): where a motion or a lamp broke the ring, the edge
 * fit can go astray (a fifth or more off in size) while the box still
 * holds, and at a fit a tenth short a zone twin can pass. The two must
 * agree: taken (into *rd) when the fit's read was and the box's names no
 * other id, or when only the box's was; 0 when they name different ids.
 * Where no other read took it, the box's is floored as a whole
 * candidate's first read is (min_first: neither its first match nor the
 * search's step out scoring it, it is read no further; counted in
 * *box_floored unless NULL). On the development folders' composites 305
 * box reads came after no other read took and 2 of them took, from first
 * matches of 0.92 and 0.94; 174 of the others were under 0.5 there. Where
 * the fit's read was taken the box's is always searched: it may name
 * another id (4 did on 3.6mm_29Sep2013). */
static int cut_agrees_with_box(rl_recog *rec, const rl_image *img, int light, const rl_detection *u,
                               const rl_accept_rule *rule, double min_first, int taken, local_read *rd,
                               int *box_floored)
{
    local_read b;
    int at_box = read_from_over(rec, img, light, rule, taken ? -INFINITY : min_first, u->u, u->v, u->radius, &b);
    if (at_box < 0) {
        if (box_floored)
            (*box_floored)++;
        at_box = 0;
    }
    if (!taken) {
        if (at_box)
            *rd = b;
        return at_box;
    }
    return !at_box || b.m.id == rd->m.id;
}

/* A candidate whose fitted circle has less than this in the frame is not
 * tried. The candidate was taken as a DUCLR with at least half of its
 * box's circle in the frame (is_duclr); its fitted circle may show less:
 * a circle fitted to half a ring sits up to a tenth of a radius further
 * out than the ring (the arc, cut by the border, fixes centre and radius
 * together only loosely), which leaves about 0.44 of it in the frame. A
 * landmark half in the frame still shows every zone along the directions
 * that point into it; one only 0.4 in it (its centre 0.16 R out) is tried
 * too, under the cut rule. */
#define CUT_MIN_VISIBLE 0.4

/* The search from rd's circle (rl_search.h), into *rd; 0 when u is whole
 * (its box's circle and the fitted circle rd both in the frame) and
 * neither its first match nor the search's step out scores min_first
 * (then it is read no further: no search, ellipse or read across the
 * motion; counted in *floored when floored is not NULL). A cut one (by its
 * box or its fitted circle) is read at the frame's size and at its box
 * too, and was taken from first matches as low as 0.15. */
static int first_read(rl_recog *rec, const rl_image *img, int light, const rl_detection *u, double min_first,
                      const rl_accept_rule *rule, local_read *rd, int *floored)
{
    int whole = rl_local_whole(rec->width, rec->height, u, rd->cx, rd->cy, rd->r);
    if (rl_search_identify_over(&rec->templates, rec->polar, rec->kept, img, rec->tone, light,
                                whole ? min_first : -INFINITY, rule->min_score, &rd->cx, &rd->cy, &rd->r, &rd->m))
        return 1;
    if (floored)
        (*floored)++;
    return 0;
}

/* The reads of a DUCLR u (of expected radius R) from rd, the circle
 * fitted to its outer edge; 1 if identified (into *out, whose box the
 * caller set). An identified one is dropped when a ring starting within
 * `reach` px of its centre encloses it (rl_inner; 0: any its size
 * allows), or whose id's contrast at the frame's levels is under
 * RL_ACCEPT_LOCAL_SHARE of the span (no print: a grey ring); a whole one
 * whose first reads score under min_first is read
 * no further (first_read, counted in *floored unless NULL), nor a cut
 * one's read at its box after no other read took it (cut_agrees_with_box,
 * in *box_floored unless NULL). */
static int circle_reads(rl_recog *rec, const rl_image *img, const rl_result *res, const rl_detection *u, double R,
                        double reach, double min_first, int *floored, int *box_floored, local_read rd,
                        rl_detection *out)
{
    rl_accept_rule rule = rl_accept_rule_of(&rec->cfg, RL_PASS_LOCAL);
    int W = rec->width, H = rec->height, light = res->levels.light;
    int taken, ellipse = 0;
    /* the fitted radius, not the frame's median: lens distortion makes
     * landmarks smaller away from the image centre */
    out->pass = RL_PASS_LOCAL;
    if (rl_geom_visible_in(W, H, rd.cx, rd.cy, rd.r) < CUT_MIN_VISIBLE)
        return 0;
    if (!first_read(rec, img, light, u, min_first, &rule, &rd, floored))
        return 0;
    /* the circle; the ellipse (whose centre is the better one where both
     * read); across the motion (the circle's cells); a cut one at the
     * frame's size, and always where its box put it too */
    taken = local_accept(&rule, &rd.m, W, H, rd.cx, rd.cy, rd.r, 255.0);
    if (!taken && (ellipse = read_ellipse(rec, img, res, &rule, &rd)) < 0)
        return 0; /* the circle and the ellipse out of the frame disagree */
    taken = taken || ellipse > 0 || read_across(rec, &rule, &rd) || read_cut_at_size(rec, img, light, R, &rule, &rd);
    if (!u->complete)
        taken = cut_agrees_with_box(rec, img, light, u, &rule, min_first, taken, &rd, box_floored);
    out->u = rd.cx;
    out->v = rd.cy;
    out->radius = rd.r;
    rl_geom_circle_box(W, H, rd.cx, rd.cy, rd.r, &out->box); /* the reads moved the located circle */
    out->complete = rl_geom_disk_complete(W, H, rd.cx, rd.cy, rd.r);
    out->visible = rl_geom_visible_in(W, H, rd.cx, rd.cy, rd.r);
    if (!taken || rl_inner_enclosed(img, light, rd.cx, rd.cy, rd.r, reach) ||
        rl_accept_plain_share(&rec->templates, &rec->illum, &res->levels, img, rec->tone, rd.cx, rd.cy, rd.r,
                              rd.m.id) < RL_ACCEPT_LOCAL_SHARE)
        return 0;
    out->id = rd.m.id;
    out->score = rd.m.score;
    out->runner_up = rd.m.second;
    return 1;
}

/* Retry one DUCLR u of expected radius R: its outer ring found again
 * (rl_locate), then read from the circle fitted to it (circle_reads). */
static int local_candidate(rl_recog *rec, const rl_image *img, const rl_result *res,
                           const rl_detection *u, double R, double reach, double min_first, int *floored,
                           int *box_floored, rl_detection *out)
{
    local_read rd;
    memset(out, 0, sizeof *out);
    if (!rl_locate_outer_ring(rec, img, res, u, R, &out->box, &rd.cx, &rd.cy, &rd.r))
        return 0;
    return circle_reads(rec, img, res, u, R, reach, min_first, floored, box_floored, rd, out);
}

/* A UCLR of about the frame's landmark size is retried wherever it is:
 * motion can break a landmark's outer ring (its inner ring is then the
 * candidate, of about half the size) or smear its zones past what the
 * frame's thresholds and one profile read. */
#define UNREAD_MIN_SIZE 0.4
#define UNREAD_MAX_SIZE 1.3

/* A DUCLR: next to a light, cut by the border with at most half of it
 * missing (as its box puts it; the fitted circle may show a little less,
 * CUT_MIN_VISIBLE), or a landmark-sized UCLR the global pass could not
 * read. */
static int is_duclr(const rl_recog_config *cfg, const rl_result *res, const rl_detection *u,
                    double R)
{
    int near_light = rl_result_light_gap(res, &u->box) <= cfg->near_light * R;
    int on_border = !u->complete;
    int landmark_sized = u->radius > UNREAD_MIN_SIZE * R && u->radius < UNREAD_MAX_SIZE * R;
    return (near_light || on_border || landmark_sized) && (!on_border || u->visible >= 0.5);
}

void rl_local_pass(rl_recog *rec, const rl_image *img, rl_result *res)
{
    double rexp = rl_result_median_radius(res);
    double reach = rexp > 0 ? RL_INNER_REACH * rexp + RL_INNER_REACH_PX : 0.0; /* 0: the frame's size unknown */
    int i, kept = 0, n = res->n_unidentified;
    for (i = 0; i < n; i++) {
        rl_detection u = res->unidentified[i], d;
        double R = rexp > 0 ? rexp : u.radius;
        if (is_duclr(&rec->cfg, res, &u, R)) {
            res->local_tried++;
            if (local_candidate(rec, img, res, &u, R, reach, rec->cfg.local_min_first, &res->local_floored,
                                &res->local_box_floored, &d)) {
                if (rl_result_add_landmark(res, &d))
                    res->local_found++;
                continue;
            }
        }
        res->unidentified[kept++] = u;
    }
    res->n_unidentified = kept;
}

int rl_local_whole(int W, int H, const rl_detection *u, double cx, double cy, double r)
{
    return u->complete && rl_geom_disk_complete(W, H, cx, cy, r);
}

int rl_local_read(rl_recog *rec, const rl_image *img, const rl_result *res, const rl_detection *u, double R,
                  rl_detection *out)
{
    return local_candidate(rec, img, res, u, R, RL_INNER_REACH * R + RL_INNER_REACH_PX, -INFINITY, NULL, NULL, out);
}

int rl_local_read_circle(rl_recog *rec, const rl_image *img, const rl_result *res, const rl_detection *u,
                         double R, double cx, double cy, double r, rl_detection *out)
{
    local_read rd;
    memset(out, 0, sizeof *out);
    memset(&rd, 0, sizeof rd);
    out->box = u->box;
    rd.cx = cx;
    rd.cy = cy;
    rd.r = r;
    return circle_reads(rec, img, res, u, R, RL_INNER_REACH * R + RL_INNER_REACH_PX, rec->cfg.local_min_first, NULL,
                        NULL, rd, out);
}
