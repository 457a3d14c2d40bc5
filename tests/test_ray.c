/* Light along rays (rl_ray_sample): a sample is the bilinear mix of its
 * four pixels' light, by hand on a small image; with no light level
 * (256) the samples are bit for bit those with a light level none of them
 * reaches (255 on an image under 255); and on random rays, with and
 * without a light level, the answer and the bits of the formula written
 * here sample by sample (in a view whose rows are longer than it); a ray
 * rl_ray_inside takes reads no pixel outside the image, its end a hair
 * under the last column or row. The light table (rl_ray_lit) against
 * its definition at every level and light level 1 .. 256, and its rays
 * against the formula and rl_ray_sample at every light level, including a
 * light pixel that weighs nothing in its sample. */
#include <math.h>
#include "rl_test.h"
#include "rl_ray.h"
#include "rl_tone.h"

#define W 96
#define H 80
static uint8_t px[W * H];

/* A random ray over the W x H image: its start (x, y) 4 px and more from
 * the top left, its step (dx, dy) up to a pixel; its sample count. */
static int random_ray(uint32_t *seed, double *x, double *y, double *dx, double *dy)
{
    *seed = *seed * 1664525u + 1013904223u;
    *x = 4 + (*seed >> 8) % 8800 / 100.0;
    *seed = *seed * 1664525u + 1013904223u;
    *y = 4 + (*seed >> 8) % 7200 / 100.0;
    *seed = *seed * 1664525u + 1013904223u;
    *dx = ((int)((*seed >> 8) % 2001) - 1000) / 1000.0;
    *seed = *seed * 1664525u + 1013904223u;
    *dy = ((int)((*seed >> 8) % 2001) - 1000) / 1000.0;
    return 1 + (int)((*seed >> 4) % 64);
}

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
        n = random_ray(&seed, &x, &y, &dx, &dy);
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
    /* a view narrower and shorter than its rows (stride W): the next row
     * is a stride on, not a width */
    rl_image img = rl_image_view(W - 13, H - 5, W, px);
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
        n = random_ray(&seed, &x, &y, &dx, &dy);
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

/* Ends within float rounding of the last column or row: the samples are
 * placed in float, so an end rl_ray_inside takes a hair under width - 1
 * in double could land on the last pixel and read the one past it. The
 * view sits in a buffer whose pixels outside it are 255 and inside 100: a
 * ray rl_ray_inside takes, sampled with light level 255, reads no pixel
 * outside the view (a sample touching one stops the ray). */
static void ends_at_the_last_pixel(void **state)
{
    static uint8_t buf[(2100 + 2) * (1600 + 2)];
    static const int sizes[][2] = {{4, 3}, {2, 2}, {97, 61}, {640, 480}, {2000, 1500}};
    rl_tone tone;
    uint32_t seed = 4242;
    int k, t, taken = 0;
    (void)state;
    rl_tone_init(&tone, 1.0);
    for (k = 0; k < (int)(sizeof sizes / sizeof sizes[0]); k++) {
        int w = sizes[k][0], h = sizes[k][1], st = w + 2;
        rl_image img = rl_image_view(w, h, st, buf);
        memset(buf, 255, sizeof buf);
        for (t = 0; t < h; t++)
            memset(buf + (size_t)t * st, 100, (size_t)w);
        for (t = 0; t < 4000; t++) {
            float g[64];
            /* an end 1e-9 .. 1e-2 px under the last column or row (or both), a
             * start anywhere inside */
            double under = pow(10.0, -9.0 + 7.0 * ((seed = seed * 1664525u + 1013904223u) >> 8) / 16777216.0);
            double x1 = w - 1 - under, y1 = h - 1 - under, x0, y0;
            int n = 2 + (int)(((seed = seed * 1664525u + 1013904223u) >> 8) % 63);
            x0 = (w - 1) * (((seed = seed * 1664525u + 1013904223u) >> 8) / 16777216.0);
            y0 = (h - 1) * (((seed = seed * 1664525u + 1013904223u) >> 8) / 16777216.0);
            if (t % 3 == 1)
                y1 = y0; /* along a row to the last column */
            else if (t % 3 == 2)
                x1 = x0; /* down a column to the last row */
            if (!rl_ray_inside(&img, x0, y0, x1, y1))
                continue;
            taken++;
            assert_int_equal(rl_ray_sample(&img, &tone, x0, y0, (x1 - x0) / (n - 1), (y1 - y0) / (n - 1), n, 255, g),
                             1);
        }
    }
    assert_true(taken > 1000);
}

/* Every grey level's entry for light levels 1 .. 256 and two curves:
 * NaN at or above the level, below it tone's light bit for bit. */
