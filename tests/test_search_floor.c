/* rl_search_identify_over's floor (issue 43): a whole landmark whose edge
 * fit came out 0.92 of its radius (glare on the outer edge) matches its id
 * at the located circle under the local pass's floor RL_LOCAL_MIN_FIRST,
 * but the search's step out (the radius 1.06 times larger) over it; the
 * floor must let it through to the search, which reads the id. The drawn
 * ring is the truth (rl_raster); a floor applied to the first match alone
 * stops it, and this test fails then. And a candidate is whole for the
 * floor only when its fitted circle is in the frame too (rl_local_whole). */
#include "rl_test.h"
#include <math.h>
#include "rl_local.h"
#include "rl_raster.h"
#include "rl_search.h"

#define S 240
#define PAPER 215
#define INK 30
#define LIGHT 250
static uint8_t px[S * S], dk[S * S];
static rl_polar pol;
static rl_tone tone; /* the drawing is linear in grey: a linear camera */
static uint8_t wsmem[1 << 20];

/* Landmark `id` of radius r at (cx, cy), ink on paper, with noise
 * uniform in +-80 grey levels (a fixed sequence): clean, the first match
 * at 0.92 r scores 0.52-0.88 over the ids, above the floor. */
static rl_image draw(int id, double cx, double cy, double r)
{
    rl_family f = {5};
    rl_image img = rl_image_view(S, S, S, px), d = rl_image_view(S, S, S, dk);
    unsigned seed = 12345u;
    int i;
    assert_int_equal(rl_raster_draw(&f, id, cx, cy, r, NULL, &d, NULL), RL_OK);
    for (i = 0; i < S * S; i++) {
        int v = PAPER - (PAPER - INK) * dk[i] / 255;
        seed = seed * 1103515245u + 12345u;
        v += (int)((seed >> 16) % 161) - 80;
        px[i] = (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : v);
    }
    return img;
}

static rl_match_kept *kept_sums;

static void init_templates(rl_templates *tt)
{
    rl_family f = {5};
    rl_ws ws;
    rl_tone_init(&tone, 1.0);
    rl_ws_init(&ws, wsmem, sizeof wsmem);
    assert_int_equal(rl_templates_init(tt, &ws, &f, NULL, 0), RL_OK);
    assert_int_equal(rl_match_kept_init(&kept_sums, &ws, tt), RL_OK); /* the search's scratch */
}

static void short_fit_read(void **state)
{
    static rl_templates tt;
    const double R = 20.0, cx = 60.3, cy = 59.6;
    const int id = 5;
    rl_image img = draw(id, cx, cy, R);
    rl_match first, m;
    double x = cx, y = cy, r = 0.92 * R;
    (void)state;
    init_templates(&tt);
    /* the first match alone (an infinite floor stops every candidate
     * after the step, *m holding the first match): under the floor */
    assert_int_equal(
        rl_search_identify_over(&tt, &pol, kept_sums, &img, &tone, LIGHT, INFINITY, 0.75, &x, &y, &r, &first), 0);
    printf("first match at 0.92 R: id %d, %.3f\n", first.id, first.score);
    assert_true(first.score < RL_LOCAL_MIN_FIRST);
    assert_true(x == cx && y == cy && r == 0.92 * R); /* the circle unchanged */
    /* the floor: the step out scores over it, so the search runs and reads
     * the id at about the true radius */
    assert_int_equal(
        rl_search_identify_over(&tt, &pol, kept_sums, &img, &tone, LIGHT, RL_LOCAL_MIN_FIRST, 0.75, &x, &y, &r, &m), 1);
    printf("searched: id %d, %.3f, r %.2f (true %d, %.1f)\n", m.id, m.score, r, id, R);
    assert_int_equal(m.id, id);
    assert_true(m.score >= 0.75); /* the local rule's score */
    assert_true(fabs(r - R) < 0.03 * R);
}

/* Whole for the floor: the box's circle and the fitted circle in the
 * frame (hand-placed circles in a 100 x 80 frame). */
static void whole_by_both_circles(void **state)
{
    rl_detection u;
    (void)state;
    memset(&u, 0, sizeof u);
    u.complete = 1;
    assert_true(rl_local_whole(100, 80, &u, 50, 40, 20));
    assert_false(rl_local_whole(100, 80, &u, 85, 40, 20)); /* the box whole, the fitted circle cut */
    assert_false(rl_local_whole(100, 80, &u, 50, 15, 20));
    u.complete = 0;
    assert_false(rl_local_whole(100, 80, &u, 50, 40, 20)); /* the box cut */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(short_fit_read),
        cmocka_unit_test(whole_by_both_circles),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
