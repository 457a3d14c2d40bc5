#include "rl_test.h"
#include "rl_image.h"

static void test_view_and_valid(void **state)
{
    uint8_t px[4 * 3];
    rl_image img = rl_image_view(3, 3, 4, px);
    (void)state;
    assert_true(rl_image_valid(&img));
    img.stride = 2;
    assert_false(rl_image_valid(&img));
    img = rl_image_view(0, 3, 4, px);
    assert_false(rl_image_valid(&img));
    img = rl_image_view(3, 3, 4, NULL);
    assert_false(rl_image_valid(&img));
    assert_false(rl_image_valid(NULL));
}

static void test_sub_honours_stride(void **state)
{
    uint8_t px[10 * 6];
    int x, y;
    rl_image img = rl_image_view(8, 6, 10, px), sub;
    (void)state;
    for (y = 0; y < 6; y++)
        for (x = 0; x < 10; x++)
            px[y * 10 + x] = (uint8_t)(y * 16 + x);
    assert_int_equal(rl_image_sub(&img, 2, 3, 4, 2, &sub), RL_OK);
    assert_int_equal(sub.width, 4);
    assert_int_equal(sub.height, 2);
    assert_int_equal(sub.stride, 10);
    assert_int_equal(rl_image_at(&sub, 0, 0), 3 * 16 + 2);
    assert_int_equal(rl_image_at(&sub, 3, 1), 4 * 16 + 5);
}

static void test_sub_rejects_outside(void **state)
{
    uint8_t px[8 * 6];
    rl_image img = rl_image_view(8, 6, 8, px), sub;
    (void)state;
    assert_int_equal(rl_image_sub(&img, 5, 0, 4, 1, &sub), RL_EINVAL);
    assert_int_equal(rl_image_sub(&img, 0, 5, 1, 2, &sub), RL_EINVAL);
    assert_int_equal(rl_image_sub(&img, -1, 0, 1, 1, &sub), RL_EINVAL);
    assert_int_equal(rl_image_sub(&img, 0, 0, 0, 1, &sub), RL_EINVAL);
    assert_int_equal(rl_image_sub(&img, 0, 0, 8, 6, &sub), RL_OK);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_view_and_valid),
        cmocka_unit_test(test_sub_honours_stride),
        cmocka_unit_test(test_sub_rejects_outside),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
