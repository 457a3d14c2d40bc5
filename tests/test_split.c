/* The second labellings (rl_split), by hand, under a frame threshold of
 * 128 everywhere: a ring whose sheet ends at its outer edge, beside a grey
 * panel (110) the threshold takes for dark too, is no candidate of its own
 * until the large region is labelled again under 0.8 x 128 = 102; a faint
 * ring (140) of which only the top half is dark (110) becomes one whole
 * candidate under 1.15 x 128 = 147. The new candidates' boxes are the drawn
 * rings'. A ring alone, and a code ring inside its outer ring, mark
 * nothing; the tiles marked around a piece stay in the frame; a ring
 * found again where a candidate was read or a landmark identified, or
 * inside a candidate as its code ring, is not new; what does not fit is
 * counted. */
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
static rl_split sp;
static rl_label lb;

/* Ink `ink` between radii rin and rout about (cx, cy) into px (paper 220
 * where nothing else is drawn); the ink's box into *box. */
static void ring_at(int cx, int cy, int rin, int rout, int ink, rl_box *box)
{
    int x, y;
    box->x0 = box->y0 = S;
    box->x1 = box->y1 = -1;
    for (y = 0; y < S; y++)
        for (x = 0; x < S; x++) {
            int d2 = (x - cx) * (x - cx) + (y - cy) * (y - cy);
            if (d2 < rin * rin || d2 > rout * rout)
                continue;
            px[y * S + x] = (uint8_t)ink;
            if (x < box->x0) box->x0 = x;
            if (x > box->x1) box->x1 = x;
            if (y < box->y0) box->y0 = y;
            if (y > box->y1) box->y1 = y;
        }
}

