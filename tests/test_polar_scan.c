/* Three parts of the polar gather (rl_polar.c, rl_polar_profile.c) held to their definitions:
 * - the candidate's brightest level under light (brightest_in_row, which
 *   sets the cells' scale: 16 bytes at a time in vectors, their even ones)
 *   against a plain loop over every second pixel, at every start parity,
 *   span and light 1-256, rows random with many levels at and next to the
 *   light;
 * - the cells depend on the image alone, not on what the struct held
 *   before: the float cells are no longer cleared whole before a gather
 *   (the first unpack sets their bins, the pads alone are zeroed), so a
 *   gather into a struct full of other numbers must leave every cell,
 *   pads included, as a gather into a zeroed one does, at a landmark's
 *   usual size and at one large enough that the packed sums are moved out
 *   during the gather;
 * - every pixel of the disk in its own cell once (the sums added four
 *   pixels a step), against a plain loop over the pixels;
 * - a profile's rescale (rescale_bins: the three sums in one vector's
 *   lanes; its scalar loop under RL_NO_VECTOR_EXT, the sanitizer build's)
 *   against its definition, summed plainly: each mid bin m lands at
 *   t = (m - SHIFT_GUARD + 0.5) / scale - 0.5, 1 - w of it in bin
 *   floor(t) and w in the next, added in the order of m, and the totals
 *   of n and q added in the order of the bins, bit for bit. */
#include "rl_test.h"
#include "rl_polar.c"
#include "rl_polar_profile.c"

static unsigned seed = 2718;
static unsigned rnd(void)
{
    seed = seed * 1103515245u + 12345u;
    return seed >> 8;
}

/* The oracle: every second pixel from x0 to x1, the brightest under light. */
static int plain_brightest(const uint8_t *row, int x0, int x1, int light, int top)
{
    int x;
    for (x = x0; x <= x1; x += 2)
        if (row[x] < light && row[x] > top)
            top = row[x];
    return top;
}

static void the_brightest_level_under_light_is_the_plain_loops(void **state)
{
    uint8_t row[128];
    int x0, x1, light, k, wrong = 0, cases = 0;
    (void)state;
    for (light = 1; light <= 256; light++)
        for (k = 0; k < 8; k++) {
            int i;
            for (i = 0; i < 128; i++) { /* half of them within 2 of the light */
                int v = rnd() % 2 ? light - 2 + (int)(rnd() % 5) : (int)(rnd() % 256);
                row[i] = (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : v);
            }
            for (x0 = 0; x0 < 4; x0++)
                for (x1 = x0; x1 < 128; x1++) {
                    int top = 1 + (int)(rnd() % 3);
                    wrong += brightest_in_row(row, x0, x1, light, top) != plain_brightest(row, x0, x1, light, top);
                    cases++;
                }
        }
    printf("  %d rows, starts and lights: %d wrong\n", cases, wrong);
    assert_int_equal(wrong, 0);
}

#define S 1100
static uint8_t px[S * S];
static rl_polar clean, dirty;

static void the_cells_do_not_depend_on_what_the_struct_held(void **state)
{
    static const double radii[] = {25.7, 420.0}; /* 420: past PACK_MAX pixels a cell */
    rl_image img = rl_image_view(S, S, S, px);
    rl_tone tone;
    int i, k;
    (void)state;
    rl_tone_init(&tone, 1.0);
    for (i = 0; i < S * S; i++) /* rings of ink and paper, noise, a few lights */
        px[i] = (uint8_t)((i / S / 9 + i % S / 7) % 3 == 0 ? 30 + rnd() % 20 : rnd() % 97 == 0 ? 255 : 190 + rnd() % 30);
    for (k = 0; k < 2; k++) {
        double r = radii[k];
        memset(&clean, 0, sizeof clean);
        memset(&dirty, 0x5a, sizeof dirty); /* floats of 1.5e16, counts of billions */
        rl_polar_gather(&img, &tone, 550.3, 549.6, r, 250, 20.0, &clean);
        rl_polar_gather(&img, &tone, 550.3, 549.6, r, 250, 20.0, &dirty);
        {
            double total = 0;
            int sct, b;
            for (sct = 0; sct < RL_SECTORS; sct++)
                for (b = 0; b < RL_POLAR_CELLS; b++)
                    total += clean.n[sct][b];
            printf("  radius %.1f px: %.0f pixels gathered\n", r, total);
        }
        assert_memory_equal(clean.n, dirty.n, sizeof clean.n);
        assert_memory_equal(clean.s, dirty.s, sizeof clean.s);
        assert_memory_equal(clean.q, dirty.q, sizeof clean.q);
    }
}

