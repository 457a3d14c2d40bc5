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
    cfg->min_lead = 1.5;
    cfg->min_radius = 0.0;
    cfg->max_radius = 0.0;
    cfg->size_tolerance = 0.35;
    cfg->need = 2;
    cfg->local = RL_LOCAL_AUTO;
    cfg->near_light = 1.5;
    cfg->min_contrast = 0.5;
}

void rl_recog_use_map(rl_recog_config *cfg, const rl_map *map, int *ids)
{
    int i;
    cfg->family = map->family;
    for (i = 0; i < map->count; i++)
        ids[i] = map->lm[i].id;
    cfg->ids = ids;
    cfg->n_ids = map->count;
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
    if (cfg->min_radius < 0 || cfg->max_radius < 0 || !(cfg->min_score > 0) ||
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
        (e = rl_label_init(&rec->light, ws, w, (h + 1) / 2, runs / 4, RL_MAX_LIGHTS * 8)) != RL_OK ||
        (e = rl_ws_alloc(ws, sizeof(rl_polar), RL_WS_ALIGN, (void **)&rec->polar)) != RL_OK)
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
    if (rec->cfg.min_radius <= 0) {
        /* below this radius code zone 1, the narrowest, is under a pixel
         * wide and the code cannot be read */
        int n = cfg->family.bits;
        rec->cfg.min_radius = 1.0 / (RL_OUTER_RING_INNER * (1.0 - sqrt((double)(n - 1) / n)));
    }
    rec->width = w;
    rec->height = h;
    rl_ws_init(&rec->ws, mem, size);
    return layout(rec, &rec->ws, &rec->cfg, w, h);
}

/* ---- global pass ------------------------------------------------------ */

/* Gap in pixels between a box and the nearest light region's box (a large
 * number when there is no light). */
static double light_gap(const rl_result *res, const rl_box *b)
{
    double best = 1e9;
    int i;
    for (i = 0; i < res->n_lights; i++) {
        const rl_box *l = &res->lights[i];
        double dx = l->x0 > b->x1 ? l->x0 - b->x1 : b->x0 > l->x1 ? b->x0 - l->x1 : 0;
        double dy = l->y0 > b->y1 ? l->y0 - b->y1 : b->y0 > l->y1 ? b->y0 - l->y1 : 0;
        double d = sqrt(dx * dx + dy * dy);
        if (d < best)
            best = d;
    }
    return best;
}


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


/* Outer radius from the grey levels: the mean intensity on circles of
 * growing radius drops to the outer ring's black and rises to the paper's
 * white; the radius where it crosses halfway is the printed edge, whatever
 * the blur (a symmetric blur moves a threshold crossing, not the 50% one).
 * Keeps the estimate when the profile has no clear edge. */
#define EDGE_ANGLES 16

static void refine_radius(const rl_image *img, double cx, double cy, double *r)
{
    double prof[64], lo = 0.75 * *r, hi = 1.3 * *r, step = (hi - lo) / 63, black = 1e9, white;
    double ca[EDGE_ANGLES], sa[EDGE_ANGLES];
    int i, a, imin = 0, used = 0;
    unsigned char inside[EDGE_ANGLES];
    /* only rays that stay inside the image: a landmark near the border
     * still gets its radius from the side that is there */
    for (a = 0; a < EDGE_ANGLES; a++) {
        double th = (a + 0.5) * 2.0 * M_PI / EDGE_ANGLES, ex, ey;
        ca[a] = cos(th);
        sa[a] = sin(th);
        ex = cx + hi * ca[a];
        ey = cy + hi * sa[a];
        inside[a] = ex >= 0 && ey >= 0 && ex < img->width - 1 && ey < img->height - 1 &&
                    cx + lo * ca[a] >= 0 && cy + lo * sa[a] >= 0 &&
                    cx + lo * ca[a] < img->width - 1 && cy + lo * sa[a] < img->height - 1;
        used += inside[a];
    }
    if (used < EDGE_ANGLES / 3)
        return;
    for (i = 0; i < 64; i++) {
        double rr = lo + i * step, acc = 0;
        for (a = 0; a < EDGE_ANGLES; a++) {
            double x, y, fx, fy;
            int x0, y0;
            const uint8_t *p;
            if (!inside[a])
                continue;
            x = cx + rr * ca[a];
            y = cy + rr * sa[a];
            x0 = (int)x;
            y0 = (int)y;
            fx = x - x0;
            fy = y - y0;
            p = img->data + (size_t)y0 * (size_t)img->stride + x0;
            acc += (1 - fy) * ((1 - fx) * p[0] + fx * p[1]) +
                   fy * ((1 - fx) * p[img->stride] + fx * p[img->stride + 1]);
        }
        prof[i] = acc / used;
        if (prof[i] < black) {
            black = prof[i];
            imin = i;
        }
    }
    white = prof[imin];
    for (i = imin; i < 64; i++)
        if (prof[i] > white)
            white = prof[i];
    if (white - black < 10.0)
        return;
    for (i = imin; i < 63; i++) {
        double half = 0.5 * (black + white);
        if (prof[i] <= half && prof[i + 1] > half) {
            *r = lo + (i + (half - prof[i]) / (prof[i + 1] - prof[i])) * step;
            return;
        }
    }
}

