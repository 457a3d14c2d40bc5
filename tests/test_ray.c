/* Light along rays (rl_ray_sample): a sample is the bilinear mix of its
 * four pixels' light, by hand on a small image; with no light level
 * (256) the samples are bit for bit those with a light level none of them
 * reaches (255 on an image under 255); and on random rays, with and
 * without a light level, the answer and the bits of the formula written
 * here sample by sample. */
#include "rl_test.h"
#include "rl_ray.h"
#include "rl_tone.h"

#define W 96
#define H 80
static uint8_t px[W * H];

static void hand_bilinear(void **state)
{
    rl_tone tone;
    rl_image img = rl_image_view(W, H, W, px);
    float g[3];
    double want;
    (void)state;
    memset(px, 100, sizeof px);
    px[10 * W + 20] = 10; /* (20, 10) dark, its neighbours 100 */
    rl_tone_init(&tone, 1.0);
    /* from (19.5, 10) in steps of (0.25, 0.5): (19.5, 10), (19.75, 10.5), (20, 11) */
    assert_int_equal(rl_ray_sample(&img, &tone, 19.5, 10.0, 0.25, 0.5, 3, 256, g), 1);
    /* half of pixel (20, 10) and half of (19, 10) */
    want = 0.5 * tone.light[10] + 0.5 * tone.light[100];
    assert_float_equal(g[0], want, 1e-3);
    /* (19.75, 10.5): weights 0.25 * 0.5 of (19, 10), 0.75 * 0.5 of (20, 10), the rest 100 */
    want = 0.75 * 0.5 * tone.light[10] + (1 - 0.75 * 0.5) * tone.light[100];
    assert_float_equal(g[1], want, 1e-3);
    assert_float_equal(g[2], tone.light[100], 1e-3);
    /* a light level the dark pixel's neighbourhood reaches stops the ray */
    assert_int_equal(rl_ray_sample(&img, &tone, 19.5, 10.0, 0.25, 0.5, 3, 100, g), 0);
}

static void no_light_path_same(void **state)
{
    rl_tone tone;
    rl_image img = rl_image_view(W, H, W, px);
    uint32_t seed = 12345;
    int i, t, rays = 0;
    (void)state;
    for (i = 0; i < W * H; i++) {
        seed = seed * 1664525u + 1013904223u;
        px[i] = (uint8_t)((seed >> 24) % 255); /* 0 .. 254 */
    }
    rl_tone_init(&tone, 2.2);
    for (t = 0; t < 20000; t++) {
        float a[64], b[64];
        double x, y, dx, dy;
        int n;
        seed = seed * 1664525u + 1013904223u;
        x = 4 + (seed >> 8) % 8800 / 100.0;
        seed = seed * 1664525u + 1013904223u;
        y = 4 + (seed >> 8) % 7200 / 100.0;
        seed = seed * 1664525u + 1013904223u;
        dx = ((int)((seed >> 8) % 2001) - 1000) / 1000.0;
        seed = seed * 1664525u + 1013904223u;
        dy = ((int)((seed >> 8) % 2001) - 1000) / 1000.0;
        n = 1 + (int)((seed >> 4) % 64);
        if (!rl_ray_inside(&img, x, y, x + (n - 1) * dx, y + (n - 1) * dy))
            continue;
        assert_int_equal(rl_ray_sample(&img, &tone, x, y, dx, dy, n, 256, a), 1);
        assert_int_equal(rl_ray_sample(&img, &tone, x, y, dx, dy, n, 255, b), 1);
        assert_memory_equal(a, b, (size_t)n * sizeof(float));
        rays++;
    }
    assert_true(rays > 5000);
}

/* The samples by the formula, sample by sample in single precision (the
 * operations rl_ray.h's bilinear mix takes, in their order); 0 when a
 * sample's four pixels reach light. */
static int oracle(const rl_image *img, const rl_tone *tone, double x, double y, double dx, double dy, int n,
                  int light, float *out)
{
    float fx0 = (float)x, fy0 = (float)y, fdx = (float)dx, fdy = (float)dy;
    int i, hit = 0;
    for (i = 0; i < n; i++) {
        float sx = fx0 + (float)i * fdx, sy = fy0 + (float)i * fdy, fx, fy, top, bot;
        int x0 = (int)sx, y0 = (int)sy;
        const uint8_t *p = img->data + y0 * img->stride + x0;
        float l00 = tone->light[p[0]], l01 = tone->light[p[1]], l10 = tone->light[p[img->stride]],
              l11 = tone->light[p[img->stride + 1]];
        hit |= p[0] >= light || p[1] >= light || p[img->stride] >= light || p[img->stride + 1] >= light;
        fx = sx - (float)x0;
        fy = sy - (float)y0;
        top = l00 + fx * (l01 - l00);
        bot = l10 + fx * (l11 - l10);
        out[i] = top + fy * (bot - top);
    }
    return !hit;
}

/* Random rays of every length and direction, with and without a light
 * level (the four-at-a-time path tests light for four samples together):
 * the same answer as the formula, and on 1 the same bits. */
static void rays_are_the_formula(void **state)
{
    rl_tone tone;
    rl_image img = rl_image_view(W, H, W, px);
    uint32_t seed = 777;
    int i, t, rays = 0, stopped = 0;
    (void)state;
    for (i = 0; i < W * H; i++) {
        seed = seed * 1664525u + 1013904223u;
        px[i] = (uint8_t)(seed >> 24);
    }
    rl_tone_init(&tone, 2.2);
    for (t = 0; t < 40000; t++) {
        float a[64], b[64];
        double x, y, dx, dy;
        int n, light, want;
        seed = seed * 1664525u + 1013904223u;
        x = 4 + (seed >> 8) % 8800 / 100.0;
        seed = seed * 1664525u + 1013904223u;
        y = 4 + (seed >> 8) % 7200 / 100.0;
        seed = seed * 1664525u + 1013904223u;
        dx = ((int)((seed >> 8) % 2001) - 1000) / 1000.0;
        seed = seed * 1664525u + 1013904223u;
        dy = ((int)((seed >> 8) % 2001) - 1000) / 1000.0;
        n = 1 + (int)((seed >> 4) % 64);
        seed = seed * 1664525u + 1013904223u;
        light = t % 4 == 0 ? 256 : 240 + (int)((seed >> 8) % 17); /* 240 .. 256 */
        if (!rl_ray_inside(&img, x, y, x + (n - 1) * dx, y + (n - 1) * dy))
            continue;
        want = oracle(&img, &tone, x, y, dx, dy, n, light, a);
        assert_int_equal(rl_ray_sample(&img, &tone, x, y, dx, dy, n, light, b), want);
        if (want)
            assert_memory_equal(a, b, (size_t)n * sizeof(float));
        stopped += !want;
        rays++;
    }
    assert_true(rays > 10000 && stopped > 1000 && rays - stopped > 1000);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(hand_bilinear),
        cmocka_unit_test(no_light_path_same),
        cmocka_unit_test(rays_are_the_formula),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
