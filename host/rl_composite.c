#include "rl_composite.h"

#include <math.h>
#include "rl_circle.h" /* rl_solve3 */
#include <stdlib.h>
#include <string.h>

#define LIGHT_LEVEL 250 /* a lamp (or its glare) saturates */
#define SHEET 1.3       /* the sheet's half side, radii: quiet zone and margin */

void rl_composite_defaults(rl_composite_config *cc)
{
    memset(cc, 0, sizeof *cc);
    cc->radius_px = 25.0;
    cc->complete = 4;
    cc->near_light = 2;
    cc->cut = 2;
    cc->blur_min = 0.4;
    cc->blur_max = 1.1;
    cc->ink_min = 0.05;
    cc->ink_max = 0.25;
    cc->noise_max = 3.0;
    cc->aspect_min = 0.85;
    cc->seed = 1;
}

static double urand(rl_composite_config *cc, double a, double b)
{
    uint64_t x = cc->state ? cc->state : cc->seed * 0x9E3779B97F4A7C15ull + 1;
    x ^= x >> 12;
    x ^= x << 25;
    x ^= x >> 27;
    cc->state = x;
    return a + (b - a) * (double)((x * 2685821657736338717ull) >> 11) / 9007199254740992.0;
}

static int grey(const rl_image *img, int x, int y)
{
    return img->data[(size_t)y * (size_t)img->stride + (size_t)x];
}

/* Distance from (u, v) to the nearest lamp pixel within reach (reach + 1
 * when there is none). */
static double light_distance(const rl_image *img, double u, double v, double reach)
{
    int x, y, x0 = (int)floor(u - reach), x1 = (int)ceil(u + reach);
    int y0 = (int)floor(v - reach), y1 = (int)ceil(v + reach);
    double best = reach + 1;
    if (x0 < 0) x0 = 0;
    if (y0 < 0) y0 = 0;
    if (x1 > img->width - 1) x1 = img->width - 1;
    if (y1 > img->height - 1) y1 = img->height - 1;
    for (y = y0; y <= y1; y++)
        for (x = x0; x <= x1; x++)
            if (grey(img, x, y) >= LIGHT_LEVEL) {
                double d = hypot(x - u, y - v);
                if (d < best)
                    best = d;
            }
    return best;
}

double rl_composite_visible(int W, int H, double u, double v, double r)
{
    /* by counting a fine grid over the disk: exact enough for truth */
    int i, j, in = 0, all = 0;
    for (j = -40; j <= 40; j++)
        for (i = -40; i <= 40; i++) {
            double x = u + r * i / 40.0, y = v + r * j / 40.0;
            if (i * i + j * j > 1600)
                continue;
            all++;
            in += x >= -0.5 && y >= -0.5 && x < W - 0.5 && y < H - 0.5;
        }
    return (double)in / all;
}

static int apart(const rl_site_mark *marks, int n, double u, double v, double r)
{
    int i;
    for (i = 0; i < n; i++)
        if (hypot(marks[i].u - u, marks[i].v - v) < 2.0 * SHEET * r + 2)
            return 0;
    return 1;
}

/* A place of the given kind, or 0 after many tries. */
static int find_place(const rl_image *img, rl_composite_config *cc, rl_site_kind kind,
                      const rl_site_mark *marks, int n, double *pu, double *pv)
{
    double R = cc->radius_px, W = img->width, H = img->height, in = SHEET * R + 1;
    int t;
    for (t = 0; t < 400; t++) {
        double u, v, gap;
        if (kind == RL_SITE_CUT) {
            /* the centre up to 0.9 R inside one side (at most half outside) */
            int side = (int)urand(cc, 0, 4);
            double d = urand(cc, -0.05 * R, 0.9 * R);
            u = side == 0 ? d : side == 1 ? W - 1 - d : urand(cc, in, W - 1 - in);
            v = side == 2 ? d : side == 3 ? H - 1 - d : urand(cc, in, H - 1 - in);
            if (rl_composite_visible(img->width, img->height, u, v, R) < 0.5)
                continue;
            gap = light_distance(img, u, v, 2.6 * R) - R;
            if (gap <= 1.5 * R || !apart(marks, n, u, v, R))
                continue;
        } else {
            u = urand(cc, in, W - 1 - in);
            v = urand(cc, in, H - 1 - in);
            gap = light_distance(img, u, v, 2.6 * R) - R;
            if (!apart(marks, n, u, v, R) || gap < (SHEET - 1.0) * R + 1)
                continue; /* no lamp under the sheet */
            if (kind == RL_SITE_COMPLETE ? gap <= 1.5 * R : gap > R)
                continue;
        }
        *pu = u;
        *pv = v;
        return 1;
    }
    return 0;
}