/* Directions of n rays at angles (a + 0.5) 2 pi / n, by rotation from the
 * first (four trigonometric calls instead of 2 n). */
static void ray_dirs(int n, double *c, double *s)
{
    double dc = cos(2 * M_PI / n), ds = sin(2 * M_PI / n);
    int a;
    c[0] = cos(M_PI / n);
    s[0] = sin(M_PI / n);
    for (a = 1; a < n; a++) {
        c[a] = c[a - 1] * dc - s[a - 1] * ds;
        s[a] = s[a - 1] * dc + c[a - 1] * ds;
    }
}

/* ---- inner rings ------------------------------------------------------- */

/* A code ring of a landmark can look like a whole landmark of half its
 * size (id 2's zone 4 ring reads as id 16). The paper drops inner rings by
 * containment in the binary image; when glare breaks the outer ring, or
 * the border cuts it, that containment is lost, so it is checked on the
 * grey levels instead: rays from the candidate's centre, beyond its quiet
 * zone, that meet a dark ring at one common radius in most directions
 * mean the candidate sits inside a larger landmark. */
#define ENCLOSE_RAYS 16
#define ENCLOSE_FROM 1.3 /* radii: past the quiet zone */
#define ENCLOSE_TO 2.9   /* radii: the outer ring around the smallest mimic
                            (a zone boundary at 0.36 R) */

/* Nearest pixel's grey level, or -1 outside the image. */
static int grey_at(const rl_image *img, double x, double y)
{
    int xi, yi;
    if (x < -0.5 || y < -0.5)
        return -1;
    xi = (int)(x + 0.5); /* rounding: x + 0.5 >= 0 */
    yi = (int)(y + 0.5);
    if (xi >= img->width || yi >= img->height)
        return -1;
    return img->data[(size_t)yi * (size_t)img->stride + xi];
}

static int enclosed(const rl_image *img, int light, double cx, double cy, double r)
{
    double hit[ENCLOSE_RAYS], med;
    int a, clear = 0, nhit = 0, agree = 0, i, j;
    double dc[ENCLOSE_RAYS], ds[ENCLOSE_RAYS];
    ray_dirs(ENCLOSE_RAYS, dc, ds);
    for (a = 0; a < ENCLOSE_RAYS; a++) {
        double c = dc[a], sn = ds[a];
        double rho;
        int ink = 256, paper = -1, mid, g = 0;
        /* the candidate's own ink (outer ring) and paper (quiet zone) here */
        for (rho = 0.8 * r; rho <= 1.2 * r; rho += 1.0) {
            if ((g = grey_at(img, cx + rho * c, cy + rho * sn)) < 0)
                break;
            if (rho <= r && g < ink)
                ink = g;
            if (rho >= r && g > paper)
                paper = g;
        }
        if (g < 0 || ink > 255 || paper < 0 || paper - ink < 20)
            continue; /* unknown */
        mid = (ink + paper) / 2;
        for (rho = ENCLOSE_FROM * r; rho <= ENCLOSE_TO * r; rho += 1.0) {
            g = grey_at(img, cx + rho * c, cy + rho * sn);
            if (g < 0 || g >= light || g < mid)
                break;
        }
        if (g >= 0 && g < mid)
            hit[nhit++] = rho / r;
        else if (rho > ENCLOSE_TO * r)
            clear++;
        /* else unknown: the border or a light came first */
    }
    if (nhit < ENCLOSE_RAYS / 4 || nhit < clear)
        return 0;
    /* the median hit radius, and how many rays agree with it */
    for (i = 1; i < nhit; i++) { /* insertion sort of a few values */
        double v = hit[i];
        for (j = i; j > 0 && hit[j - 1] > v; j--)
            hit[j] = hit[j - 1];
        hit[j] = v;
    }
    med = hit[nhit / 2];
    for (i = 0; i < nhit; i++)
        agree += fabs(hit[i] - med) <= 0.15 * med;
    return agree >= ENCLOSE_RAYS / 4 && 4 * agree >= 3 * (nhit + clear);
}

static void add_detection(rl_detection *list, int *n, int cap, const rl_detection *d)
{
    if (*n < cap)
        list[(*n)++] = *d;
}

/* Identify one candidate of centre (cx, cy) and radius r against levels
 * `lv`; 1 if it is. Besides the correlation, the best id must explain the
 * candidate clearly better than any other: the runner-up's unexplained
 * variance (1 - r^2) must be min_lead times the best's. Neighbouring codes
 * differ in one zone, so a blurred true landmark has a close runner-up in
 * r but not in residual, while ring-like clutter fits many codes equally
 * badly. And a printed landmark must show the full contrast of ink on
 * paper: grey ring-like clutter (speaker grilles) correlates, but only at
 * a fraction of the frame's foreground/background span. */
static int identify(rl_recog *rec, const rl_image *img, const rl_levels *lv, double cx,
                    double cy, double r, rl_match *m, int *visible)
{
    rl_profile p;
    rl_ident_profile(img, cx, cy, r, &p);
    rl_ident_match(&rec->ident, &p, m);
    if (visible)
        *visible = (int)p.total;
    return m->id >= 0 && m->score >= rec->cfg.min_score &&
           (1.0 - m->second * m->second) >= rec->cfg.min_lead * (1.0 - m->score * m->score) &&
           m->contrast >= rec->cfg.min_contrast * (lv->bg - lv->fg);
}


