#include "rl_split.h"

#include <string.h>
#include "rl_geom.h"

/* A region this long (box side, in the smallest readable landmark radii)
 * can hold a landmark and something beside it. */
#define LARGE_SIDE 4.0
/* Pieces of a faint outer ring: landmark-sized, filling little of their
 * box (a closed ring fills 0.28, an arc less); the rest of the ring lies
 * within half a piece's size of it. */
#define PIECE_MIN_SIDE 1.5
#define PIECE_MAX_SIDE 6.0
#define PIECE_MAX_FILL 0.3

rl_err rl_split_init(rl_split *sp, rl_ws *ws, const rl_label_map *frame)
{
    size_t n = (size_t)frame->nx * (size_t)frame->ny;
    rl_err e;
    sp->frame = frame;
    sp->n_lower = sp->n_higher = 0;
    if ((e = rl_ws_alloc(ws, n, RL_WS_ALIGN, (void **)&sp->lower)) != RL_OK ||
        (e = rl_ws_alloc(ws, n, RL_WS_ALIGN, (void **)&sp->higher)) != RL_OK ||
        (e = rl_ws_alloc(ws, RL_MAX_CANDIDATES * sizeof(rl_clr), RL_WS_ALIGN, (void **)&sp->found)) !=
            RL_OK)
        return e;
    return RL_OK;
}

/* 1 when region g is a candidate of cand[0 .. n) that the image border does
 * not cut: a closed ring, or one a lamp broke (the local pass reads it). */
static int whole_candidate(const rl_region *g, const rl_clr *cand, int n, int W, int H)
{
    int k;
    if (g->x0 == 0 || g->y0 == 0 || g->x1 == W - 1 || g->y1 == H - 1)
        return 0;
    for (k = 0; k < n; k++)
        if (cand[k].box.x0 == g->x0 && cand[k].box.y0 == g->y0 && cand[k].box.x1 == g->x1 &&
            cand[k].box.y1 == g->y1)
            return 1;
    return 0;
}

/* 1 when region g lies inside a candidate of cand[0 .. n) (its centre in
 * the box): a code ring, not a piece of an outer ring. */
static int in_candidate(const rl_region *g, const rl_clr *cand, int n)
{
    int k;
    for (k = 0; k < n; k++)
        if (rl_geom_box_has(&cand[k].box, (g->x0 + g->x1) / 2.0, (g->y0 + g->y1) / 2.0))
            return 1;
    return 0;
}

/* The tiles under region g's box, grown by `grow` px each way (within
 * the frame), get `ratio` of the frame's thresholds in hi. */
static void set_tiles(const rl_label_map *frame, uint8_t *hi, const rl_region *g, int grow,
                      double ratio)
{
    int T = frame->tile, tx, ty;
    int tx0 = g->x0 - grow < 0 ? 0 : (g->x0 - grow) / T, tx1 = (g->x1 + grow) / T;
    int ty0 = g->y0 - grow < 0 ? 0 : (g->y0 - grow) / T, ty1 = (g->y1 + grow) / T;
    tx1 = tx1 >= frame->nx ? frame->nx - 1 : tx1;
    ty1 = ty1 >= frame->ny ? frame->ny - 1 : ty1;
    for (ty = ty0; ty <= ty1; ty++)
        for (tx = tx0; tx <= tx1; tx++) {
            int i = ty * frame->nx + tx, v = (int)(ratio * frame->hi[i] + 0.5);
            hi[i] = (uint8_t)(v > 254 ? 254 : v); /* under the light threshold's top */
        }
}

void rl_split_mark(rl_split *sp, const rl_label *lb, const rl_clr *cand, int n,
                   const rl_recog_config *cfg)
{
    size_t tiles = (size_t)sp->frame->nx * (size_t)sp->frame->ny;
    double r = cfg->min_radius;
    int i;
    memset(sp->lower, 0, tiles);
    memset(sp->higher, 0, tiles);
    sp->n_lower = sp->n_higher = 0;
    for (i = 0; i < lb->n_regions; i++) {
        const rl_region *g = &lb->reg[i];
        int bw = g->x1 - g->x0 + 1, bh = g->y1 - g->y0 + 1, side = bw > bh ? bw : bh;
        double fill = g->area / ((double)bw * bh);
        if (side >= PIECE_MIN_SIDE * r && side <= PIECE_MAX_SIDE * r && fill <= PIECE_MAX_FILL &&
            !in_candidate(g, cand, n)) {
            set_tiles(sp->frame, sp->higher, g, side / 2, RL_SPLIT_HIGHER);
            sp->n_higher++;
        }
        if (side >= LARGE_SIDE * r && !whole_candidate(g, cand, n, lb->width, lb->height)) {
            set_tiles(sp->frame, sp->lower, g, 0, RL_SPLIT_LOWER);
            sp->n_lower++;
        }
    }
}

