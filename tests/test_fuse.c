/* rl_fuse against hand calculations: the motion model, a Kalman update
 * of one coordinate, the gate's distance, the capture time from a frame,
 * a late frame applied at its time with the odometry since replayed, the
 * scales learned on a straight drive, frames waiting for the odometry,
 * and what is refused and counted. */
#include <math.h>
#include "rl_test.h"
#include "rl_fuse.h"
#include "rl_fuse_kf.h"

static rl_fuse f;
static rl_fuse_entry hist[128];

static void setup(double wheel_noise)
{
    rl_fuse_config cfg;
    rl_fuse_defaults(&cfg);
    cfg.wheel_noise = wheel_noise;
    cfg.time_sigma = 0;
    assert_int_equal(rl_fuse_init(&f, &cfg, hist, 128), RL_OK);
}

static rl_fuse_frame frame(double t, double x, double y, double yaw, double sd)
{
    rl_fuse_frame fr;
    fr.t = t;
    fr.x = x;
    fr.y = y;
    fr.yaw = yaw;
    fr.sx = fr.sy = fr.syaw = sd;
    fr.st = 0;
    return fr;
}

/* A quarter circle of radius 1 as one increment: the chord, sqrt(2) long
 * along 45 degrees, takes (0, 0, 0) to (1, 1, 90 degrees); with the
 * distance scale 2 to (2, 2); with the turn scale 2 the chord runs along
 * 90 degrees, to (0, sqrt 2), heading 180. */
static void test_motion_model(void **state)
{
    rl_fuse_config cfg;
    rl_fuse_kf_state s;
    double a[3] = {5, 5, M_PI / 2}, b[3] = {4, 6, M_PI}, z[3] = {0, 0, 0}, R[3][3] = {{0}};
    rl_fuse_kf_incr d;
    (void)state;
    rl_fuse_defaults(&cfg);
    d = rl_fuse_kf_increment(a, b); /* odometry turned left 90 degrees on an arc of radius 1 */
    assert_true(fabs(d.fwd - sqrt(2.0)) < 1e-12 && fabs(d.lat) < 1e-12 && fabs(d.turn - M_PI / 2) < 1e-12);
    rl_fuse_kf_start(&s, z, R, 1, 0, 1, 0);
    rl_fuse_kf_propagate(&s, d, &cfg);
    assert_true(fabs(s.m[0] - 1) < 1e-12 && fabs(s.m[1] - 1) < 1e-12 && fabs(s.m[2] - M_PI / 2) < 1e-12);
    rl_fuse_kf_start(&s, z, R, 2, 0, 1, 0);
    rl_fuse_kf_propagate(&s, d, &cfg);
    assert_true(fabs(s.m[0] - 2) < 1e-12 && fabs(s.m[1] - 2) < 1e-12);
    /* turn scale 2: the chord along 90 degrees, the heading 180 */
    rl_fuse_kf_start(&s, z, R, 1, 0, 2, 0);
    rl_fuse_kf_propagate(&s, d, &cfg);
    assert_true(fabs(s.m[0]) < 1e-12 && fabs(s.m[1] - sqrt(2.0)) < 1e-12 && fabs(fabs(s.m[2]) - M_PI) < 1e-12);
}

/* Straight 1 m, wheel noise w per sqrt(m): each wheel's variance w^2, the
 * distance's (w^2 + w^2) / 4, the heading's 2 w^2 / b^2; y's variance is
 * the heading's through the lever: the exact sum over a continuous drive
 * is 2 w^2 / b^2 / 3, one increment puts the heading's spread at the
 * chord's middle: 2 w^2 / b^2 * (1/2)^2. */
static void test_process_noise(void **state)
{
    rl_fuse_config cfg;
    rl_fuse_kf_state s;
    double z[3] = {0, 0, 0}, R[3][3] = {{0}}, w = 0.01, b = 0.5;
    rl_fuse_kf_incr d = {1.0, 0, 0};
    (void)state;
    rl_fuse_defaults(&cfg);
    cfg.wheel_noise = w;
    cfg.track = b;
    cfg.scale_drift = 0;
    rl_fuse_kf_start(&s, z, R, 1, 0, 1, 0);
    rl_fuse_kf_propagate(&s, d, &cfg);
    assert_true(fabs(s.P[0][0] - w * w / 2) < 1e-15);
    assert_true(fabs(s.P[2][2] - 2 * w * w / (b * b)) < 1e-15);
    assert_true(fabs(s.P[1][1] - 2 * w * w / (b * b) / 4) < 1e-15);
}

/* One coordinate: prior variance 4, measurement variance 1: gain 0.8, the
 * mean moves 0.8 of the way, the variance 4 * 1 / 5; distance^2 = 5^2 / 5. */
