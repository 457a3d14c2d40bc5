/* rl_module: a module found on the program's run path and its entry
 * points; a missing module or symbol is one error naming it. */
#include "rl_test.h"
#include "rl_module.h"

static void not_found(void)
{
}

static void test_missing_module_named(void **state)
{
    void (*fn)(void) = not_found;
    char err[512] = "";
    (void)state;
    assert_int_equal(rl_module_symbol("ringloc-nothing.so", "rl_nothing", &fn, err, sizeof err),
                     RL_EUNSUPPORTED);
    assert_null(fn);
    assert_non_null(strstr(err, "ringloc-nothing.so"));
    assert_null(strchr(err, '\n'));
}

/* module: built beside the tests (the build's lib/ringloc), found through
 * the test's run path as a program finds it; its entry point resolves and
 * nothing it did not mark for export does. */
static void check_module(const char *module, const char *entry, const char *hidden)
{
    void (*fn)(void) = NULL;
    char err[512] = "";
    assert_int_equal(rl_module_symbol(module, entry, &fn, err, sizeof err), RL_OK);
    assert_non_null(fn);
    fn = not_found;
    assert_int_equal(rl_module_symbol(module, hidden, &fn, err, sizeof err), RL_EUNSUPPORTED);
    assert_null(fn);
    assert_non_null(strstr(err, module));
    assert_non_null(strstr(err, hidden));
}

static void test_survey_module(void **state)
{
    (void)state;
#ifdef RL_HAVE_SURVEY_MODULE
    /* rl_pose_fit_model: the module's own copy of the pose model, hidden */
    check_module("ringloc-ceres.so", "rl_survey_adjust_ceres", "rl_pose_fit_model");
#else
    skip(); /* a firmware-only build has no survey */
#endif
}

static void test_libcamera_module(void **state)
{
    (void)state;
#ifdef RL_HAVE_LIBCAMERA
    check_module("ringloc-libcamera.so", "rl_cam_libcamera_open", "rl_clock_now_us");
    check_module("ringloc-libcamera.so", "rl_cam_libcamera_probe", "rl_image_view");
#else
    skip();
#endif
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_missing_module_named),
        cmocka_unit_test(test_survey_module),
        cmocka_unit_test(test_libcamera_module),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
