#include "rl_inner.h"

#include <math.h>
#include "rl_median.h"
#include "rl_ray.h"

#define ENCLOSE_RAYS 16
#define ENCLOSE_FROM 1.3 /* radii: past the quiet zone */
#define ENCLOSE_TO 2.9   /* radii: the outer ring around the smallest mimic
                            (a zone boundary at 0.36 R) */
/* An outer ring's dark ends within 1 / RL_OUTER_RING_INNER of where it
 * starts (1.25), blur and rounding allowed for: past that the dark goes
 * on, a dark ceiling or wall around the sheet, not a ring. */
#define RING_END 1.45

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

/* grey_at where (x, y) is known to round into the image. */
static inline int grey_in(const rl_image *img, double x, double y)
{
    return img->data[(size_t)(int)(y + 0.5) * (size_t)img->stride + (int)(x + 0.5)];
}

/* 1 when every point of the ray from rho0 to rho1 (px) rounds into the
 * image (grey_at never -1 along it): both ends do, the image is convex. */
static int ray_in(const rl_image *img, double cx, double cy, double c, double s, double rho0, double rho1)
{
    double xa = cx + rho0 * c, ya = cy + rho0 * s, xb = cx + rho1 * c, yb = cy + rho1 * s;
    const double m = 1e-6; /* the points between are rounded too */
    return xa >= m - 0.5 && ya >= m - 0.5 && xb >= m - 0.5 && yb >= m - 0.5 && xa + 0.5 + m < img->width &&
           xb + 0.5 + m < img->width && ya + 0.5 + m < img->height && yb + 0.5 + m < img->height;
}

/* A ray from (cx, cy) in direction (c, s); `in` when all of it that is
 * read lies in the image (ray_in). */
typedef struct {
    const rl_image *img;
    double cx, cy, c, s;
    int in;
} inner_ray;

/* The pixel at rho along the ray: unchecked where the whole ray is in.
 * Inline (and grey_in): it is called for every sample of every ray, some
 * 1,100 a verification, and the call was a quarter of the check. */
static inline int ray_grey(const inner_ray *ray, double rho)
{
    double x = ray->cx + rho * ray->c, y = ray->cy + rho * ray->s;
    return ray->in ? grey_in(ray->img, x, y) : grey_at(ray->img, x, y);
}

enum { RAY_UNKNOWN, RAY_CLEAR, RAY_HIT };

/* What the ray in direction (c, s) meets beyond the candidate's quiet
 * zone: a dark ring with paper beyond it (its radius in radii in *hit),
 * nothing up to `to` px, or unknown (no contrast of its own here, the
 * border or a light came first, or the dark does not end like a ring's). */
static int ray_meets(const rl_image *img, int light, double cx, double cy, double r, double to,
                     double c, double s, double *hit)
{
    double rho;
    int ink = 256, paper = -1, mid, g = 0;
    /* past every rho sampled below: the ring's end from the farthest start */
    const double far = fmax(1.2 * r, RING_END * (to + 1.0) + 2.0);
    const inner_ray ray = {img, cx, cy, c, s, ray_in(img, cx, cy, c, s, 0.8 * r, far)};
    /* the candidate's own ink (outer ring) and paper (quiet zone) here */
    for (rho = 0.8 * r; rho <= 1.2 * r; rho += 1.0) {
        if ((g = ray_grey(&ray, rho)) < 0)
            break;
        if (rho <= r && g < ink)
            ink = g;
        if (rho >= r && g > paper)
            paper = g;
    }
    if (g < 0 || ink > 255 || paper < 0 || paper - ink < 20)
        return RAY_UNKNOWN;
    mid = (ink + paper) / 2;
    for (rho = ENCLOSE_FROM * r; rho <= to; rho += 1.0) {
        g = ray_grey(&ray, rho);
        if (g < 0 || g >= light || g < mid)
            break;
    }
    if (g >= 0 && g < mid) {
        double start = rho;
        for (; rho <= RING_END * start + 1.0; rho += 1.0) {
            g = ray_grey(&ray, rho);
            if (g < 0 || g >= light)
                return RAY_UNKNOWN;
            if (g >= mid) {
                *hit = start / r;
                return RAY_HIT;
            }
        }
        return RAY_UNKNOWN;
    }
    return rho > to ? RAY_CLEAR : RAY_UNKNOWN;
}

int rl_inner_enclosed(const rl_image *img, int light, double cx, double cy, double r, double reach)
{
    double hit[ENCLOSE_RAYS], dc[ENCLOSE_RAYS], ds[ENCLOSE_RAYS], med;
    double to = reach > 0 && reach < ENCLOSE_TO * r ? reach : ENCLOSE_TO * r;
    /* one sample at least: the ring around the largest mimic (a zone
     * boundary at 0.72 R) is under it */
    if (to < ENCLOSE_FROM * r)
        to = ENCLOSE_FROM * r;
    int a, clear = 0, nhit = 0, agree = 0, i;
    rl_ray_dirs(ENCLOSE_RAYS, dc, ds);
    for (a = 0; a < ENCLOSE_RAYS; a++) {
        int k = ray_meets(img, light, cx, cy, r, to, dc[a], ds[a], &hit[nhit]), left = ENCLOSE_RAYS - 1 - a;
        nhit += k == RAY_HIT;
        clear += k == RAY_CLEAR;
        /* the rays left cannot bring the hits to a quarter of the rays, nor
         * past the clear ones: not enclosed, as all 16 would say */
        if (nhit + left < ENCLOSE_RAYS / 4 || nhit + left < clear)
            return 0;
    }
    if (nhit < ENCLOSE_RAYS / 4 || nhit < clear)
        return 0;
    /* the median hit radius, and how many rays agree with it */
    med = rl_median(hit, nhit);
    for (i = 0; i < nhit; i++)
        agree += fabs(hit[i] - med) <= 0.15 * med;
    return agree >= ENCLOSE_RAYS / 4 && 4 * agree >= 3 * (nhit + clear);
}
