#include "rl_clr.h"

#include "rl_geom.h"
#include "rl_result.h"

/* Shape limits of an outer ring's region (with whatever code rings merged
 * into it). The outer ring alone fills 0.28 of its bounding box, a nearly
 * black landmark 0.75; blur and thresholding move both a little, and a
 * motion thins the ring's arcs along it down to 0.11-0.14. */
#define FILL_MIN 0.08
#define FILL_MAX 0.85
#define ASPECT_MAX 1.4   /* bounding box width/height (lens distortion) */
#define CENTROID_MAX 0.2 /* centroid to box centre, in radii */

/* A region touching the border: its uncut extent is the diameter, and at
 * most half may be missing. A corner cut is kept too: the rings inside it
 * must not pass for landmarks, and the local pass reads it. */
static int cut_candidate(const rl_region *g, const rl_recog_config *cfg, int W, int H)
{
    int bw = g->x1 - g->x0 + 1, bh = g->y1 - g->y0 + 1;
    int cut_x = g->x0 == 0 || g->x1 == W - 1, cut_y = g->y0 == 0 || g->y1 == H - 1;
    double r = cut_x && cut_y ? (bw > bh ? bw : bh) / 2.0 : cut_x ? bh / 2.0 : bw / 2.0;
    return !(r < cfg->min_radius || r > cfg->max_radius ||
             (!(cut_x && cut_y) && (cut_x ? bw : bh) < r));
}

/* A whole region shaped like a closed outer ring. */
static int ring_shaped(const rl_region *g, const rl_recog_config *cfg)
{
    int bw = g->x1 - g->x0 + 1, bh = g->y1 - g->y0 + 1;
    double r = (bw + bh) / 4.0, fill = (double)g->area / ((double)bw * bh);
    double ox = g->sx / g->area - (g->x0 + g->x1) / 2.0;
    double oy = g->sy / g->area - (g->y0 + g->y1) / 2.0;
    return !(r < cfg->min_radius || r > cfg->max_radius || fill < FILL_MIN || fill > FILL_MAX ||
             bw > ASPECT_MAX * bh || bh > ASPECT_MAX * bw ||
             ox * ox + oy * oy > CENTROID_MAX * CENTROID_MAX * r * r);
}

/* Not a closed outer ring; but next to a light, glare may have washed
 * part of one out: landmark-sized by its larger side, it is kept for the
 * local pass. */
static int broken_by_light(const rl_region *g, const rl_recog_config *cfg, const rl_result *res,
                           const rl_box *b)
{
    int bw = g->x1 - g->x0 + 1, bh = g->y1 - g->y0 + 1;
    double rr = (bw > bh ? bw : bh) / 2.0;
    return !(rr < cfg->min_radius || rr > cfg->max_radius || bw < rr || bh < rr ||
             rl_result_light_gap(res, b) > cfg->near_light * rr);
}

/* The ellipse of region i from its central second moments. */
static rl_shape region_shape(const rl_label *lb, int i)
{
    double cxx, cxy, cyy;
    rl_label_moments(lb, i, &cxx, &cxy, &cyy);
    return rl_shape_from_moments(cxx, cxy, cyy);
}

/* Motion breaks an outer ring: along the motion its thin arcs smear
 * lighter than the threshold, and what is left are two arcs facing each
 * other across the code. Arcs (regions of at least a minimum radius
 * along their longer side, not ring-shaped themselves; a cut candidate
 * too) are kept here, at most ARCS_MAX of them (the first in label
 * order), to be paired. */
#define ARCS_MAX 48

/* Two halves of one broken ring: each box well short of the whole
 * (HALF_WHOLE of its area at most), and with a cut half each nearly as
 * long as the ring is wide (HALF_SPAN). */
#define HALF_SPAN 0.8
#define HALF_WHOLE 1.25

/* The larger side of a box. */
static int box_size(const rl_box *b)
{
    int w = b->x1 - b->x0 + 1, h = b->y1 - b->y0 + 1;
    return w > h ? w : h;
}

static rl_box region_box(const rl_region *g)
{
    rl_box b;
    b.x0 = g->x0;
    b.y0 = g->y0;
    b.x1 = g->x1;
    b.y1 = g->y1;
    return b;
}

static int longer_side(const rl_region *g)
{
    rl_box b = region_box(g);
    return box_size(&b);
}

/* Long enough to be part of a ring, no longer than a whole one (a wall,
 * a fixture: they would take the places of arcs). */
static int arc_like(const rl_region *g, const rl_recog_config *cfg)
{
    int side = longer_side(g);
    return side >= 1.4 * cfg->min_radius && side <= 2 * cfg->max_radius;
}

static double box_area(const rl_region *g)
{
    return (double)(g->x1 - g->x0 + 1) * (g->y1 - g->y0 + 1);
}

static int touches_border(const rl_region *g, int W, int H)
{
    return g->x0 == 0 || g->y0 == 0 || g->x1 == W - 1 || g->y1 == H - 1;
}

/* Two arcs, halves of one ring (each box well short of their union's),
 * whose union is shaped like a closed outer ring, or, where one of them
 * runs into the border (the other not), like a cut one; the union into
 * *u. */