/* The cells against every pixel summed one at a time: the gather adds a
 * row's chunk four pixels a step (and the rest one by one), and must add
 * each pixel of the disk once, to its own cell. Centres at every
 * sub-pixel phase and radii from 5 to 60 px give spans of every length
 * modulo 4; some disks run off the image. One unpack (no cell reaches
 * PACK_MAX at these radii), so a cell's float is its integer sum. */
static uint64_t plain_acc[RL_SECTORS][RL_POLAR_CELLS];

static void plain_cells(const rl_polar *pol, const rl_image *img)
{
    double cx = pol->cx, cy = pol->cy, r = pol->r;
    double bw = RL_PROFILE_EXTENT * r / RL_PROFILE_BINS, lim = RL_POLAR_BINS * bw;
    float inv = (float)(1.0 / bw), fcx = (float)cx;
    int x, y;
    memset(plain_acc, 0, sizeof plain_acc);
    for (y = 0; y < img->height; y++) {
        double dy = y - cy, half = lim * lim - dy * dy;
        float fdy = (float)dy, dy2 = fdy * fdy, ady = fabsf(fdy);
        int x0, x1;
        if (half <= 0 || y < iceil(cy - lim) || y > ifloor(cy + lim))
            continue;
        half = sqrt(half);
        x0 = iceil(cx - half);
        x1 = ifloor(cx + half);
        for (x = x0 < 0 ? 0 : x0; x <= x1 && x < img->width; x++) {
            float dx = (float)x - fcx, adx = fabsf(dx);
            float lo = adx < ady ? adx : ady, hi = adx < ady ? ady : adx;
            float d = sqrtf(dx * dx + dy2) * inv;
            int sct = (dy < 0 ? 4 : 0) + (dx < 0 ? 8 : 0) + (adx > ady ? 2 : 0) +
                      (lo > 0.41421356f * hi ? 1 : 0);
            d = d < RL_POLAR_BINS - 0.5f ? d : RL_POLAR_BINS - 0.5f;
            plain_acc[sct][RL_POLAR_PAD + (int)d] +=
                pol->lut[img->data[(size_t)y * (size_t)img->stride + x]];
        }
    }
}

static void every_pixel_is_gathered_once(void **state)
{
    rl_image img = rl_image_view(S, S, S, px);
    rl_tone tone;
    int t, i, pixels = 0;
    (void)state;
    rl_tone_init(&tone, 2.2);
    for (i = 0; i < S * S; i++)
        px[i] = (uint8_t)(rnd() % 256);
    for (t = 0; t < 300; t++) {
        double r = 5.0 + (t % 56);
        double cx = (t % 3 == 0 ? 2.0 : 200.0) + (t % 8) * 0.125 + (rnd() % 400) * 0.01;
        double cy = (t % 5 == 0 ? 1.0 : 300.0) + (t % 7) * 0.15;
        int sct, b;
        polar_setup(&clean, &tone, 200, cx, cy, r, 250);
        gather_cells(&clean, &img);
        plain_cells(&clean, &img);
        for (sct = 0; sct < RL_SECTORS; sct++)
            for (b = RL_POLAR_PAD; b < RL_POLAR_PAD + RL_POLAR_BINS; b++) {
                uint64_t a = plain_acc[sct][b];
                uint32_t hi = (uint32_t)(a >> PACK_S_SHIFT), lo = (uint32_t)a;
                assert_true(clean.n[sct][b] == (float)(int32_t)(hi >> (PACK_N_SHIFT - PACK_S_SHIFT)));
                assert_true(clean.s[sct][b] ==
                            (float)(int32_t)(hi & ((1u << (PACK_N_SHIFT - PACK_S_SHIFT)) - 1)));
                assert_true(clean.q[sct][b] == (float)(int32_t)lo);
                pixels += (int)(hi >> (PACK_N_SHIFT - PACK_S_SHIFT));
            }
    }
    printf("  300 disks, %d pixels under light: each in its cell once\n", pixels);
    assert_true(pixels > 300000);
}

