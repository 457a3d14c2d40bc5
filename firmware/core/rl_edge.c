#include "rl_edge.h"

#include <math.h>
#include <stdint.h>
#include "rl_circle.h"
#include "rl_ray.h"

int rl_edge_fit_outline(const rl_label *lb, int reg, const rl_edge_window *w, int thr,
                        int light, double *cx, double *cy, double *r)
{
    const rl_image *win = w->img;
    rl_circle_fit f;
    int y;
    rl_circle_clear(&f);
    for (y = 0; y < win->height; y++) {
        int first = -1, last = -1, i, side;
        const uint8_t *row = win->data + (size_t)y * (size_t)win->stride;
        for (i = lb->row[y]; i < lb->row[y + 1]; i++)
            if (rl_label_region_of(lb, i) == reg) {
                if (first < 0)
                    first = i;
                last = i;
            }
        if (first < 0 || y + w->y0 == 0 || y + w->y0 == w->frame_h - 1)
            continue;
        for (side = 0; side < 2; side++) {
            int xin = side ? lb->x1[last] : lb->x0[first], xout = side ? xin + 1 : xin - 1;
            int beyond = side ? xout + 1 : xout - 1;
            double t;
            if (xout < 0 || xout >= win->width || xin + w->x0 == 0 || xin + w->x0 == w->frame_w - 1)
                continue;
            if (row[xout] >= light || (beyond >= 0 && beyond < win->width && row[beyond] >= light))
                continue;
            /* sub-pixel: where the grey level crosses the threshold between
             * xin (dark) and xout (light) */
            t = row[xout] != row[xin] ? (double)(thr - row[xin]) / (row[xout] - row[xin]) : 0.5;
            if (t < 0) t = 0;
            if (t > 1) t = 1;
            rl_circle_add(&f, side ? xin + t : xin - t, y);
        }
    }
    if (f.n < 8)
        return 0;
    return rl_circle_solve(&f, cx, cy, r);
}

/* A ray is sampled from EDGE_FROM radii over
 * EDGE_SPAN radii (the outer edge within a fifth of a radius of the first
 * estimate), every EDGE_STEP px, or in EDGE_MAX_SAMPLES samples on larger
 * landmarks. */
#define EDGE_FROM 0.8
#define EDGE_SPAN 0.45
#define EDGE_STEP 0.25
#define EDGE_MAX_SAMPLES 128

/* Sub-sample position of the steepest rise of prof after the black at ib
 * (a 4-sample difference, its peak interpolated by a parabola); -1 when
 * the rise is under 0.3 of the span. */
static double steepest_rise(const float *prof, int ns, int ib, double span)
{
    double gbest = 0, gm, gp, den, off;
    int i, ig = -1;
    /* from 3: the peak interpolation reads prof[ig - 3] */
    for (i = ib + 2 > 3 ? ib + 2 : 3; i + 2 < ns; i++) {
        double g = prof[i + 2] - prof[i - 2];
        if (g > gbest) {
            gbest = g;
            ig = i;
        }
    }
    if (!(ig > 0 && ig + 3 < ns && gbest > 0.3 * span))
        return -1;
    gm = prof[ig + 1] - prof[ig - 3];
    gp = prof[ig + 3] - prof[ig - 1];
    den = gm - 2 * gbest + gp;
    off = den < 0 ? 0.5 * (gm - gp) / den : 0.0;
    if (off > 1) off = 1;
    if (off < -1) off = -1;
    return ig + off;
}

/* The outer edge's radius along direction (c, s) from (cx, cy), between
 * the ring's black inside r and the paper's white outside it; -1 when the
 * ray leaves the image, meets light or shows no clear edge. */
static double ray_edge(const rl_image *img, const rl_ray_lit *lit, double cx, double cy, double r,
                       double c, double s)
{
    float prof[EDGE_MAX_SAMPLES], black = 1e9f, white = -1e9f;
    int i, ns = (int)(EDGE_SPAN * r / EDGE_STEP) + 1, ib = 0, ir;
    double step = EDGE_STEP, r0 = EDGE_FROM * r, x = cx + r0 * c, y = cy + r0 * s, at;
    if (ns > EDGE_MAX_SAMPLES) {
        ns = EDGE_MAX_SAMPLES;
        step = EDGE_SPAN * r / (ns - 1);
    }
    if (!rl_ray_inside(img, x, y, x + (ns - 1) * step * c, y + (ns - 1) * step * s) ||
        !rl_ray_sample_lit(img, lit, x, y, step * c, step * s, ns, prof))
        return -1;
    ir = (int)((r - r0) / step);
    for (i = 0; i < ns; i++) {
        if (i <= ir && prof[i] < black) {
            black = prof[i];
            ib = i;
        }
        if (i >= ir && prof[i] > white)
            white = prof[i];
    }
    if (white - black < 0.2f * white || white - black < 3.0f || (at = steepest_rise(prof, ns, ib, white - black)) < 0)
        return -1;
    return r0 + at * step;
}

