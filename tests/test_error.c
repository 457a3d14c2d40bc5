#include "rl_test.h"
#include "rl_error.h"

static const rl_err all[] = {RL_EINVAL, RL_ENOMEM, RL_ELIMIT, RL_ERANGE, RL_EFORMAT, RL_EIO,
                             RL_ENOTFOUND, RL_ETIMEOUT, RL_ENODEV, RL_ETOOFEW,
                             RL_EUNSUPPORTED, RL_EAMBIGUOUS};

static void test_ok_is_zero_errors_negative(void **state)
{
    size_t i;
    (void)state;
    assert_int_equal(RL_OK, 0);
    for (i = 0; i < sizeof all / sizeof all[0]; i++)
        assert_true(all[i] < 0);
}

static void test_messages_distinct_and_static(void **state)
{
    size_t i, j;
    (void)state;
    assert_string_equal(rl_strerror(RL_OK), "success");
    for (i = 0; i < sizeof all / sizeof all[0]; i++) {
        const char *m = rl_strerror(all[i]);
        assert_non_null(m);
        assert_true(strlen(m) > 3);
        assert_string_not_equal(m, "unknown error");
        assert_ptr_equal(m, rl_strerror(all[i]));
        for (j = 0; j < i; j++)
            assert_string_not_equal(m, rl_strerror(all[j]));
    }
    assert_string_equal(rl_strerror((rl_err)-999), "unknown error");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ok_is_zero_errors_negative),
        cmocka_unit_test(test_messages_distinct_and_static),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