/* The oracle: rescale_bins by its definition, one bin array a sum. */
static void plain_rescale(const float *mn, const float *ms, const float *mq, double scale, rl_profile *p)
{
    float bn[RL_PROFILE_BINS + 2] = {0}, bs[RL_PROFILE_BINS + 2] = {0}, bq[RL_PROFILE_BINS + 2] = {0};
    float tn = 0, tq = 0;
    double a = 1.0 / scale;
    int m, k;
    for (m = 0; m < MID_BINS; m++) {
        double t = a * m + (a * (0.5 - SHIFT_GUARD) - 0.5);
        int j;
        float w;
        if (t < -1.0 || t >= RL_PROFILE_BINS)
            continue;
        j = (int)floor(t);
        w = (float)(t - j);
        /* bin j + 1 at index j + 2, so bin -1 has a place */
        bn[j + 1] += (1.0f - w) * mn[m];
        bs[j + 1] += (1.0f - w) * ms[m];
        bq[j + 1] += (1.0f - w) * mq[m];
        bn[j + 2] += w * mn[m];
        bs[j + 2] += w * ms[m];
        bq[j + 2] += w * mq[m];
    }
    for (k = 0; k < RL_PROFILE_BINS; k++) {
        p->n[k] = bn[k + 1];
        p->sx[k] = bs[k + 1];
        tn += bn[k + 1];
        tq += bq[k + 1];
    }
    p->total = tn;
    p->sxx = tq;
    p->plane = 0;
}

static void the_rescale_is_its_definition(void **state)
{
    static const double fixed[] = {1.0, 0.5, 0.9, 0.95, 1.05, 1.1, 1.06, 0.985, 1.015, 2.0, 0.01, 40.0};
    float mn[MID_BINS], ms[MID_BINS], mq[MID_BINS];
    int trial, m, k, wrong = 0;
    (void)state;
    for (trial = 0; trial < 20000; trial++) {
        rl_profile got, want;
        double scale = trial < 12 ? fixed[trial] : 0.85 + 0.3 * (rnd() % 100000) / 100000.0;
        for (m = 0; m < MID_BINS; m++) { /* some mid bins empty, as a sector's pads and lights leave them */
            int empty = rnd() % 5 == 0;
            mn[m] = empty ? 0.0f : (float)(rnd() % 4000) / 7.0f;
            ms[m] = empty ? 0.0f : mn[m] * (float)(rnd() % 256);
            mq[m] = empty ? 0.0f : ms[m] * (float)(rnd() % 256) / 3.0f;
        }
        memset(&got, 0x5a, sizeof got);
        memset(&want, 0xa5, sizeof want);
        rescale_bins(mn, ms, mq, scale, &got);
        plain_rescale(mn, ms, mq, scale, &want);
        for (k = 0; k < RL_PROFILE_BINS; k++)
            wrong += memcmp(&got.n[k], &want.n[k], sizeof got.n[k]) != 0 ||
                     memcmp(&got.sx[k], &want.sx[k], sizeof got.sx[k]) != 0;
        wrong += memcmp(&got.total, &want.total, sizeof got.total) != 0 ||
                 memcmp(&got.sxx, &want.sxx, sizeof got.sxx) != 0 || got.plane != want.plane;
    }
    printf("  20000 rescales: %d numbers wrong\n", wrong);
    assert_int_equal(wrong, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(the_brightest_level_under_light_is_the_plain_loops),
        cmocka_unit_test(the_cells_do_not_depend_on_what_the_struct_held),
        cmocka_unit_test(every_pixel_is_gathered_once),
        cmocka_unit_test(the_rescale_is_its_definition),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
