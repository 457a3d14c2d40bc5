#include "rl_recog.h"

#include <math.h>
#include <string.h>

/* Shape limits of an outer ring's region (with whatever code rings merged
 * into it). The outer ring alone fills 0.28 of its bounding box, a nearly
 * black landmark 0.75; blur and thresholding move both a little. */
#define FILL_MIN 0.15
#define FILL_MAX 0.85
#define ASPECT_MAX 1.4   /* bounding box width/height (lens distortion) */
#define CENTROID_MAX 0.2 /* centroid to box centre, in radii */

void rl_recog_defaults(rl_recog_config *cfg)
{
    memset(cfg, 0, sizeof *cfg);
    cfg->family.bits = 5;
    cfg->ids = NULL;
    cfg->n_ids = 0;
    cfg->min_score = 0.80;
    cfg->min_margin = 0.04;
    cfg->min_radius = 6.0;
    cfg->max_radius = 0.0;
    cfg->size_tolerance = 0.35;
    cfg->need = 2;
    cfg->local = RL_LOCAL_AUTO;
    cfg->near_light = 1.5;
}

static int cap_runs(int w, int h)
{
    long n = (long)w * h / RL_PIXELS_PER_RUN;
    return n < 1024 ? 1024 : (int)n;
}

static rl_err check_config(const rl_recog_config *cfg, int w, int h)
{
    int i;
    if (w <= 0 || h <= 0 || w > RL_MAX_IMAGE_DIM || h > RL_MAX_IMAGE_DIM)
        return RL_EINVAL;
    if (cfg->family.bits < RL_FAMILY_MIN_BITS || cfg->family.bits > RL_MAX_BITS)
        return RL_ERANGE;
    if (cfg->ids != NULL) {
        if (cfg->n_ids <= 0)
            return RL_EINVAL;
        if (cfg->n_ids > RL_MAX_MAP_LANDMARKS)
            return RL_ELIMIT;
        for (i = 0; i < cfg->n_ids; i++)
            if (!rl_family_valid(&cfg->family, cfg->ids[i]))
                return RL_ERANGE;
    }
    if (!(cfg->min_radius >= 2.0) || cfg->max_radius < 0 || !(cfg->min_score > 0) ||
        cfg->min_score > 1 || cfg->need < 1)
        return RL_EINVAL;
    return RL_OK;
}

/* The one allocation sequence, shared by sizing (ws counts) and init. */
static rl_err layout(rl_recog *rec, rl_ws *ws, const rl_recog_config *cfg, int w, int h)
{
    rl_err e;
    int runs = cap_runs(w, h);
    if ((e = rl_ident_init(&rec->ident, ws, &cfg->family, cfg->ids, cfg->ids ? cfg->n_ids : 0)) != RL_OK ||
        (e = rl_label_init(&rec->dark, ws, w, h, runs, RL_MAX_REGIONS)) != RL_OK ||
        (e = rl_label_init(&rec->light, ws, w, h, runs / 4, RL_MAX_LIGHTS * 8)) != RL_OK ||
        (e = rl_ws_alloc(ws, RL_TMPL_PIXELS, RL_WS_ALIGN, (void **)&rec->samples)) != RL_OK ||
        (e = rl_ws_alloc(ws, RL_TMPL_PIXELS, RL_WS_ALIGN, (void **)&rec->mask)) != RL_OK)
        return e;
    return RL_OK;
}

size_t rl_recog_workspace_size(int w, int h, const rl_recog_config *cfg)
{
    rl_ws ws;
    static rl_recog scratch; /* only pointers are written, all NULL when sizing */
    if (cfg == NULL || check_config(cfg, w, h) != RL_OK)
        return 0;
    rl_ws_init_sizing(&ws);
    if (layout(&scratch, &ws, cfg, w, h) != RL_OK)
        return 0;
    return ws.peak;
}

rl_err rl_recog_init(rl_recog *rec, const rl_recog_config *cfg, int w, int h, void *mem,
                     size_t size)
{
    rl_err e;
    if (rec == NULL || cfg == NULL || mem == NULL)
        return RL_EINVAL;
    if ((e = check_config(cfg, w, h)) != RL_OK)
        return e;
    if (size < rl_recog_workspace_size(w, h, cfg))
        return RL_ENOMEM;
    memset(rec, 0, sizeof *rec);
    rec->cfg = *cfg;
    if (cfg->ids != NULL) {
        memcpy(rec->ids, cfg->ids, (size_t)cfg->n_ids * sizeof(int));
        rec->cfg.ids = rec->ids; /* the caller's array need not outlive init */
    }
    if (rec->cfg.max_radius <= 0)
        rec->cfg.max_radius = (w < h ? w : h) / 2.0;
    rec->width = w;
    rec->height = h;
    rl_ws_init(&rec->ws, mem, size);
    return layout(rec, &rec->ws, &rec->cfg, w, h);
}

/* ---- global pass ------------------------------------------------------ */

/* Specks: smaller than 10% of the narrowest code ring of the smallest
 * landmark considered (the paper's rule). */
