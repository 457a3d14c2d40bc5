/* Ellipses: the conic fit recovers ellipses drawn from their equation (a
 * whole outline and the half a border leaves), a profile gathered as a
 * circle or an ellipse holds what a brute-force count over every pixel
 * finds, and the recognizer
 * identifies a landmark seen as an ellipse and cut by the border, drawn
 * here pixel by pixel from the family's rings (not by the templates). */
#include "rl_test.h"
#include <math.h>
#include "rl_ellipse.h"
#include "rl_profile.h"
#include "rl_recog.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* Points of the ellipse with centre (cx, cy), semi-axes a >= b, major
 * axis at angle phi, at parameters t0 .. t1. */
static int ellipse_points(double cx, double cy, double a, double b, double phi, double t0,
                          double t1, int n, double *x, double *y)
{
    int i;
    for (i = 0; i < n; i++) {
        double t = t0 + (t1 - t0) * i / (n - 1), u = a * cos(t), v = b * sin(t);
        x[i] = cx + u * cos(phi) - v * sin(phi);
        y[i] = cy + u * sin(phi) + v * cos(phi);
    }
    return n;
}

static void check_fit(double t0, double t1)
{
    double x[24], y[24];
    rl_ellipse e;
    int n = ellipse_points(40.0, 30.0, 26.0, 22.1, 0.6, t0, t1, 24, x, y);
    /* the guess: a circle somewhere near, as the edge fit gives */
    assert_int_equal(rl_ellipse_fit(x, y, n, 42.0, 29.0, 23.0, &e), 1);
    assert_true(fabs(e.cx - 40.0) < 1e-6);
    assert_true(fabs(e.cy - 30.0) < 1e-6);
    assert_true(fabs(e.r - sqrt(26.0 * 22.1)) < 1e-6);
    assert_true(fabs(rl_ellipse_aspect(&e.shape) - 22.1 / 26.0) < 1e-6);
    /* the shape's normalized radius of an outline point is e.r */
    {
        double dx = x[5] - e.cx, dy = y[5] - e.cy;
        double rho = sqrt(e.shape.a * dx * dx + 2 * e.shape.b * dx * dy + e.shape.c * dy * dy);
        assert_true(fabs(rho - e.r) < 1e-6);
    }
}

static void test_fit_whole_outline(void **state)
{
    (void)state;
    check_fit(0.0, 2 * M_PI * 23.0 / 24.0);
}

static void test_fit_half_outline(void **state)
{
    (void)state;
    check_fit(-0.5 * M_PI, 0.5 * M_PI); /* the side a left border leaves */
}

static void test_fit_refuses_what_is_no_ellipse(void **state)
{
    double x[8] = {0}, y[8] = {0};
    rl_ellipse e;
    int i;
    (void)state;
    assert_int_equal(rl_ellipse_fit(x, y, 5, 0, 0, 10, &e), 0); /* too few points */
    for (i = 0; i < 8; i++) { /* a hyperbola x^2 - y^2 = 100 */
        double t = -1.0 + 2.0 * i / 7;
        x[i] = 10 * cosh(t) * (i % 2 ? 1 : -1);
        y[i] = 10 * sinh(t);
    }
    assert_int_equal(rl_ellipse_fit(x, y, 8, 0, 0, 10, &e), 0);
    for (i = 0; i < 8; i++) { /* a line */
        x[i] = i;
        y[i] = 2 * i;
    }
    assert_int_equal(rl_ellipse_fit(x, y, 8, 3, 6, 10, &e), 0);
    assert_true(fabs(rl_ellipse_aspect(&(rl_shape){1, 0, 1}) - 1.0) < 1e-12);
}

#define W 320
#define H 240
static uint8_t frame[W * H];

static rl_tone tone;

/* Every pixel of the frame tested against the shape's normalized radius
 * in double precision: the profile's bins as the formula defines them,
 * the darkness of light through the tone curve written out (pow), and the
 * plane's share of the spread by least squares on (1, x, y) solved by
 * Cramer's rule (0 when the disk reaches past the frame). */
static void brute_profile(double cx, double cy, double r, const rl_shape *sh, rl_profile *p)
{
    double ext = RL_PROFILE_EXTENT * r, m[3][3] = {{0}}, b[3] = {0}, ss = 0, sv = 0;
    int x, y, k, i, j, cut = 0;
    memset(p, 0, sizeof *p);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            double dx = x - cx, dy = y - cy;
            double rho = sqrt(sh->a * dx * dx + 2 * sh->b * dx * dy + sh->c * dy * dy);
            double v = RL_TONE_MAX - floor(RL_TONE_MAX * pow(frame[y * W + x] / 255.0, 2.2) + 0.5);
            double f[3] = {1, dx, dy};
            if (rho >= ext)
                continue;
            k = (int)(rho / ext * RL_PROFILE_BINS);
            p->n[k] += 1;
            p->sx[k] += v;
            p->sxx += v * v;
            p->total += 1;
            for (i = 0; i < 3; i++) {
                for (j = 0; j < 3; j++)
                    m[i][j] += f[i] * f[j];
                b[i] += f[i] * v;
            }
            ss += v * v;
            sv += v;
        }
    /* any of the disk past the frame: the gather leaves the plane out there */
    for (y = -H; y < 2 * H && !cut; y++)
        for (x = -W; x < 2 * W && !cut; x++) {
            double dx = x - cx, dy = y - cy;
            cut = (x < 0 || y < 0 || x >= W || y >= H) &&
                  sqrt(sh->a * dx * dx + 2 * sh->b * dx * dy + sh->c * dy * dy) < ext;
        }
    if (!cut && p->total > 16) {
        /* explained by (1, x, y) less explained by 1 alone */
        double d = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                   m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                   m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]), c[3];
        for (i = 0; i < 3; i++) {
            double a[3][3];
            memcpy(a, m, sizeof a);
            for (j = 0; j < 3; j++)
                a[j][i] = b[j];
            c[i] = (a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                    a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                    a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0])) / d;
        }
        p->plane = c[0] * b[0] + c[1] * b[1] + c[2] * b[2] - sv * sv / p->total;
    }
    (void)ss;
}

