/* rl_shutter against calculations by hand: an ideal camera (fx = fy =
 * 500 px, principal point (320, 240), 640 x 480), 2 m below the ceiling,
 * rows read top to bottom in 40 ms. A row's time from the middle row's is
 * ((v + 0.5) / 480 - 0.5) 0.04 s; rows 359.5 and 119.5 are read 10 ms
 * after and before it.
 * - Driving forward at 1 m/s, row 359.5 saw the ceiling from 10 mm
 *   further forward: the middle row sees its landmark 10 mm further ahead,
 *   10 mm x 500 / 2 m = 2.5 px higher (image top = forward); row 119.5
 *   2.5 px lower; u unchanged.
 * - Turning left at 1 rad/s, row 359.5 was seen with the camera turned
 *   0.01 rad further: from the middle row, the offset (du, dv) = (100,
 *   119.5) from the principal point turns to (du cos a - dv sin a, dv cos
 *   a + du sin a) = (98.8000, 120.4940): u -1.2000, v +0.9940.
 * - Sideways (left) at 0.5 m/s, row 359.5: 5 mm further left, 1.25 px
 *   further left in the image (+u is left).
 * - The camera mounted 0.2 m ahead of the robot's centre, turning at 1
 *   rad/s: the camera also moves 0.2 m/s to the left. */
#include "rl_test.h"
#include <math.h>
#include <string.h>
#include "rl_shutter.h"

static rl_calib ideal(void)
{
    rl_calib c;
    rl_calib_defaults(&c, 640, 480, 1.0);
    c.fx = c.fy = 500;
    c.cx = 320;
    c.cy = 240;
    return c;
}

static rl_detection at(double u, double v)
{
    rl_detection d;
    memset(&d, 0, sizeof d);
    d.u = u;
    d.v = v;
    return d;
}

static void test_forward(void **state)
{
    rl_calib c = ideal();
    rl_mount mount = {0, 0, 0.9, 0, 0, 0, RL_POSE_TILT_PRIOR};
    rl_motion m = {1.0, 0, 0};
    rl_detection d[3] = {at(420, 359.5), at(200, 119.5), at(320, 239.5)};
    (void)state;
    rl_shutter_correct(&c, &mount, 2.0, 0.04, &m, d, 3);
    assert_true(fabs(d[0].v - (359.5 - 2.5)) < 1e-6 && fabs(d[0].u - 420) < 1e-6);
    assert_true(fabs(d[1].v - (119.5 + 2.5)) < 1e-6 && fabs(d[1].u - 200) < 1e-6);
    assert_true(fabs(d[2].v - 239.5) < 1e-6); /* the middle row: its own instant */
}

/* Each landmark at its own distance: forward at 1 m/s, row 359.5 (10 ms
 * after the middle row) saw the ceiling from 10 mm further forward; a
 * landmark 1.6 m above the camera (on a beam 0.4 m below a ceiling 2 m
 * above the camera)
 * moves 10 mm x 500 / 1.6 m = 3.125 px, one on the ceiling 2.5 px, one
 * at a bad distance (hung at the camera) not at all. */
static void test_each_distance(void **state)
{
    rl_calib c = ideal();
    rl_mount mount = {0, 0, 0.9, 0, 0, 0, RL_POSE_TILT_PRIOR};
    rl_motion m = {1.0, 0, 0};
    rl_detection d[3] = {at(420, 359.5), at(200, 359.5), at(300, 359.5)};
    double distance[3] = {1.6, 2.0, 0.0};
    (void)state;
    rl_shutter_correct_each(&c, &mount, distance, 0.04, &m, d, 3);
    assert_true(fabs(d[0].v - (359.5 - 3.125)) < 1e-6 && fabs(d[0].u - 420) < 1e-6);
    assert_true(fabs(d[1].v - (359.5 - 2.5)) < 1e-6 && fabs(d[1].u - 200) < 1e-6);
    assert_true(d[2].v == 359.5 && d[2].u == 300);
    rl_shutter_correct_each(&c, &mount, NULL, 0.04, &m, d, 3); /* no distances: nothing */
    assert_true(fabs(d[0].v - (359.5 - 3.125)) < 1e-6);
}

static void test_turn(void **state)
{
    rl_calib c = ideal();
    rl_mount mount = {0, 0, 0.9, 0, 0, 0, RL_POSE_TILT_PRIOR};
    rl_motion m = {0, 0, 1.0};
    rl_detection d = at(420, 359.5);
    (void)state;
    rl_shutter_correct(&c, &mount, 2.0, 0.04, &m, &d, 1);
    assert_true(fabs(d.u - (420 - 1.2000)) < 1e-3);
    assert_true(fabs(d.v - (359.5 + 0.9940)) < 1e-3);
}

static void test_sideways_and_mount(void **state)
{
    rl_calib c = ideal();
    rl_mount mount = {0, 0, 0.9, 0, 0, 0, RL_POSE_TILT_PRIOR};
    rl_motion left = {0, 0.5, 0};
    rl_detection d = at(300, 359.5);
    (void)state;
    rl_shutter_correct(&c, &mount, 2.0, 0.04, &left, &d, 1);
    assert_true(fabs(d.u - (300 + 1.25)) < 1e-6 && fabs(d.v - 359.5) < 1e-6);
    /* the principal point's row-359.5 landmark at (320, 359.5): a turn
     * alone moves it by 1 rad/s x 10 ms about the principal point (0.01
     * rad of (0, 119.5): u -1.1950, v -0.0060), and the mount's 0.2 m
     * ahead adds 0.2 m/s x 10 ms = 2 mm to the left: +0.5 px */
    {
        rl_mount ahead = {0.2, 0, 0.9, 0, 0, 0, RL_POSE_TILT_PRIOR};
        rl_motion turn = {0, 0, 1.0};
        rl_detection e = at(320, 359.5);
        rl_shutter_correct(&c, &ahead, 2.0, 0.04, &turn, &e, 1);
        assert_true(fabs(e.u - (320 - 1.1950 + 0.5)) < 1e-3);
        assert_true(fabs(e.v - (359.5 - 0.0060)) < 1e-3);
    }
}

