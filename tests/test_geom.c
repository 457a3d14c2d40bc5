/* rl_geom: the pixels of a square about a point within an image
 * (rl_geom_square_in, the span rl_motion_measure and
 * rl_profile_gather_axis walk), against hand counts. */
#include "rl_test.h"
#include "rl_geom.h"

static void assert_box(const rl_box *b, int x0, int y0, int x1, int y1)
{
    assert_int_equal(b->x0, x0);
    assert_int_equal(b->y0, y0);
    assert_int_equal(b->x1, x1);
    assert_int_equal(b->y1, y1);
}

static void test_square_inside(void **state)
{
    rl_box b;
    (void)state;
    /* 100.3 +- 10.5: 89.8 .. 110.8, the pixels 90 .. 110; 50 +- 10.5:
     * 39.5 .. 60.5, the pixels 40 .. 60 */
    rl_geom_square_in(640, 480, 100.3, 50.0, 10.5, 1, &b);
    assert_box(&b, 90, 40, 110, 60);
    /* whole pixels on the square's edges are in it */
    rl_geom_square_in(640, 480, 100.0, 50.0, 10.0, 0, &b);
    assert_box(&b, 90, 40, 110, 60);
}

static void test_square_cut_by_the_border(void **state)
{
    rl_box b;
    (void)state;
    /* the header's example: -24.5 .. 44.5 from x 1 (one in), 205.5 .. 274.5 */
    rl_geom_square_in(640, 480, 10.0, 240.0, 34.5, 1, &b);
    assert_box(&b, 1, 206, 44, 274);
    rl_geom_square_in(640, 480, 10.0, 240.0, 34.5, 0, &b);
    assert_box(&b, 0, 206, 44, 274);
    /* past the right and bottom: the last column 639 (638 one in) */
    rl_geom_square_in(640, 480, 630.0, 470.0, 20.0, 0, &b);
    assert_box(&b, 610, 450, 639, 479);
    rl_geom_square_in(640, 480, 630.0, 470.0, 20.0, 1, &b);
    assert_box(&b, 610, 450, 638, 478);
}

static void test_square_outside_is_empty(void **state)
{
    rl_box b;
    (void)state;
    rl_geom_square_in(640, 480, -40.0, 240.0, 24.0, 1, &b);
    assert_true(b.x1 < b.x0);
    rl_geom_square_in(640, 480, 320.0, 700.0, 24.0, 0, &b);
    assert_true(b.y1 < b.y0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_square_inside),
        cmocka_unit_test(test_square_cut_by_the_border),
        cmocka_unit_test(test_square_outside_is_empty),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