/* Fraction of a disk of radius r left visible when a straight edge passes
 * at signed distance d from its centre (d > 0: centre on the visible side). */
static double disk_visible(double r, double d)
{
    double seg;
    if (d >= r)
        return 1.0;
    if (d <= -r)
        return 0.0;
    seg = r * r * acos(d / r) - d * sqrt(r * r - d * d); /* the part beyond the edge */
    return 1.0 - seg / (M_PI * r * r);
}

/* Fraction of a disk of radius r at (cx, cy) inside a W x H image, from
 * the side that cuts most (a corner cut counts as its larger cut). */
static double visible_in(int W, int H, double cx, double cy, double r)
{
    double v = 1.0;
    v = fmin(v, disk_visible(r, cx + 0.5));
    v = fmin(v, disk_visible(r, W - 0.5 - cx));
    v = fmin(v, disk_visible(r, cy + 0.5));
    v = fmin(v, disk_visible(r, H - 0.5 - cy));
    return v;
}

/* Centre, radius and visible fraction of a CLR from its bounding box:
 * an uncut box is the disk's; a box cut by one image side keeps the true
 * diameter across the cut, and the centre lies one radius in from the far
 * side. Corner cuts (two sides) are left unidentified. */
static int clr_geometry(const rl_box *b, int W, int H, rl_detection *d)
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
        return 1;
    if ((cut_l || cut_r) && (cut_t || cut_b))
        return 0;
    if (cut_l || cut_r) {
        d->radius = bh / 2.0;
        d->u = cut_l ? b->x1 + 0.5 - d->radius : b->x0 - 0.5 + d->radius;
        d->visible = disk_visible(d->radius, cut_l ? d->u + 0.5 : W - 0.5 - d->u);
    } else {
        d->radius = bw / 2.0;
        d->v = cut_t ? b->y1 + 0.5 - d->radius : b->y0 - 0.5 + d->radius;
        d->visible = disk_visible(d->radius, cut_t ? d->v + 0.5 : H - 0.5 - d->v);
    }
    return 1;
}

/* Only where glare or the border can have broken a larger ring around a
 * candidate is it checked for one. */
static int may_be_inner(const rl_result *res, const rl_detection *d)
{
    double reach = ENCLOSE_TO * d->radius;
    return light_gap(res, &d->box) <= reach || d->u < reach || d->v < reach ||
           res->width - 1 - d->u < reach || res->height - 1 - d->v < reach;
}

/* Border landmarks with at most this much missing are identified in the
 * global pass (their outer ring is closed but for a sliver); the rest wait
 * for the local pass. */
#define GLOBAL_MIN_VISIBLE 0.95

static void global_candidate(rl_recog *rec, const rl_image *img, const rl_box *b, rl_result *res)
{
    rl_detection d;
    rl_match m;
    memset(&d, 0, sizeof d);
    d.id = -1;
    d.pass = RL_PASS_GLOBAL;
    if (!clr_geometry(b, rec->width, rec->height, &d))
        return;
    res->n_candidates++;
    /* 4. identification: the global pass takes closed outer rings */
    if (d.complete)
        refine_centre(img, &res->levels, &d.u, &d.v, d.radius);
    refine_radius(img, d.u, d.v, &d.radius);
    if (d.visible >= GLOBAL_MIN_VISIBLE &&
        identify(rec, img, &res->levels, d.u, d.v, d.radius, &m, NULL) &&
        !(may_be_inner(res, &d) && enclosed(img, res->levels.light, d.u, d.v, d.radius))) {
        d.id = m.id;
        d.score = m.score;
        add_detection(res->landmarks, &res->n_landmarks, RL_MAX_LANDMARKS, &d);
    } else {
        d.score = d.visible >= GLOBAL_MIN_VISIBLE ? m.score : 0.0;
        add_detection(res->unidentified, &res->n_unidentified, RL_MAX_CANDIDATES, &d);
    }
}

/* A map holds each id once: when one id is reported twice in a frame, the
 * better match stays and the others become unidentified. */
static void dedupe(rl_result *res)
{
    unsigned char keep[RL_MAX_LANDMARKS];
    int i, j, kept = 0;
    for (i = 0; i < res->n_landmarks; i++) {
        const rl_detection *d = &res->landmarks[i];
        keep[i] = 1;
        for (j = 0; j < res->n_landmarks && keep[i]; j++)
            if (j != i && res->landmarks[j].id == d->id &&
                (res->landmarks[j].score > d->score || (res->landmarks[j].score == d->score && j < i)))
                keep[i] = 0;
    }
    for (i = 0; i < res->n_landmarks; i++) {
        if (keep[i]) {
            res->landmarks[kept++] = res->landmarks[i];
        } else {
            rl_detection u = res->landmarks[i];
            u.id = -1;
            add_detection(res->unidentified, &res->n_unidentified, RL_MAX_CANDIDATES, &u);
        }
    }
    res->n_landmarks = kept;
}