static void ring(int cx, int rin, int rout, int ink, rl_box *box)
{
    ring_at(cx, 100, rin, rout, ink, box);
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

static rl_recog_config config(void)
{
    rl_recog_config cfg;
    rl_recog_defaults(&cfg);
    cfg.min_radius = 11.8; /* as the recognizer resolves them for ring5 */
    cfg.max_radius = S / 2.0;
    return cfg;
}

/* The frame's labelling of px and its CLRs into cand (how many into
 * *first), the tiles marked; res empty. */
static void label_and_mark(rl_clr *cand, int *first)
{
    static const rl_label_map map = {thr, TILE, NT, NT};
    rl_recog_config cfg = config();
    rl_image img = rl_image_view(S, S, S, px);
    rl_ws ws;
    memset(thr, 128, sizeof thr);
    rl_ws_init(&ws, wsmem, sizeof wsmem);
    assert_int_equal(rl_label_init(&lb, &ws, S, S, 20000, 64), RL_OK);
    assert_int_equal(rl_split_init(&sp, &ws, &map), RL_OK);
    assert_int_equal(rl_label_dark(&lb, &img, &map, 3), RL_OK);
    rl_result_clear(&res, S, S);
    *first = rl_clr_find(&lb, &cfg, &res, cand, 16);
    rl_split_mark(&sp, &lb, cand, *first, &cfg);
}

static int find(rl_clr *out, int cap)
{
    rl_recog_config cfg = config();
    rl_image img = rl_image_view(S, S, S, px);
    return rl_split_find(&sp, &lb, &img, &cfg, 3, &res, out, cap);
}

/* Radii 24 .. 30 about (110, 100); the panel from x = 40 up to the ring's
 * left edge (x = 80), top to bottom. */
static void test_ring_beside_panel_comes_apart(void **state)
{
    rl_clr cand[16], out[16];
    rl_box ring_box;
    int first, n, x, y;
    (void)state;
    memset(px, 220, sizeof px);
    for (y = 0; y < S; y++)
        for (x = 40; x < 80; x++)
            px[y * S + x] = 110;
    ring(110, 24, 30, 20, &ring_box);
    label_and_mark(cand, &first);
    assert_false(has_box(cand, first, &ring_box)); /* joined: no candidate of its own */
    assert_int_equal(sp.n_lower, 1);
    n = find(out, 16);
    assert_int_equal(n, 1);
    assert_true(has_box(out, 1, &ring_box));
    assert_int_equal(res.dropped.candidates, 0);
}

/* Radii 24 .. 30 about (c, c) in grey 140 (not dark under 128), but 110
 * (dark) above y = c: an arc filling 0.27 of its box. */
static void faint_ring_at(int c, rl_box *ring_box)
{
    int x, y;
    memset(px, 220, sizeof px);
    ring_at(c, c, 24, 30, 140, ring_box);
    for (y = 0; y < c; y++)
        for (x = 0; x < S; x++)
            if (px[y * S + x] == 140)
                px[y * S + x] = 110;
}

static void faint_ring(rl_box *ring_box)
{
    faint_ring_at(100, ring_box);
}

static void test_faint_ring_is_whole_nearer_the_paper(void **state)
{
    rl_clr cand[16], out[16];
    rl_box ring_box;
    int first, n;
    (void)state;
    faint_ring(&ring_box);
    label_and_mark(cand, &first);
    assert_int_equal(first, 0); /* an arc is no ring */
    assert_int_equal(sp.n_higher, 1);
    n = find(out, 16);
    assert_int_equal(n, 1);
    assert_true(has_box(out, 1, &ring_box));
}

static void test_ring_alone_marks_nothing(void **state)
{
    rl_clr cand[16], out[16];
    rl_box ring_box;
    int first;
    (void)state;
    memset(px, 220, sizeof px);
    ring(100, 24, 30, 20, &ring_box);
    label_and_mark(cand, &first);
    assert_int_equal(first, 1);
    assert_int_equal(sp.n_lower + sp.n_higher, 0);
    assert_int_equal(find(out, 16), 0);
}

/* A thin code ring (radii 8 .. 10: piece-sized, but too small for a
 * CLR) inside an outer ring is no piece of a faint outer ring; alone, it
 * is one. */
static void test_code_ring_marks_nothing(void **state)
{
    rl_clr cand[16];
    rl_box outer, code;
    int first;
    (void)state;
    memset(px, 220, sizeof px);
    ring(100, 24, 30, 20, &outer);
    ring(100, 8, 10, 20, &code);
    label_and_mark(cand, &first);
    assert_int_equal(first, 1);
    assert_true(has_box(cand, first, &outer));
    assert_int_equal(sp.n_lower + sp.n_higher, 0);
    memset(px, 220, sizeof px);
    ring(100, 8, 10, 20, &code);
    label_and_mark(cand, &first);
    assert_int_equal(first, 0);
    assert_int_equal(sp.n_higher, 1);
}

/* The tiles marked around a piece: its box grown by half its size, within
 * the frame. The arc above y = c of a ring about (c, c), radii 24 .. 30,
 * has the box c - 29 .. c + 29 by c - 30 .. c - 1 (at y = c - 1 the ring
 * reaches (x - c)^2 <= 899, 29 px either side): 59 wide, grown by 29,
 * tiles (c - 58) / 16 .. (c + 58) / 16 by (c - 59) / 16 .. (c + 28) / 16,
 * clipped to 0 .. 12; 1.15 x 128 = 147 there, 0 elsewhere. */
static void test_piece_tiles_stay_in_the_frame(void **state)
{
    static const int centres[] = {35, 165};
    rl_clr cand[16];
    rl_box ring_box;
    size_t k;
    int first, tx, ty;
    (void)state;
    for (k = 0; k < 2; k++) {
        int c = centres[k];
        int tx0 = c - 58 < 0 ? 0 : (c - 58) / TILE, tx1 = (c + 58) / TILE > NT - 1 ? NT - 1 : (c + 58) / TILE;
        int ty0 = c - 59 < 0 ? 0 : (c - 59) / TILE, ty1 = (c + 28) / TILE;
        faint_ring_at(c, &ring_box);
        label_and_mark(cand, &first);
        assert_int_equal(sp.n_higher, 1);
        for (ty = 0; ty < NT; ty++)
            for (tx = 0; tx < NT; tx++) {
                int in = tx >= tx0 && tx <= tx1 && ty >= ty0 && ty <= ty1;
                if (sp.higher[ty * NT + tx] != (in ? 147 : 0))
                    fail_msg("ring at %d: tile (%d, %d) %d", c, tx, ty, sp.higher[ty * NT + tx]);
            }
    }
}

/* The faint ring of the test above, found again where it was read as an
 * unidentified candidate, or where a landmark was identified: not new. */
static void test_ring_read_before_is_not_new(void **state)
{
    rl_clr cand[16], out[16];
    rl_box ring_box;
    rl_detection d;
    int first;
    (void)state;
    faint_ring(&ring_box);
    label_and_mark(cand, &first);
    assert_int_equal(find(out, 16), 1); /* nothing read yet: new */
    memset(&d, 0, sizeof d);
    d.box = ring_box;
    d.u = 100;
    d.v = 100;
    d.radius = 30;
    assert_true(rl_result_add_unidentified(&res, &d));
    assert_int_equal(find(out, 16), 0);
    rl_result_clear(&res, S, S);
    d.id = 5;
    assert_true(rl_result_add_landmark(&res, &d));
    assert_int_equal(find(out, 16), 0);
}

/* Inside a candidate read before (radius 40 about (100, 100)), the faint
 * ring (30) is its code ring: not new; 20 px off that centre (more than
 * 0.3 of its radius), it is. */
static void test_code_ring_of_a_candidate_is_not_new(void **state)
{
    rl_clr cand[16], out[16];
    rl_box ring_box;
    rl_detection d;
    int first;
    (void)state;
    faint_ring(&ring_box);
    label_and_mark(cand, &first);
    memset(&d, 0, sizeof d);
    d.id = -1;
    d.u = 100;
    d.v = 100;
    d.radius = 40;
    d.box.x0 = d.box.y0 = 60;
    d.box.x1 = d.box.y1 = 140;
    assert_true(rl_result_add_unidentified(&res, &d));
    assert_int_equal(find(out, 16), 0);
    rl_result_clear(&res, S, S);
    d.u = 120;
    d.box.x0 = 80;
    d.box.x1 = 160;
    assert_true(rl_result_add_unidentified(&res, &d));
    assert_int_equal(find(out, 16), 1);
}

static void test_no_room_is_counted(void **state)
{
    rl_clr cand[16], out[1];
    rl_box ring_box;
    int first, x, y;
    (void)state;
    memset(px, 220, sizeof px);
    for (y = 0; y < S; y++)
        for (x = 40; x < 80; x++)
            px[y * S + x] = 110;
    ring(110, 24, 30, 20, &ring_box);
    label_and_mark(cand, &first);
    assert_int_equal(find(out, 0), 0);
    assert_int_equal(res.dropped.candidates, 1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ring_beside_panel_comes_apart),
        cmocka_unit_test(test_faint_ring_is_whole_nearer_the_paper),
        cmocka_unit_test(test_ring_alone_marks_nothing),
        cmocka_unit_test(test_code_ring_marks_nothing),
        cmocka_unit_test(test_piece_tiles_stay_in_the_frame),
        cmocka_unit_test(test_ring_read_before_is_not_new),
        cmocka_unit_test(test_code_ring_of_a_candidate_is_not_new),
        cmocka_unit_test(test_no_room_is_counted),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