/* 1 when box b is at an identified landmark of res: its centre inside the
 * landmark's box (a code ring), or the landmark's centre inside b (the
 * landmark joined to something). */
static int at_landmark(const rl_result *res, const rl_box *b)
{
    double cx = (b->x0 + b->x1) / 2.0, cy = (b->y0 + b->y1) / 2.0;
    int j;
    for (j = 0; j < res->n_landmarks; j++)
        if (rl_geom_box_has(&res->landmarks[j].box, cx, cy) ||
            rl_geom_box_has(b, res->landmarks[j].u, res->landmarks[j].v))
            return 1;
    return 0;
}

/* 1 when box b is box a found again: its centre inside a, and of about
 * a's size. */
static int same_box(const rl_box *a, const rl_box *b)
{
    double sa = a->x1 - a->x0 + a->y1 - a->y0, sb = b->x1 - b->x0 + b->y1 - b->y0;
    return rl_geom_box_has(a, (b->x0 + b->x1) / 2.0, (b->y0 + b->y1) / 2.0) && sa > 0.75 * sb &&
           sa < 1.33 * sb;
}

/* 1 when box b is a code ring of candidate d: about concentric with it
 * (its centre within CODE_RING_OFFSET radii; a box the border cuts is off
 * by part of what is cut) and smaller (a code ring lies inside
 * RL_OUTER_RING_INNER of the radius; blur widens it a little). */
#define CODE_RING_MAX 0.9
#define CODE_RING_OFFSET 0.3
static int code_ring_of(const rl_detection *d, const rl_box *b)
{
    double bw = b->x1 - b->x0 + 1, bh = b->y1 - b->y0 + 1, side = bw > bh ? bw : bh;
    double dx = (b->x0 + b->x1) / 2.0 - d->u, dy = (b->y0 + b->y1) / 2.0 - d->v;
    return side <= CODE_RING_MAX * 2 * d->radius &&
           dx * dx + dy * dy <= CODE_RING_OFFSET * CODE_RING_OFFSET * d->radius * d->radius;
}

/* 1 when CLR box b is no new candidate: at a landmark, at an unidentified
 * candidate already read or one of its code rings (a cut landmark's, never
 * identified in the global pass), or at one of out[0 .. n). */
static int known(const rl_result *res, const rl_clr *out, int n, const rl_box *b)
{
    int k;
    if (at_landmark(res, b))
        return 1;
    for (k = 0; k < res->n_unidentified; k++)
        if (same_box(&res->unidentified[k].box, b) || code_ring_of(&res->unidentified[k], b))
            return 1;
    for (k = 0; k < n; k++)
        if (same_box(&out[k].box, b))
            return 1;
    return 0;
}

/* The marked tiles labelled under hi, their new CLRs appended to out[0 ..
 * n) (cap in all); returns the new count. */
static int label_tiles(rl_split *sp, const uint8_t *hi, rl_label *lb, const rl_image *img,
                       const rl_recog_config *cfg, int speck, rl_result *res, rl_clr *out, int n,
                       int cap)
{
    rl_label_map map = *sp->frame;
    int i, m;
    map.hi = hi;
    if (rl_label_dark(lb, img, &map, speck) != RL_OK)
        return n;
    res->dropped.regions += lb->overflow + (lb->rows_left > 0);
    m = rl_clr_find(lb, cfg, res, sp->found, RL_MAX_CANDIDATES);
    for (i = 0; i < m; i++) {
        if (known(res, out, n, &sp->found[i].box))
            continue;
        if (n < cap)
            out[n++] = sp->found[i];
        else
            res->dropped.candidates++;
    }
    return n;
}

int rl_split_find(rl_split *sp, rl_label *lb, const rl_image *img, const rl_recog_config *cfg,
                  int speck, rl_result *res, rl_clr *out, int cap)
{
    int n = 0;
    if (sp->n_lower > 0)
        n = label_tiles(sp, sp->lower, lb, img, cfg, speck, res, out, n, cap);
    if (sp->n_higher > 0)
        n = label_tiles(sp, sp->higher, lb, img, cfg, speck, res, out, n, cap);
    return n;
}
