/* render_random: the renderer's random numbers, the same on every machine
 * (xorshift64*), and value noise for textures hashed from integer lattice
 * points (no state: the same place always looks the same).
 *
 * One stream drives a frame's scene, looks and sensor noise; a frame seeds
 * it from the run's seed and the frame's number, so each frame can be
 * rendered alone. A caller that must not disturb the stream (a site's
 * clutter, placed by its grid cell) saves and restores its state.
 *
 *   render_random_seed(0x9E3779B97F4A7C15ull ^ 42);
 *   double x = render_random_uniform(2, 8), n = render_random_normal();
 *   uint64_t keep = render_random_state();
 *   render_random_seed(1);                  // a side stream ...
 *   render_random_seed(keep);               // ... and back
 *   double t = render_random_vnoise(x * 90, 0.5);
 *
 * A frame that samples the noise millions of times over one area hashes
 * its lattice there once (render_noise): the same values, looked up. A
 * table made again keeps its memory where it is large enough (frame after
 * frame), and is freed once.
 *
 *   render_noise nz = {0};
 *   if (render_random_noise_make(&nz, 0, 0, 300, 200) == 0) {  // lattice units
 *       double u = render_random_vnoise_in(&nz, 12.3, 45.6);  // = render_random_vnoise(12.3, 45.6)
 *       int hi = render_random_vnoise_over(&nz, 12.3, 45.6, 0.93);
 *       render_random_noise_free(&nz);
 *   }
 */
#ifndef RENDER_RANDOM_H
#define RENDER_RANDOM_H

#include <stddef.h>
#include <stdint.h>

/* The stream's state: set, read. */
void render_random_seed(uint64_t state);
uint64_t render_random_state(void);

/* The next 64 random bits. */
uint64_t render_random_next(void);

/* Uniform in [a, b). */
double render_random_uniform(double a, double b);

/* Normal, mean 0, sigma 1 (Box-Muller, two uniforms each). */
double render_random_normal(void);

/* A lattice point's value in [0, 1], and value noise between them. */
double render_random_hash(int i, int j);
double render_random_vnoise(double x, double y);

/* The lattice's values over [x0, x1] x [y0, y1] (lattice units), made
 * once for many look-ups. */
typedef struct {
    int i0, j0, ni, nj; /* lattice points i0 .. i0 + ni - 1, j0 .. j0 + nj - 1 */
    /* the (x, y) whose cells it holds, [lo, hi): (i0, j0) and (i0 + ni - 1,
     * j0 + nj - 1), kept as doubles for the look-up's test (from the ints
     * there, a frame's render takes 3% more instructions) */
    double lo[2], hi[2];
    double *v;           /* render_random_hash of each (row j - j0, column i - i0); malloc'ed */
    size_t room;         /* values v has room for */
} render_noise;

/* Made, in t zeroed or made before (its memory reused where it has the
 * room, else freed): 0, or -1 (out of memory; t holds none). A rectangle
 * too large holds none either (0): every look-up then hashes. Freed once,
 * by render_random_noise_free. */
int render_random_noise_make(render_noise *t, double x0, double y0, double x1, double y1);
void render_random_noise_free(render_noise *t);

/* The corners' values mixed at (fx, fy) in their cell, smoothly: the
 * one expression of the hashed and the looked-up noise (the same bits). */
static inline double render_random_mix(double a, double b, double c, double d, double fx, double fy)
{
    fx = fx * fx * (3 - 2 * fx);
    fy = fy * fy * (3 - 2 * fy);
    return (a * (1 - fx) + b * fx) * (1 - fy) + (c * (1 - fx) + d * fx) * fy;
}

/* The first of (x, y)'s cell's corners in t (the others follow it by 1
 * and by a row) and the cell's lattice point (floor of x and y), or NULL
 * where t does not hold the cell. */
static inline const double *render_random_noise_cell(const render_noise *t, double x, double y, int *i, int *j)
{
    if (!(x >= t->lo[0] && x < t->hi[0] && y >= t->lo[1] && y < t->hi[1]))
        return NULL; /* NaN too */
    /* floor: the truncation, moved down below 0 */
    *i = (int)x;
    *i -= x < *i;
    *j = (int)y;
    *j -= y < *j;
    return t->v + (size_t)(*j - t->j0) * t->ni + (*i - t->i0);
}

/* render_random_vnoise(x, y), bit for bit: looked up inside t's
 * rectangle, hashed outside it. */
static inline double render_random_vnoise_in(const render_noise *t, double x, double y)
{
    int i, j;
    const double *c = render_random_noise_cell(t, x, y, &i, &j);
    if (c == NULL)
        return render_random_vnoise(x, y);
    return render_random_mix(c[0], c[1], c[t->ni], c[t->ni + 1], x - i, y - j);
}

/* render_random_vnoise(x, y) > level, the same answer: where no corner
 * of (x, y)'s lattice cell is over level, without the mix. */
static inline int render_random_vnoise_over(const render_noise *t, double x, double y, double level)
{
    int i, j;
    const double *c = render_random_noise_cell(t, x, y, &i, &j);
    double top;
    if (c == NULL)
        return render_random_vnoise(x, y) > level;
    top = c[0] > c[1] ? c[0] : c[1];
    top = top > c[t->ni] ? top : c[t->ni];
    top = top > c[t->ni + 1] ? top : c[t->ni + 1];
    /* a mix of values under level less a margin stays under level: its
     * rounding is some 1e-16 */
    if (top < level - 1e-9)
        return 0;
    return render_random_mix(c[0], c[1], c[t->ni], c[t->ni + 1], x - i, y - j) > level;
}

#endif
