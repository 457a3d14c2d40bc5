/* The planner against a hand calculation for the paper's set-up:
 * 640x480, 70 degrees horizontal field of view, 1.87 m to the ceiling. */
#include "rl_test.h"
#include "rl_plan.h"
#include <math.h>

/* Independent of rl_plan: fewest grid points of pitch p inside a w x h
 * rectangle, brute force over positions and headings. */
static int fewest_in_view(double p, double w, double h, int steps, double deg_step)
{
    int best = 1000, ix, iy, i, j;
    double a;
    for (a = 0; a < 90.0; a += deg_step) {
        double c = cos(a * M_PI / 180), s = sin(a * M_PI / 180);
        for (ix = 0; ix < steps; ix++)
            for (iy = 0; iy < steps; iy++) {
                double ox = p * ix / steps, oy = p * iy / steps;
                int n = 0;
                for (i = -12; i <= 12; i++)
                    for (j = -12; j <= 12; j++) {
                        double dx = i * p - ox, dy = j * p - oy;
                        if (fabs(c * dx + s * dy) <= w / 2 && fabs(-s * dx + c * dy) <= h / 2)
                            n++;
                    }
                if (n < best)
                    best = n;
            }
    }
    return best;
}

static void test_paper_setup(void **state)
{
    rl_plan_input in;
    rl_plan_result out;
    /* hand calculation */
    double fx = 320.0 / tan(35.0 * M_PI / 180.0);  /* 457.01 px */
    double ppm = fx / 1.87;                          /* 244.39 px/m */
    double zone1 = 0.8 * (1.0 - sqrt(4.0 / 5.0));    /* ring5 zone 1 width / R = 0.08446 */
    double rpx = 2.0 / zone1;                        /* R for a 2 px zone 1: 23.68 px */
    double dmin = 2.0 * rpx / ppm;                   /* 0.1938 m */
    double d = ceil(dmin / 0.005) * 0.005;           /* 0.195 m */
    double R = d / 2 * ppm;
    double uw = (640 - 2 * (R + 1)) / ppm, uh = (480 - 2 * (R + 1)) / ppm;
    (void)state;
    assert_true(fabs(d - 0.195) < 1e-9);

    rl_plan_defaults(&in);
    in.landmarks = 30;
    in.fx = fx;
    in.distance = 1.87;
    assert_int_equal(rl_plan_compute(&in, &out), RL_OK);
    assert_int_equal(out.bits, 5);
    assert_true(fabs(out.px_per_m - ppm) < 1e-9);
    assert_true(fabs(out.view_w - 640 / ppm) < 1e-9);
    assert_true(fabs(out.diameter_min - dmin) < 1e-9);
    assert_true(fabs(out.diameter - d) < 1e-9);
    assert_true(fabs(out.ring_px[0] - 0.2 * R) < 1e-9);
    assert_true(fabs(out.ring_px[1] - zone1 * R) < 1e-9);
    assert_true(out.ring_px[1] >= 2.0);
    assert_true(fabs(out.ring_px[5] - 0.8 * sqrt(1.0 / 5) * R) < 1e-9);

    /* A disk of radius rho = min(uw, uh) / 2 fits in the view at any
     * heading, and every disk of radius >= p holds two points of a grid of
     * pitch p: so p = rho is always enough, a lower bound on pitch_max. */
    assert_true(out.pitch_max >= fmin(uw, uh) / 2);
    assert_true(out.pitch <= 0.95 * out.pitch_max + 1e-9);
    assert_true(out.pitch >= 0.95 * out.pitch_max - 0.005 - 1e-9);
    /* the recommendation holds under a finer independent search ... */
    assert_true(fewest_in_view(out.pitch, uw, uh, 40, 0.5) >= 2);
    /* ... and is not needlessly dense: 15% above the maximum fails */
    assert_true(fewest_in_view(out.pitch_max * 1.15, uw, uh, 40, 0.5) < 2);
}

static void test_family_choice_and_limits(void **state)
{
    rl_plan_input in;
    rl_plan_result out;
    (void)state;
    rl_plan_defaults(&in);
    in.fx = 457.0;
    in.distance = 1.87;
    in.landmarks = 14;
    assert_int_equal(rl_plan_compute(&in, &out), RL_OK);
    assert_int_equal(out.bits, 4);
    in.landmarks = 15;
    assert_int_equal(rl_plan_compute(&in, &out), RL_OK);
    assert_int_equal(out.bits, 5);
    in.landmarks = 31;
    assert_int_equal(rl_plan_compute(&in, &out), RL_ERANGE); /* ring6 at 2 px needs > A4 */
    assert_int_equal(out.bits, 6);
    assert_true(out.diameter > 0.21);
    in.max_diameter = 0.297;
    assert_int_equal(rl_plan_compute(&in, &out), RL_OK);
    in.landmarks = 255;
    out.bits = 0;
    assert_int_equal(rl_plan_compute(&in, &out), RL_ERANGE);
    in.landmarks = 0;
    assert_int_equal(rl_plan_compute(&in, &out), RL_EINVAL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_paper_setup),
        cmocka_unit_test(test_family_choice_and_limits),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