/* rl_edge_points, and in *found a bit for each ray that found the edge. */
static int edge_points(const rl_image *img, const rl_tone *tone, int light, double cx, double cy, double r,
                       double *ex, double *ey, uint64_t *found)
{
    double dc[RL_EDGE_RAYS], ds[RL_EDGE_RAYS];
    rl_ray_lit lit; /* light folded into the tone curve, once for the rays */
    int a, n = 0;
    rl_ray_dirs(RL_EDGE_RAYS, dc, ds);
    rl_ray_lit_init(&lit, tone, light);
    *found = 0;
    for (a = 0; a < RL_EDGE_RAYS; a++) {
        double rr = ray_edge(img, &lit, cx, cy, r, dc[a], ds[a]);
        if (rr < 0)
            continue;
        ex[n] = cx + rr * dc[a];
        ey[n] = cy + rr * ds[a];
        *found |= (uint64_t)1 << a;
        n++;
    }
    return n;
}

int rl_edge_points(const rl_image *img, const rl_tone *tone, int light, double cx, double cy,
                   double r, double *ex, double *ey)
{
    uint64_t found;
    return edge_points(img, tone, light, cx, cy, r, ex, ey, &found);
}

/* Whether fewer than `gap` rays in a row (around the circle) found no
 * edge: the misses' bits twice over, shifted onto themselves gap - 1 times
 * (a bit stays set where a miss is followed by gap - 1 more). */
/* the found bits, doubled into 64 to read a run across the start */
typedef char rl_edge_rays_fit_64_bits[RL_EDGE_RAYS <= 32 ? 1 : -1];

static int misses_under(uint64_t found, int gap)
{
    uint64_t all = ((uint64_t)1 << RL_EDGE_RAYS) - 1, miss = ~found & all, d = miss | (miss << RL_EDGE_RAYS);
    int k;
    for (k = 1; k < gap && d; k++)
        d &= d >> 1;
    return d == 0;
}

/* An edge point further than this (px) off the circle through the points
 * kept, itself included, is no point of the edge: noise or a motion smear
 * put the steepest rise out in the paper (traced on the moving set: 28.2
 * and 30.1 px among a dozen at 22.4-24.8). */
#define EDGE_OUTLIER_PX 3.0

/* The least-squares circle through the points use[] keeps; 0 when none. */
static int fit_used(const double *ex, const double *ey, const unsigned char *use, int n, double *cx,
                    double *cy, double *r)
{
    rl_circle_fit f;
    int i;
    rl_circle_clear(&f);
    for (i = 0; i < n; i++)
        if (use[i])
            rl_circle_add(&f, ex[i], ey[i]);
    return rl_circle_solve(&f, cx, cy, r);
}

/* The least-squares circle through the n points with at most n /
 * EDGE_FEW_OUTLIERS of them left out, one at a time the farthest off the
 * circle through the points kept (itself included) while it lies over
 * EDGE_OUTLIER_PX off; through
 * all of them when more would go (points that far apart are no circle
 * and a few outliers, and the gate after the fit decides as before). 0
 * when no circle. A least-squares circle through a gross outlier leans
 * towards it, and the points a pixel off it are then the wrong ones. */
#define EDGE_FEW_OUTLIERS 6
static int fit_few_outliers(const double *ex, const double *ey, int n, double *cx, double *cy, double *r)
{
    unsigned char use[RL_EDGE_RAYS];
    double c0x, c0y, r0;
    int i, dropped;
    for (i = 0; i < n; i++)
        use[i] = 1;
    if (!fit_used(ex, ey, use, n, &c0x, &c0y, &r0))
        return 0;
    *cx = c0x;
    *cy = c0y;
    *r = r0;
    for (dropped = 0;; dropped++) {
        double worst = 0;
        int k = -1;
        for (i = 0; i < n; i++) {
            double d = fabs(hypot(ex[i] - *cx, ey[i] - *cy) - *r);
            if (use[i] && d > worst) {
                worst = d;
                k = i;
            }
        }
        if (worst <= EDGE_OUTLIER_PX)
            return 1;
        if (dropped >= n / EDGE_FEW_OUTLIERS)
            break;
        use[k] = 0;
        if (!fit_used(ex, ey, use, n, cx, cy, r))
            break;
    }
    *cx = c0x;
    *cy = c0y;
    *r = r0;
    return 1;
}