static void test_profile_matches_brute_force(void **state)
{
    uint64_t rng = 7;
    int trial, k;
    (void)state;
    for (k = 0; k < W * H; k++) {
        rng = rng * 6364136223846793005ull + 1442695040888963407ull;
        /* noise on a slope: a plane for the gather to find */
        frame[k] = (uint8_t)((rng >> 57) + (k % W) / 3 + (k / W) / 4);
    }
    for (trial = 0; trial < 40; trial++) {
        /* circles and ellipses, whole and cut by every side */
        double cx = 5.0 + trial * 7.63, cy = 3.0 + trial * 5.91, r = 9.0 + trial * 0.77;
        rl_shape sh = trial % 2 ? rl_shape_from_moments(1.0, 0.15 * (trial % 5), 0.7)
                                : rl_shape_circle();
        rl_profile got, want;
        double off = 0;
        rl_tone_init(&tone, 2.2);
        if (trial % 2)
            rl_profile_gather_shaped(&(rl_image){W, H, W, frame}, &tone, cx, cy, r, &sh, &got);
        else
            rl_profile_gather(&(rl_image){W, H, W, frame}, &tone, cx, cy, r, &got);
        brute_profile(cx, cy, r, &sh, &want);
        /* a pixel whose radius lies within rounding of a bin's edge may
         * fall either side of it: a few at most */
        for (k = 0; k < RL_PROFILE_BINS; k++)
            off += fabs(got.n[k] - want.n[k]);
        if (off > 4 || fabs(got.total - want.total) > 2)
            fail_msg("trial %d: %.0f pixels binned differently, %.0f of %.0f gathered", trial, off,
                     got.total, want.total);
        assert_true(fabs(got.sxx - want.sxx) <= 2.0 * RL_TONE_MAX * RL_TONE_MAX);
        /* the plane: the same but for a few rim pixels' worth */
        if (fabs(got.plane - want.plane) > 0.01 * want.plane + 2e4)
            fail_msg("trial %d: plane %.0f, by least squares %.0f", trial, got.plane, want.plane);
    }
}

/* Landmark id as an ellipse (semi-axes a >= b, major axis at phi) on paper
 * 215 with ink 30, 4 x 4 samples a pixel, its white sheet 1.45 a across;
 * the rings from rl_family_dark_at. */
static void draw_ellipse(int id, double cx, double cy, double a, double b, double phi)
{
    rl_family f = {5};
    int x, y, i, j;
    for (y = (int)(cy - 1.5 * a); y <= (int)(cy + 1.5 * a) + 1; y++)
        for (x = (int)(cx - 1.5 * a); x <= (int)(cx + 1.5 * a) + 1; x++) {
            double dark = 0;
            if (x < 0 || y < 0 || x >= W || y >= H)
                continue;
            for (j = 0; j < 4; j++)
                for (i = 0; i < 4; i++) {
                    double dx = x + (i + 0.5) / 4 - 0.5 - cx, dy = y + (j + 0.5) / 4 - 0.5 - cy;
                    double u = dx * cos(phi) + dy * sin(phi), v = -dx * sin(phi) + dy * cos(phi);
                    double rho = sqrt(u * u / (a * a) + v * v / (b * b));
                    dark += rho <= 1.0 ? rl_family_dark_at(&f, id, rho) : 0;
                }
            frame[y * W + x] = (uint8_t)lround(215 - (215 - 30) * dark / 16);
        }
}

static void test_cut_ellipse_identified(void **state)
{
    /* two round landmarks for the frame's size, and id 22 seen as an
     * ellipse of aspect 0.86 with its centre 9 px inside the left border
     * (about 0.64 of it visible) */
    rl_recog_config cfg;
    rl_image img = rl_image_view(W, H, W, frame);
    static rl_result res;
    rl_recog *rec;
    void *mem;
    size_t n;
    int j, found = 0;
    (void)state;
    memset(frame, 215, sizeof frame);
    draw_ellipse(9, 150.0, 70.0, 25.0, 25.0, 0.0);
    draw_ellipse(26, 230.0, 160.0, 25.0, 25.0, 0.0);
    draw_ellipse(22, 9.0, 130.0, 26.0, 22.4, 1.2);
    rl_recog_defaults(&cfg);
    n = rl_recog_workspace_size(W, H, &cfg);
    mem = malloc(n);
    assert_non_null(mem);
    assert_int_equal(rl_recog_init(&rec, &cfg, W, H, mem, n), RL_OK);
    assert_int_equal(rl_recog_run(rec, &img, &res), RL_OK);
    for (j = 0; j < res.n_landmarks; j++) {
        const rl_detection *d = &res.landmarks[j];
        if (d->u > 40)
            continue;
        assert_int_equal(d->id, 22);
        assert_int_equal(d->pass, RL_PASS_LOCAL);
        assert_false(d->complete);
        if (hypot(d->u - 9.0, d->v - 130.0) > 1.5)
            fail_msg("centre (%.2f, %.2f), drawn at (9, 130)", d->u, d->v);
        found = 1;
    }
    assert_true(found);
    free(mem);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_fit_whole_outline),
        cmocka_unit_test(test_fit_half_outline),
        cmocka_unit_test(test_fit_refuses_what_is_no_ellipse),
        cmocka_unit_test(test_profile_matches_brute_force),
        cmocka_unit_test(test_cut_ellipse_identified),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
