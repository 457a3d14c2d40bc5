#include "rl_locate.h"

#include <math.h>
#include "rl_edge.h"
#include "rl_geom.h"
#include "rl_hist.h"
#include "rl_speck.h"

/* Window half-size around a DUCLR, in expected radii: room for the whole
 * landmark and its quiet zone with a quarter radius to spare for the
 * centre estimate of a ring broken by glare. */
#define WINDOW_RADII 1.5

/* Extension: the window around candidate u (expected radius R), clipped
 * to the frame and shrunk on any side that would reach into a light
 * source (never into the landmark itself); 0 when too small. */
static int local_window(const rl_result *res, const rl_detection *u, double R, rl_box *w)
{
    double half = WINDOW_RADII * R;
    int i, x0 = (int)floor(u->u - half), x1 = (int)ceil(u->u + half);
    int y0 = (int)floor(u->v - half), y1 = (int)ceil(u->v + half);
    for (i = 0; i < res->n_lights; i++) {
        const rl_box *l = &res->lights[i];
        if (l->x1 < x0 || l->x0 > x1 || l->y1 < y0 || l->y0 > y1)
            continue;
        if (l->x0 > u->u + 1.1 * R && l->x0 - 1 < x1) x1 = l->x0 - 1;
        if (l->x1 < u->u - 1.1 * R && l->x1 + 1 > x0) x0 = l->x1 + 1;
        if (l->y0 > u->v + 1.1 * R && l->y0 - 1 < y1) y1 = l->y0 - 1;
        if (l->y1 < u->v - 1.1 * R && l->y1 + 1 > y0) y0 = l->y1 + 1;
    }
    w->x0 = x0 < 0 ? 0 : x0;
    w->y0 = y0 < 0 ? 0 : y0;
    w->x1 = x1 > res->width - 1 ? res->width - 1 : x1;
    w->y1 = y1 > res->height - 1 ? res->height - 1 : y1;
    return w->x1 - w->x0 >= 8 && w->y1 - w->y0 >= 8;
}

/* Local clustering: the dark/paper threshold by K-means on the histogram
 * of the landmark's own square (LEVELS_RADII about the candidate, inside
 * the window), light excluded; into *thr, and the ink's level into *ink.
 * Not the whole window: beside a lamp its glare is the brightest class,
 * and the midway would fall between paper and glare. 0 when the square
 * has no clear contrast. */
#define LEVELS_RADII 1.0
static int local_threshold(const rl_image *img, const rl_box *w, const rl_detection *u, double R,
                           const rl_tone *tone, int light, int *thr, double *ink)
{
    double centre[2], half = LEVELS_RADII * R;
    int x0 = (int)floor(u->u - half), x1 = (int)ceil(u->u + half);
    int y0 = (int)floor(u->v - half), y1 = (int)ceil(u->v + half);
    rl_image sq;
    rl_hist h;
    x0 = x0 < w->x0 ? w->x0 : x0;
    y0 = y0 < w->y0 ? w->y0 : y0;
    x1 = x1 > w->x1 ? w->x1 : x1;
    y1 = y1 > w->y1 ? w->y1 : y1;
    if (x1 - x0 < 8 || y1 - y0 < 8 || rl_image_sub(img, x0, y0, x1 - x0 + 1, y1 - y0 + 1, &sq) != RL_OK)
        return 0;
    rl_hist_compute_rows(&sq, &h, 4); /* every fourth row: 600 pixels at 25 px */
    if (rl_hist_kmeans(&h, 0, light, 2, centre, NULL) != RL_OK || centre[1] - centre[0] < 8.0)
        return 0;
    *thr = rl_tone_midway(tone, centre[0], centre[1]);
    *ink = centre[0];
    return 1;
}

/* A region smaller than this (box side, in expected radii) is no outer
 * ring: a code ring, taken for the centre it surrounds. */
#define RING_MIN_SIZE 1.6

/* The longer side of a region's box. */
static double region_size(const rl_region *g)
{
    double bw = g->x1 - g->x0 + 1, bh = g->y1 - g->y0 + 1;
    return bw > bh ? bw : bh;
}

/* Re-extraction: the largest region of landmark size near the candidate
 * (window coordinates, the window at w), one whose box holds the
 * candidate's centre before any other (a ring surrounds its centre; a
 * printed marker or a fixture beside the landmark does not, and the
 * candidate's centre, pulled towards such a thing when the two were one
 * region, still lies within the ring), or -1. */
static int local_outer_ring(const rl_label *lb, const rl_box *w, const rl_detection *u, double R)
{
    double best_size = 0;
    int i, best = -1, best_holds = 0;
    for (i = 0; i < lb->n_regions; i++) {
        const rl_region *g = &lb->reg[i];
        double size = region_size(g);
        double gx = w->x0 + (g->x0 + g->x1) / 2.0, gy = w->y0 + (g->y0 + g->y1) / 2.0;
        rl_box b;
        int holds;
        if (size < R || size > 2.5 * R || fabs(gx - u->u) > 1.2 * R || fabs(gy - u->v) > 1.2 * R)
            continue;
        b.x0 = w->x0 + g->x0;
        b.y0 = w->y0 + g->y0;
        b.x1 = w->x0 + g->x1;
        b.y1 = w->y0 + g->y1;
        holds = rl_geom_box_has(&b, u->u, u->v);
        if (holds > best_holds || (holds == best_holds && size > best_size)) {
            best_size = size;
            best = i;
            best_holds = holds;
        }
    }
    return best;
}

#define LOCATE_SIZE_TOLERANCE 0.45