/* Median radius of the identified landmarks (ICLRs), or 0. */
static double iclr_radius(const rl_result *res)
{
    double r[RL_MAX_LANDMARKS];
    int i, j, n = res->n_landmarks;
    if (n == 0)
        return 0.0;
    for (i = 0; i < n; i++) { /* insertion sort: a few dozen at most */
        double v = res->landmarks[i].radius;
        for (j = i; j > 0 && r[j - 1] > v; j--)
            r[j] = r[j - 1];
        r[j] = v;
    }
    return r[n / 2];
}

/* ---- local pass ------------------------------------------------------- */

/* Least-squares circle (algebraic, Kasa) through accumulated normal
 * equations s: rows [x y 1] . (D E F) = -(x^2 + y^2). */
typedef struct {
    double s[3][4];
    int n;
} circle_fit;

static void circle_add(circle_fit *f, double x, double y)
{
    double v[3];
    int k, m;
    v[0] = x;
    v[1] = y;
    v[2] = 1.0;
    for (k = 0; k < 3; k++) {
        for (m = 0; m < 3; m++)
            f->s[k][m] += v[k] * v[m];
        f->s[k][3] -= v[k] * (x * x + y * y);
    }
    f->n++;
}

/* Solve the 3 x 3 system A x = A[.][3] by Gaussian elimination with
 * partial pivoting (A is destroyed); 0 if singular. */
static int solve3(double A[3][4], double x[3])
{
    int k, m, c;
    for (k = 0; k < 3; k++) {
        int piv = k;
        for (m = k + 1; m < 3; m++)
            if (fabs(A[m][k]) > fabs(A[piv][k]))
                piv = m;
        if (fabs(A[piv][k]) < 1e-12)
            return 0;
        for (c = 0; c < 4; c++) {
            double t = A[k][c];
            A[k][c] = A[piv][c];
            A[piv][c] = t;
        }
        for (m = k + 1; m < 3; m++) {
            double q = A[m][k] / A[k][k];
            for (c = k; c < 4; c++)
                A[m][c] -= q * A[k][c];
        }
    }
    for (k = 2; k >= 0; k--) {
        double v = A[k][3];
        for (c = k + 1; c < 3; c++)
            v -= A[k][c] * x[c];
        x[k] = v / A[k][k];
    }
    return 1;
}

static int circle_solve(circle_fit *f, double *cx, double *cy, double *r)
{
    double a[3], s[3][4];
    memcpy(s, f->s, sizeof s);
    if (f->n < 5 || !solve3(s, a))
        return 0;
    *cx = -a[0] / 2;
    *cy = -a[1] / 2;
    *r = *cx * *cx + *cy * *cy - a[2];
    if (!(*r > 0))
        return 0;
    *r = sqrt(*r);
    return 1;
}

/* Rays for the edge fit; samples along a ray every EDGE_STEP px. */
#define FIT_RAYS 24
/* A ray is sampled from EDGE_FROM radii over EDGE_SPAN radii: the outer
 * edge within a fifth of a radius of the first estimate. */
#define EDGE_FROM 0.8
#define EDGE_SPAN 0.45
#define EDGE_STEP 0.25

/* Refine a landmark's centre and radius from its outer edge seen along
 * FIT_RAYS rays: on each ray the edge is where the grey level crosses
 * halfway between that ray's own ring black and paper white (so glare,
 * which shifts both, does not move it). Rays that leave the image or run
 * into light are skipped; a circle is fitted to the edge points, points
 * far off it are dropped and it is fitted again. 1 on success. */