static void lit_table_is_its_definition(void **state)
{
    static const double gammas[] = {1.0, 2.2};
    int k, light, g;
    (void)state;
    for (k = 0; k < 2; k++) {
        rl_tone tone;
        rl_tone_init(&tone, gammas[k]);
        for (light = 1; light <= 256; light++) {
            rl_ray_lit lit;
            rl_ray_lit_init(&lit, &tone, light);
            for (g = 0; g < 256; g++) {
                if (g >= light) {
                    assert_true(isnan(lit.light[g]));
                } else {
                    assert_false(isnan(lit.light[g]));
                    assert_memory_equal(&lit.light[g], &tone.light[g], sizeof(float));
                }
            }
        }
    }
}

/* Random rays at every light level 1 .. 256 over an image of 8 x 8 blocks
 * (each a random level 0 .. 239 and noise up to 15 over it, every grey
 * level in the image): rl_ray_sample_lit gives the formula's answer (and
 * rl_ray_sample's), and on 1 the formula's bits; rays of both answers at
 * most levels. */
static void lit_rays_are_the_formula(void **state)
{
    rl_tone tone;
    rl_image img = rl_image_view(W - 13, H - 5, W, px);
    uint32_t seed = 31337;
    uint8_t base[(H / 8) * (W / 8)];
    int i, light, stopped = 0, passed = 0, both = 0;
    (void)state;
    for (i = 0; i < (H / 8) * (W / 8); i++) {
        seed = seed * 1664525u + 1013904223u;
        base[i] = (uint8_t)((seed >> 8) % 240);
    }
    for (i = 0; i < W * H; i++) {
        seed = seed * 1664525u + 1013904223u;
        px[i] = (uint8_t)(base[i / W / 8 * (W / 8) + i % W / 8] + (seed >> 28));
    }
    rl_tone_init(&tone, 2.2);
    for (light = 1; light <= 256; light++) {
        rl_ray_lit lit;
        int t, stops = 0, passes = 0;
        rl_ray_lit_init(&lit, &tone, light);
        for (t = 0; t < 300; t++) {
            float a[64], b[64], c[64];
            double x, y, dx, dy;
            int n = random_ray(&seed, &x, &y, &dx, &dy), want;
            if (!rl_ray_inside(&img, x, y, x + (n - 1) * dx, y + (n - 1) * dy))
                continue;
            want = oracle(&img, &tone, x, y, dx, dy, n, light, a);
            assert_int_equal(rl_ray_sample(&img, &tone, x, y, dx, dy, n, light, c), want);
            assert_int_equal(rl_ray_sample_lit(&img, &lit, x, y, dx, dy, n, b), want);
            if (want)
                assert_memory_equal(a, b, (size_t)n * sizeof(float));
            stops += !want;
            passes += want;
        }
        both += stops > 0 && passes > 0;
        stopped += stops;
        passed += passes;
    }
    assert_true(stopped > 10000 && passed > 5000 && both > 200);
}

/* A light pixel at weight 0 still stops the ray, as in rl_ray_sample (a
 * sample touches its four pixels whatever their weights): samples on
 * whole pixels, the light one right of, below or diagonal to a sample,
 * that sample first, in the middle of four, or in the tail past the last
 * four. */
static void lit_pixel_at_weight_zero(void **state)
{
    static const int at[3][2] = {{1, 0}, {0, 1}, {1, 1}};
    rl_tone tone;
    rl_image img = rl_image_view(W, H, W, px);
    rl_ray_lit lit;
    int k, s, n;
    (void)state;
    rl_tone_init(&tone, 2.2);
    rl_ray_lit_init(&lit, &tone, 200);
    for (k = 0; k < 3; k++) {
        for (n = 1; n <= 9; n++) {
            for (s = 0; s < n; s++) {
                float a[9], b[9];
                memset(px, 100, sizeof px);
                /* the ray (10, 20), (11, 20) .. in whole pixels; sample s's pixel
                 * (10 + s, 20) offset by at[k] is light */
                px[(20 + at[k][1]) * W + 10 + s + at[k][0]] = 230;
                if (at[k][0] == 1 && s + 1 < n)
                    continue; /* that pixel is the next sample's own, at weight 1 */
                assert_int_equal(oracle(&img, &tone, 10.0, 20.0, 1.0, 0.0, n, 200, a), 0);
                assert_int_equal(rl_ray_sample_lit(&img, &lit, 10.0, 20.0, 1.0, 0.0, n, b), 0);
                /* under a level it does not reach, the ray passes */
                assert_int_equal(rl_ray_sample_lit(&img, (rl_ray_lit_init(&lit, &tone, 231), &lit), 10.0, 20.0,
                                                   1.0, 0.0, n, b),
                                 1);
                rl_ray_lit_init(&lit, &tone, 200);
            }
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(hand_bilinear),
        cmocka_unit_test(no_light_path_same),
        cmocka_unit_test(rays_are_the_formula),
        cmocka_unit_test(ends_at_the_last_pixel),
        cmocka_unit_test(lit_table_is_its_definition),
        cmocka_unit_test(lit_rays_are_the_formula),
        cmocka_unit_test(lit_pixel_at_weight_zero),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
