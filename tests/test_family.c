#include "rl_test.h"
#include "rl_family.h"
#include <math.h>

static void test_parse(void **state)
{
    rl_family f;
    (void)state;
    assert_int_equal(rl_family_parse("ring5", &f), RL_OK);
    assert_int_equal(f.bits, 5);
    assert_int_equal(rl_family_parse("ring2", &f), RL_OK);
    assert_int_equal(rl_family_parse("ring8", &f), RL_OK);
    assert_int_equal(rl_family_parse("ring1", &f), RL_ERANGE);
    assert_int_equal(rl_family_parse("ring9", &f), RL_ERANGE);
    assert_int_equal(rl_family_parse("ring0", &f), RL_ERANGE);
    assert_int_equal(rl_family_parse("ring", &f), RL_EFORMAT);
    assert_int_equal(rl_family_parse("ring5x", &f), RL_EFORMAT);
    assert_int_equal(rl_family_parse("RING5", &f), RL_EFORMAT);
    assert_int_equal(rl_family_parse("tag36h11", &f), RL_EFORMAT);
    assert_int_equal(rl_family_parse("ring99999", &f), RL_EFORMAT);
    assert_int_equal(rl_family_parse(NULL, &f), RL_EINVAL);
}

static void test_spec_example(void **state)
{
    rl_family f;
    char code[RL_MAX_BITS + 1];
    int id;
    (void)state;
    assert_int_equal(rl_family_init(&f, 5), RL_OK);
    assert_int_equal(rl_family_count(&f), 30);
    assert_int_equal(rl_family_code(&f, 25, code, sizeof code), RL_OK);
    assert_string_equal(code, "11001");
    assert_int_equal(rl_family_id(&f, "11001", &id), RL_OK);
    assert_int_equal(id, 25);
    assert_int_equal(rl_family_bit(&f, 25, 1), 1);
    assert_int_equal(rl_family_bit(&f, 25, 3), 0);
    assert_int_equal(rl_family_bit(&f, 25, 5), 1);
}

static void test_round_trip_every_id_every_family(void **state)
{
    int n, id, back, k, total = 0;
    char code[RL_MAX_BITS + 1];
    (void)state;
    for (n = RL_FAMILY_MIN_BITS; n <= RL_MAX_BITS; n++) {
        rl_family f;
        assert_int_equal(rl_family_init(&f, n), RL_OK);
        assert_int_equal(rl_family_count(&f), (1 << n) - 2);
        for (id = 1; id <= (1 << n) - 2; id++) {
            int v = 0;
            assert_int_equal(rl_family_code(&f, id, code, sizeof code), RL_OK);
            assert_int_equal((int)strlen(code), n);
            for (k = 0; k < n; k++) /* independent decode: c_1 is the MSB */
                v = v * 2 + (code[k] - '0');
            assert_int_equal(v, id);
            assert_int_equal(rl_family_id(&f, code, &back), RL_OK);
            assert_int_equal(back, id);
            total++;
        }
        /* invalid ids */
        assert_int_equal(rl_family_code(&f, 0, code, sizeof code), RL_ERANGE);
        assert_int_equal(rl_family_code(&f, (1 << n) - 1, code, sizeof code), RL_ERANGE);
        assert_int_equal(rl_family_code(&f, 1 << n, code, sizeof code), RL_ERANGE);
        assert_int_equal(rl_family_code(&f, -3, code, sizeof code), RL_ERANGE);
        assert_false(rl_family_valid(&f, 0));
        assert_false(rl_family_valid(&f, (1 << n) - 1));
        memset(code, '0', (size_t)n);
        code[n] = '\0';
        assert_int_equal(rl_family_id(&f, code, &back), RL_ERANGE);
        memset(code, '1', (size_t)n);
        assert_int_equal(rl_family_id(&f, code, &back), RL_ERANGE);
        code[0] = '2';
        assert_int_equal(rl_family_id(&f, code, &back), RL_EFORMAT);
        assert_int_equal(rl_family_code(&f, 1, code, (size_t)n), RL_ENOMEM);
    }
    assert_int_equal(total, 2 + 6 + 14 + 30 + 62 + 126 + 254);
    {
        rl_family f5;
        assert_int_equal(rl_family_init(&f5, 5), RL_OK);
        assert_int_equal(rl_family_id(&f5, "1100", &back), RL_EFORMAT);
        assert_int_equal(rl_family_id(&f5, "110011", &back), RL_EFORMAT);
    }
}

static void test_radii_equal_area(void **state)
{
    int n, k;
    (void)state;
    for (n = RL_FAMILY_MIN_BITS; n <= RL_MAX_BITS; n++) {
        rl_family f;
        double r[RL_MAX_BITS + 2];
        double total = 0.8 * 0.8;
        assert_int_equal(rl_family_init(&f, n), RL_OK);
        rl_family_radii(&f, r);
        assert_true(r[0] == 1.0);
        assert_true(fabs(r[1] - 0.8) < 1e-12);
        assert_true(r[n + 1] == 0.0);
        for (k = 1; k <= n; k++) {
            double area = r[k] * r[k] - r[k + 1] * r[k + 1];
            assert_true(fabs(area - total / n) < 1e-12);
            assert_true(r[k + 1] < r[k]);
        }
    }
}

