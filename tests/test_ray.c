/* Light along rays (rl_ray_sample): a sample is the bilinear mix of its
 * four pixels' light, by hand on a small image; and with no light level
 * (256) the samples are bit for bit those of the path that tests each
 * sample's pixels against a light level none of them reaches (255 on an
 * image under 255), on random rays of every length and direction. */
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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(hand_bilinear),
        cmocka_unit_test(no_light_path_same),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
