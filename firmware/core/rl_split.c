#include "rl_split.h"

#include <string.h>

/* A region this long (box side, in the smallest readable landmark radii)
 * can hold a landmark and something beside it. */
#define LARGE_SIDE 4.0

rl_err rl_split_init(rl_split *sp, rl_ws *ws, const rl_label_map *frame)
{
    rl_err e = rl_ws_alloc(ws, (size_t)frame->nx * (size_t)frame->ny, RL_WS_ALIGN, (void **)&sp->hi);
    if (e != RL_OK)
        return e;
    sp->map = *frame;
    sp->map.hi = sp->hi;
    return RL_OK;
}

/* 1 when region g is a CLR of cand[0 .. n) that the image border does not
 * cut: a closed outer ring, nothing joined to it. */
static int whole_clr(const rl_region *g, const rl_clr *cand, int n, int W, int H)
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

/* The tiles under region g get the lowered thresholds. */
static void mark(rl_split *sp, const rl_label_map *frame, const rl_region *g)
{
    int tx, ty, T = frame->tile;
    for (ty = g->y0 / T; ty <= g->y1 / T; ty++)
        for (tx = g->x0 / T; tx <= g->x1 / T; tx++) {
            int i = ty * frame->nx + tx;
            sp->hi[i] = (uint8_t)(RL_SPLIT_RATIO * frame->hi[i] + 0.5);
        }
}

/* 1 when CLR b is CLR a found again: its centre inside a's box, and of
 * about a's size. */
static int same_clr(const rl_box *a, const rl_box *b)
{
    double cx = (b->x0 + b->x1) / 2.0, cy = (b->y0 + b->y1) / 2.0;
    double sa = a->x1 - a->x0 + a->y1 - a->y0, sb = b->x1 - b->x0 + b->y1 - b->y0;
    return cx >= a->x0 && cx <= a->x1 && cy >= a->y0 && cy <= a->y1 && sa > 0.75 * sb &&
           sa < 1.33 * sb;
}

int rl_split_find(rl_split *sp, const rl_label_map *frame, rl_label *lb, const rl_image *img,
                  const rl_recog_config *cfg, int speck, rl_result *res, rl_clr *cand, int n,
                  int cap)
{
    int i, j, m, large = 0;
    memset(sp->hi, 0, (size_t)frame->nx * (size_t)frame->ny);
    for (i = 0; i < lb->n_regions; i++) {
        const rl_region *g = &lb->reg[i];
        int bw = g->x1 - g->x0 + 1, bh = g->y1 - g->y0 + 1;
        if ((bw > bh ? bw : bh) < LARGE_SIDE * cfg->min_radius ||
            whole_clr(g, cand, n, lb->width, lb->height))
            continue;
        mark(sp, frame, g);
        large++;
    }
    if (large == 0 || rl_label_dark(lb, img, &sp->map, speck) != RL_OK)
        return n;
    /* the new CLRs after the first labelling's, then the ones found again
     * left out */
    m = n + rl_clr_find(lb, cfg, res, cand + n, cap - n);
    for (i = n, j = n; i < m; i++) {
        int k, again = 0;
        for (k = 0; k < n && !again; k++)
            again = same_clr(&cand[k].box, &cand[i].box);
        if (!again)
            cand[j++] = cand[i];
    }
    return j;
}
