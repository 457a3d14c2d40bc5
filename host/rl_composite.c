#include "rl_composite.h"

#include <math.h>
#include "rl_circle.h" /* rl_solve3 */
#include <stdlib.h>
#include <string.h>

#define LIGHT_LEVEL 250 /* a lamp (or its glare) saturates */

void rl_composite_defaults(rl_composite_config *cc)
{
    memset(cc, 0, sizeof *cc);
    cc->radius_px = 25.0;
    cc->sheet_w = cc->sheet_h = 2.6;
    cc->gamma = 2.2;
    cc->complete = 4;
    cc->near_light = 2;
    cc->cut = 2;
    cc->blur_min = 0.4;
    cc->blur_max = 1.1;
    cc->ink_min = 0.02;
    cc->ink_max = 0.08;
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

/* The sheet's half diagonal and half of its longer side, radii. */
static double sheet_reach(const rl_composite_config *cc)
{
    return 0.5 * hypot(cc->sheet_w, cc->sheet_h);
}

static double sheet_half_long(const rl_composite_config *cc)
{
    return 0.5 * (cc->sheet_w > cc->sheet_h ? cc->sheet_w : cc->sheet_h);
}

static int apart(const rl_composite_config *cc, const rl_site_mark *marks, int n, double u,
                 double v, double r)
{
    int i;
    for (i = 0; i < n; i++)
        if (hypot(marks[i].u - u, marks[i].v - v) < 2.0 * sheet_reach(cc) * r + 2)
            return 0;
    return 1;
}

/* A place of the given kind, or 0 after many tries. */
static int find_place(const rl_image *img, rl_composite_config *cc, rl_site_kind kind,
                      const rl_site_mark *marks, int n, double *pu, double *pv)
{
    double R = cc->radius_px, W = img->width, H = img->height, in = sheet_half_long(cc) * R + 1;
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
            if (gap <= 1.5 * R || !apart(cc, marks, n, u, v, R))
                continue;
        } else {
            u = urand(cc, in, W - 1 - in);
            v = urand(cc, in, H - 1 - in);
            gap = light_distance(img, u, v, 2.6 * R) - R;
            if (!apart(cc, marks, n, u, v, R) || gap < (sheet_half_long(cc) - 1.0) * R + 1)
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
    m->paper_gain = urand(cc, 0.85, 1.25); /* ceilings darker and lighter than paper */
    m->ink = urand(cc, cc->ink_min, cc->ink_max);
    /* veiling glare: light scattered in the lens lifts the ink next to a lamp */
    m->veil = gap < 2 * R ? urand(cc, 0.3, 1.0) * 0.12 * exp(-gap / R) : 0.0;
    m->blur = urand(cc, cc->blur_min, cc->blur_max);
    m->noise = urand(cc, 0.5, cc->noise_max);
    m->read_noise = urand(cc, 0.05, 0.1 * cc->noise_max);
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

/* Light (0 .. 1) of a grey level through the photos' tone curve, and back. */
static double to_light(const rl_composite_config *cc, double g)
{
    return pow(g / 255.0, cc->gamma);
}

static double to_grey(const rl_composite_config *cc, double l)
{
    return 255.0 * pow(l < 0 ? 0 : l > 1 ? 1 : l, 1.0 / cc->gamma);
}

/* Plane a + b x + c y fitted to the light of the ceiling around a mark
 * (an annulus, lamps left out): the light falling on the sheet, gradients
 * included. */
static void local_light(const rl_image *img, const rl_composite_config *cc, const rl_site_mark *m,
                        double *abc)
{
    double s[3][4] = {{0}}, R = m->r, lv;
    int x, y, k, j, x0 = (int)(m->u - 2.3 * R), y0 = (int)(m->v - 2.3 * R);
    for (y = y0; y <= (int)(m->v + 2.3 * R); y++)
        for (x = x0; x <= (int)(m->u + 2.3 * R); x++) {
            double d = hypot(x - m->u, y - m->v), f[3];
            int g;
            if (x < 0 || y < 0 || x >= img->width || y >= img->height || d < 1.45 * R || d > 2.3 * R)
                continue;
            if ((g = grey(img, x, y)) >= LIGHT_LEVEL)
                continue;
            lv = to_light(cc, g);
            f[0] = 1;
            f[1] = (x - m->u) / R;
            f[2] = (y - m->v) / R;
            for (k = 0; k < 3; k++) {
                for (j = 0; j < 3; j++)
                    s[k][j] += f[k] * f[j];
                s[k][3] += f[k] * lv;
            }
        }
    /* too few ceiling pixels (a frame corner): a flat level */
    if (s[0][0] < 50 || !rl_solve3(s, abc)) {
        abc[0] = s[0][0] > 0 ? s[0][3] / s[0][0] : to_light(cc, 180);
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

/* A patch of the frame around a mark: val its light, cov the sheet's
 * coverage of each pixel. */
typedef struct {
    int x0, y0, w, h;
    float *val, *cov;
} patch;

/* The sheet laid over the photo's light in the patch (3 x 3 samples per
 * pixel), unblurred. */
static void lay_sheet(const rl_image *img, const rl_composite_config *cc, const rl_site_mark *m,
                      rl_composite_pattern pattern, const void *ctx, patch *p)
{
    double abc[3], hw = 0.5 * cc->sheet_w, hh = 0.5 * cc->sheet_h;
    int x, y, i, j;
    local_light(img, cc, m, abc);
    for (y = p->y0; y < p->y0 + p->h; y++)
        for (x = p->x0; x < p->x0 + p->w; x++) {
            double light = abc[0] + abc[1] * (x - m->u) / m->r + abc[2] * (y - m->v) / m->r;
            double paper = fmin(0.98, fmax(0.005, light * m->paper_gain)), ink = paper * m->ink + m->veil;
            double dark = 0, in = 0;
            size_t k = (size_t)(y - p->y0) * (size_t)p->w + (size_t)(x - p->x0);
            for (j = 0; j < 3; j++)
                for (i = 0; i < 3; i++) {
                    double sx, sy;
                    to_sheet(m, x + (i - 1) / 3.0, y + (j - 1) / 3.0, &sx, &sy);
                    if (fabs(sx) > hw || fabs(sy) > hh)
                        continue;
                    in += 1;
                    dark += pattern(ctx, m->id, sx, sy);
                }
            in /= 9.0;
            dark /= 9.0;
            p->cov[k] = (float)in;
            p->val[k] = (float)((1 - in) * to_light(cc, grey(img, x, y)) + in * paper - dark * (paper - ink));
        }
}

/* The patch's light back to grey levels where the sheet reaches, with the
 * sensor's noise: photon noise (about even in grey under the curve) and
 * read noise in light, which the curve stretches in the dark. */
static void develop(rl_image *img, rl_composite_config *cc, const rl_site_mark *m, const patch *p)
{
    int x, y;
    for (y = 0; y < p->h; y++)
        for (x = 0; x < p->w; x++) {
            double l = p->val[y * p->w + x], slope, sg, v;
            if (p->cov[y * p->w + x] < 0.002)
                continue;
            /* grey per unit of light at l (floored: the curve's foot is steep) */
            slope = 255.0 / cc->gamma * pow(l > 0.002 ? l : 0.002, 1.0 / cc->gamma - 1.0);
            sg = hypot(m->noise, slope * m->read_noise / 255.0);
            v = to_grey(cc, l) + sg * gauss(cc);
            img->data[(size_t)(p->y0 + y) * (size_t)img->stride + (size_t)(p->x0 + x)] =
                (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : v + 0.5);
        }
}

/* The patch's values v raised to power e: light to grey levels (over
 * 255) with 1 / gamma, back with gamma. */
static void patch_curve(patch *p, double e)
{
    size_t k, n = (size_t)p->w * (size_t)p->h;
    for (k = 0; k < n; k++)
        p->val[k] = (float)pow(p->val[k] > 0 ? p->val[k] : 0.0f, e);
}

static void draw_one(rl_image *img, rl_composite_config *cc, const rl_site_mark *m,
                     rl_composite_pattern pattern, const void *ctx)
{
    double reach = sheet_reach(cc) * m->r + 3 * m->blur + 3;
    int x1 = (int)ceil(m->u + reach), y1 = (int)ceil(m->v + reach);
    patch p;
    p.x0 = (int)floor(m->u - reach);
    p.y0 = (int)floor(m->v - reach);
    if (p.x0 < 0) p.x0 = 0;
    if (p.y0 < 0) p.y0 = 0;
    if (x1 > img->width - 1) x1 = img->width - 1;
    if (y1 > img->height - 1) y1 = img->height - 1;
    p.w = x1 - p.x0 + 1;
    p.h = y1 - p.y0 + 1;
    if (p.w <= 0 || p.h <= 0)
        return;
    p.val = malloc(sizeof(float) * (size_t)p.w * (size_t)p.h);
    p.cov = calloc((size_t)p.w * (size_t)p.h, sizeof(float));
    if (p.val != NULL && p.cov != NULL) {
        lay_sheet(img, cc, m, pattern, ctx, &p);
        if (cc->mix_grey)
            patch_curve(&p, 1.0 / cc->gamma);
        blur_patch(p.val, p.w, p.h, m->blur);
        if (cc->mix_grey)
            patch_curve(&p, cc->gamma);
        blur_patch(p.cov, p.w, p.h, m->blur);
        develop(img, cc, m, &p);
    }
    free(p.val);
    free(p.cov);
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
