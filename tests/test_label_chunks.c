/* The labeller's skip of a whole chunk (rl_label.c, chunk_under): a chunk
 * outside a run is passed by when every pixel is under the band's foot
 * lo. Passing by a chunk that holds a pixel of the band loses its runs;
 * not passing by one that holds none only costs its tests, which the
 * flood-fill comparisons (test_label_bounds) cannot see. So the skip is
 * held here to its definition, the chunk's largest byte under lo, both
 * ways: chunks whose largest byte m (0-255) is at every place, the rest
 * of them random below m, against every foot 1-256. On x86 that is SSE2's
 * maximum; elsewhere (aarch64 in the cross build, RL_NO_VECTOR_EXT in the
 * sanitizer build) the 64-bit words. */
#include "rl_test.h"
#include "rl_label.c"

static unsigned seed = 4321;
static unsigned rnd(void)
{
    seed = seed * 1103515245u + 12345u;
    return seed >> 8;
}

static void a_chunk_is_under_lo_when_its_largest_byte_is(void **state)
{
    uint8_t chunk[CHUNK];
    int m, lo, i, wrong = 0, cases = 0;
    (void)state;
    for (m = 0; m < 256; m++)
        for (i = 0; i < CHUNK; i++) {
            int k;
            for (k = 0; k < CHUNK; k++) /* below m, a quarter of them just below */
                chunk[k] = (uint8_t)(m == 0 ? 0 : rnd() % 4 == 0 ? m - 1 : (int)(rnd() % (unsigned)m));
            chunk[i] = (uint8_t)m;
            for (lo = 1; lo <= 256; lo++) {
                wrong += chunk_under(chunk, lo) != (m < lo);
                cases++;
            }
        }
    printf("  %d chunks and feet: %d wrong\n", cases, wrong);
    assert_int_equal(wrong, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(a_chunk_is_under_lo_when_its_largest_byte_is),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