/* How the mark looks: random within the configuration's ranges. */
static void look(rl_composite_config *cc, const rl_image *img, rl_site_mark *m)
{
    double R = cc->radius_px, gap = light_distance(img, m->u, m->v, 3 * R) - R;
    m->r = R * urand(cc, 0.95, 1.05);
    m->aspect = urand(cc, cc->aspect_min, 1.0);
    m->angle = urand(cc, 0, M_PI);
    m->turn = urand(cc, 0, 2 * M_PI);
    m->paper_gain = urand(cc, 1.0, 1.2);
    m->ink = urand(cc, cc->ink_min, cc->ink_max);
    /* veiling glare: light scattered in the lens lifts the ink next to a lamp */
    m->veil = gap < 2 * R ? urand(cc, 0.3, 1.0) * 60.0 * exp(-gap / R) : 0.0;
    m->blur = urand(cc, cc->blur_min, cc->blur_max);
    m->noise = urand(cc, 0.5, cc->noise_max);
    m->visible = rl_composite_visible(img->width, img->height, m->u, m->v, m->r);
}

/* An id not yet in the frame (a map holds each id once), when there is one. */
static int pick_id(rl_composite_config *cc, const int *ids, int n_ids, const rl_site_mark *marks,
                   int n)
{
    int t, i, id = ids[0];
    for (t = 0; t < 64; t++) {
        int used = 0;
        id = ids[(int)urand(cc, 0, n_ids) % n_ids];
        for (i = 0; i < n; i++)
            used |= marks[i].id == id;
        if (!used)
            break;
    }
    return id;
}

int rl_composite_plan(const rl_image *img, rl_composite_config *cc, const int *ids, int n_ids,
                      rl_site_mark *marks)
{
    int counts[3], k, i, n = 0;
    counts[RL_SITE_COMPLETE] = cc->complete;
    counts[RL_SITE_NEAR_LIGHT] = cc->near_light;
    counts[RL_SITE_CUT] = cc->cut;
    /* near lights first: their places are the rarest */
    for (k = 2; k >= 0; k--) {
        rl_site_kind kind = k == 2 ? RL_SITE_NEAR_LIGHT : k == 1 ? RL_SITE_CUT : RL_SITE_COMPLETE;
        for (i = 0; i < counts[kind] && n < RL_COMPOSITE_MAX; i++) {
            rl_site_mark *m = &marks[n];
            memset(m, 0, sizeof *m);
            if (!find_place(img, cc, kind, marks, n, &m->u, &m->v))
                break;
            m->kind = kind;
            m->id = pick_id(cc, ids, n_ids, marks, n);
            look(cc, img, m);
            n++;
        }
    }
    return n;
}

double rl_composite_ring(const void *ctx, int id, double x, double y)
{
    double rho = sqrt(x * x + y * y);
    return rho > 1.0 ? 0.0 : rl_family_dark_at((const rl_family *)ctx, id, rho);
}

/* Plane a + b x + c y fitted to the ceiling around a mark (an annulus,
 * lamps left out): the light falling on the sheet, gradients included. */
static void local_light(const rl_image *img, const rl_site_mark *m, double *abc)
{
    double s[3][4] = {{0}}, R = m->r;
    int x, y, k, j, x0 = (int)(m->u - 2.3 * R), y0 = (int)(m->v - 2.3 * R);
    for (y = y0; y <= (int)(m->v + 2.3 * R); y++)
        for (x = x0; x <= (int)(m->u + 2.3 * R); x++) {
            double d = hypot(x - m->u, y - m->v), f[3];
            int g;
            if (x < 0 || y < 0 || x >= img->width || y >= img->height || d < 1.45 * R || d > 2.3 * R)
                continue;
            if ((g = grey(img, x, y)) >= LIGHT_LEVEL)
                continue;
            f[0] = 1;
            f[1] = (x - m->u) / R;
            f[2] = (y - m->v) / R;
            for (k = 0; k < 3; k++) {
                for (j = 0; j < 3; j++)
                    s[k][j] += f[k] * f[j];
                s[k][3] += f[k] * g;
            }
        }
    /* too few ceiling pixels (a frame corner): a flat level */
    if (s[0][0] < 50 || !rl_solve3(s, abc)) {
        abc[0] = s[0][0] > 0 ? s[0][3] / s[0][0] : 180;
        abc[1] = abc[2] = 0;
    }
}

static void blur_patch(float *p, int w, int h, double sigma)
{
    float k[32], *tmp = malloc(sizeof(float) * (size_t)w * (size_t)h);
    int r = (int)ceil(3 * sigma), i, x, y;
    double sum = 0;
    if (tmp == NULL || r > 15) {
        free(tmp);
        return;
    }
    for (i = -r; i <= r; i++)
        sum += k[i + r] = (float)exp(-0.5 * i * i / (sigma * sigma));
    for (i = 0; i <= 2 * r; i++)
        k[i] = (float)(k[i] / sum);
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            float a = 0;
            for (i = -r; i <= r; i++)
                a += k[i + r] * p[y * w + (x + i < 0 ? 0 : x + i >= w ? w - 1 : x + i)];
            tmp[y * w + x] = a;
        }
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            float a = 0;
            for (i = -r; i <= r; i++)
                a += k[i + r] * tmp[(y + i < 0 ? 0 : y + i >= h ? h - 1 : y + i) * w + x];
            p[y * w + x] = a;
        }
    free(tmp);
}

