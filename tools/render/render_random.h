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
 */
#ifndef RENDER_RANDOM_H
#define RENDER_RANDOM_H

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

#endif
