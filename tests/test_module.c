/* rl_module: a module found next to the program's folder (../lib/ringloc)
 * and its entry points; a missing module, one built for another layout,
 * or a missing symbol is one error line naming it. */
#include "rl_test.h"
#include "rl_module.h"
#ifdef RL_HAVE_LIBCAMERA
#include "cam_libcamera.h"
#endif
#ifdef RL_HAVE_SURVEY_MODULE
#include "rl_survey_ceres.h"
#endif

static void not_found(void)
{
}

static void check_fails(const rl_module *m, const char *symbol, const char *says)
{
    void (*fn)(void) = not_found;
    char err[512] = "";
    assert_int_equal(rl_module_symbol(m, symbol, &fn, err, sizeof err), RL_EUNSUPPORTED);
    assert_null(fn);
    assert_non_null(strstr(err, m->what));
    assert_non_null(strstr(err, m->file));
    if (strstr(err, says) == NULL)
        fail_msg("'%s' does not say '%s'", err, says);
    assert_null(strchr(err, '\n'));
}

static void test_missing_module_named(void **state)
{
    static const rl_module none = {"ringloc-nothing.so", "nothing at all", 1};
    (void)state;
    check_fails(&none, "rl_nothing", "cannot be loaded");
}

#if defined(RL_HAVE_LIBCAMERA) || defined(RL_HAVE_SURVEY_MODULE)
/* module m: built for the tests (the build's lib/ringloc, which tests/
 * reaches as ../lib/ringloc, as a program does); its entry point
 * resolves, nothing it did not mark for export does, and the same file
 * taken for another layout is refused */
static void check_module(rl_module m, const char *entry, const char *hidden)
{
    void (*fn)(void) = NULL;
    char err[512] = "";
    assert_int_equal(rl_module_symbol(&m, entry, &fn, err, sizeof err), RL_OK);
    assert_non_null(fn);
    check_fails(&m, hidden, hidden);
    m.abi += 1;
    check_fails(&m, entry, "another version or layout");
}
#endif

static void test_survey_module(void **state)
{
    (void)state;
#ifdef RL_HAVE_SURVEY_MODULE
    {
        /* rl_pose_fit_model: the module's own copy of the pose model, hidden */
        rl_module m = RL_SURVEY_CERES_MODULE;
        check_module(m, "rl_survey_adjust_ceres", "rl_pose_fit_model");
    }
#else
    skip(); /* a firmware-only build has no survey */
#endif
}

static void test_libcamera_module(void **state)
{
    (void)state;
#ifdef RL_HAVE_LIBCAMERA
    {
        rl_module m = RL_CAM_LIBCAMERA_MODULE;
        check_module(m, "rl_cam_libcamera_open", "rl_clock_now_us");
        check_module(m, "rl_cam_libcamera_probe", "rl_image_view");
    }
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
