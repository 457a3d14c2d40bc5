#include "rl_test.h"
#include "rl_raster.h"
#include <math.h>

#define S 200
static uint8_t px[S * S], mk[S * S];

static int popcount(int v)
{
    int n = 0;
    for (; v; v >>= 1)
        n += v & 1;
    return n;
}

static double dark_area(const rl_image *t)
{
    double sum = 0;
    int x, y;
    for (y = 0; y < t->height; y++)
        for (x = 0; x < t->width; x++)
            sum += rl_image_at(t, x, y) / 255.0;
    return sum;
}

/* The anti-aliased dark area equals the analytic one: outer ring
 * pi(R^2 - 0.64R^2) plus each black code zone 0.64 pi R^2 / N. */
static void test_coverage_matches_area(void **state)
{
    int n, id;
    rl_image t = rl_image_view(S, S, S, px);
    (void)state;
    for (n = 2; n <= 8; n++) {
        rl_family f;
        assert_int_equal(rl_family_init(&f, n), RL_OK);
        for (id = 1; id <= rl_family_count(&f); id += (n > 5 ? 7 : 1)) {
            double R = S / 2.0, want;
            assert_int_equal(rl_raster_square(&f, id, NULL, &t, NULL), RL_OK);
            want = M_PI * R * R * (0.36 + 0.64 * popcount(id) / n);
            if (fabs(dark_area(&t) - want) > 0.002 * want)
                fail_msg("ring%d id %d: dark area %.1f, want %.1f", n, id, dark_area(&t), want);
        }
    }
}

static void test_off_centre_and_stride(void **state)
{
    rl_family f;
    uint8_t big[60 * 50];
    rl_image t = rl_image_view(40, 50, 60, big);
    (void)state;
    memset(big, 0x77, sizeof big);
    assert_int_equal(rl_family_init(&f, 3), RL_OK);
    assert_int_equal(rl_raster_draw(&f, 5, 10.0, 30.0, 8.0, NULL, &t, NULL), RL_OK);
    assert_int_equal(big[30 * 60 + 10], 255);         /* centre: 101 -> c3 = 1 */
    assert_int_equal(big[30 * 60 + 10 + 7], 255);     /* outer ring at 7 px */
    assert_int_equal(big[30 * 60 + 10 + 12], 0);      /* outside */
    assert_int_equal(big[30 * 60 + 45], 0x77);        /* beyond width: untouched */
}

static void test_cut_template(void **state)
{
    rl_family f;
    rl_image t = rl_image_view(S, S, S, px), m = rl_image_view(S, S, S, mk);
    rl_raster_cut cut = rl_raster_cut_side(0, (S - 1) / 2.0 + 0.25); /* keep x <= centre */
    double whole, half;
    int x, y, vis = 0;
    (void)state;
    assert_int_equal(rl_family_init(&f, 5), RL_OK);
    assert_int_equal(rl_raster_square(&f, 25, NULL, &t, NULL), RL_OK);
    whole = dark_area(&t);
    assert_int_equal(rl_raster_square(&f, 25, &cut, &t, &m), RL_OK);
    half = dark_area(&t);
    assert_true(fabs(half - whole / 2) < 0.01 * whole);
    for (y = 0; y < S; y++)
        for (x = 0; x < S; x++) {
            int in = x <= (S - 1) / 2;
            assert_int_equal(mk[y * S + x], in ? 255 : 0);
            vis += in;
            if (!in)
                assert_int_equal(px[y * S + x], 0);
        }
    assert_int_equal(vis, S * S / 2);
    cut = rl_raster_cut_side(3, 150.0); /* keep y >= 150 */
    assert_int_equal(rl_raster_square(&f, 25, &cut, &t, &m), RL_OK);
    assert_int_equal(mk[149 * S + 100], 0);
    assert_int_equal(mk[150 * S + 100], 255);
}

static void test_errors(void **state)
{
    rl_family f;
    rl_image t = rl_image_view(S, S, S, px), m = rl_image_view(10, 10, 10, mk);
    rl_image rect = rl_image_view(S, S / 2, S, px);
    (void)state;
    assert_int_equal(rl_family_init(&f, 5), RL_OK);
    assert_int_equal(rl_raster_square(&f, 31, NULL, &t, NULL), RL_ERANGE);
    assert_int_equal(rl_raster_square(&f, 0, NULL, &t, NULL), RL_ERANGE);
    assert_int_equal(rl_raster_square(&f, 25, NULL, &t, &m), RL_EINVAL);
    assert_int_equal(rl_raster_square(&f, 25, NULL, &rect, NULL), RL_EINVAL);
    assert_int_equal(rl_raster_draw(&f, 25, 5, 5, 0.0, NULL, &t, NULL), RL_EINVAL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_coverage_matches_area),
        cmocka_unit_test(test_off_centre_and_stride),
        cmocka_unit_test(test_cut_template),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
