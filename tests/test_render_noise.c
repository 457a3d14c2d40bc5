/* The renderer's looked-up value noise (render_noise, made once a frame,
 * in the memory of the frame before where it has the room)
 * against the hashed noise it stands for, the oracle: bit for bit at
 * random points in and around its rectangle (negative coordinates, lattice
 * points, the rectangle's edges), and its "over a level" answer, which
 * skips the mix where no corner of the cell is over the level, the same as
 * the hashed noise compared with the level. The renderer's frames are the
 * suite's truth; this keeps a change to the table from drifting them. */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "rl_test.h"

#include "render_random.h"

static uint64_t rng = 0x2545F4914F6CDD1Dull;

static double uniform(double a, double b)
{
    rng ^= rng >> 12;
    rng ^= rng << 25;
    rng ^= rng >> 27;
    return a + (b - a) * (double)((rng * 0x2545F4914F6CDD1Dull) >> 11) / 9007199254740992.0;
}

static int same_bits(double a, double b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

/* the table over [x0, x1] x [y0, y1], made in t (zeroed or made before),
 * sampled over a rectangle 20% larger */
static void made_matches_hash(render_noise *tp, double x0, double y0, double x1, double y1)
{
    render_noise t;
    int k, differ = 0, over_differ = 0, inside = 0, near = 0;
    double mx = 0.1 * (x1 - x0), my = 0.1 * (y1 - y0);
    assert_int_equal(render_random_noise_make(tp, x0, y0, x1, y1), 0);
    assert_non_null(tp->v);
    t = *tp;
    for (k = 0; k < 400000; k++) {
        double x = uniform(x0 - mx, x1 + mx), y = uniform(y0 - my, y1 + my), level = k % 2 ? 0.93 : 0.5, h;
        if (k % 7 == 0)
            x = floor(x); /* on a lattice line */
        if (k % 11 == 0)
            y = floor(y);
        h = render_random_vnoise(x, y);
        inside += x >= x0 && x <= x1 && y >= y0 && y <= y1;
        near += fabs(h - level) < 0.01;
        differ += !same_bits(render_random_vnoise_in(&t, x, y), h);
        over_differ += render_random_vnoise_over(&t, x, y, level) != (h > level);
    }
    printf("[%g, %g] x [%g, %g]: %d of 400000 points inside, %d within 0.01 of the level; %d values differ, %d "
           "answers over the level differ\n",
           x0, x1, y0, y1, inside, near, differ, over_differ);
    assert_true(inside > 250000); /* the table was looked up (a 69% share) */
    assert_true(near > 1000);     /* the level's neighbourhood was met */
    assert_int_equal(differ, 0);
    assert_int_equal(over_differ, 0);
}

static void table_matches_hash(double x0, double y0, double x1, double y1)
{
    render_noise t = {0};
    made_matches_hash(&t, x0, y0, x1, y1);
    render_random_noise_free(&t);
}

static void positive_rectangle(void **state)
{
    (void)state;
    table_matches_hash(3.5, 7.25, 303.5, 207.25);
}

static void across_zero(void **state)
{
    (void)state;
    table_matches_hash(-150.75, -99.5, 149.25, 100.5);
}

/* at the renderer's finest scale, a view some metres from the origin */
static void far_from_origin(void **state)
{
    (void)state;
    table_matches_hash(-3000.0, 2100.0, -2400.0, 2600.0);
}

/* a table made again, frame after frame: in its own memory where it has
 * the room (a smaller rectangle), in more where not, each the hash's */
static void made_again(void **state)
{
    render_noise t = {0};
    const double *first;
    (void)state;
    made_matches_hash(&t, -3000.0, 2100.0, -2400.0, 2600.0);
    first = t.v;
    made_matches_hash(&t, 3.5, 7.25, 303.5, 207.25);
    assert_ptr_equal(t.v, first);
    made_matches_hash(&t, -3000.5, 2099.5, -2300.0, 2700.0);
    made_matches_hash(&t, -150.75, -99.5, 149.25, 100.5);
    render_random_noise_free(&t);
    assert_null(t.v);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(positive_rectangle),
        cmocka_unit_test(across_zero),
        cmocka_unit_test(far_from_origin),
        cmocka_unit_test(made_again),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