static int fit_edge_rays(const rl_image *img, int light, double *cx, double *cy, double *r)
{
    double ex[FIT_RAYS], ey[FIT_RAYS], ncx, ncy, nr;
    int a, n = 0, pass;
    circle_fit f;
    double dc[FIT_RAYS], ds[FIT_RAYS];
    ray_dirs(FIT_RAYS, dc, ds);
    for (a = 0; a < FIT_RAYS; a++) {
        double c = dc[a], sn = ds[a];
        float prof[128], black = 1e9f, white = -1e9f;
        int i, ns = (int)(EDGE_SPAN * *r / EDGE_STEP) + 1, ok = 1, ib = 0, st = img->stride, ir;
        double r0 = EDGE_FROM * *r, x = *cx + r0 * c, y = *cy + r0 * sn, xe, ye;
        float fx0 = (float)x, fy0 = (float)y, dx = (float)(EDGE_STEP * c), dy = (float)(EDGE_STEP * sn);
        if (ns > 128)
            ns = 128;
        xe = x + (ns - 1) * EDGE_STEP * c;
        ye = y + (ns - 1) * EDGE_STEP * sn;
        /* a ray that leaves the image is not used: check its ends once */
        if (x < 0 || xe < 0 || y < 0 || ye < 0 || x >= img->width - 1 || xe >= img->width - 1 ||
            y >= img->height - 1 || ye >= img->height - 1)
            continue;
        for (i = 0; i < ns; i++) {
            float px = fx0 + (float)i * dx, py = fy0 + (float)i * dy, fx, fy, top, bot;
            int x0 = (int)px, y0 = (int)py; /* px, py >= 0: truncation is floor */
            const uint8_t *p = img->data + (size_t)y0 * (size_t)st + x0;
            int p00 = p[0], p01 = p[1], p10 = p[st], p11 = p[st + 1];
            if (p00 >= light || p01 >= light || p10 >= light || p11 >= light) {
                ok = 0;
                break;
            }
            fx = px - (float)x0;
            fy = py - (float)y0;
            top = (float)p00 + fx * (float)(p01 - p00);
            bot = (float)p10 + fx * (float)(p11 - p10);
            prof[i] = top + fy * (bot - top);
        }
        if (!ok)
            continue;
        /* the ring's black inside the first estimate, the paper's white
         * outside it */
        ir = (int)((*r - r0) / EDGE_STEP);
        for (i = 0; i < ns; i++) {
            if (i <= ir && prof[i] < black) {
                black = prof[i];
                ib = i;
            }
            if (i >= ir && prof[i] > white)
                white = prof[i];
        }
        if (white - black < 15.0f)
            continue;
        /* the edge is the steepest rise after the ring's black: a smooth
         * glare gradient adds a constant slope, which moves a level
         * crossing but hardly the gradient's peak */
        {
            double gbest = 0;
            int ig = -1;
            /* from 3: the peak interpolation below reads prof[ig - 3] */
            for (i = ib + 2 > 3 ? ib + 2 : 3; i + 2 < ns; i++) {
                double g = prof[i + 2] - prof[i - 2];
                if (g > gbest) {
                    gbest = g;
                    ig = i;
                }
            }
            if (ig > 0 && ig + 3 < ns && gbest > 0.3 * (white - black)) {
                double gm = prof[ig + 1] - prof[ig - 3], gp = prof[ig + 3] - prof[ig - 1];
                double den = gm - 2 * gbest + gp, off = den < 0 ? 0.5 * (gm - gp) / den : 0.0;
                double rr;
                if (off > 1) off = 1;
                if (off < -1) off = -1;
                rr = EDGE_FROM * *r + (ig + off) * EDGE_STEP;
                ex[n] = *cx + rr * c;
                ey[n] = *cy + rr * sn;
                n++;
            }
        }
    }
    if (n < FIT_RAYS / 4)
        return 0;
    for (pass = 0; pass < 2; pass++) {
        int i;
        memset(&f, 0, sizeof f);
        for (i = 0; i < n; i++)
            if (pass == 0 || fabs(hypot(ex[i] - ncx, ey[i] - ncy) - nr) < 1.0)
                circle_add(&f, ex[i], ey[i]);
        if (!circle_solve(&f, &ncx, &ncy, &nr))
            return 0;
    }
    /* The algebraic fit leans inwards on a partial arc (glare hides the
     * near side): finish with Gauss-Newton on the geometric distances. */
    {
        int it, i;
        for (it = 0; it < 8; it++) {
            double A[3][4] = {{0}}, step[3];
            int k, m, used = 0;
            for (i = 0; i < n; i++) {
                double dx = ex[i] - ncx, dy = ey[i] - ncy, d = sqrt(dx * dx + dy * dy), J[3], res;
                if (d < 1e-9 || fabs(d - nr) > 1.5)
                    continue;
                J[0] = -dx / d;
                J[1] = -dy / d;
                J[2] = -1.0;
                res = d - nr;
                for (k = 0; k < 3; k++) {
                    for (m = 0; m < 3; m++)
                        A[k][m] += J[k] * J[m];
                    A[k][3] -= J[k] * res;
                }
                used++;
            }
            if (used < 6)
                break;
            if (!solve3(A, step))
                break;
            ncx += step[0];
            ncy += step[1];
            nr += step[2];
            if (fabs(step[0]) + fabs(step[1]) + fabs(step[2]) < 1e-3)
                break;
        }
    }
    *cx = ncx;
    *cy = ncy;
    *r = nr;
    return 1;
}

/* Circle through the visible outer edge of region `reg` of the window
 * labelling (algebraic least squares): edge points at sub-pixel positions
 * where the grey level crosses the local threshold, at the left end of each
 * row's first run and the right end of its last run. Points on the image
 * border, or next to light, are not the landmark's edge and are skipped.
 * 1 on success with (cx, cy, r) in window coordinates. */
static int fit_outer_edge(const rl_label *lb, int reg, const rl_image *win, int thr, int light,
                          int x_off, int y_off, int W, int H, double *cx, double *cy, double *r)
{
    circle_fit f;
    int y;
    memset(&f, 0, sizeof f);
    for (y = 0; y < win->height; y++) {
        int first = -1, last = -1, i, side;
        const uint8_t *row = win->data + (size_t)y * (size_t)win->stride;
        for (i = lb->row[y]; i < lb->row[y + 1]; i++)
            if (rl_label_region_of(lb, i) == reg) {
                if (first < 0)
                    first = i;
                last = i;
            }
        if (first < 0 || y + y_off == 0 || y + y_off == H - 1)
            continue;
        for (side = 0; side < 2; side++) {
            int xin = side ? lb->x1[last] : lb->x0[first], xout = side ? xin + 1 : xin - 1;
            int beyond = side ? xout + 1 : xout - 1;
            double t;
            if (xout < 0 || xout >= win->width || xin + x_off == 0 || xin + x_off == W - 1)
                continue;
            if (row[xout] >= light || (beyond >= 0 && beyond < win->width && row[beyond] >= light))
                continue;
            /* sub-pixel: where the grey level crosses the threshold between
             * xin (dark) and xout (light) */
            t = row[xout] != row[xin] ? (double)(thr - row[xin]) / (row[xout] - row[xin]) : 0.5;
            if (t < 0) t = 0;
            if (t > 1) t = 1;
            circle_add(&f, side ? xin + t : xin - t, y);
        }
    }
    if (f.n < 8)
        return 0;
    return circle_solve(&f, cx, cy, r);
}

