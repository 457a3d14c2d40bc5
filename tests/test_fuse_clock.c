/* rl_fuse's camera-board clock against hand calculations: the offset from
 * the lowest of one-sided delays, the capture moved earlier by the lowest
 * of n uniform delays' expected excess, the drift fitted on a 60 s base,
 * restarts and changed offsets; and rl_fuse_msg_add's frame fates. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "rl_test.h"
#include "rl_fuse.h"
#include "rl_fuse_clock.h"

/* The board's clock 100 s behind the controller's; delays 0, then 20 and
 * 40 ms alternately: the envelope is 100 s, the mean excess 30 ms after
 * five frames, the capture 2 x 30 / 6 = 10 ms before the envelope's, give
 * or take 10 ms; unknown before four excesses are seen. */
static void test_offset(void **state)
{
    static const double delay[5] = {0, 0.02, 0.04, 0.02, 0.04};
    rl_fuse_clock k;
    double t = 0, sd = 0;
    int i;
    (void)state;
    rl_fuse_clock_init(&k);
    for (i = 0; i < 5; i++) {
        double c = 1.0 + 0.1 * i;
        assert_int_equal(rl_fuse_clock_stamp(&k, (uint32_t)lround(c * 1e3), (uint16_t)i, 0.003,
                                             c + 100 + 0.003 + delay[i], &t, &sd), 0);
        if (i < 4)
            assert_true(isinf(sd));
    }
    assert_true(fabs(t - (1.4 + 100 - 0.010)) < 1e-9);
    assert_true(fabs(sd - 0.010) < 1e-9);
}

/* 60 s of frames, 10 a second, on a board clock 100 ppm fast; delays
 * uniform-ish in 0 .. 100 ms but every 25th frame met none: the envelope's
 * slope is -r / (1 + r) and every capture comes back to within the
 * expected excess (0.2 ms after 600 frames) and time_ms's rounding. */
static void test_drift(void **state)
{
    rl_fuse_clock k;
    double r = 100e-6, t = 0, sd = 0, worst = 0, truth = 0;
    int i;
    (void)state;
    rl_fuse_clock_init(&k);
    for (i = 0; i < 600; i++) {
        double c;
        truth = 5.0 + 0.1 * i;
        c = 40.0 + truth * (1 + r);
        double d = i % 25 == 0 ? 0 : 0.1 * ((i * 37) % 100) / 100.0;
        c = lround(c * 1e3) * 1e-3; /* time_ms */
        assert_int_equal(rl_fuse_clock_stamp(&k, (uint32_t)lround(c * 1e3), (uint16_t)i, 0, truth + d, &t, &sd), 0);
        truth = (c - 40.0) / (1 + r); /* the capture the millisecond stands for */
        if (i >= 100)
            worst = fmax(worst, fabs(t - truth));
    }
    assert_true(fabs(k.b + r / (1 + r)) < 2e-6);
    assert_true(worst < 0.0025); /* before 32 s: the last 16 s's lowest, 1.6 ms of drift */
    assert_true(fabs(t - truth) < 0.001); /* time_ms's rounding: 0.5 ms */
}

/* Captures anywhere in a millisecond, time_ms truncated as the firmware
 * does (rl_packet_sink), delays spread evenly over 0 .. 100 ms: once the
 * envelope is known (300 frames), the captures come back unbiased, mean
 * within 0.15 ms (the dropped fraction is not: the lowest of the delays
 * plus it, with delays this wide, carries its mean, 0.5 ms, so adding
 * that back would put the captures half a millisecond late), each within
 * 2 ms (the fraction and the envelope's excess). */
static void test_truncated(void **state)
{
    rl_fuse_clock k;
    double t = 0, sd = 0, sum = 0, worst = 0;
    int i, n = 0;
    (void)state;
    rl_fuse_clock_init(&k);
    for (i = 0; i < 1000; i++) {
        double capture = 3.0 + 0.1 * i + 0.001 * ((i * 7919) % 1000) / 1000.0;
        double d = 0.1 * ((i * 7907) % 10007) / 10007.0;
        uint32_t ms = (uint32_t)floor((capture + 40.0) * 1e3);
        assert_int_equal(rl_fuse_clock_stamp(&k, ms, (uint16_t)i, 0.01, capture + 0.01 + d, &t, &sd), 0);
        if (i >= 300) {
            sum += t - capture;
            worst = fmax(worst, fabs(t - capture));
            n++;
        }
    }
    assert_true(fabs(sum / n) < 0.00015);
    assert_true(worst < 0.002);
}

/* time_ms going back, the sequence going back or far ahead, a frame
 * arriving long before the envelope allows: a reset; lost frames are not. */
