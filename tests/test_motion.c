/* rl_motion: which way a landmark moved, from its rings' edges. Landmarks
 * drawn here from the family's zone radii (rl_templates_value_at, a
 * Gaussian focus blur), smeared by a straight motion of known direction
 * and length (the mean of the landmark drawn at every instant of the
 * exposure, as light adds on a sensor): the sharpest axis must be the one
 * across the motion, the ratio low; a still landmark, at any sub-pixel
 * centre, must read as still (over RL_TWINS_MOVED, the bar rl_twins reads
 * its twins across a motion under), or, drawn slanted (which smooths the
 * edges along its major axis too), show an outer edge whose ellipse is
 * too flat for the moved read (RL_TWINS_MOVED_ASPECT) while a moved round
 * one's is not. rl_profile_gather_axis against the wedge counted here
 * pixel by pixel. */
#include "rl_test.h"
#include <math.h>
#include <string.h>
#include "draw_slanted.h"
#include "rl_edge.h"
#include "rl_ellipse.h"
#include "rl_motion.h"
#include "rl_profile.h"
#include "rl_templates.h"
#include "rl_tone.h"
#include "rl_twins.h"

#define W 120
#define H 120
#define STEPS 24

static uint8_t pix[W * H];

/* id drawn at (cx, cy), radius r px, focus sigma (share of r), moved by
 * (mx, my) px during the exposure about its centre; paper 220, ink 30. */
static void draw(rl_image *img, int id, double cx, double cy, double r, double sigma, double mx, double my)
{
    rl_family fam = {5};
    int x, y, s;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            double dark = 0;
            for (s = 0; s < STEPS; s++) {
                double t = (s + 0.5) / STEPS - 0.5, dx = x - (cx + t * mx), dy = y - (cy + t * my);
                dark += rl_templates_value_at(&fam, id, sqrt(dx * dx + dy * dy) / r, sigma);
            }
            pix[y * W + x] = (uint8_t)lround(220 - 190 * dark / STEPS);
        }
    img->width = W;
    img->height = H;
    img->stride = W;
    img->data = pix;
}

/* The aspect of the ellipse fitted to the outer edge about (cx, cy),
 * read as linear light (nothing counts as a lamp's light); 0 when none. */
static double edge_aspect(const rl_image *img, double cx, double cy, double r)
{
    double ex[RL_EDGE_RAYS], ey[RL_EDGE_RAYS];
    rl_tone tone;
    rl_ellipse e;
    int n;
    rl_tone_init(&tone, 1.0);
    n = rl_edge_points(img, &tone, 255, cx, cy, r, ex, ey);
    return rl_ellipse_fit(ex, ey, n, cx, cy, r, &e) ? rl_ellipse_aspect(&e.shape) : 0.0;
}

/* A still landmark seen slanted at 0.85 measures as moved at 12-16 px
 * (the reviewer's probe: ratio 0.775-0.793), so the twins must not read
 * it across a motion: its edge's ellipse is flatter than
 * RL_TWINS_MOVED_ASPECT. This checks the measures and the constant that
 * rl_twins.c's guard compares; test_twins_slanted checks the guard's call
 * (moved_keeps refusing such a landmark its id would pass along the axis).
 * A round one moved 5 px (the moving frames' motion) keeps a round edge
 * and is read across its motion. */
static void test_slanted_still_not_moved(void **state)
{
    static const double radii[] = {12, 14, 16};
    rl_image img;
    rl_motion m;
    size_t i;
    (void)state;
    for (i = 0; i < sizeof radii / sizeof radii[0]; i++) {
        double r = radii[i];
        img = draw_slanted(pix, W, H, 23, 60.3, 59.6, r, 0.03, 0.85);
        assert_true(rl_motion_measure(&img, 60.3, 59.6, r, &m));
        /* what the moved read would take: it must be refused */
        assert_false(m.ratio < RL_TWINS_MOVED && edge_aspect(&img, 60.3, 59.6, r) >= RL_TWINS_MOVED_ASPECT);
        draw(&img, 23, 60.3, 59.6, r, 0.03, 5, 0);
        assert_true(rl_motion_measure(&img, 60.3, 59.6, r, &m));
        assert_true(m.ratio < RL_TWINS_MOVED);
        assert_true(edge_aspect(&img, 60.3, 59.6, r) >= RL_TWINS_MOVED_ASPECT);
    }
}

static void test_still_reads_still(void **state)
{
    rl_image img;
    rl_motion m;
    double off;
    (void)state;
    for (off = 0; off < 1; off += 0.25) {
        draw(&img, 23, 60 + off, 60 + off / 2, 24, 0.03, 0, 0);
        assert_true(rl_motion_measure(&img, 60 + off, 60 + off / 2, 24, &m));
        assert_true(m.ratio > RL_TWINS_MOVED);
    }
}

static void test_axis_across_the_motion(void **state)
{
    /* motion direction (degrees) and the axis across it: 0 along x, 1 at
     * 45 degrees towards +y, 2 along y, 3 at 135 */
    static const struct {
        double deg;
        int axis;
    } cases[] = {{0, 2}, {90, 0}, {45, 3}, {135, 1}, {180, 2}, {-45, 1}};
    rl_image img;
    rl_motion m;
    size_t i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        double a = cases[i].deg * 3.14159265358979 / 180, len = 5;
        draw(&img, 12, 60.3, 59.6, 24, 0.03, len * cos(a), len * sin(a));
        assert_true(rl_motion_measure(&img, 60.3, 59.6, 24, &m));
        assert_int_equal(m.axis, cases[i].axis);
        assert_true(m.ratio < RL_TWINS_MOVED);
    }
}

static void test_cut_too_far(void **state)
{
    rl_image img;
    rl_motion m;
    (void)state;
    draw(&img, 23, 60, 60, 24, 0.03, 0, 0);
    /* the centre 20 px past the left border: the axis along x has only
     * its far side's few pixels in the frame */
    assert_false(rl_motion_measure(&img, -20, 60, 24, &m));
}

static void test_axis_gather_is_the_wedge(void **state)
{
    rl_image img;
    rl_tone tone;
    rl_profile p;
    int a, x, y;
    (void)state;
    draw(&img, 23, 60, 60, 24, 0.03, 0, 0);
    rl_tone_init(&tone, 1.0);
    for (a = 0; a < RL_MOTION_AXES; a++) {
        double ext = RL_PROFILE_EXTENT * 24, n = 0;
        rl_profile_gather_axis(&img, &tone, 60.2, 59.9, 24, a, &p);
        for (y = 0; y < H; y++)
            for (x = 0; x < W; x++) {
                double dx = x - 60.2, dy = y - 59.9;
                /* within 22.5 degrees of the axis, either side */
                double ang = atan2(dy, dx) - a * 3.14159265358979 / 4;
                double c = fabs(cos(ang)), s = fabs(sin(ang));
                if (sqrt(dx * dx + dy * dy) < ext && s <= tan(3.14159265358979 / 8) * c)
                    n++;
            }
        assert_true(fabs(p.total - n) <= 2);
        /* a quarter of the disk, give or take the grid */
        assert_true(fabs(p.total - 3.14159265358979 * ext * ext / 4) < 0.05 * p.total);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_still_reads_still),
        cmocka_unit_test(test_axis_across_the_motion),
        cmocka_unit_test(test_cut_too_far),
        cmocka_unit_test(test_slanted_still_not_moved),
        cmocka_unit_test(test_axis_gather_is_the_wedge),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