static int speck_area(const rl_recog_config *cfg)
{
    int n = cfg->family.bits;
    double r = cfg->min_radius;
    double zone = M_PI * 0.64 * r * r / n;
    int a = (int)(0.1 * zone);
    return a < 2 ? 2 : a;
}

static int box_inside(const rl_box *in, const rl_box *out)
{
    return in->x0 >= out->x0 && in->x1 <= out->x1 && in->y0 >= out->y0 && in->y1 <= out->y1;
}

/* Darkness-weighted centroid of the disk (cx, cy, r): code rings are
 * concentric, so every ROI pixel, weighted by how dark it is, pulls
 * towards the true centre with sub-pixel precision (the paper takes the
 * binary centroid of all ROI pixels). */
static void refine_centre(const rl_image *img, const rl_levels *lv, double *cx, double *cy,
                          double r)
{
    int x, y, x0, x1, y0, y1;
    double sw = 0, sx = 0, sy = 0, bg = lv->bg, span = lv->bg - lv->fg, rr = (r + 1) * (r + 1);
    if (span < 1)
        return;
    x0 = (int)floor(*cx - r - 1);
    x1 = (int)ceil(*cx + r + 1);
    y0 = (int)floor(*cy - r - 1);
    y1 = (int)ceil(*cy + r + 1);
    if (x0 < 0 || y0 < 0 || x1 >= img->width || y1 >= img->height)
        return; /* only for complete landmarks */
    for (y = y0; y <= y1; y++) {
        const uint8_t *row = img->data + (size_t)y * (size_t)img->stride;
        double dy = y - *cy;
        for (x = x0; x <= x1; x++) {
            double dx = x - *cx, w;
            if (dx * dx + dy * dy > rr)
                continue;
            w = bg - row[x];
            if (w <= 0)
                continue;
            if (w > span)
                w = span;
            sw += w;
            sx += w * x;
            sy += w * y;
        }
    }
    if (sw > 0) {
        *cx = sx / sw;
        *cy = sy / sw;
    }
}

static void add_detection(rl_detection *list, int *n, int cap, const rl_detection *d)
{
    if (*n < cap)
        list[(*n)++] = *d;
}

/* Identify one candidate of centre (cx, cy) and radius r; 1 if it is. */
static int identify(rl_recog *rec, const rl_image *img, double cx, double cy, double r,
                    rl_match *m, int *visible)
{
    int vis;
    rl_ident_sample(img, cx, cy, r, rec->samples, rec->mask, &vis);
    rl_ident_match(&rec->ident, rec->samples, vis < RL_TMPL_PIXELS ? rec->mask : NULL, m);
    if (visible)
        *visible = vis;
    return m->id >= 0 && m->score >= rec->cfg.min_score &&
           m->score - m->second >= rec->cfg.min_margin;
}

static int cmp_det(const rl_detection *a, const rl_detection *b)
{
    if (a->u != b->u)
        return a->u < b->u ? -1 : 1;
    return a->v < b->v ? -1 : a->v > b->v;
}

static void sort_dets(rl_detection *d, int n)
{
    int i, j;
    for (i = 1; i < n; i++) { /* insertion sort: a few dozen at most */
        rl_detection t = d[i];
        for (j = i; j > 0 && cmp_det(&d[j - 1], &t) > 0; j--)
            d[j] = d[j - 1];
        d[j] = t;
    }
}

/* Landmarks in one frame have nearly the same size (the camera faces the
 * ceiling): an identified landmark far from the frame's median radius is
 * demoted to unidentified. */
static void size_filter(rl_recog *rec, rl_result *res)
{
    double r[RL_MAX_LANDMARKS], med, t;
    int i, j, n = res->n_landmarks, kept = 0;
    if (n < 3)
        return;
    for (i = 0; i < n; i++) {
        double v = res->landmarks[i].radius;
        for (j = i; j > 0 && r[j - 1] > v; j--)
            r[j] = r[j - 1];
        r[j] = v;
    }
    med = r[n / 2];
    t = rec->cfg.size_tolerance * med;
    for (i = 0; i < n; i++) {
        rl_detection *d = &res->landmarks[i];
        if (fabs(d->radius - med) <= t) {
            res->landmarks[kept++] = *d;
        } else {
            rl_detection u = *d;
            u.id = -1;
            add_detection(res->unidentified, &res->n_unidentified, RL_MAX_CANDIDATES, &u);
        }
    }
    res->n_landmarks = kept;
}

