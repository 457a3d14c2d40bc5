/* Landmarks joined to the ceiling beside them (rl_split), by hand: a
 * ring whose sheet ends at its outer edge, beside a grey panel that the
 * threshold takes for dark too, is no candidate of its own until the
 * large region is labelled again nearer the ink; then it is one, its box
 * the drawn ring's. A ring alone is left as it is, and a ring the border
 * cuts, labelled again, is not added twice. */
#include "rl_test.h"
#include "rl_result.h"
#include "rl_split.h"

#define S 200
#define TILE 16
#define NT ((S + TILE - 1) / TILE)
static uint8_t px[S * S];
static uint8_t thr[NT * NT];
static uint8_t wsmem[1 << 20];
static rl_result res;

/* A ring of radii 24 .. 30 about (cx, 100), ink 20 on paper 220; with a
 * panel of grey 110 from x = 40 up to the ring's left edge (x = cx - 30),
 * top to bottom of the frame. The ink's box into *box. */
static rl_image draw(int cx, int panel, rl_box *box)
{
    int x, y;
    box->x0 = box->y0 = S;
    box->x1 = box->y1 = -1;
    for (y = 0; y < S; y++)
        for (x = 0; x < S; x++) {
            int d2 = (x - cx) * (x - cx) + (y - 100) * (y - 100);
            int ink = d2 >= 24 * 24 && d2 <= 30 * 30;
            px[y * S + x] = ink ? 20 : panel && x >= 40 && x < cx - 30 ? 110 : 220;
            if (ink) {
                if (x < box->x0) box->x0 = x;
                if (x > box->x1) box->x1 = x;
                if (y < box->y0) box->y0 = y;
                if (y > box->y1) box->y1 = y;
            }
        }
    return rl_image_view(S, S, S, px);
}

static int has_box(const rl_clr *cand, int n, const rl_box *b)
{
    int i;
    for (i = 0; i < n; i++)
        if (cand[i].box.x0 == b->x0 && cand[i].box.x1 == b->x1 && cand[i].box.y0 == b->y0 &&
            cand[i].box.y1 == b->y1)
            return 1;
    return 0;
}

/* The CLRs of img under a threshold of 128 everywhere into cand (*first
 * of them before the split); returns how many after it. */
static int split(const rl_image *img, rl_clr *cand, int cap, int *first)
{
    rl_ws ws;
    rl_label lb;
    rl_split sp;
    rl_recog_config cfg;
    rl_label_map map = {thr, TILE, NT, NT};
    rl_recog_defaults(&cfg);
    cfg.min_radius = 11.8; /* as the recognizer resolves them for ring5 */
    cfg.max_radius = S / 2.0;
    memset(thr, 128, sizeof thr);
    rl_ws_init(&ws, wsmem, sizeof wsmem);
    assert_int_equal(rl_label_init(&lb, &ws, S, S, 20000, 64), RL_OK);
    assert_int_equal(rl_split_init(&sp, &ws, &map), RL_OK);
    assert_int_equal(rl_label_dark(&lb, img, &map, 3), RL_OK);
    rl_result_clear(&res, S, S);
    *first = rl_clr_find(&lb, &cfg, &res, cand, cap);
    return rl_split_find(&sp, &map, &lb, img, &cfg, 3, &res, cand, *first, cap);
}

/* The panel (110) is under 128 but over RL_SPLIT_RATIO * 128 = 102. */
static void test_ring_beside_panel_comes_apart(void **state)
{
    rl_clr cand[16];
    rl_box ring;
    rl_image img = draw(110, 1, &ring);
    int first, n;
    (void)state;
    n = split(&img, cand, 16, &first);
    assert_false(has_box(cand, first, &ring)); /* joined: no candidate of its own */
    assert_int_equal(n, first + 1);
    assert_true(has_box(cand + first, 1, &ring));
    assert_int_equal(res.dropped.candidates, 0);
}

static void test_ring_alone_is_left_alone(void **state)
{
    rl_clr cand[16];
    rl_box ring;
    rl_image img = draw(100, 0, &ring);
    int first, n;
    (void)state;
    n = split(&img, cand, 16, &first);
    assert_int_equal(first, 1);
    assert_true(has_box(cand, 1, &ring));
    assert_int_equal(n, 1);
}

/* Cut by the left border (centre 20 px in): labelled again, as any region
 * the border cuts is, and found again; not a second candidate. */
static void test_cut_ring_is_not_added_twice(void **state)
{
    rl_clr cand[16];
    rl_box ring;
    rl_image img = draw(20, 0, &ring);
    int first, n;
    (void)state;
    n = split(&img, cand, 16, &first);
    assert_int_equal(first, 1);
    assert_int_equal(n, 1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ring_beside_panel_comes_apart),
        cmocka_unit_test(test_ring_alone_is_left_alone),
        cmocka_unit_test(test_cut_ring_is_not_added_twice),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