int rl_edge_fit_points(const double *ex, const double *ey, int n, int few_outliers, double *cx, double *cy,
                       double *r)
{
    double ncx = 0, ncy = 0, nr = 0;
    unsigned char use[RL_EDGE_RAYS];
    int i, kept = 0;
    if (n < RL_EDGE_RAYS / 4 || n > RL_EDGE_RAYS)
        return 0;
    for (i = 0; i < n; i++)
        use[i] = 1;
    if (!(few_outliers ? fit_few_outliers(ex, ey, n, &ncx, &ncy, &nr) : fit_used(ex, ey, use, n, &ncx, &ncy, &nr)))
        return 0;
    for (i = 0; i < n; i++) {
        use[i] = fabs(hypot(ex[i] - ncx, ey[i] - ncy) - nr) < 1.0;
        kept += use[i];
    }
    if (!fit_used(ex, ey, use, n, &ncx, &ncy, &nr))
        return 0;
    rl_circle_refine(ex, ey, n, &ncx, &ncy, &nr);
    *cx = ncx;
    *cy = ncy;
    *r = nr;
    return kept;
}

/* How many of the n points lie within tol px of the circle. */
static int count_near(const double *ex, const double *ey, int n, double cx, double cy, double r, double tol)
{
    int i, k = 0;
    for (i = 0; i < n; i++)
        k += fabs(hypot(ex[i] - cx, ey[i] - cy) - r) <= tol;
    return k;
}

/* The few-outlier step's arc: rays in a row without an edge, fewer than
 * this (the largest gap between rays with one under 105 degrees). A circle
 * the frame's border cuts loses the rays whose path (out to 1.25 radii)
 * crosses the border, how many set by how deep the cut is against the
 * radius, not by the size: the four 7.5 and 22.5 degrees either side of
 * the border's normal once the circle comes within a quarter radius of
 * the border, the six out to 37.5 degrees once the border cuts it by
 * about 1% of its radius (0.25 px at 24 px, 1.2 px at 120 px). */
#define EDGE_FEW_GAP 6

/* rl_edge_fit_rays on the n edge points its rays found (edge_points,
 * the rays' bits in found). */
static int fit_found(const double *ex, const double *ey, int n, uint64_t found, double *cx, double *cy,
                     double *r)
{
    /* a few outliers left out (a whole 2 of the moving set, two of its
     * dozen points 4-6 px out, read a twentieth too large, its twin 18
     * leading) only where the rays that found the edge go round it, with
     * fewer than EDGE_FEW_GAP in a row without one: an arc (the border or a
     * lamp's glare hides the rest) fixes the circle loosely, and leaving
     * its farthest point out let the circle wander (2 cut landmarks of
     * the held-out moving set lost) */
    return rl_edge_fit_points(ex, ey, n, misses_under(found, EDGE_FEW_GAP), cx, cy, r);
}

int rl_edge_fit_rays(const rl_image *img, const rl_tone *tone, int light, double *cx, double *cy,
                     double *r)
{
    double ex[RL_EDGE_RAYS], ey[RL_EDGE_RAYS];
    uint64_t found;
    int n = edge_points(img, tone, light, *cx, *cy, *r, ex, ey, &found);
    return fit_found(ex, ey, n, found, cx, cy, r);
}

/* The tolerance of rl_edge_fit_arc's count: ARC_NEAR_PX, or a 25th of the
 * radius where that is more (the edge's scatter grows with the size). */
#define ARC_NEAR_PX 1.0
#define ARC_NEAR 25.0

int rl_edge_fit_arc(const rl_image *img, const rl_tone *tone, int light, double *cx, double *cy, double *r)
{
    double ex[RL_EDGE_RAYS], ey[RL_EDGE_RAYS], tol;
    uint64_t found;
    /* the rays sampled once: rl_edge_fit_rays' points from the same start
     * are both what it fits and what the circle is counted against (they
     * were sampled twice: half the fallback's rays) */
    int n = edge_points(img, tone, light, *cx, *cy, *r, ex, ey, &found);
    if (!fit_found(ex, ey, n, found, cx, cy, r))
        return 0;
    tol = *r / ARC_NEAR > ARC_NEAR_PX ? *r / ARC_NEAR : ARC_NEAR_PX;
    return count_near(ex, ey, n, *cx, *cy, *r, tol) >= RL_EDGE_ARC_MIN_POINTS;
}
