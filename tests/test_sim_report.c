/* sim_report (issue 42): a `make sim` run judged against the simulator's
 * truth. Logs written here by hand; every expectation a hand calculation
 * (the truth and the fused pose in whole mm and degrees, the truth's
 * resolution). */
#include "rl_test.h"
#include <math.h>
#include "sim_report.h"

#define DEG (3.14159265358979323846 / 180)

static void put(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

/* one tick line: t, the fused pose, ARIA's (= fused), sigma, the truth, wp */
static void tick(FILE *f, double t, double fx, double fy, double fyaw, double tx, double ty, double tyaw, int wp)
{
    fprintf(f, "%.4f %.5f %.5f %.5f %.5f %.5f %.5f 0.001 %.3f %.3f %.6f %d\n", t, fx, fy, fyaw, fx, fy, fyaw, tx, ty,
            tyaw, wp);
}

static void error_at_the_truths_resolution(void **state)
{
    sim_tick k = {0};
    (void)state;
    k.fx = 1.0004; k.fy = 2.0006; k.tx = 1.000; k.ty = 2.001; /* 1000 = 1000, 2001 = 2001 */
    assert_true(fabs(sim_report_error_mm(&k)) < 1e-9);
    k.fx = 1.0034; k.fy = 2.0; k.tx = 1.0; k.ty = 2.004;      /* 3 and -4 mm */
    assert_true(fabs(sim_report_error_mm(&k) - 5) < 1e-9);
    k.fyaw = 10.4 * DEG; k.tyaw = 9 * DEG;                    /* 10 against 9 degrees */
    assert_true(fabs(sim_report_yaw_error_deg(&k) - 1) < 1e-9);
    k.fyaw = 179.6 * DEG; k.tyaw = -179 * DEG;                /* 180 against -179: 1 degree */
    assert_true(fabs(sim_report_yaw_error_deg(&k) - 1) < 1e-9);
}

/* before the route: not judged; on it: 3 and 4 mm; after the last waypoint: not */
static void route_rms_and_waypoints(void **state)
{
    char poses[1024], route[1024];
    sim_run r;
    char err[1200];
    FILE *f;
    (void)state;
    rl_test_path(poses, sizeof poses, "sim_report_poses.log");
    rl_test_path(route, sizeof route, "sim_report_route.log");
    f = fopen(poses, "w");
    assert_non_null(f);
    tick(f, 10.0, 1.1, 1.0, 0, 1.0, 1.0, 0, -1);        /* 100 mm, before the route */
    tick(f, 10.1, 1.003, 1.0, 0, 1.0, 1.0, 0, 0);       /* 3 mm: the route starts */
    tick(f, 10.2, 1.5, 1.004, 0, 1.5, 1.0, 0, 0);       /* 4 mm */
    tick(f, 10.4, 2.0, 1.0, 0, 2.0, 1.0, 0, 1);         /* 0 mm: the last waypoint reached */
    tick(f, 10.5, 2.0, 1.2, 0, 2.0, 1.0, 0, -1);        /* 200 mm after the route: not judged */
    fclose(f);
    put(route, "0 1.5 1.0 10.2 1.5 1.0 1.510 1.0\n"      /* the truth 10 mm off */
               "1 2.0 1.0 10.4 2.0 1.0 2.0 1.030\n");    /* 30 mm */
    sim_report_defaults(&r);
    assert_int_equal(sim_report_load(&r, poses, route, err, sizeof err), 0);
    sim_report_judge(&r);
    assert_int_equal(r.judged, 3);
    assert_true(fabs(r.rms_mm - sqrt((9.0 + 16.0) / 3)) < 1e-9);
    assert_true(fabs(r.max_mm - 4) < 1e-9);
    assert_true(fabs(r.worst_waypoint_mm - 30) < 1e-9);
    assert_true(fabs(r.start - 10.1) < 1e-9);
    sim_report_free(&r);
}

/* pushed 1 s into the route: 50, 20 mm, then 5, 4: back under 10 mm 0.2 s
 * after the push, those two ticks left out of the RMS */
static void push_recovery(void **state)
{
    char poses[1024];
    sim_run r;
    char err[1200];
    FILE *f;
    (void)state;
    rl_test_path(poses, sizeof poses, "sim_report_push.log");
    f = fopen(poses, "w");
    assert_non_null(f);
    tick(f, 20.0, 1.002, 1.0, 0, 1.0, 1.0, 0, 0);       /* the route's start, 2 mm */
    tick(f, 21.0, 1.0, 1.0, 0, 1.05, 1.0, 0, 0);        /* pushed: 50 mm */
    tick(f, 21.1, 1.0, 1.0, 0, 1.02, 1.0, 0, 0);        /* 20 */
    tick(f, 21.2, 1.0, 1.0, 0, 1.005, 1.0, 0, 0);       /* 5 */
    tick(f, 21.3, 1.0, 1.0, 0, 1.0, 1.004, 0, 0);       /* 4 */
    fclose(f);
    sim_report_defaults(&r);
    r.push_at = 1.0;
    assert_int_equal(sim_report_load(&r, poses, NULL, err, sizeof err), 0);
    sim_report_judge(&r);
    assert_true(fabs(r.recovery_s - 0.2) < 1e-6);
    assert_int_equal(r.excluded, 2);
    assert_int_equal(r.judged, 3);
    assert_true(fabs(r.rms_mm - sqrt((4.0 + 25.0 + 16.0) / 3)) < 1e-9);
    sim_report_free(&r);
}

/* a malformed line: one error naming the file and the line */
static void malformed_log(void **state)
{
    char poses[1024], want[1100];
    sim_run r;
    char err[1200];
    (void)state;
    rl_test_path(poses, sizeof poses, "sim_report_bad.log");
    put(poses, "10.0 1 1 0 1 1 0 0.001 1 1 0 0\n10.1 1 1 0 1 1 0 0.001\n");
    sim_report_defaults(&r);
    assert_int_equal(sim_report_load(&r, poses, NULL, err, sizeof err), -1);
    snprintf(want, sizeof want, "%s:2: ", poses);
    assert_true(strncmp(err, want, strlen(want)) == 0);
    sim_report_free(&r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(error_at_the_truths_resolution),
        cmocka_unit_test(route_rms_and_waypoints),
        cmocka_unit_test(push_recovery),
        cmocka_unit_test(malformed_log),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
