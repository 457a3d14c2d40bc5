#include "rl_refine.h"

#include <math.h>
#include "rl_clones.h"
#include "rl_ray.h"

void rl_refine_centre(const rl_image *img, const rl_levels *lv, double *cx, double *cy, double r)
{
    rl_refine_centre_rows(img, lv, cx, cy, r, 1);
}

#if defined(__GNUC__) && !defined(RL_NO_VECTOR_EXT)
/* the four sums of a row in one vector (GCC's vector extension) */
#define REFINE_VECTORS 1
typedef double refine_v4 __attribute__((vector_size(32)));
#endif

/* On x86 also built for AVX2 (rl_clones.h): the same operations on each
 * of the four sums, no fused multiply-add. */
RL_CLONES_AVX2
double rl_refine_centre_rows(const rl_image *img, const rl_levels *lv, double *cx, double *cy, double r,
                             int ystep)
{
    int x, y, x0, x1, y0, y1, v;
    double sw = 0, sx = 0, sy = 0, bg = lv->bg, span = lv->bg - lv->fg, rr = (r + 1) * (r + 1);
    double weight[256];
    if (span < 1)
        return 0;
    x0 = (int)floor(*cx - r - 1);
    x1 = (int)ceil(*cx + r + 1);
    y0 = (int)floor(*cy - r - 1);
    y1 = (int)ceil(*cy + r + 1);
    if (x0 < 0 || y0 < 0 || x1 >= img->width || y1 >= img->height)
        return 0; /* only for complete landmarks */
    /* a pixel's weight: how much darker than the background, at most the span */
    for (v = 0; v < 256; v++)
        weight[v] = bg - v <= 0 ? 0.0 : bg - v > span ? span : bg - v;
    if (ystep < 1)
        ystep = 1;
    for (y = y0; y <= y1; y += ystep) {
        const uint8_t *row = img->data + (size_t)y * (size_t)img->stride;
        double dy = y - *cy, h2 = rr - dy * dy, h, rw = 0, rx = 0;
        int xa, xb;
        if (h2 < 0)
            continue;
        /* the row's chord of the disk */
        h = sqrt(h2);
        xa = (int)ceil(*cx - h);
        xb = (int)floor(*cx + h);
        if (xa < x0) xa = x0;
        if (xb > x1) xb = x1;
#ifdef REFINE_VECTORS
        {
            /* four sums each, pixel x + k's in lane k: one would make every
             * add wait on the one before (the plain loop's sums below, the
             * same adds lane by lane) */
            refine_v4 w = {0, 0, 0, 0}, xs = w, four = {4, 4, 4, 4};
            refine_v4 xv = {(double)xa, (double)xa + 1, (double)xa + 2, (double)xa + 3};
            for (x = xa; x + 3 <= xb; x += 4, xv += four) {
                refine_v4 a = {weight[row[x]], weight[row[x + 1]], weight[row[x + 2]], weight[row[x + 3]]};
                w += a;
                xs += a * xv;
            }
            for (; x <= xb; x++) {
                double a = weight[row[x]];
                w[0] += a;
                xs[0] += a * x;
            }
            rw = (w[0] + w[1]) + (w[2] + w[3]);
            rx = (xs[0] + xs[1]) + (xs[2] + xs[3]);
        }
#else
        {
            /* four sums each: one would make every add wait on the one before */
            double w0 = 0, w1 = 0, w2 = 0, w3 = 0, x0s = 0, x1s = 0, x2s = 0, x3s = 0;
            for (x = xa; x + 3 <= xb; x += 4) {
                double a = weight[row[x]], b = weight[row[x + 1]], c = weight[row[x + 2]], d = weight[row[x + 3]];
                w0 += a;
                w1 += b;
                w2 += c;
                w3 += d;
                x0s += a * x;
                x1s += b * (x + 1);
                x2s += c * (x + 2);
                x3s += d * (x + 3);
            }
            for (; x <= xb; x++) {
                double a = weight[row[x]];
                w0 += a;
                x0s += a * x;
            }
            rw = (w0 + w1) + (w2 + w3);
            rx = (x0s + x1s) + (x2s + x3s);
        }
#endif
        sw += rw;
        sx += rx;
        sy += rw * y;
    }
    if (sw > 0) {
        *cx = sx / sw;
        *cy = sy / sw;
    }
    return sw;
}

#define EDGE_ANGLES 16
#define EDGE_SAMPLES 64

/* The mean profile over the rays inside the image, from lo in steps of
 * step; 0 when too few rays are inside. */