static double gauss(rl_composite_config *cc)
{
    double u = urand(cc, 1e-12, 1.0), v = urand(cc, 0.0, 1.0);
    return sqrt(-2 * log(u)) * cos(2 * M_PI * v);
}

/* The sheet's frame (radii) of image point (x, y). */
static void to_sheet(const rl_site_mark *m, double x, double y, double *sx, double *sy)
{
    double dx = (x - m->u) / m->r, dy = (y - m->v) / m->r;
    double ca = cos(m->angle), sa = sin(m->angle), ct = cos(m->turn), st = sin(m->turn);
    double a = ca * dx + sa * dy, b = (-sa * dx + ca * dy) / m->aspect; /* undo the ellipse */
    double px = ca * a - sa * b, py = sa * a + ca * b;
    *sx = ct * px + st * py;
    *sy = -st * px + ct * py;
}

static void draw_one(rl_image *img, rl_composite_config *cc, const rl_site_mark *m,
                     rl_composite_pattern pattern, const void *ctx)
{
    double abc[3], reach = SHEET * 1.42 * m->r + 3 * m->blur + 3;
    int x0 = (int)floor(m->u - reach), y0 = (int)floor(m->v - reach);
    int x1 = (int)ceil(m->u + reach), y1 = (int)ceil(m->v + reach), w, h, x, y, i, j;
    float *val, *cov;
    if (x0 < 0) x0 = 0;
    if (y0 < 0) y0 = 0;
    if (x1 > img->width - 1) x1 = img->width - 1;
    if (y1 > img->height - 1) y1 = img->height - 1;
    w = x1 - x0 + 1;
    h = y1 - y0 + 1;
    if (w <= 0 || h <= 0)
        return;
    val = malloc(sizeof(float) * (size_t)w * (size_t)h);
    cov = calloc((size_t)w * (size_t)h, sizeof(float));
    if (val == NULL || cov == NULL) {
        free(val);
        free(cov);
        return;
    }
    local_light(img, m, abc);
    for (y = y0; y <= y1; y++)
        for (x = x0; x <= x1; x++) {
            double light = abc[0] + abc[1] * (x - m->u) / m->r + abc[2] * (y - m->v) / m->r;
            double paper = fmin(252.0, fmax(20.0, light * m->paper_gain)), ink = paper * m->ink + m->veil;
            double dark = 0, in = 0;
            for (j = 0; j < 3; j++)
                for (i = 0; i < 3; i++) { /* 3 x 3 samples per pixel */
                    double sx, sy;
                    to_sheet(m, x + (i - 1) / 3.0, y + (j - 1) / 3.0, &sx, &sy);
                    if (fabs(sx) > SHEET || fabs(sy) > SHEET)
                        continue;
                    in += 1;
                    dark += pattern(ctx, m->id, sx, sy);
                }
            in /= 9.0;
            dark /= 9.0;
            cov[(y - y0) * w + x - x0] = (float)in;
            val[(y - y0) * w + x - x0] =
                (float)((1 - in) * grey(img, x, y) + in * paper - dark * (paper - ink));
        }
    blur_patch(val, w, h, m->blur);
    blur_patch(cov, w, h, m->blur);
    for (y = y0; y <= y1; y++)
        for (x = x0; x <= x1; x++) {
            double v;
            if (cov[(y - y0) * w + x - x0] < 0.002)
                continue;
            v = val[(y - y0) * w + x - x0] + m->noise * gauss(cc);
            img->data[(size_t)y * (size_t)img->stride + (size_t)x] =
                (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : v + 0.5);
        }
    free(val);
    free(cov);
}

void rl_composite_draw(rl_image *img, const rl_composite_config *cc, const rl_site_mark *marks,
                       int n, rl_composite_pattern pattern, const void *ctx)
{
    rl_composite_config noise = *cc; /* noise draws its own numbers */
    int i;
    noise.state ^= 0x5DEECE66Dull;
    for (i = 0; i < n; i++)
        draw_one(img, &noise, &marks[i], pattern, ctx);
}

int rl_composite_mark_at(const rl_site_mark *marks, int n, double u, double v)
{
    int i;
    for (i = 0; i < n; i++)
        if (hypot(u - marks[i].u, v - marks[i].v) < 0.5 * marks[i].r)
            return i;
    return -1;
}
