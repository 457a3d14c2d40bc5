/* rl_ray: light along straight rays from a candidate's centre, the
 * camera's tone curve undone (internal).
 *
 *   double c[16], s[16];
 *   float g[40];
 *   rl_ray_dirs(16, c, s);
 *   if (rl_ray_inside(&img, cx, cy, cx + 10 * c[0], cy + 10 * s[0]) &&
 *       rl_ray_sample(&img, &tone, cx, cy, 0.25 * c[0], 0.25 * s[0], 40, light, g))
 *       use(g[0], g[39]);
 *   rl_ray_lit lit;            // the same samples, many rays under one light level
 *   rl_ray_lit_init(&lit, &tone, light);
 *   if (rl_ray_inside(&img, cx, cy, cx + 10 * c[1], cy + 10 * s[1]) &&
 *       rl_ray_sample_lit(&img, &lit, cx, cy, 0.25 * c[1], 0.25 * s[1], 40, g))
 *       use(g[0], g[39]);
 */
#ifndef RL_RAY_H
#define RL_RAY_H

#include "rl_image.h"
#include "rl_tone.h"

/* Directions of n rays at angles (a + 0.5) 2 pi / n, a = 0 .. n - 1. */
void rl_ray_dirs(int n, double *c, double *s);

/* Bilinear light (tone->light of the four pixels) at (x + i dx, y + i dy),
 * i = 0 .. n - 1, into out[0 .. n). Every sample must lie in [0, width - 1) x [0, height - 1)
 * (the caller checks the ends). 0 as soon as a sample touches a pixel at
 * or above `light` (256: none), else 1. */
int rl_ray_sample(const rl_image *img, const rl_tone *tone, double x, double y, double dx,
                  double dy, int n, int light, float *out);

/* A tone curve's light with a light level folded in: light[g] is
 * tone->light[g] for grey levels under the level, NaN at or above it. A
 * bilinear sample that touches such a pixel comes out NaN (NaN carries
 * through the interpolation), so rl_ray_sample_lit tests each sample, or
 * four at once, instead of its four pixels. Made once for many rays (256
 * entries against some 24 rays of dozens of samples each). */
typedef struct {
    float light[256];
} rl_ray_lit;

/* Fill lit from tone's light table and the light level `light` (256 or
 * more: none is light, lit is tone's table; 0 or less: every level). */
void rl_ray_lit_init(rl_ray_lit *lit, const rl_tone *tone, int light);

/* rl_ray_sample(img, tone, x, y, dx, dy, n, light, out) for the tone and
 * light lit was made from: the same return value and, when 1, the same
 * samples in out[0 .. n) (bit for bit); when 0, out may be part written. */
int rl_ray_sample_lit(const rl_image *img, const rl_ray_lit *lit, double x, double y, double dx,
                      double dy, int n, float *out);

/* 1 if the segment from (x0, y0) to (x1, y1) stays where rl_ray_sample
 * can read. */
int rl_ray_inside(const rl_image *img, double x0, double y0, double x1, double y1);

#endif