/* Search steps of the local identification: centre (px) and radius
 * (fraction) steps of each round, after a first sweep over radii. The
 * sweep only looks further out: an edge fit that glare or the border
 * leaves with a short arc errs inwards (5-12% short), while the crosses
 * reach 4.5% either way. */
#define SEARCH_ROUNDS 2
static const double search_shift[SEARCH_ROUNDS] = {1.0, 0.5};
static const double search_scale[SEARCH_ROUNDS] = {0.03, 0.015};
#define SWEEP 1
static const double sweep_scale[SWEEP] = {1.06};

/* Where the search stands: the best centre shift and radius scale so far
 * and their score, over the likely ids at one blur. */
typedef struct {
    const int *ids;
    int n_ids, blur;
    double x, y, s, score;
} search_state;

/* Score the likely ids with the centre moved by (x, y) and the radius
 * scaled by s; kept if better. The score is returned. */
static double search_try(const rl_recog *rec, const rl_polar *pol, search_state *st, double x,
                         double y, double s)
{
    rl_profile p;
    rl_match mm;
    rl_ident_polar_profile(pol, x, y, s, &p);
    rl_ident_match_ids(&rec->ident, &p, st->ids, st->n_ids, st->blur, &mm);
    if (mm.score > st->score) {
        st->score = mm.score;
        st->x = x;
        st->y = y;
        st->s = s;
    }
    return mm.score;
}

/* Identification of a DUCLR on sector-normalized grey levels (glare
 * varies by direction), gathered once into polar cells around
 * (*cx, *cy). The edge fit's centre and radius can be off where glare or
 * the border hides most of the outer edge, and a wrong radius reads the
 * outer ring as a code ring: so the centre and the radius that fit the
 * likely ids best are searched, scoring them at the first match's blur:
 * a sweep to larger radii, then a cross over the centre and one step either
 * way in radius; if the cross's centre stays best, the peak of a parabola
 * through each axis's three scores is tried and the search ends, else a
 * finer cross follows the same way. Every id at every blur is scored at
 * the end. (*cx, *cy, *r) are updated to the best fit. */