static void test_update_and_gate(void **state)
{
    rl_fuse_kf_state s;
    double z0[3] = {0, 0, 0}, z[3] = {5, 0, 0};
    double P[3][3] = {{4, 0, 0}, {0, 4, 0}, {0, 0, 4}}, R[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    (void)state;
    rl_fuse_kf_start(&s, z0, P, 1, 0.01, 1, 0.01);
    assert_true(fabs(rl_fuse_kf_distance(&s, z, R) - 5.0) < 1e-12);
    rl_fuse_kf_update(&s, z, R);
    assert_true(fabs(s.m[0] - 4.0) < 1e-12 && fabs(s.P[0][0] - 0.8) < 1e-12);
    assert_true(fabs(s.m[3] - 1) < 1e-12); /* nothing correlated: the scales untouched */
}

/* 39 bytes at 115200 baud: 3.385 ms; latency 20.0 ms: captured 23.385 ms
 * before it arrived. Sigmas 0.1 mm units -> m. */
static void test_capture_time(void **state)
{
    rl_msg m;
    rl_fuse_frame fr;
    (void)state;
    memset(&m, 0, sizeof m);
    m.type = RL_PACKET_POSE;
    m.version = 2;
    m.x_mm = 1500;
    m.yaw_e4 = -31416;
    m.latency_e4 = 200;
    m.sigma_x_e4 = 12;
    rl_fuse_frame_from_msg(&m, 10.0, 115200, &fr);
    assert_true(fabs(fr.t - (10.0 - 0.020 - 390.0 / 115200)) < 1e-12);
    assert_true(fabs(fr.x - 1.5) < 1e-12 && fabs(fr.yaw + 3.1416) < 1e-12 && fabs(fr.sx - 0.0012) < 1e-12);
    m.version = 1; /* 24-byte payload, no sigmas */
    rl_fuse_frame_from_msg(&m, 10.0, 115200, &fr);
    assert_true(fabs(fr.t - (10.0 - 0.020 - 290.0 / 115200)) < 1e-12 && fr.sx == 0);
}

/* The robot drives along x at 1 m/s; odometry every 0.1 s says so exactly.
 * A frame captured at 0.25 s, far more certain than the pose, says x =
 * 0.26 (1 cm ahead) after the odometry reached 0.5 s: the pose at 0.25 s
 * becomes the frame's, and the 0.25 m since are replayed on top with the
 * distance scale the frame taught. By hand: P_xx = 1e-4 + 0.03^2 0.25^2,
 * P_xs = 0.03^2 0.25, so the scale moves by P_xs / P_xx * 0.01 = 0.0144. */
static void test_late_frame_replayed(void **state)
{
    rl_fuse_frame fr;
    rl_fuse_pose p;
    int k;
    (void)state;
    setup(1e-4);
    for (k = 0; k <= 5; k++)
        assert_int_equal(rl_fuse_odometry(&f, k * 0.1, k * 0.1, 0, 0), RL_OK);
    fr = frame(0.0, 0.0, 0.0, 0.0, 0.01); /* first frame: the pose (x = 0 at t = 0) */
    assert_int_equal(rl_fuse_frame_add(&f, &fr), RL_OK);
    assert_int_equal(rl_fuse_pose_at(&f, 0.5, &p), RL_OK);
    assert_true(fabs(p.x - 0.5) < 1e-9);
    fr = frame(0.25, 0.26, 0.0, 0.0, 1e-5);
    assert_int_equal(rl_fuse_frame_add(&f, &fr), RL_OK);
    assert_int_equal(rl_fuse_pose_at(&f, 0.25, &p), RL_OK);
    assert_true(fabs(p.x - 0.26) < 1e-4);
    assert_true(fabs(p.scale - 1.0144) < 5e-4);
    assert_int_equal(rl_fuse_pose_at(&f, 0.5, &p), RL_OK);
    assert_true(fabs(p.x - (0.26 + 0.25 * 1.0144)) < 2e-4);
    /* before the frame: the frame's state moved back, 0.1 m at the new scale */
    assert_int_equal(rl_fuse_pose_at(&f, 0.15, &p), RL_OK);
    assert_true(fabs(p.x - (0.26 - 0.1 * 1.0144)) < 2e-4);
    assert_int_equal((int)f.stats.applied, 2);
}

/* Odometry 2% short, frames every metre: the scale converges on 1.02. */
static void test_scale_learned(void **state)
{
    rl_fuse_pose p;
    int k;
    (void)state;
    setup(1e-4);
    for (k = 0; k <= 100; k++) {
        double t = k * 0.1;
        assert_int_equal(rl_fuse_odometry(&f, t, t / 1.02, 0, 0), RL_OK);
        if (k % 10 == 5) {
            rl_fuse_frame fr = frame(t - 0.05, t - 0.05, 0, 0, 0.001);
            assert_int_equal(rl_fuse_frame_add(&f, &fr), RL_OK);
        }
    }
    assert_int_equal(rl_fuse_pose_at(&f, 10.0, &p), RL_OK);
    assert_true(fabs(p.scale - 1.02) < 0.001);
    assert_true(fabs(p.x - 10.0) < 0.003);
}

/* A warm start: the odometry 2% short, the scale 1.02 learned yesterday
 * given back: from a frame at x = 0 the pose 1 s later at 1 m/s is
 * odometry 1 / 1.02 times 1.02 = 1 m, and the fused speed 1 m/s; a cold
 * start (scale 1) is 1 / 1.02 m and m/s. */
static void test_warm_start(void **state)
{
    rl_fuse_config cfg;
    rl_fuse_frame fr;
    rl_fuse_pose p;
    int k, warm;
    (void)state;
    for (warm = 0; warm <= 1; warm++) {
        rl_fuse_defaults(&cfg);
        cfg.scale = warm ? 1.02 : 1;
        cfg.scale_sigma = 0.001;
        assert_int_equal(rl_fuse_init(&f, &cfg, hist, 128), RL_OK);
        for (k = 0; k <= 100; k++)
            assert_int_equal(rl_fuse_odometry(&f, k * 0.01, k * 0.01 / 1.02, 0, 0), RL_OK);
        fr = frame(0.0, 0.0, 0.0, 0.0, 0.001);
        assert_int_equal(rl_fuse_frame_add(&f, &fr), RL_OK);
        assert_int_equal(rl_fuse_pose_at(&f, 1.0, &p), RL_OK);
        assert_true(fabs(p.x - (warm ? 1.0 : 1 / 1.02)) < 1e-9);
        assert_true(fabs(p.v - (warm ? 1.0 : 1 / 1.02)) < 1e-9 && fabs(p.w) < 1e-12);
    }
}

static void test_refused_and_counted(void **state)
{
    rl_fuse_event ev;
    unsigned long n;
    rl_fuse_frame fr;
    rl_fuse_pose p;
    rl_fuse_config cfg;
    int k;
    (void)state;
    setup(1e-3);
    assert_int_equal(rl_fuse_pose_at(&f, 0, &p), RL_ENOTFOUND);
    fr = frame(0.05, 0, 0, 0, 0.001); /* before any odometry: waits */
    assert_int_equal(rl_fuse_frame_add(&f, &fr), RL_OK);
    fr.t = 0.06; /* a second one replaces it: counted */
    assert_int_equal(rl_fuse_frame_add(&f, &fr), RL_OK);
    assert_int_equal((int)f.stats.waiting_lost, 1);
    for (k = 0; k < 256; k++) /* twice the history */
        assert_int_equal(rl_fuse_odometry(&f, k * 0.01, 0, 0, 0), RL_OK);
    assert_int_equal((int)f.stats.applied, 1); /* fused once the odometry passed its time */
    assert_int_equal(rl_fuse_odometry(&f, 0.0, 0, 0, 0), RL_EINVAL); /* time not increasing */
    assert_int_equal(rl_fuse_odometry(&f, 100, NAN, 0, 0), RL_EINVAL);
    fr = frame(0.5, 0, 0, 0, 0.001); /* older than the history */
    assert_int_equal(rl_fuse_frame_add(&f, &fr), RL_ERANGE);
    assert_int_equal((int)f.stats.too_old, 1);
    fr = frame(2.5, 0, 0, 0, 0.001);
    assert_int_equal(rl_fuse_frame_add(&f, &fr), RL_OK);
    fr = frame(2.4, 0, 0, 0, 0.001); /* older than the last fused */
    assert_int_equal(rl_fuse_frame_add(&f, &fr), RL_ERANGE);
    assert_int_equal((int)f.stats.out_of_order, 1);
    fr = frame(2.54, 0.5, 0, 0, 0.001); /* 0.5 m off a robot standing still */
    assert_int_equal(rl_fuse_frame_add(&f, &fr), RL_ERANGE);
    assert_int_equal((int)f.stats.rejected, 1);
    assert_int_equal(rl_fuse_pose_at(&f, 2.54, &p), RL_OK);
    assert_true(fabs(p.x) < 1e-3);
    /* its event: each frame's x variance 1e-6 + the floor's 0.0005^2, two
     * fused on a robot standing still (which adds none): the pose's half
     * of it, 0.5^2 / (0.625e-6 + 1.25e-6) */
    rl_fuse_last_event(&f, &ev);
    assert_int_equal(ev.fate, RL_FUSE_REJECTED);
    assert_true(fabs(ev.d2 - 0.25 / 1.875e-6) < 1 && ev.t == 2.54 && ev.clock_reset == 0);
    n = ev.n;
    fr = frame(2.55, 0.5, 0, 0, 0.001); /* a second that agrees: carried, restarted */
    assert_int_equal(rl_fuse_frame_add(&f, &fr), RL_OK);
    rl_fuse_last_event(&f, &ev);
    assert_true(ev.fate == RL_FUSE_RESTARTED && ev.n == n + 1 && ev.d2 > 1e4);
    assert_int_equal((int)f.stats.recoveries, 1);
    rl_fuse_defaults(&cfg);
    assert_int_equal(rl_fuse_init(&f, &cfg, hist, 1), RL_EINVAL); /* no room for a past */
    cfg.track = 0;
    assert_int_equal(rl_fuse_init(&f, &cfg, hist, 128), RL_EINVAL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_motion_model),
        cmocka_unit_test(test_process_noise),
        cmocka_unit_test(test_update_and_gate),
        cmocka_unit_test(test_capture_time),
        cmocka_unit_test(test_late_frame_replayed),
        cmocka_unit_test(test_scale_learned),
        cmocka_unit_test(test_warm_start),
        cmocka_unit_test(test_refused_and_counted),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
