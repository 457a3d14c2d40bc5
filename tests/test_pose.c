/* The pose never leaves as a number that is not one (issue 18): camera
 * models and maps out of their limits are refused, and detections no
 * camera can produce give an error, never a pose of NaN or infinity.
 * The geometry itself is checked against OpenCV in test_locate. */
#include "rl_test.h"
#include <math.h>
#include "rl_calib.h"
#include "rl_map.h"
#include "rl_pose.h"

static rl_calib camera(void)
{
    rl_calib c;
    rl_calib_defaults(&c, 640, 480, 70.0 * 3.14159265358979 / 180.0);
    return c;
}

static void test_camera_limits(void **state)
{
    rl_calib c = camera();
    (void)state;
    assert_int_equal(rl_calib_check(&c), RL_OK);
    c.fx = c.fy = 1e-300; /* accepted once: a NaN pose followed */
    assert_int_equal(rl_calib_check(&c), RL_ERANGE);
    c = camera();
    c.fy = 2e6;
    assert_int_equal(rl_calib_check(&c), RL_ERANGE);
    c = camera();
    c.cx = 1e9;
    assert_int_equal(rl_calib_check(&c), RL_ERANGE);
    c = camera();
    c.k[0] = 1e300;
    assert_int_equal(rl_calib_check(&c), RL_ERANGE);
    c = camera();
    c.width = 100000;
    assert_int_equal(rl_calib_check(&c), RL_ERANGE);
    c = camera();
    c.k[1] = NAN;
    assert_int_equal(rl_calib_check(&c), RL_ERANGE);
}

static rl_map map2(double x1)
{
    static rl_map m;
    memset(&m, 0, sizeof m);
    m.family.bits = 5;
    m.diameter = 0.21;
    m.ceiling_height = 2.75;
    m.count = 2;
    m.lm[0].id = 3;
    m.lm[0].x = 0.0;
    m.lm[1].id = 7;
    m.lm[1].x = x1;
    return m;
}

static void test_map_limits(void **state)
{
    rl_map m = map2(0.61);
    int bad;
    (void)state;
    assert_int_equal(rl_map_check(&m, &bad), RL_OK);
    m = map2(1e300); /* accepted once: "residual": inf followed */
    assert_int_equal(rl_map_check(&m, &bad), RL_ERANGE);
    assert_int_equal(bad, 1);
    m = map2(NAN);
    assert_int_equal(rl_map_check(&m, &bad), RL_ERANGE);
}

static void test_no_pose_from_impossible_detections(void **state)
{
    rl_calib c = camera();
    rl_map m = map2(0.61);
    rl_mount mount = {0, 0, 0.88, 0, 0, 0, RL_POSE_TILT_PRIOR};
    rl_detection d[2];
    rl_pose p;
    static const double far[3] = {1e308, -1e308, 1e200};
    int k;
    (void)state;
    for (k = 0; k < 3; k++) {
        rl_err e;
        memset(d, 0, sizeof d);
        d[0].id = 3;
        d[0].u = 320;
        d[0].v = 240;
        d[0].radius = 25;
        d[1].id = 7;
        d[1].u = far[k];
        d[1].v = 240;
        d[1].radius = 25;
        e = rl_pose_solve(&c, &m, &mount, d, 2, NULL, &p);
        if (e == RL_OK && !(isfinite(p.x) && isfinite(p.y) && isfinite(p.yaw) && isfinite(p.residual)))
            fail_msg("u = %g: a pose of (%g, %g, %g), residual %g", far[k], p.x, p.y, p.yaw, p.residual);
        assert_int_not_equal(e, RL_OK);
    }
    /* both beyond any image: the distance between them agrees with the
     * map's (both huge), and a pose 4e305 m away came out */
    d[0].u = d[1].u = 1e308;
    d[1].v = 390;
    if (rl_pose_solve(&c, &m, &mount, d, 2, NULL, &p) == RL_OK)
        fail_msg("a pose of (%g, %g, %g) from detections at u = 1e308", p.x, p.y, p.yaw);
    c.fx = c.fy = 1e-300;
    d[0].u = 320;
    d[1].u = 400;
    assert_int_not_equal(rl_pose_solve(&c, &m, &mount, d, 2, NULL, &p), RL_OK);
}

/* A landmark with its own height (z: on a beam, a lower panel): the
 * detections of a level camera worked out by hand (image top forward, +u
 * left; the pinhole of rl_calib_defaults), the pose from them exact; the
 * map that puts it on the ceiling drops it or places the robot off. */