static void local_identify(rl_recog *rec, const rl_image *img, int light, double *cx,
                           double *cy, double *r, rl_match *m)
{
    rl_polar *pol = rec->polar;
    rl_profile p;
    int top[4], ntop = 0, k, it, bits = rec->cfg.family.bits;
    search_state st;
    rl_ident_polar(img, *cx, *cy, *r, light, 20.0, pol);
    rl_ident_polar_profile(pol, 0, 0, 1.0, &p);
    rl_ident_match(&rec->ident, &p, m);
    if (m->id < 0)
        return;
    top[ntop++] = m->id;
    /* the likely ids: the best and those one code zone away that come
     * close (a radius error confuses the outer ring with zone 1) */
    for (k = 1; k <= bits && ntop < 4; k++) {
        int alt = m->id ^ (1 << (bits - k));
        rl_match mm;
        if (!rl_family_valid(&rec->cfg.family, alt))
            continue;
        rl_ident_match_ids(&rec->ident, &p, &alt, 1, -1, &mm);
        if (mm.id >= 0 && mm.score > m->second - 0.05)
            top[ntop++] = alt;
    }
    st.ids = top;
    st.n_ids = ntop;
    st.blur = m->blur;
    st.x = st.y = 0;
    st.s = 1.0;
    st.score = m->score;
    for (k = 0; k < SWEEP; k++)
        search_try(rec, pol, &st, 0, 0, sweep_scale[k]);
    for (it = 0; it < SEARCH_ROUNDS; it++) {
        static const int dir[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
        double cx0 = st.x, cy0 = st.y, cs0 = st.s, f0 = st.score, fv[6], off[3];
        double step = search_shift[it], sstep = search_scale[it];
        for (k = 0; k < 6; k++)
            fv[k] = search_try(rec, pol, &st, cx0 + dir[k][0] * step, cy0 + dir[k][1] * step,
                               cs0 * (1.0 + dir[k][2] * sstep));
        if (st.x != cx0 || st.y != cy0 || st.s != cs0)
            continue; /* moved: a finer cross around the new best */
        for (k = 0; k < 3; k++) {
            double den = fv[2 * k] - 2 * f0 + fv[2 * k + 1];
            off[k] = den < 0 ? 0.5 * (fv[2 * k + 1] - fv[2 * k]) / den : 0.0;
        }
        search_try(rec, pol, &st, cx0 + off[0] * step, cy0 + off[1] * step,
                   cs0 * (1.0 + off[2] * sstep));
        break;
    }
    if (st.x == 0 && st.y == 0 && st.s == 1.0)
        return; /* the first match stands: every id was scored there */
    rl_ident_polar_profile(pol, st.x, st.y, st.s, &p);
    rl_ident_match(&rec->ident, &p, m);
    *cx += st.x;
    *cy += st.y;
    *r *= st.s;
}

/* Acceptance in the local pass: a DUCLR is already a landmark-sized ring
 * next to a light or on the border, re-extracted and centred on its own
 * edge, so a little less lead is needed than in the global pass. */
#define LOCAL_MIN_SCORE 0.75
#define LOCAL_MIN_LEAD 1.3

/* Window half-size around a DUCLR, in expected radii: room for the whole
 * landmark and its quiet zone with a quarter radius to spare for the
 * centre estimate of a ring broken by glare. */
#define WINDOW_RADII 1.5

/* Retry one DUCLR; 1 if identified (into *out). */
static int local_candidate(rl_recog *rec, const rl_image *img, const rl_result *res,
                           const rl_detection *u, double R, rl_detection *out)
{
    int W = rec->width, H = rec->height, x0, y0, x1, y1, i, best = -1, thr;
    double half = WINDOW_RADII * R, best_size = 0, cx, cy, fr;
    rl_image win;
    rl_hist h;
    rl_levels lv;
    rl_match m;
    rl_box b;
    /* extension: a window around the candidate, clipped to the image and
     * shrunk on any side that would reach into a light source (never into
     * the landmark itself) */
    x0 = (int)floor(u->u - half);
    x1 = (int)ceil(u->u + half);
    y0 = (int)floor(u->v - half);
    y1 = (int)ceil(u->v + half);
    for (i = 0; i < res->n_lights; i++) {
        const rl_box *l = &res->lights[i];
        if (l->x1 < x0 || l->x0 > x1 || l->y1 < y0 || l->y0 > y1)
            continue;
        if (l->x0 > u->u + 1.1 * R && l->x0 - 1 < x1) x1 = l->x0 - 1;
        if (l->x1 < u->u - 1.1 * R && l->x1 + 1 > x0) x0 = l->x1 + 1;
        if (l->y0 > u->v + 1.1 * R && l->y0 - 1 < y1) y1 = l->y0 - 1;
        if (l->y1 < u->v - 1.1 * R && l->y1 + 1 > y0) y0 = l->y1 + 1;
    }
    if (x0 < 0) x0 = 0;
    if (y0 < 0) y0 = 0;
    if (x1 > W - 1) x1 = W - 1;
    if (y1 > H - 1) y1 = H - 1;
    if (x1 - x0 < 8 || y1 - y0 < 8 || rl_image_sub(img, x0, y0, x1 - x0 + 1, y1 - y0 + 1, &win) != RL_OK)
        return 0;
    /* local clustering: K-means on the window alone, light excluded, so the
     * threshold follows the local illumination */
    rl_hist_compute_rows(&win, &h, 4); /* every fourth row: over a thousand pixels still */
    if (rl_hist_kmeans(&h, 0, res->levels.light, 2, lv.centre, NULL) != RL_OK)
        return 0;
    if (lv.centre[1] - lv.centre[0] < 8.0)
        return 0;
    thr = (int)(0.5 * (lv.centre[0] + lv.centre[1]) + 0.5);
    /* re-extraction: the outer ring is the largest region of landmark size
     * near the candidate */
    if (rl_label_resize(&rec->dark, win.width, win.height) != RL_OK ||
        rl_label_band(&rec->dark, &win, 0, thr, speck_area(&rec->cfg)) != RL_OK)
        return 0;
    for (i = 0; i < rec->dark.n_regions; i++) {
        const rl_region *g = &rec->dark.reg[i];
        double bw = g->x1 - g->x0 + 1, bh = g->y1 - g->y0 + 1, size = bw > bh ? bw : bh;
        double gx = x0 + (g->x0 + g->x1) / 2.0, gy = y0 + (g->y0 + g->y1) / 2.0;
        if (size < R || size > 2.5 * R || fabs(gx - u->u) > 1.2 * R || fabs(gy - u->v) > 1.2 * R)
            continue;
        if (size > best_size) {
            best_size = size;
            best = i;
        }
    }
    if (best < 0)
        return 0;
    b.x0 = x0 + rec->dark.reg[best].x0;
    b.y0 = y0 + rec->dark.reg[best].y0;
    b.x1 = x0 + rec->dark.reg[best].x1;
    b.y1 = y0 + rec->dark.reg[best].y1;
    /* the centre from the visible outer edge, not the centroid of what is
     * left (biased inwards when part is missing) */
    if (!fit_outer_edge(&rec->dark, best, &win, thr, res->levels.light, x0, y0, W, H, &cx, &cy, &fr))
        return 0;
    cx += x0;
    cy += y0;
    {
        /* then the grey outer edge, from that centre (the identification
         * below refines centre and radius once more) */
        double tx = cx, ty = cy, tr = R;
        if (fit_edge_rays(img, res->levels.light, &tx, &ty, &tr)) {
            cx = tx;
            cy = ty;
            fr = tr;
        }
    }
    if (fabs(fr - R) > 0.3 * R)
        return 0;
    memset(out, 0, sizeof *out);
    out->box = b;
    /* the fitted radius, not the frame's median: lens distortion makes
     * landmarks smaller away from the image centre */
    R = fr;
    out->pass = RL_PASS_LOCAL;
    if (visible_in(W, H, cx, cy, R) < 0.5) /* more than half missing: not tried */
        return 0;
    /* identification on sector-normalized grey levels, searching the
     * centre and the radius */
    local_identify(rec, img, res->levels.light, &cx, &cy, &R, &m);
    out->u = cx;
    out->v = cy;
    out->radius = R;
    out->complete = cx - R >= -0.5 && cy - R >= -0.5 && cx + R <= W - 0.5 && cy + R <= H - 0.5;
    out->visible = visible_in(W, H, cx, cy, R);
    if (m.id < 0 || m.score < LOCAL_MIN_SCORE ||
        (1.0 - m.second * m.second) < LOCAL_MIN_LEAD * (1.0 - m.score * m.score) ||
        m.contrast < rec->cfg.min_contrast * 255.0 || enclosed(img, res->levels.light, cx, cy, R))
        return 0;
    out->id = m.id;
    out->score = m.score;
    return 1;
}

/* The paper's local recognition: retry unidentified CLRs next to a light
 * or on the image border (DUCLRs) in their own window. */
static void local_pass(rl_recog *rec, const rl_image *img, rl_result *res)
{
    double rexp = iclr_radius(res);
    int i, kept = 0, n = res->n_unidentified;
    for (i = 0; i < n; i++) {
        rl_detection u = res->unidentified[i], d;
        double R = rexp > 0 ? rexp : u.radius;
        int near_light = light_gap(res, &u.box) <= rec->cfg.near_light * R;
        int on_border = !u.complete;
        if ((near_light || on_border) && (!on_border || u.visible >= 0.5) &&
            res->n_landmarks < RL_MAX_LANDMARKS) {
            res->local_tried++;
            if (local_candidate(rec, img, res, &u, R, &d)) {
                res->local_found++;
                res->landmarks[res->n_landmarks++] = d;
                continue;
            }
        }
        res->unidentified[kept++] = u;
    }
    res->n_unidentified = kept;
    /* the labeller goes back to frame size for the next frame */
    if (rl_label_resize(&rec->dark, rec->width, rec->height) != RL_OK)
        res->n_unidentified = kept; /* cannot fail: same size as at init */
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
    double med, t;
    int i, n = res->n_landmarks, kept = 0;
    if (n < 3)
        return;
    med = iclr_radius(res);
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
    /* every other row suffices for the levels, except in small windows */
    rl_hist_compute_rows(img, &h, H >= 120 ? 2 : 1);
    if ((e = rl_hist_levels(&h, &res->levels)) != RL_OK)
        return RL_OK; /* a frame that is all light: nothing to find */
    if (res->levels.light < 256) {
        /* Light sources are large blobs: every other row (a view with twice
         * the stride) finds them at half the cost. */
        rl_image half = rl_image_view(W, (H + 1) / 2, img->stride * 2, img->data);
        if ((e = rl_label_band(&rec->light, &half, res->levels.light, 256, speck_area(cfg))) != RL_OK)
            return e;
        for (i = 0; i < rec->light.n_regions && res->n_lights < RL_MAX_LIGHTS; i++) {
            const rl_region *g = &rec->light.reg[i];
            rl_box b;
            b.x0 = g->x0;
            b.y0 = 2 * g->y0;
            b.x1 = g->x1;
            b.y1 = 2 * g->y1 + 1 < H ? 2 * g->y1 + 1 : H - 1;
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
            /* a corner cut is kept too, though it is never identified:
             * the rings inside it must not pass for landmarks */
            r = cut_x && cut_y ? (bw > bh ? bw : bh) / 2.0 : cut_x ? bh / 2.0 : bw / 2.0;
            if (r < cfg->min_radius || r > cfg->max_radius ||
                (!(cut_x && cut_y) && (cut_x ? bw : bh) < r))
                continue;
        } else if (r < cfg->min_radius || r > cfg->max_radius || fill < FILL_MIN ||
                   fill > FILL_MAX || bw > ASPECT_MAX * bh || bh > ASPECT_MAX * bw ||
                   ox * ox + oy * oy > CENTROID_MAX * CENTROID_MAX * r * r) {
            /* Not a closed outer ring; but next to a light, glare may have
             * washed part of one out: keep it as an unidentified CLR for
             * the local pass, sized by its larger side. */
            rl_box b;
            double rr = (bw > bh ? bw : bh) / 2.0;
            b.x0 = g->x0;
            b.y0 = g->y0;
            b.x1 = g->x1;
            b.y1 = g->y1;
            if (rr < cfg->min_radius || rr > cfg->max_radius || bw < rr || bh < rr ||
                light_gap(res, &b) > cfg->near_light * rr)
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
        if (!inner)
            global_candidate(rec, img, &cand[i], res);
    }
    dedupe(res);
    if (cfg->local == RL_LOCAL_ALWAYS ||
        (cfg->local == RL_LOCAL_AUTO && res->n_landmarks < cfg->need)) {
        local_pass(rec, img, res);
        dedupe(res);
    }
    size_filter(rec, res);
    sort_dets(res->landmarks, res->n_landmarks);
    return RL_OK;
}
