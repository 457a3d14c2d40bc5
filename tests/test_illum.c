/* The ceiling's light per tile (rl_illum_measure): tile levels worked out
 * by hand from the samples the definition takes (every fourth row and
 * eighth column of a tile, from its corner; lamps left out; the mean of
 * the samples at or above the dark threshold when they are a quarter of
 * the tile's, else of them all; 0 under three). Pixels that are no
 * sample are drawn black, so a tile read at other pixels goes wrong. */
#include "rl_test.h"
#include "rl_illum.h"

#define W 640
#define H 480
static uint8_t px[W * H];
static uint8_t wsmem[1 << 16];

/* Tile (tx, 0) of 32 px: its k-th sample (row-major, 4 a row) at v(k). */
static void draw_tile(int tx, const int *v)
{
    int k;
    for (k = 0; k < 32; k++)
        px[(size_t)(4 * (k / 4)) * W + 32 * tx + 8 * (k % 4)] = (uint8_t)v[k];
}

static void test_tile_levels_by_hand(void **state)
{
    rl_ws ws;
    rl_illum il;
    rl_image img = rl_image_view(W, H, W, px);
    rl_levels lv;
    int a[32], k;
    (void)state;
    memset(px, 0, sizeof px);
    memset(&lv, 0, sizeof lv);
    lv.light = 240;
    lv.threshold = 100;
    lv.bg = 200;
    for (k = 0; k < 32; k++) a[k] = 200;
    draw_tile(0, a); /* all ceiling: 200 */
    for (k = 0; k < 32; k++) a[k] = 250;
    draw_tile(1, a); /* all lamp: 0 */
    for (k = 0; k < 32; k++) a[k] = k % 2 ? 180 : 50;
    draw_tile(2, a); /* 16 of 32 over the threshold: their mean, 180 */
    for (k = 0; k < 32; k++) a[k] = k < 4 ? 180 : 50;
    draw_tile(3, a); /* 4 of 32 over it: all, (4 x 180 + 28 x 50) / 32 = 66.25 */
    for (k = 0; k < 32; k++) a[k] = k < 2 ? 150 : 245;
    draw_tile(4, a); /* two samples no lamp: unknown, 0 */
    for (k = 0; k < 32; k++) a[k] = k < 3 ? 150 : 245;
    draw_tile(5, a); /* three: 150 */
    for (k = 0; k < 32; k++) a[k] = k < 3 ? 150 : k < 12 ? 60 : 245;
    draw_tile(6, a); /* 3 of 12 over it, a quarter: 150 */
    for (k = 0; k < 32; k++) a[k] = k < 3 ? 150 : k < 13 ? 60 : 245;
    draw_tile(7, a); /* 3 of 13: all, (3 x 150 + 10 x 60) / 13 = 80.8 */
    for (k = 0; k < 32; k++) a[k] = k % 2 ? 100 : 50;
    draw_tile(9, a); /* 16 exactly at the threshold count over it: 100 (75 if not) */
    for (k = 0; k < 32; k++) a[k] = k % 2 ? 240 : 200;
    draw_tile(10, a); /* 16 exactly at the lamp level are lamps: 200 (220 if not) */
    rl_ws_init(&ws, wsmem, sizeof wsmem);
    assert_int_equal(rl_illum_init(&il, &ws, W, H), RL_OK);
    assert_int_equal(il.tile, 32);
    rl_illum_measure(&il, &img, &lv);
    assert_int_equal(il.level[0], 200);
    assert_int_equal(il.level[1], 0);
    assert_int_equal(il.level[2], 180);
    assert_int_equal(il.level[3], 66);
    assert_int_equal(il.level[4], 0);
    assert_int_equal(il.level[5], 150);
    assert_int_equal(il.level[6], 150);
    assert_int_equal(il.level[7], 80);
    assert_int_equal(il.level[8], 0); /* black, under the threshold: all, 0 */
    assert_int_equal(il.level[9], 100);
    assert_int_equal(il.level[10], 200);
}

/* The largest tiles (64 px, frames 896 px wide and more) hold 128
 * samples: their counts and sums at the brightest level that is no lamp. */
#define WL 1792
#define HL 64
static uint8_t big[WL * HL];

static void test_largest_tile_at_the_top_level(void **state)
{
    rl_ws ws;
    rl_illum il;
    rl_image img = rl_image_view(WL, HL, WL, big);
    rl_levels lv;
    int x, y;
    (void)state;
    memset(big, 0, sizeof big);
    for (y = 0; y < HL; y++)
        for (x = 0; x < 64; x++)
            big[(size_t)y * WL + x] = 255; /* tile 0: every sample 255 */
    for (y = 0; y < HL; y += 4)
        for (x = 64; x < 128; x += 8)
            big[(size_t)y * WL + x] = (uint8_t)(y < 32 ? 255 : 99); /* tile 1: 64 of 128 */
    memset(&lv, 0, sizeof lv);
    lv.light = 256; /* no lamp */
    lv.threshold = 100;
    lv.bg = 255;
    rl_ws_init(&ws, wsmem, sizeof wsmem);
    assert_int_equal(rl_illum_init(&il, &ws, WL, HL), RL_OK);
    assert_int_equal(il.tile, 64);
    rl_illum_measure(&il, &img, &lv);
    assert_int_equal(il.level[0], 255);
    assert_int_equal(il.level[1], 255);
    lv.threshold = 256; /* every sample under it: the mean of all */
    rl_illum_measure(&il, &img, &lv);
    assert_int_equal(il.level[0], 255);
    assert_int_equal(il.level[1], 177); /* (64 x 255 + 64 x 99) / 128 */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_tile_levels_by_hand),
        cmocka_unit_test(test_largest_tile_at_the_top_level),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