static void test_landmark_heights(void **state)
{
    rl_calib c = camera();
    rl_map m = map2(0.61);
    rl_mount mount = {0, 0, 0.88, 0, 0, 0, RL_POSE_TILT_PRIOR};
    static const double X[3] = {0.0, 0.61, 0.0}, Y[3] = {0.0, 0.0, 0.61}, Z[3] = {2.45, 2.75, 2.75};
    const double rx = 0.3, ry = 0.2;
    rl_detection d[3];
    rl_pose p;
    int k, bad;
    (void)state;
    m.count = 3;
    m.lm[2].id = 11;
    m.lm[2].y = 0.61;
    m.lm[0].z = 2.45; /* 0.3 m below the ceiling */
    assert_int_equal(rl_map_check(&m, &bad), RL_OK);
    assert_true(fabs(rl_map_height(&m, 0) - 2.45) < 1e-12 && fabs(rl_map_height(&m, 1) - 2.75) < 1e-12);
    /* an id's height: its one landmark's; an id repeated at two heights, or
     * absent: the ceiling's; repeated at one height: that one */
    {
        static rl_map twice;
        double h[RL_MAX_IDS];
        rl_map_id_heights(&m, h);
        assert_true(h[m.lm[0].id] == 2.45 && h[m.lm[1].id] == 2.75 && h[29] == 2.75);
        twice = m;
        twice.lm[3] = twice.lm[0];
        twice.lm[3].y = 1.5;
        twice.lm[3].z = 2.5;
        twice.count = 4;
        rl_map_id_heights(&twice, h);
        assert_true(h[m.lm[0].id] == 2.75);
        twice.lm[3].z = 2.45;
        rl_map_id_heights(&twice, h);
        assert_true(h[m.lm[0].id] == 2.45);
    }
    memset(d, 0, sizeof d);
    for (k = 0; k < 3; k++) {
        double up = Z[k] - 0.88, fwd = X[k] - rx, left = Y[k] - ry;
        d[k].id = m.lm[k].id;
        d[k].u = c.cx + c.fx * left / up;
        d[k].v = c.cy - c.fy * fwd / up;
        d[k].radius = c.fx * 0.105 / up;
        d[k].complete = 1;
    }
    assert_int_equal(rl_pose_solve(&c, &m, &mount, d, 3, NULL, &p), RL_OK);
    if (hypot(p.x - rx, p.y - ry) > 1e-6 || fabs(p.yaw) > 1e-6 || p.used != 3)
        fail_msg("pose (%g, %g, %g) from %d landmarks, not (%g, %g, 0) from 3", p.x, p.y, p.yaw, p.used, rx, ry);
    /* the same detections against a map of one plane: landmark 3 lies
     * (2.75 - 0.88) / (2.45 - 0.88) times as far from the camera's point:
     * dropped, or outvoted by the robust fit but not without moving it */
    m.lm[0].z = 0;
    assert_int_equal(rl_pose_solve(&c, &m, &mount, d, 3, NULL, &p), RL_OK);
    if (!(p.used == 2 || hypot(p.x - rx, p.y - ry) > 1e-4))
        fail_msg("the map of one plane gave (%g, %g) from %d landmarks: the height made no difference", p.x, p.y,
                 p.used);
    m.lm[0].z = -1;
    assert_int_equal(rl_map_check(&m, &bad), RL_ERANGE);
    assert_int_equal(bad, 0);
    m.lm[0].z = NAN;
    assert_int_equal(rl_map_check(&m, &bad), RL_ERANGE);
}

/* Nine landmarks seen by a camera tilted by t about its image's x axis
 * (projected here by hand), t growing in steps of 10 urad: the tilted fit
 * goes from unneeded to needed, and the pose must follow continuously (a
 * choice of one fit or the other moved a pose by 13 mm for a 0.03 px
 * shift of one centre, on the demo's drive). */
