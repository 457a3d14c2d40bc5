/* An application built with its own -DRL_FUSE_HISTORY=16 (CMake gives it)
 * against the library built without: the struct it compiles against must
 * be the library's. Before the history moved to the caller's memory, the
 * macro shrank the application's rl_fuse to a ninth of the library's and
 * rl_fuse_init's memset ran 30 kB past it (over the guard below). Now the
 * history is the caller's array, of any length chosen at run time. */
#include <string.h>
#include "rl_test.h"
#include "rl_fuse.h"

#ifndef RL_FUSE_HISTORY
#error "built without -DRL_FUSE_HISTORY: the test would prove nothing"
#endif

static struct {
    rl_fuse f;
    unsigned char guard[65536]; /* what an overflow of the struct would write over */
} app;

static void test_layout_is_the_librarys(void **state)
{
    static rl_fuse_entry hist[RL_FUSE_HISTORY];
    rl_fuse_config cfg;
    rl_fuse_frame fr;
    rl_fuse_pose p;
    size_t i;
    int k;
    (void)state;
    memset(app.guard, 0xA5, sizeof app.guard);
    rl_fuse_defaults(&cfg);
    assert_int_equal(rl_fuse_init(&app.f, &cfg, hist, RL_FUSE_HISTORY), RL_OK);
    for (k = 0; k < 200; k++) /* the ring wraps many times over its 16 entries */
        assert_int_equal(rl_fuse_odometry(&app.f, k * 0.02, k * 0.02, 0, 0), RL_OK);
    memset(&fr, 0, sizeof fr);
    fr.t = 3.6; /* 16 samples of 20 ms: 0.3 s back at most, 3.68 s */
    assert_int_equal(rl_fuse_frame_add(&app.f, &fr), RL_ERANGE);
    assert_int_equal((int)app.f.stats.too_old, 1);
    fr.t = 199 * 0.02 - 0.1;
    fr.x = fr.t;
    assert_int_equal(rl_fuse_frame_add(&app.f, &fr), RL_OK);
    assert_int_equal(rl_fuse_pose_at(&app.f, 199 * 0.02, &p), RL_OK);
    assert_true(p.x > 3.97 && p.x < 3.99);
    for (i = 0; i < sizeof app.guard; i++)
        if (app.guard[i] != 0xA5)
            fail_msg("the library wrote %zu bytes past the application's rl_fuse", i + 1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_layout_is_the_librarys),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
