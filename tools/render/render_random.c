/* render_random: reproducible random numbers and value noise (render_random.h). */
#include "render_random.h"

#include <math.h>

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
    double fx = x - i, fy = y - j;
    double a = render_random_hash(i, j), b = render_random_hash(i + 1, j), c = render_random_hash(i, j + 1),
           d = render_random_hash(i + 1, j + 1);
    fx = fx * fx * (3 - 2 * fx);
    fy = fy * fy * (3 - 2 * fy);
    return (a * (1 - fx) + b * fx) * (1 - fy) + (c * (1 - fx) + d * fx) * fy;
}
