/* The planner against a hand calculation for the paper's set-up:
 * 640x480, 70 degrees horizontal field of view, 1.87 m to the ceiling. */
#include "rl_test.h"
#include "rl_plan.h"
#include "rl_site_plan.h"
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

/* ---- rl_site_plan against brute force ---- */

#define SITE_MAX 400
static int site_ids[SITE_MAX];

/* Independent of rl_site_plan: the grid points whose whole landmark a
 * footprint holds, and the fewest ids that differ under any other grid
 * motion (every quarter turn and every shift that keeps a point on the
 * site), off-site points counting as different. */
static int brute_view(const rl_site_plan_input *in, const rl_site_plan_result *r, double cx, double cy, double th,
                      int *vx, int *vy)
{
    double hw = 0.5 * (in->view_w - in->diameter), hh = 0.5 * (in->view_h - in->diameter);
    int i, j, n = 0;
    for (j = 0; j < r->rows; j++)
        for (i = 0; i < r->cols; i++) {
            double dx = r->x0 + i * in->pitch - cx, dy = r->y0 + j * in->pitch - cy;
            if (fabs(cos(th) * dx + sin(th) * dy) <= hw && fabs(-sin(th) * dx + cos(th) * dy) <= hh) {
                vx[n] = i;
                vy[n] = j;
                n++;
            }
        }
    return n;
}

static int brute_fewest_differences(const rl_site_plan_result *r, const int *vx, const int *vy, int n)
{
    int k, tx, ty, p, fewest = 1000;
    for (k = 0; k < 4; k++)
        for (ty = -2 * r->rows; ty <= 2 * r->rows; ty++)
            for (tx = -2 * r->cols; tx <= 2 * r->cols; tx++) {
                int diff = 0, on = 0;
                if (k == 0 && tx == 0 && ty == 0)
                    continue;
                for (p = 0; p < n && diff < fewest; p++) {
                    /* turn by k quarters about the origin, then shift */
                    int x = vx[p], y = vy[p], q, t;
                    for (q = 0; q < k; q++)
                        t = x, x = -y, y = t;
                    x += tx;
                    y += ty;
                    if (x < 0 || y < 0 || x >= r->cols || y >= r->rows) {
                        diff++;
                        continue;
                    }
                    on++;
                    diff += site_ids[y * r->cols + x] != site_ids[vy[p] * r->cols + vx[p]];
                }
                if (on > 0 && diff < fewest)
                    fewest = diff;
            }
    return fewest;
}

static void test_site_views_unique(void **state)
{
    rl_site_plan_input in;
    rl_site_plan_result r;
    uint64_t s = 99;
    int k, checked = 0, i;
    (void)state;
    rl_site_plan_defaults(&in);
    in.width = 9;
    in.height = 7;
    in.pitch = 0.61;
    in.view_w = 2.62;
    in.view_h = 1.96;
    in.diameter = 0.195;
    in.n_ids = 30;
    in.bits = 5;
    in.seed = 4;
    assert_int_equal(rl_site_plan(&in, site_ids, SITE_MAX, &r), RL_OK);
    assert_int_equal(r.cols, 14);
    assert_int_equal(r.rows, 11);
    assert_int_equal(r.k_achieved, 3);
    assert_int_equal(r.failing, 0);
    for (i = 0; i < r.cols * r.rows; i++) {
        assert_true(site_ids[i] >= 1 && site_ids[i] <= 30);
    }
    /* views at random places and headings, none on the planner's own sampling */
    for (k = 0; k < 600; k++) {
        int vx[64], vy[64], n;
        double cx, cy, th;
        s ^= s << 13, s ^= s >> 7, s ^= s << 17;
        cx = in.clearance + (in.width - 2 * in.clearance) * (double)(s >> 11) / 9007199254740992.0;
        s ^= s << 13, s ^= s >> 7, s ^= s << 17;
        cy = in.clearance + (in.height - 2 * in.clearance) * (double)(s >> 11) / 9007199254740992.0;
        s ^= s << 13, s ^= s >> 7, s ^= s << 17;
        th = M_PI * (double)(s >> 11) / 9007199254740992.0;
        n = brute_view(&in, &r, cx, cy, th, vx, vy);
        if (n < r.k_achieved)
            continue;
        assert_true(brute_fewest_differences(&r, vx, vy, n) >= 2);
        checked++;
    }
    assert_true(checked > 500);
    {
        /* the oracle can fail: a 5 x 5 block copied elsewhere makes a view over it not unique */
        int vx[64], vy[64], n, a, b;
        for (b = 0; b < 5; b++)
            for (a = 0; a < 5; a++)
                site_ids[(b + 5) * r.cols + a + 8] = site_ids[b * r.cols + a];
        n = brute_view(&in, &r, r.x0 + 2 * in.pitch, r.y0 + 2 * in.pitch, 0.1, vx, vy);
        assert_true(n >= 3);
        assert_true(brute_fewest_differences(&r, vx, vy, n) < 2);
    }
    /* even parity only: every id's code has an even number of black zones */
    in.even_parity = 1;
    {
        rl_err e = rl_site_plan(&in, site_ids, SITE_MAX, &r);
        assert_int_equal(e, r.k_achieved > 3 ? RL_ELIMIT : RL_OK);
    }
    for (i = 0; i < r.cols * r.rows; i++) {
        int b, bits = 0;
        for (b = 0; b < 5; b++)
            bits += (site_ids[i] >> b) & 1;
        assert_int_equal(bits % 2, 0);
    }
    /* too small a grid for its ids, and refusals */
    assert_int_equal(rl_site_plan(&in, site_ids, 10, &r), RL_ENOMEM);
    in.pitch = 0;
    assert_int_equal(rl_site_plan(&in, site_ids, SITE_MAX, &r), RL_EINVAL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_paper_setup),
        cmocka_unit_test(test_family_choice_and_limits),
        cmocka_unit_test(test_site_views_unique),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
