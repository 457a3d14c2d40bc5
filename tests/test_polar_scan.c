/* Two parts of the polar gather (rl_polar.c) held to their definitions:
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
 *   during the gather. */
#include "rl_test.h"
#include "rl_polar.c"

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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(the_brightest_level_under_light_is_the_plain_loops),
        cmocka_unit_test(the_cells_do_not_depend_on_what_the_struct_held),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