static void test_dark_at(void **state)
{
    rl_family f;
    (void)state;
    assert_int_equal(rl_family_init(&f, 5), RL_OK);
    /* 11001: zones 1,2 black, 3,4 white, 5 (centre) black */
    assert_int_equal(rl_family_dark_at(&f, 25, 1.01), 0);
    assert_int_equal(rl_family_dark_at(&f, 25, 0.9), 1);
    assert_int_equal(rl_family_dark_at(&f, 25, 0.8 * sqrt(4.5 / 5)), 1);
    assert_int_equal(rl_family_dark_at(&f, 25, 0.8 * sqrt(3.5 / 5)), 1);
    assert_int_equal(rl_family_dark_at(&f, 25, 0.8 * sqrt(2.5 / 5)), 0);
    assert_int_equal(rl_family_dark_at(&f, 25, 0.8 * sqrt(1.5 / 5)), 0);
    assert_int_equal(rl_family_dark_at(&f, 25, 0.8 * sqrt(0.5 / 5)), 1);
    assert_int_equal(rl_family_dark_at(&f, 25, 0.0), 1);
}

/* The outer black band's inner edge, by hand for ring5 (zone k's outer
 * radius 0.8 sqrt((6 - k) / 5)): 00111 (7) white zones 1-2 inside the ring,
 * 0.180 R wide: 0.8; 01010 (10) zone 1 white but only 0.085 R: none;
 * 10011 (19) black zone 1, white 2-3 (0.209 R): 0.7155; 11110 (30) the
 * white central disk: 0.3578. */
static void band_inner_by_hand(void **state)
{
    rl_family f;
    (void)state;
    assert_int_equal(rl_family_init(&f, 5), RL_OK);
    assert_true(fabs(rl_family_band_inner(&f, 7) - 0.8) < 1e-9);
    assert_true(rl_family_band_inner(&f, 10) == 0.0);
    assert_true(fabs(rl_family_band_inner(&f, 19) - 0.8 * sqrt(4.0 / 5)) < 1e-9);
    assert_true(fabs(rl_family_band_inner(&f, 30) - 0.8 * sqrt(1.0 / 5)) < 1e-9);
    assert_true(rl_family_band_inner(&f, 31) == 0.0); /* not an id */
}

/* Zone twins by hand, ring5 (ids 1 .. 30): 1 = 00001 -> 00011, 00101,
 * 01001, 10001 (00000 is no id); 30 = 11110 -> 11100, 11010, 10110,
 * 01110 (11111 is no id); 21 = 10101 -> all five flips valid. */
static void zone_twins_by_hand(void **state)
{
    rl_family fam;
    int out[RL_MAX_BITS], n;
    const int want1[] = {3, 5, 9, 17}, want30[] = {28, 26, 22, 14}, want21[] = {20, 23, 17, 29, 5};
    (void)state;
    assert_int_equal(rl_family_init(&fam, 5), RL_OK);
    n = rl_family_zone_twins(&fam, 1, out);
    assert_int_equal(n, 4);
    assert_memory_equal(out, want1, sizeof want1);
    n = rl_family_zone_twins(&fam, 30, out);
    assert_int_equal(n, 4);
    assert_memory_equal(out, want30, sizeof want30);
    n = rl_family_zone_twins(&fam, 21, out);
    assert_int_equal(n, 5);
    assert_memory_equal(out, want21, sizeof want21);
}

/* Every family, every id: the set is exactly the ids whose code differs
 * in one zone (brute force over every id of the family: one bit of the
 * xor set, and valid), none twice. */
static void zone_twins_are_the_one_zone_ids(void **state)
{
    int bits;
    (void)state;
    for (bits = RL_FAMILY_MIN_BITS; bits <= RL_MAX_BITS; bits++) {
        rl_family fam;
        int id, other;
        assert_int_equal(rl_family_init(&fam, bits), RL_OK);
        for (id = 0; id < (1 << bits); id++) {
            int out[RL_MAX_BITS], n, k, want = 0;
            if (!rl_family_valid(&fam, id))
                continue;
            n = rl_family_zone_twins(&fam, id, out);
            for (other = 0; other < (1 << bits); other++) {
                int x = id ^ other, one = x != 0 && (x & (x - 1)) == 0, found = 0;
                for (k = 0; k < n; k++)
                    found += out[k] == other;
                if (one && rl_family_valid(&fam, other)) {
                    want++;
                    assert_int_equal(found, 1);
                } else
                    assert_int_equal(found, 0);
            }
            assert_int_equal(n, want);
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_parse),
        cmocka_unit_test(test_spec_example),
        cmocka_unit_test(test_round_trip_every_id_every_family),
        cmocka_unit_test(test_radii_equal_area),
        cmocka_unit_test(test_dark_at),
        cmocka_unit_test(band_inner_by_hand),
        cmocka_unit_test(zone_twins_by_hand),
        cmocka_unit_test(zone_twins_are_the_one_zone_ids),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
