/* render_random: reproducible random numbers and value noise (render_random.h). */
#include "render_random.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static uint64_t rng_state = 88172645463325252ull;

void render_random_seed(uint64_t state)
{
    rng_state = state;
}

uint64_t render_random_state(void)
{
    return rng_state;
}

uint64_t render_random_next(void)
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return rng_state * 2685821657736338717ull;
}

double render_random_uniform(double a, double b)
{
    return a + (b - a) * ((render_random_next() >> 11) * (1.0 / 9007199254740992.0));
}

double render_random_normal(void)
{
    double u = render_random_uniform(1e-12, 1), v = render_random_uniform(0, 1);
    return sqrt(-2 * log(u)) * cos(2 * M_PI * v);
}

double render_random_hash(int i, int j)
{
    uint64_t h = (uint64_t)(uint32_t)i * 0x9E3779B97F4A7C15ull ^ (uint64_t)(uint32_t)j * 0xC2B2AE3D27D4EB4Full;
    h ^= h >> 29;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 32;
    return (h & 0xFFFF) / 65535.0;
}

double render_random_vnoise(double x, double y)
{
    int i = (int)floor(x), j = (int)floor(y);
    return render_random_mix(render_random_hash(i, j), render_random_hash(i + 1, j), render_random_hash(i, j + 1),
                             render_random_hash(i + 1, j + 1), x - i, y - j);
}

/* at most 4 M points (32 MB): a frame's view at the finest scale is some 0.6 M */
#define NOISE_MAX_POINTS (4 << 20)

int render_random_noise_make(render_noise *t, double x0, double y0, double x1, double y1)
{
    double ni = floor(x1) - floor(x0) + 2, nj = floor(y1) - floor(y0) + 2, *v = t->v;
    size_t room = t->room;
    int a, b;
    memset(t, 0, sizeof *t); /* holds none until made */
    t->v = v;
    t->room = room;
    if (!(ni > 0 && nj > 0 && ni * nj <= NOISE_MAX_POINTS && fabs(x0) < 1e9 && fabs(y0) < 1e9))
        return 0;
    if ((size_t)(ni * nj) > t->room) {
        free(t->v);
        t->room = 0;
        if ((t->v = malloc(sizeof *t->v * (size_t)(ni * nj))) == NULL)
            return -1;
        t->room = (size_t)(ni * nj);
    }
    t->i0 = (int)floor(x0);
    t->j0 = (int)floor(y0);
    t->ni = (int)ni;
    t->nj = (int)nj;
    for (b = 0; b < t->nj; b++)
        for (a = 0; a < t->ni; a++)
            t->v[(size_t)b * t->ni + a] = render_random_hash(t->i0 + a, t->j0 + b);
    /* a cell needs its corners on both sides */
    t->lo[0] = t->i0;
    t->lo[1] = t->j0;
    t->hi[0] = t->i0 + t->ni - 1;
    t->hi[1] = t->j0 + t->nj - 1;
    return 0;
}

void render_random_noise_free(render_noise *t)
{
    free(t->v);
    memset(t, 0, sizeof *t);
}
