/* rl_tone_midway against its definition read off the curve's table: the
 * first grey level v under 255 whose light at v + 0.5 (halfway between
 * the table's entries v and v + 1) reaches the mean of the two levels'
 * light, else 255; every pair of levels, for curves of gamma 1 to 3. By
 * hand at gamma 1: 20 and 200 meet at 110 (109.5 falls short of 110). */
#include "rl_test.h"
#include "rl_tone.h"

/* The definition, scanned level by level. */
static int midway_scan(const rl_tone *t, int g0, int g1)
{
    double mid = 0.5 * (rl_tone_light(t, g0) + rl_tone_light(t, g1));
    int v;
    for (v = 0; v < 255; v++)
        if (!(rl_tone_light(t, v + 0.5) < mid))
            return v;
    return 255;
}

static void test_midway_by_hand(void **state)
{
    rl_tone t;
    (void)state;
    rl_tone_init(&t, 1.0);
    assert_int_equal(rl_tone_midway(&t, 20, 200), 110);
    assert_int_equal(rl_tone_midway(&t, 0, 0), 0);
    assert_int_equal(rl_tone_midway(&t, 255, 255), 255);
    assert_int_equal(rl_tone_midway(&t, 254, 255), 254); /* 254.5 is the midway itself */
}

static void test_midway_every_pair(void **state)
{
    static const double gammas[] = {1.0, 1.5, 2.2, 3.0};
    int k, g0, g1;
    (void)state;
    for (k = 0; k < 4; k++) {
        rl_tone t;
        rl_tone_init(&t, gammas[k]);
        for (g0 = 0; g0 < 256; g0++)
            for (g1 = g0; g1 < 256; g1++)
                if (rl_tone_midway(&t, g0, g1) != midway_scan(&t, g0, g1))
                    fail_msg("gamma %.1f, %d and %d: %d, the definition %d", gammas[k], g0, g1,
                             rl_tone_midway(&t, g0, g1), midway_scan(&t, g0, g1));
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_midway_by_hand),
        cmocka_unit_test(test_midway_every_pair),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