static void test_tilt_continuous(void **state)
{
    rl_calib c = camera();
    static rl_map m;
    rl_mount mount = {0, 0, 0.88, 0, 0, 0, RL_POSE_TILT_PRIOR};
    rl_detection d[9];
    rl_pose p, last;
    const double rx = 0.3, ry = 0.2, up = 2.75 - 0.88;
    double t, step, worst = 0, w_last = -1, t_half = -1, reproj = 0, zmax = 0, sy0 = 0, symax = 0;
    int k, n = 0;
    (void)state;
    m = map2(0.61);
    m.count = 9;
    for (k = 0; k < 9; k++) {
        m.lm[k].id = k + 1;
        m.lm[k].x = 0.61 * (k % 3 - 1) + rx;
        m.lm[k].y = 0.61 * (k / 3 - 1) + ry;
    }
    memset(d, 0, sizeof d);
    memset(&last, 0, sizeof last);
    for (t = 0; t <= 0.01; t += 1e-5, n++) {
        /* where the robot is: a lean of t backwards (a centre straight
         * above shows forward) puts the camera 0.88 sin t behind the base */
        const double tx = rx + 0.88 * sin(t);
        for (k = 0; k < 9; k++) {
            double fwd = m.lm[k].x - rx, left = m.lm[k].y - ry;
            double f2 = fwd * cos(t) + up * sin(t), u2 = up * cos(t) - fwd * sin(t);
            d[k].id = m.lm[k].id;
            d[k].u = c.cx + c.fx * left / u2;
            d[k].v = c.cy - c.fy * f2 / u2;
            d[k].radius = c.fx * 0.105 / u2;
            d[k].complete = 1;
        }
        assert_int_equal(rl_pose_solve(&c, &m, &mount, d, 9, NULL, &p), RL_OK);
        assert_int_equal(p.used, 9);
        assert_true(p.tilt_weight >= 0 && p.tilt_weight <= 1);
        /* the map seen again from the pose lands on the centres */
        for (k = 0; k < 9; k++) {
            double u, v;
            assert_true(rl_pose_project(&c, &m, &mount, &p, m.lm[k].x, m.lm[k].y, 2.75, &u, &v));
            reproj = fmax(reproj, hypot(u - d[k].u, v - d[k].v));
        }
        /* level: the camera's point; tilted all the way: the robot's base
         * 0.88 m under a camera leaning by t */
        if (n == 0 && hypot(p.x - rx, p.y - ry) > 1e-6)
            fail_msg("level camera: pose (%g, %g), not (%g, %g)", p.x, p.y, rx, ry);
        /* the pose's sigma covers its error: a level fit is off by the
         * lean it assumed away (2.75 m times it), and must say so */
        zmax = fmax(zmax, fabs(p.x - tx) / fmax(p.sigma_x, 1e-9));
        /* the lean is about one axis: the other's sigma stays as level */
        if (n == 0)
            sy0 = p.sigma_y;
        symax = fmax(symax, p.sigma_y);
        if (n > 0) {
            step = hypot(p.x - last.x, p.y - last.y);
            worst = fmax(worst, step);
        }
        if (w_last < 0.5 && p.tilt_weight >= 0.5)
            t_half = t;
        w_last = p.tilt_weight;
        last = p;
    }
    /* the sweep crosses the line: level at first, tilted at the end */
    if (!(t_half > 0 && w_last > 0.99))
        fail_msg("the tilted fit never took over (weight %g at %g rad)", w_last, t);
    t -= 1e-5;
    if (fabs(hypot(last.x - rx, last.y - ry) - 0.88 * sin(t)) > 0.0001)
        fail_msg("camera leaning %g rad: the robot %.3f mm from under it, not %.3f", t,
                 1000 * hypot(last.x - rx, last.y - ry), 1000 * 0.88 * sin(t));
    /* a centre's noise is 0.15 px (RL_POSE_PIXEL_SIGMA); the averaged pose
     * must still put the map where the camera saw it */
    if (reproj > 0.25)
        fail_msg("the map projected from the pose lands %.2f px from a centre", reproj);
    /* the camera's 10 urad step moves its point on the ceiling 1.87 m up
     * by 0.019 mm; near the line the pose may move some times that, not
     * the level fit's bias at once */
    printf("  tilt 0 .. 10 mrad: the fits weigh the same at %g rad; the largest move of the pose in one step "
           "%.3f mm; the map projected from the pose %.3f px from the centres at most\n", t_half, 1000 * worst,
           reproj);
    if (worst > 0.0005)
        fail_msg("the pose moved %.3f mm in one 10 urad step (the fits weigh the same at %g rad)", 1000 * worst,
                 t_half);
    printf("  the pose's error at most %.2f of its sigma; sigma across the lean %.2f mm level, %.2f mm at most\n",
           zmax, 1000 * sy0, 1000 * symax);
    if (symax > 3 * sy0)
        fail_msg("a lean about one axis made the other unsure: sigma %.2f mm, %.2f level", 1000 * symax, 1000 * sy0);
    if (zmax > 3)
        fail_msg("the pose was %.1f sigmas from the robot (sigma too small for the lean it ignored)", zmax);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_camera_limits),
        cmocka_unit_test(test_map_limits),
        cmocka_unit_test(test_no_pose_from_impossible_detections),
        cmocka_unit_test(test_landmark_heights),
        cmocka_unit_test(test_tilt_continuous),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
