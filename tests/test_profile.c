/* The profile gather's sums (rl_profile.c): per bin the pixels and their
 * summed darkness, and the squares over every pixel, are integers, so the
 * gather must give them exactly as one pixel at a time would. The oracle
 * here walks the disk's pixels one by one: the row span and each pixel's
 * bin from the formulas the module documents (the shape's normalized
 * radius, the bin from its square root in single precision, a rim pixel
 * in the last bin), its darkness from the curve's definition
 * (RL_TONE_MAX less its light, RL_TONE_MAX (g / 255)^gamma, rounded), and adds. Circles
 * and ellipses, small and wider than a 64-pixel chunk, whole and cut by
 * every border, every row and every third row, two tone curves, images
 * whose rows are longer than they are. */
#include "rl_test.h"
#include <math.h>
#include "rl_profile.h"

#define W 203
#define STRIDE 211
#define H 157
static uint8_t frame[STRIDE * H];

static uint64_t rng = 99; /* 64 bits on every target: (rng >> 11) / 2^53 is uniform */
static double uniform(void)
{
    rng = rng * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(rng >> 11) / 9007199254740992.0;
}

/* A grey level's darkness under a curve of exponent gamma, by definition. */
static double darkness(double gamma, int g)
{
    return RL_TONE_MAX - (int)(RL_TONE_MAX * pow(g / 255.0, gamma) + 0.5);
}

/* Pixel by pixel: the rows ystep apart from the disk's top, each row's
 * span where a dx^2 + 2 b dy dx + c dy^2 < ext^2, clipped to the image. */
static void one_by_one(double gamma, double cx, double cy, double r, const rl_shape *sh, int ystep,
                       rl_profile *p)
{
    double ext = RL_PROFILE_EXTENT * r, scale = RL_PROFILE_BINS / ext, hy = ext * sqrt(sh->a);
    float fa = (float)sh->a, fscale = (float)scale;
    int y, x, y0 = (int)ceil(cy - hy), y1 = (int)floor(cy + hy);
    memset(p, 0, sizeof *p);
    if (y0 < 0)
        y0 = 0;
    if (y1 > H - 1)
        y1 = H - 1;
    for (y = y0; y <= y1; y += ystep) {
        double dy = y - cy, disc = sh->b * sh->b * dy * dy - sh->a * (sh->c * dy * dy - ext * ext), h, mid;
        float b2dy = (float)(2 * sh->b * dy), cdy2 = (float)(sh->c * dy * dy);
        int xa, xb;
        if (disc <= 0)
            continue;
        h = sqrt(disc) / sh->a;
        mid = cx - sh->b * dy / sh->a;
        xa = (int)ceil(mid - h);
        xb = (int)floor(mid + h);
        if (xa < 0)
            xa = 0;
        if (xb > W - 1)
            xb = W - 1;
        for (x = xa; x <= xb; x++) {
            float dx = (float)(x - cx), d2 = (fa * dx + b2dy) * dx + cdy2;
            int k = (int)(sqrtf(d2) * fscale);
            double v = darkness(gamma, frame[(size_t)y * STRIDE + (size_t)x]);
            k = k < RL_PROFILE_BINS - 1 ? k : RL_PROFILE_BINS - 1;
            p->n[k] += 1;
            p->sx[k] += v;
            p->sxx += v * v;
            p->total += 1;
        }
    }
}

static void test_sums_are_the_pixels_one_by_one(void **state)
{
    int trial, k, g;
    (void)state;
    for (k = 0; k < STRIDE * H; k++)
        frame[k] = (uint8_t)(uniform() * 256);
    for (trial = 0; trial < 400; trial++) {
        rl_tone tone;
        rl_shape sh = trial % 3 ? rl_shape_from_moments(1.0, 0.4 * (uniform() - 0.5), 0.5 + 0.5 * uniform())
                                : rl_shape_circle();
        /* centres inside, near and past every border; radii up to a disk
         * wider than the image */
        double cx = -20 + (W + 40) * uniform(), cy = -20 + (H + 40) * uniform(), r = 2 + 90 * uniform() * uniform();
        int step = trial % 4 == 3 ? 3 : 1;
        rl_image img = {W, H, STRIDE, frame};
        rl_profile got, want;
        double gamma = trial % 2 ? 2.2 : 1.0;
        rl_tone_init(&tone, gamma);
        if (step != 1 && rl_shape_is_circle(&sh))
            rl_profile_gather_rows(&img, &tone, cx, cy, r, step, &got);
        else if (rl_shape_is_circle(&sh) && trial % 2)
            rl_profile_gather(&img, &tone, cx, cy, r, &got);
        else {
            step = 1;
            rl_profile_gather_shaped(&img, &tone, cx, cy, r, &sh, &got);
        }
        one_by_one(gamma, cx, cy, r, &sh, step, &want);
        for (g = 0; g < RL_PROFILE_BINS; g++)
            if (got.n[g] != want.n[g] || got.sx[g] != want.sx[g])
                fail_msg("trial %d (%.2f, %.2f) r %.2f: bin %d holds %.0f pixels, %.0f dark; one by one %.0f, %.0f",
                         trial, cx, cy, r, g, got.n[g], got.sx[g], want.n[g], want.sx[g]);
        if (got.sxx != want.sxx || got.total != want.total)
            fail_msg("trial %d: squares %.0f of %.0f pixels; one by one %.0f of %.0f", trial, got.sxx, got.total,
                     want.sxx, want.total);
    }
}

/* A gather larger than one packed word holds: a 2100 x 2100 frame
 * (4,410,000 pixels, over the 4,198,404 a bin's 32-bit darkness sum holds
 * at 1023 a pixel), every pixel black, at a radius so large that all of
 * them fall in bin 0. By hand: bin 0 holds every pixel, its darkness
 * 4,410,000 times the darkest grey's; a sum that carried would be about
 * 2^32 short and count one pixel too many. */
static void test_a_bin_over_four_megapixels(void **state)
{
    enum { BIG = 2100 };
    uint8_t *black = calloc((size_t)BIG * BIG, 1);
    rl_image img = {BIG, BIG, BIG, black};
    rl_tone tone;
    rl_profile got;
    double pixels = (double)BIG * BIG;
    int k;
    (void)state;
    assert_non_null(black);
    rl_tone_init(&tone, 2.2);
    rl_profile_gather(&img, &tone, BIG / 2.0, BIG / 2.0, 1e6, &got);
    assert_true(got.n[0] == pixels);
    assert_true(got.sx[0] == pixels * darkness(2.2, 0));
    for (k = 1; k < RL_PROFILE_BINS; k++)
        assert_true(got.n[k] == 0 && got.sx[k] == 0);
    assert_true(got.total == pixels);
    free(black);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sums_are_the_pixels_one_by_one),
        cmocka_unit_test(test_a_bin_over_four_megapixels),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