rl_err rl_recog_run(rl_recog *rec, const rl_image *img, rl_result *res)
{
    rl_hist h;
    rl_err e;
    const rl_recog_config *cfg = &rec->cfg;
    rl_box cand[RL_MAX_CANDIDATES];
    int ncand = 0, i, j, W = rec->width, H = rec->height;

    if (rec == NULL || res == NULL || !rl_image_valid(img))
        return RL_EINVAL;
    if (img->width != W || img->height != H)
        return RL_EINVAL;
    memset(res, 0, offsetof(rl_result, landmarks));
    res->n_landmarks = res->n_unidentified = res->n_lights = 0;
    res->n_candidates = res->local_tried = res->local_found = 0;
    res->width = W;
    res->height = H;

    /* 1. histogram analysis: light sources, foreground and background */
    rl_hist_compute(img, &h);
    if ((e = rl_hist_levels(&h, &res->levels)) != RL_OK)
        return RL_OK; /* a frame that is all light: nothing to find */
    if (res->levels.light < 256) {
        if ((e = rl_label_band(&rec->light, img, res->levels.light, 256, speck_area(cfg))) != RL_OK)
            return e;
        for (i = 0; i < rec->light.n_regions && res->n_lights < RL_MAX_LIGHTS; i++) {
            const rl_region *g = &rec->light.reg[i];
            rl_box b;
            b.x0 = g->x0;
            b.y0 = g->y0;
            b.x1 = g->x1;
            b.y1 = g->y1;
            res->lights[res->n_lights++] = b;
        }
    }
    if (res->levels.threshold <= 0)
        return RL_OK; /* no dark class in the frame */

    /* 2. image clustering and 3. CLR extraction: dark ROIs as regions */
    if ((e = rl_label_band(&rec->dark, img, 0, res->levels.threshold, speck_area(cfg))) != RL_OK)
        return e;
    res->n_regions = rec->dark.n_regions;
    for (i = 0; i < rec->dark.n_regions && ncand < RL_MAX_CANDIDATES; i++) {
        const rl_region *g = &rec->dark.reg[i];
        int bw = g->x1 - g->x0 + 1, bh = g->y1 - g->y0 + 1;
        double r = (bw + bh) / 4.0, fill = (double)g->area / ((double)bw * bh);
        double ox = g->sx / g->area - (g->x0 + g->x1) / 2.0;
        double oy = g->sy / g->area - (g->y0 + g->y1) / 2.0;
        int cut = g->x0 == 0 || g->y0 == 0 || g->x1 == W - 1 || g->y1 == H - 1;
        if (cut) {
            /* a border UCLR: its uncut extent is the diameter; at most half
             * may be missing */
            int cut_x = g->x0 == 0 || g->x1 == W - 1, cut_y = g->y0 == 0 || g->y1 == H - 1;
            if (cut_x && cut_y)
                continue;
            r = cut_x ? bh / 2.0 : bw / 2.0;
            if (r < cfg->min_radius || r > cfg->max_radius || (cut_x ? bw : bh) < r)
                continue;
        } else {
            if (r < cfg->min_radius || r > cfg->max_radius || fill < FILL_MIN ||
                fill > FILL_MAX || bw > ASPECT_MAX * bh || bh > ASPECT_MAX * bw ||
                ox * ox + oy * oy > CENTROID_MAX * CENTROID_MAX * r * r)
                continue;
        }
        cand[ncand].x0 = g->x0;
        cand[ncand].y0 = g->y0;
        cand[ncand].x1 = g->x1;
        cand[ncand].y1 = g->y1;
        ncand++;
    }
    /* a candidate inside another's bounding box is an inner ring */
    for (i = 0; i < ncand; i++) {
        int inner = 0;
        for (j = 0; j < ncand && !inner; j++)
            inner = j != i && box_inside(&cand[i], &cand[j]) &&
                    !(box_inside(&cand[j], &cand[i]) && j > i);
        if (inner)
            continue;
        {
            rl_detection d;
            rl_box *b = &cand[i];
            int bw = b->x1 - b->x0 + 1, bh = b->y1 - b->y0 + 1;
            int complete = !(b->x0 == 0 || b->y0 == 0 || b->x1 == W - 1 || b->y1 == H - 1);
            rl_match m;
            memset(&d, 0, sizeof d);
            d.box = *b;
            d.complete = complete;
            d.pass = RL_PASS_GLOBAL;
            d.u = (b->x0 + b->x1) / 2.0;
            d.v = (b->y0 + b->y1) / 2.0;
            d.radius = (bw + bh) / 4.0;
            d.visible = 1.0;
            d.id = -1;
            res->n_candidates++;
            /* 4. identification: the global pass takes closed outer rings */
            if (complete && identify(rec, img, d.u, d.v, d.radius, &m, NULL)) {
                d.id = m.id;
                d.score = m.score;
                refine_centre(img, &res->levels, &d.u, &d.v, d.radius);
                add_detection(res->landmarks, &res->n_landmarks, RL_MAX_LANDMARKS, &d);
            } else {
                if (!complete) {
                    /* centre and radius from the uncut extent */
                    int cut_x = b->x0 == 0 || b->x1 == W - 1;
                    d.radius = cut_x ? bh / 2.0 : bw / 2.0;
                    if (cut_x)
                        d.u = b->x0 == 0 ? b->x1 + 0.5 - d.radius : b->x0 - 0.5 + d.radius;
                    else
                        d.v = b->y0 == 0 ? b->y1 + 0.5 - d.radius : b->y0 - 0.5 + d.radius;
                } else {
                    d.score = m.score;
                }
                add_detection(res->unidentified, &res->n_unidentified, RL_MAX_CANDIDATES, &d);
            }
        }
    }
    size_filter(rec, res);
    sort_dets(res->landmarks, res->n_landmarks);
    return RL_OK;
}