/* Thresholds tried, each midway between the ink and the one before: the
 * first may join the outer ring to its surroundings (a ceiling darker
 * than the paper past a narrow margin, paper dimmed away from a lamp)
 * into one region too large for a landmark. */
#define LOCATE_STEPS 3

/* The grey outer edge along rays from the candidate's own centre, at the
 * frame's radius R, where the circle of the region's outline (*cx, *cy
 * on entry, its radius outline_r) lies more than ARC_OFF radii from it or
 * is over ARC_LARGE times its size; 1 when found (into
 * *cx, *cy, *r). Where motion broke the outer ring into arcs, the region
 * taken for the ring (or, under RING_MIN_SIZE, for the code ring) is an
 * arc, and the circle of its outline can sit a landmark's width away
 * (45-50 px on a whole 12 and a whole 8 of the moving set, 4.9 and 5.3 px
 * of motion, whose candidates' centres and the global pass's reads were
 * right): no ray from there finds the edge. A circle nearer the
 * candidate is the ring's own; trying the candidate's centre there too
 * located a few more (5 of 27 on the bench's moving frames) that no read
 * then took, at 5-10% of the local pass's time. An outline's circle half
 * again as large as the landmark is no ring's either, however near it
 * lies (a whole 12 of the sanitizer build's moving set, 4.9 px of motion:
 * 44 px about a point 10 px from the candidate). */
#define ARC_OFF 0.5
#define ARC_LARGE 1.5
/* ... and the circle found from there is taken only where at least 9
 * (RL_EDGE_ARC_MIN_POINTS) of the 24 rays' edge points (from the
 * candidate's centre) lie within 1 px of the circle returned, or a 25th
 * of its radius where that is more (rl_edge_fit_arc; the edge's scatter
 * grows with the size: at 1 px, against the first least-squares circle,
 * the letter sheets of
 * 3.6mm_28Sep2013 at 40-80 px lost 1-2 landmarks a setting). The broken
 * rings of the moving set give 10, 12 and 18; over the moving, cluttered,
 * clutter_only, glare, motion and border sets the fallback found 13
 * circles that are no landmark (clutter, fixtures, the paper's corners),
 * 12 of them through 5-8 points (one of 11, clutter_only), each then a
 * local read that no rule took. Without the check (0) the moving,
 * held-out, border, glare, motion, cluttered and clutter_only sets read
 * the same (the fallback's failed fit taken as a circle, as ">= 0" on
 * the old count did, loses a cut landmark of the held-out set: 178 ->
 * 177); no read test shows it (test_edge_fit's
 * a_bar_is_no_arc does). */
static int rays_from_candidate(const rl_recog *rec, const rl_image *img, int light, const rl_detection *u,
                               double R, double outline_r, double *cx, double *cy, double *r)
{
    if (hypot(*cx - u->u, *cy - u->v) <= ARC_OFF * R && outline_r <= ARC_LARGE * R)
        return 0;
    *cx = u->u;
    *cy = u->v;
    *r = R;
    return rl_edge_fit_arc(img, rec->tone, light, cx, cy, r);
}

int rl_locate_outer_ring(rl_recog *rec, const rl_image *img, const rl_result *res,
                         const rl_detection *u, double R, rl_box *box, double *cx, double *cy,
                         double *r)
{
    rl_image win;
    rl_box w;
    rl_edge_window ew;
    int thr, reg = -1, step, light = res->levels.light, code_ring, found;
    double ink, tx, ty, tr = R;
    if (!local_window(res, u, R, &w) ||
        rl_image_sub(img, w.x0, w.y0, w.x1 - w.x0 + 1, w.y1 - w.y0 + 1, &win) != RL_OK ||
        !local_threshold(img, &w, u, R, rec->tone, light, &thr, &ink))
        return 0;
    for (step = 0; step < LOCATE_STEPS && reg < 0; step++) {
        if (step > 0)
            thr = rl_tone_midway(rec->tone, ink, thr);
        if (rl_label_band(&rec->dark, &win, 0, thr, rl_speck_area(&rec->cfg)) != RL_OK)
            return 0;
        reg = local_outer_ring(&rec->dark, &w, u, R);
    }
    if (reg < 0)
        return 0;
    code_ring = region_size(&rec->dark.reg[reg]) < RING_MIN_SIZE * R;
    /* the centre from the visible outer edge, not the centroid of what is
     * left (biased inwards when part is missing) */
    ew.img = &win;
    ew.x0 = w.x0;
    ew.y0 = w.y0;
    ew.frame_w = rec->width;
    ew.frame_h = rec->height;
    if (!rl_edge_fit_outline(&rec->dark, reg, &ew, thr, light, cx, cy, r))
        return 0;
    *cx += w.x0;
    *cy += w.y0;
    /* then the grey outer edge, from that centre (the identification
     * refines centre and radius once more) */
    tx = *cx;
    ty = *cy;
    found = rl_edge_fit_rays(img, rec->tone, light, &tx, &ty, &tr);
    if (!found)
        found = rays_from_candidate(rec, img, light, u, R, *r, &tx, &ty, &tr);
    if (found) {
        *cx = tx;
        *cy = ty;
        *r = tr;
    } else if (code_ring) {
        return 0; /* a code ring taken for its centre: its radius is not the landmark's */
    }
    /* the box: the fitted circle's within the frame, whatever region was
     * taken (a code ring, an arc, a part of a ring motion broke) */
    rl_geom_circle_box(rec->width, rec->height, *cx, *cy, *r, box);
    /* the frame's landmarks are of one size but for the lens: a wide angle
     * shrinks them towards the corners, where a circle fitted to an
     * ellipse's arc comes out shorter still */
    return fabs(*r - R) <= LOCATE_SIZE_TOLERANCE * R;
}
