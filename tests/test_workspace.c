#include "rl_test.h"
#include "rl_workspace.h"

static uint8_t block[4096 + 64];

static void test_alignment_from_unaligned_block(void **state)
{
    size_t off, align;
    (void)state;
    for (off = 0; off < 16; off++) {
        rl_ws ws;
        rl_ws_init(&ws, block + off, 1024);
        for (align = 1; align <= 64; align *= 2) {
            void *p;
            assert_int_equal(rl_ws_alloc(&ws, 3, align, &p), RL_OK);
            assert_non_null(p);
            assert_int_equal((uintptr_t)p % align, 0);
            assert_true((uint8_t *)p >= block + off);
            assert_true((uint8_t *)p + 3 <= block + off + 1024);
        }
    }
}

static void test_too_small_fails_cleanly(void **state)
{
    rl_ws ws;
    void *a, *b;
    size_t used;
    (void)state;
    rl_ws_init(&ws, block, 100);
    assert_int_equal(rl_ws_alloc(&ws, 60, 1, &a), RL_OK);
    used = ws.used;
    b = (void *)1;
    assert_int_equal(rl_ws_alloc(&ws, 60, 1, &b), RL_ENOMEM);
    assert_null(b);
    assert_int_equal(ws.used, used);
    /* a huge request must not wrap around */
    assert_int_equal(rl_ws_alloc(&ws, (size_t)-8, 16, &b), RL_ENOMEM);
    assert_int_equal(rl_ws_alloc(&ws, 40, 1, &b), RL_OK);
    assert_int_equal(rl_ws_remaining(&ws), 0);
    assert_int_equal(rl_ws_alloc(&ws, 1, 3, &b), RL_EINVAL);
    assert_int_equal(rl_ws_alloc(&ws, 1, 0, &b), RL_EINVAL);
}

static void test_slices_do_not_overlap(void **state)
{
    rl_ws ws;
    uint8_t *p[20];
    int i, j;
    (void)state;
    rl_ws_init(&ws, block + 3, 2000);
    for (i = 0; i < 20; i++) {
        assert_int_equal(rl_ws_alloc(&ws, (size_t)(i * 7 + 1), 8, (void **)&p[i]), RL_OK);
        memset(p[i], i, (size_t)(i * 7 + 1));
    }
    for (i = 0; i < 20; i++)
        for (j = 0; j < i * 7 + 1; j++)
            assert_int_equal(p[i][j], i);
}

static void test_mark_and_reset(void **state)
{
    rl_ws ws;
    void *a, *b, *c;
    size_t m;
    (void)state;
    rl_ws_init(&ws, block, 256);
    assert_int_equal(rl_ws_alloc(&ws, 10, 16, &a), RL_OK);
    m = rl_ws_mark(&ws);
    assert_int_equal(rl_ws_alloc(&ws, 100, 16, &b), RL_OK);
    rl_ws_reset(&ws, m);
    assert_int_equal(rl_ws_alloc(&ws, 100, 16, &c), RL_OK);
    assert_ptr_equal(b, c);
    assert_true(ws.peak >= 110);
}

static void sequence(rl_ws *ws, int *failures)
{
    void *p;
    size_t m;
    if (rl_ws_alloc(ws, 33, 16, &p) != RL_OK) (*failures)++;
    if (rl_ws_alloc(ws, 7, 1, &p) != RL_OK) (*failures)++;
    m = rl_ws_mark(ws);
    if (rl_ws_alloc(ws, 500, 64, &p) != RL_OK) (*failures)++;
    rl_ws_reset(ws, m);
    if (rl_ws_alloc(ws, 200, 8, &p) != RL_OK) (*failures)++;
}

static void test_sizing_counts_enough(void **state)
{
    rl_ws sizing, ws;
    size_t off;
    int failures = 0;
    void *p;
    (void)state;
    rl_ws_init_sizing(&sizing);
    assert_true(rl_ws_is_sizing(&sizing));
    sequence(&sizing, &failures);
    assert_int_equal(failures, 0);
    assert_int_equal(rl_ws_alloc(&sizing, 1, 1, &p), RL_OK);
    assert_null(p);
    assert_true(sizing.peak >= 33 + 7 + 500);
    for (off = 0; off < 64; off++) {
        rl_ws_init(&ws, block + off, sizing.peak);
        sequence(&ws, &failures);
        assert_int_equal(failures, 0);
    }
    /* and a block clearly too small fails */
    rl_ws_init(&ws, block, 300);
    sequence(&ws, &failures);
    assert_true(failures > 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_alignment_from_unaligned_block),
        cmocka_unit_test(test_too_small_fails_cleanly),
        cmocka_unit_test(test_slices_do_not_overlap),
        cmocka_unit_test(test_mark_and_reset),
        cmocka_unit_test(test_sizing_counts_enough),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
