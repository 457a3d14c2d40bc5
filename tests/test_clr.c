/* Candidate regions (rl_clr) by hand: a ring a motion broke into two
 * halves is one candidate, its box the drawn ring's (found by scanning
 * the drawing); one half alone is none; a corner cut's centre and radius
 * from its box as worked out on paper. */
#include "rl_test.h"
#include "rl_clr.h"
#include "rl_result.h"

#define S 200
static uint8_t px[S * S];
static uint8_t wsmem[1 << 20];
static rl_result res;

/* A ring of radii 24 .. 30 about (100, 100), ink 20 on paper 220, with a
 * gap 7 px wide down its middle (x = 97 .. 103): two halves; only the
 * left one when `halves` is 1. The ink's box into *box. */
static rl_image draw_halves(int halves, rl_box *box)
{
    int x, y;
    box->x0 = box->y0 = S;
    box->x1 = box->y1 = -1;
    for (y = 0; y < S; y++)
        for (x = 0; x < S; x++) {
            int d2 = (x - 100) * (x - 100) + (y - 100) * (y - 100);
            int ink = d2 >= 24 * 24 && d2 <= 30 * 30 && (x < 97 || (halves == 2 && x > 103));
            px[y * S + x] = ink ? 20 : 220;
            if (ink) {
                if (x < box->x0) box->x0 = x;
                if (x > box->x1) box->x1 = x;
                if (y < box->y0) box->y0 = y;
                if (y > box->y1) box->y1 = y;
            }
        }
    return rl_image_view(S, S, S, px);
}

static int candidates(const rl_image *img, rl_clr *cand, int cap)
{
    rl_ws ws;
    rl_label lb;
    rl_recog_config cfg;
    rl_recog_defaults(&cfg);
    cfg.min_radius = 11.8; /* as the recognizer resolves them for ring5 */
    cfg.max_radius = S / 2.0;
    rl_ws_init(&ws, wsmem, sizeof wsmem);
    assert_int_equal(rl_label_init(&lb, &ws, S, S, 20000, 64), RL_OK);
    assert_int_equal(rl_label_band(&lb, img, 0, 128, 3), RL_OK);
    rl_result_clear(&res, S, S);
    return rl_clr_find(&lb, &cfg, &res, cand, cap);
}

static void test_two_halves_are_one_candidate(void **state)
{
    rl_clr cand[8];
    rl_box want;
    rl_image img = draw_halves(2, &want);
    int n;
    (void)state;
    n = candidates(&img, cand, 8);
    assert_int_equal(n, 1);
    assert_int_equal(cand[0].box.x0, want.x0);
    assert_int_equal(cand[0].box.x1, want.x1);
    assert_int_equal(cand[0].box.y0, want.y0);
    assert_int_equal(cand[0].box.y1, want.y1);
    assert_int_equal(res.dropped.candidates, 0);
}

static void test_one_half_is_none(void **state)
{
    rl_clr cand[8];
    rl_box box;
    rl_image img = draw_halves(1, &box);
    (void)state;
    assert_int_equal(candidates(&img, cand, 8), 0);
}

/* A box in the top-left corner, 20 wide and 30 high, of a 320 x 240
 * frame: the longer side is the diameter, r = 15; the circle touches the
 * box's far sides: u = 19.5 - 15 = 4.5, v = 29.5 - 15 = 14.5. */
static void test_corner_geometry(void **state)
{
    rl_box b = {0, 0, 19, 29};
    rl_detection d;
    (void)state;
    rl_clr_geometry(&b, 320, 240, &d);
    assert_int_equal(d.complete, 0);
    assert_true(d.radius == 15.0 && d.u == 4.5 && d.v == 14.5);
    assert_true(d.visible > 0.25 && d.visible < 1.0);
    /* the bottom-right corner, mirrored: u = 300 - 0.5 + 15, v = 210 - 0.5 + 15 */
    b.x0 = 300;
    b.y0 = 210;
    b.x1 = 319;
    b.y1 = 239;
    rl_clr_geometry(&b, 320, 240, &d);
    assert_true(d.radius == 15.0 && d.u == 314.5 && d.v == 224.5);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_two_halves_are_one_candidate),
        cmocka_unit_test(test_one_half_is_none),
        cmocka_unit_test(test_corner_geometry),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