static int arcs_close(const rl_region *a, const rl_region *b, const rl_recog_config *cfg, int W,
                      int H, rl_region *u)
{
    int cut_a = touches_border(a, W, H), cut_b = touches_border(b, W, H);
    if (cut_a && cut_b)
        return 0;
    u->x0 = a->x0 < b->x0 ? a->x0 : b->x0;
    u->y0 = a->y0 < b->y0 ? a->y0 : b->y0;
    u->x1 = a->x1 > b->x1 ? a->x1 : b->x1;
    u->y1 = a->y1 > b->y1 ? a->y1 : b->y1;
    u->area = a->area + b->area;
    u->sx = a->sx + b->sx;
    u->sy = a->sy + b->sy;
    if (!cut_a && !cut_b)
        return box_area(u) >= HALF_WHOLE * box_area(a) && box_area(u) >= HALF_WHOLE * box_area(b) &&
               ring_shaped(u, cfg);
    /* with a cut one: two halves of one ring, each nearly as long as the
     * ring is wide and each well short of the whole */
    return longer_side(a) >= HALF_SPAN * longer_side(u) && longer_side(b) >= HALF_SPAN * longer_side(u) &&
           box_area(u) >= HALF_WHOLE * box_area(a) && box_area(u) >= HALF_WHOLE * box_area(b) &&
           cut_candidate(u, cfg, W, H);
}

/* Candidate (box, shape) after the n in cand, or counted dropped at cap;
 * the new count. */
static int add_candidate(rl_clr *cand, int n, int cap, const rl_box *box, rl_shape shape,
                         rl_result *res)
{
    if (n == cap) {
        res->dropped.candidates++;
        return n;
    }
    cand[n].box = *box;
    cand[n].shape = shape;
    return n + 1;
}

/* The closed rings of the arcs kept, as candidates after the n in cand. */
static int close_arcs(const rl_region *arcs, int na, const rl_recog_config *cfg, int W, int H,
                      rl_result *res, rl_clr *cand, int n, int cap)
{
    int i, j;
    for (i = 0; i < na; i++)
        for (j = i + 1; j < na; j++) {
            rl_region u;
            rl_box b;
            if (!arcs_close(&arcs[i], &arcs[j], cfg, W, H, &u))
                continue;
            b = region_box(&u);
            n = add_candidate(cand, n, cap, &b, rl_shape_circle(), res);
        }
    return n;
}

int rl_clr_find(const rl_label *lb, const rl_recog_config *cfg, rl_result *res, rl_clr *cand,
                int cap)
{
    rl_region arcs[ARCS_MAX];
    int i, n = 0, na = 0, W = lb->width, H = lb->height;
    for (i = 0; i < lb->n_regions; i++) {
        const rl_region *g = &lb->reg[i];
        int cut = touches_border(g, W, H), ring = !cut && ring_shaped(g, cfg);
        rl_box b = region_box(g);
        /* any region but a closed ring may be half of a broken one (a
         * cut candidate too: the half the border does not cut is apart);
         * arcs past ARCS_MAX are counted with the candidates dropped */
        if (!ring && arc_like(g, cfg)) {
            if (na < ARCS_MAX)
                arcs[na++] = *g;
            else
                res->dropped.candidates++;
        }
        if (cut ? !cut_candidate(g, cfg, W, H) : !ring && !broken_by_light(g, cfg, res, &b))
            continue;
        n = add_candidate(cand, n, cap, &b, ring ? region_shape(lb, i) : rl_shape_circle(), res);
    }
    return close_arcs(arcs, na, cfg, W, H, res, cand, n, cap);
}

/* A code ring's box is at least 0.36 of its landmark's outer ring (the
 * smallest zone boundary, ring5's); a larger box around a candidate is
 * not its outer ring but something else (a lamp's fixture, a wall). */
#define INNER_MAX_RATIO 3.2

int rl_clr_is_inner(const rl_clr *cand, int n, int i)
{
    int j;
    for (j = 0; j < n; j++)
        if (j != i && rl_geom_box_inside(&cand[i].box, &cand[j].box) &&
            !(rl_geom_box_inside(&cand[j].box, &cand[i].box) && j > i) &&
            box_size(&cand[j].box) <= INNER_MAX_RATIO * box_size(&cand[i].box))
            return 1;
    return 0;
}

void rl_clr_geometry(const rl_box *b, int W, int H, rl_detection *d)
{
    int bw = b->x1 - b->x0 + 1, bh = b->y1 - b->y0 + 1;
    int cut_l = b->x0 == 0, cut_r = b->x1 == W - 1, cut_t = b->y0 == 0, cut_b = b->y1 == H - 1;
    d->box = *b;
    d->u = (b->x0 + b->x1) / 2.0;
    d->v = (b->y0 + b->y1) / 2.0;
    d->radius = (bw + bh) / 4.0;
    d->visible = 1.0;
    d->complete = !(cut_l || cut_r || cut_t || cut_b);
    if (d->complete)
        return;
    if ((cut_l || cut_r) && (cut_t || cut_b)) {
        /* a corner: the longer side is at most the diameter (the local
         * pass fits the circle) */
        d->radius = (bw > bh ? bw : bh) / 2.0;
        d->u = cut_l ? b->x1 + 0.5 - d->radius : b->x0 - 0.5 + d->radius;
        d->v = cut_t ? b->y1 + 0.5 - d->radius : b->y0 - 0.5 + d->radius;
        d->visible = rl_geom_visible_in(W, H, d->u, d->v, d->radius);
        return;
    }
    if (cut_l || cut_r) {
        d->radius = bh / 2.0;
        d->u = cut_l ? b->x1 + 0.5 - d->radius : b->x0 - 0.5 + d->radius;
        d->visible = rl_geom_disk_visible(d->radius, cut_l ? d->u + 0.5 : W - 0.5 - d->u);
    } else {
        d->radius = bw / 2.0;
        d->v = cut_t ? b->y1 + 0.5 - d->radius : b->y0 - 0.5 + d->radius;
        d->visible = rl_geom_disk_visible(d->radius, cut_t ? d->v + 0.5 : H - 0.5 - d->v);
    }
}