static void test_resets(void **state)
{
    rl_fuse_clock k;
    double t, sd;
    int i;
    (void)state;
    rl_fuse_clock_init(&k);
    for (i = 0; i < 10; i++)
        assert_int_equal(rl_fuse_clock_stamp(&k, 1000 + 100 * (uint32_t)i, (uint16_t)i, 0,
                                             10 + 0.1 * i + 0.01 * (i % 3), &t, &sd), 0);
    assert_int_equal(rl_fuse_clock_stamp(&k, 2000, 15, 0, 11.0, &t, &sd), 0);  /* 5 lost */
    assert_int_equal(rl_fuse_clock_stamp(&k, 300, 0, 0, 11.1, &t, &sd), 1);    /* restarted */
    /* the excess learned before stays (the line's delays did not change):
     * 6.7 ms on average, the capture that much earlier, give or take it */
    assert_true(t < 11.1 && t > 11.09 && fabs(t - (11.1 - sd)) < 1e-12);
    assert_int_equal(rl_fuse_clock_stamp(&k, 400, 1, 0, 11.2, &t, &sd), 0);
    assert_int_equal(rl_fuse_clock_stamp(&k, 500, 1, 0, 11.3, &t, &sd), 1);    /* seq again */
    assert_int_equal(rl_fuse_clock_stamp(&k, 600, 3000, 0, 11.4, &t, &sd), 1); /* far ahead */
    for (i = 0; i < 6; i++)
        assert_int_equal(rl_fuse_clock_stamp(&k, 700 + 100 * (uint32_t)i, (uint16_t)(3001 + i), 0,
                                             11.5 + 0.1 * i + 0.01 * (i % 2), &t, &sd), 0);
    /* the offset was 10.8 s; a frame 1 s early cannot be */
    assert_int_equal(rl_fuse_clock_stamp(&k, 1300, 3007, 0, 11.1, &t, &sd), 1);
}

/* Through rl_fuse_msg_add, the robot standing at x = 1, the frames at
 * x = 2 arriving 0 or 20 ms after their capture (board clock 49 s ahead):
 * the first four wait for the clock (UNTIMED), then fused at time_ms - 49
 * s, less 2 x the mean excess (10 of 19 frames 20 ms late) / 21; a
 * restart is a clock reset, not a pose restart; a status frame is refused. */
static void test_msg_add(void **state)
{
    static rl_fuse f;
    static rl_fuse_entry hist[512];
    rl_fuse_config cfg;
    rl_fuse_event ev;
    rl_fuse_pose p;
    rl_msg m;
    double t = 0;
    int i;
    (void)state;
    rl_fuse_defaults(&cfg);
    assert_int_equal(rl_fuse_init(&f, &cfg, hist, rl_fuse_history_count(2.5, 100)), RL_OK);
    memset(&m, 0, sizeof m);
    m.type = RL_PACKET_POSE;
    m.x_mm = 2000;
    for (i = 0; i < 20; i++) {
        double arrival = 1.0 + 0.1 * i + 0.02 * (i % 2);
        for (; t <= arrival + 0.05; t += 0.01) /* the wheels read since */
            assert_int_equal(rl_fuse_odometry(&f, t, 1, 0, 0), RL_OK);
        m.seq = (uint16_t)i;
        m.time_ms = 50000 + 100 * (uint32_t)i;
        (void)!rl_fuse_msg_add(&f, &m, arrival, 0);
        rl_fuse_last_event(&f, &ev);
        assert_true(ev.seq == (unsigned)i && ev.fate == (i < 4 ? RL_FUSE_UNTIMED : RL_FUSE_APPLIED));
    }
    assert_true(fabs(ev.t - (2.9 - 2 * (0.2 / 19) / 21)) < 1e-9);
    assert_int_equal((int)f.stats.untimed, 4);
    m.seq = 0;
    m.time_ms = 700;
    (void)!rl_fuse_msg_add(&f, &m, 3.0, 0);
    rl_fuse_last_event(&f, &ev);
    assert_true(ev.clock_reset == 1 && f.stats.clock_resets == 1 && f.stats.recoveries == 0);
    assert_int_equal(rl_fuse_pose_at(&f, 2.95, &p), RL_OK);
    assert_true(fabs(p.x - 2.0) < 1e-3);
    m.type = RL_PACKET_STATUS;
    assert_int_equal(rl_fuse_msg_add(&f, &m, 3.1, 0), RL_EINVAL);
}

/* The odometry's cycle (rl_fuse_cycle): samples sent every 100 ms from
 * 50 s, read 1 ms late (every 5th on time): once known (2 s of cycles),
 * each stamp is its send time within 1 ms, the first 20 their read times;
 * sample 25 stalled 60 ms gets its cycle's time
 * (its read is 61 ms off); sample 30 lost: 31 is read a cycle late and
 * given its read time (1 ms off), 32 shows the loss, counted once, and
 * from there the stamps are the send times again; sample 40 stalled a
 * whole cycle is given its read time (documented), and 41, on time,
 * counts no loss. */
static void test_cycle(void **state)
{
    rl_fuse_cycle cy;
    int k;
    (void)state;
    assert_int_equal(rl_fuse_cycle_init(&cy, 0), RL_EINVAL);
    assert_int_equal(rl_fuse_cycle_init(&cy, 0.1), RL_OK);
    for (k = 0; k < 60; k++) {
        double sent = 50 + 0.1 * k, read = sent + (k % 5 ? 0.001 : 0), t;
        if (k == 30)
            continue;
        if (k == 25)
            read = sent + 0.061;
        if (k == 40)
            read = sent + 0.100;
        t = rl_fuse_cycle_stamp(&cy, read);
        if (k == 40 || k < 20)
            assert_true(t == read);
        else
            assert_true(fabs(t - sent) <= 0.001 + 1e-9);
        assert_true(t <= read);
    }
    assert_int_equal(cy.lost, 1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_offset),
        cmocka_unit_test(test_drift),
        cmocka_unit_test(test_truncated),
        cmocka_unit_test(test_resets),
        cmocka_unit_test(test_msg_add),
        cmocka_unit_test(test_cycle),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