static int mean_profile(const rl_image *img, const rl_tone *tone, double cx, double cy,
                        const rl_shape *sh, double lo, double step, double *prof)
{
    double ca[EDGE_ANGLES], sa[EDGE_ANGLES], hi = lo + (EDGE_SAMPLES - 1) * step;
    float g[EDGE_SAMPLES];
    int i, a, used = 0;
    rl_ray_dirs(EDGE_ANGLES, ca, sa);
    for (i = 0; i < EDGE_SAMPLES; i++)
        prof[i] = 0;
    for (a = 0; a < EDGE_ANGLES; a++) {
        /* along an ellipse's normalized radius */
        double c = ca[a], s = sa[a];
        if (sh != NULL) {
            double f = rl_shape_step(sh, c, s);
            c *= f;
            s *= f;
        }
        /* a landmark near the border still gets its radius from the side
         * that is there */
        if (!rl_ray_inside(img, cx + lo * c, cy + lo * s, cx + hi * c, cy + hi * s))
            continue;
        rl_ray_sample(img, tone, cx + lo * c, cy + lo * s, step * c, step * s, EDGE_SAMPLES, 256, g);
        for (i = 0; i < EDGE_SAMPLES; i++)
            prof[i] += g[i];
        used++;
    }
    if (used < EDGE_ANGLES / 3)
        return 0;
    for (i = 0; i < EDGE_SAMPLES; i++)
        prof[i] /= used;
    return 1;
}

void rl_refine_radius(const rl_image *img, const rl_tone *tone, double cx, double cy, double *r)
{
    rl_refine_radius_shaped(img, tone, cx, cy, NULL, r);
}

/* The profile's halfway crossing going from index `from` to `to`; 0 if none. */
static int crossing(const double *prof, int from, int to, double half, double lo, double step, double *at)
{
    int i, dir = to > from ? 1 : -1;
    for (i = from; i != to; i += dir)
        if ((prof[i] - half) * (prof[i + dir] - half) <= 0 && prof[i] != prof[i + dir]) {
            *at = lo + (i + dir * (half - prof[i]) / (prof[i + dir] - prof[i])) * step;
            return 1;
        }
    return 0;
}

/* Index of the profile's least value in a .. b (inclusive), into *v. */
static int darkest(const double *prof, int a, int b, double *v)
{
    int i, k = a;
    for (i = a; i <= b && i < EDGE_SAMPLES; i++)
        if (prof[i] < prof[k])
            k = i;
    *v = prof[k];
    return k;
}

/* An edge from black to white light that noise does not make: a fair
 * part of the white's light, whatever the exposure. */
static int clear_edge(double black, double white)
{
    return white - black >= 0.15 * white && white - black >= 2.0;
}

/* The profile's greatest value from a on. */
static double brightest(const double *prof, int a)
{
    double w = prof[a];
    int i;
    for (i = a; i < EDGE_SAMPLES; i++)
        if (prof[i] > w)
            w = prof[i];
    return w;
}

void rl_refine_radius_shaped(const rl_image *img, const rl_tone *tone, double cx, double cy,
                             const rl_shape *sh, double *r)
{
    double prof[EDGE_SAMPLES], lo = 0.75 * *r, hi = 1.3 * *r, step = (hi - lo) / (EDGE_SAMPLES - 1);
    double black, white;
    int imin;
    if (sh != NULL && rl_shape_is_circle(sh))
        sh = NULL;
    if (!mean_profile(img, tone, cx, cy, sh, lo, step, prof))
        return;
    imin = darkest(prof, 0, EDGE_SAMPLES - 1, &black);
    white = brightest(prof, imin);
    if (!clear_edge(black, white))
        return;
    crossing(prof, imin, EDGE_SAMPLES - 1, 0.5 * (black + white), lo, step, r);
}

void rl_refine_radius_band(const rl_image *img, const rl_tone *tone, const rl_family *fam, int id,
                           double cx, double cy, double *r)
{
    double rho = rl_family_band_inner(fam, id), prof[EDGE_SAMPLES], lo, step, black, white, half, ro, ri, est;
    int iout, imin;
    if (!(rho > 0))
        return;
    lo = (rho - 0.6 * RL_FAMILY_BAND_WHITE) * *r;
    step = (1.3 * *r - lo) / (EDGE_SAMPLES - 1);
    if (!mean_profile(img, tone, cx, cy, NULL, lo, step, prof))
        return;
    iout = (int)((*r - lo) / step);
    imin = darkest(prof, (int)((rho * *r - lo) / step), iout, &black);
    white = brightest(prof, iout);
    if (!clear_edge(black, white))
        return;
    half = 0.5 * (black + white);
    if (!crossing(prof, imin, EDGE_SAMPLES - 1, half, lo, step, &ro) || !crossing(prof, imin, 0, half, lo, step, &ri))
        return;
    est = (ro + ri) / (1.0 + rho);
    if (fabs(est - *r) < 0.05 * *r)
        *r = est;
}