static void test_nothing_moved(void **state)
{
    rl_calib c = ideal();
    rl_mount mount = {0, 0, 0.9, 0, 0, 0, RL_POSE_TILT_PRIOR};
    rl_motion m = {1.0, 0.2, 0.5};
    rl_detection d = at(420, 359.5);
    (void)state;
    rl_shutter_correct(&c, &mount, 2.0, 0, &m, &d, 1);     /* a global shutter */
    rl_shutter_correct(&c, &mount, 2.0, 0.04, NULL, &d, 1); /* no motion known */
    rl_shutter_correct(&c, &mount, NAN, 0.04, &m, &d, 1);   /* no distance */
    assert_true(d.u == 420 && d.v == 359.5);
}

static void test_motion_between(void **state)
{
    /* a steady arc of radius 1 m, turning left 0.2 rad in 0.2 s: from
     * (0, 0) heading 0 to (sin 0.2, 1 - cos 0.2) heading 0.2; along the arc
     * 1 m/s, nothing sideways, 1 rad/s. The same arc turned 90 degrees
     * (heading from 90 degrees, 1 m north of (1, 2)): the same motion. */
    rl_pose a, b;
    rl_motion m;
    (void)state;
    memset(&a, 0, sizeof a);
    memset(&b, 0, sizeof b);
    b.x = sin(0.2), b.y = 1 - cos(0.2), b.yaw = 0.2;
    assert_true(rl_motion_between(&a, 10.0, &b, 10.2, 10.3, 0.5, &m));
    assert_true(fabs(m.forward - 1.0) < 1e-9 && fabs(m.left) < 1e-9 && fabs(m.turn - 1.0) < 1e-9);
    a.x = 1.0, a.y = 2.0, a.yaw = 1.5707963267948966;
    b.x = 1.0 - (1 - cos(0.2)), b.y = 2.0 + sin(0.2), b.yaw = 1.5707963267948966 + 0.2;
    assert_true(rl_motion_between(&a, 10.0, &b, 10.2, 10.3, 0.5, &m));
    assert_true(fabs(m.forward - 1.0) < 1e-9 && fabs(m.left) < 1e-9 && fabs(m.turn - 1.0) < 1e-9);
    /* straight ahead 0.1 m in 0.1 s, heading 90 degrees: 1 m/s forward */
    b = a;
    b.y += 0.1;
    assert_true(rl_motion_between(&a, 10.0, &b, 10.1, 10.2, 0.5, &m));
    assert_true(fabs(m.forward - 1.0) < 1e-9 && fabs(m.left) < 1e-9 && fabs(m.turn) < 1e-9);
    assert_false(rl_motion_between(&a, 10.0, &b, 11.0, 11.1, 0.5, &m)); /* the poses too far apart */
    assert_false(rl_motion_between(&a, 10.0, &b, 10.1, 13.0, 0.5, &m)); /* the frame long after them */
    assert_false(rl_motion_between(&a, 10.0, &b, 10.1, 10.0, 0.5, &m)); /* time went back */
    assert_false(rl_motion_between(&a, 10.1, &b, 10.1, 10.2, 0.5, &m)); /* no time between */
    b.x = NAN;
    assert_false(rl_motion_between(&a, 10.0, &b, 10.1, 10.2, 0.5, &m));
}

static void test_mount_turned(void **state)
{
    /* the camera's image top along the robot's left (mount yaw 90
     * degrees): driving forward 1 m/s, row 359.5's landmark was seen from
     * 10 mm further towards the camera's right, so from the middle row it
     * lies 10 mm further right: 2.5 px less u, v unchanged */
    rl_calib c = ideal();
    rl_mount side = {0, 0, 0.9, 1.5707963267948966, 0, 0, RL_POSE_TILT_PRIOR};
    rl_motion fwd = {1.0, 0, 0};
    rl_detection d = at(420, 359.5);
    (void)state;
    rl_shutter_correct(&c, &side, 2.0, 0.04, &fwd, &d, 1);
    assert_true(fabs(d.u - (420 - 2.5)) < 1e-6 && fabs(d.v - 359.5) < 1e-6);
    /* the camera 0.2 m left of the centre, turning 1 rad/s: it moves 0.2
     * m/s backwards, 2 mm in 10 ms: the landmark at (320, 359.5) turns as
     * in test_sideways_and_mount (u -1.1950, v -0.0060) and lies 2 mm
     * further back: 0.5 px lower */
    {
        rl_mount left = {0, 0.2, 0.9, 0, 0, 0, RL_POSE_TILT_PRIOR};
        rl_motion turn = {0, 0, 1.0};
        rl_detection e = at(320, 359.5);
        rl_shutter_correct(&c, &left, 2.0, 0.04, &turn, &e, 1);
        assert_true(fabs(e.u - (320 - 1.1950)) < 1e-3);
        assert_true(fabs(e.v - (359.5 - 0.0060 + 0.5)) < 1e-3);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_forward), cmocka_unit_test(test_each_distance), cmocka_unit_test(test_turn), cmocka_unit_test(test_sideways_and_mount),
        cmocka_unit_test(test_nothing_moved), cmocka_unit_test(test_motion_between),
        cmocka_unit_test(test_mount_turned),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
