/* rl_hist_kmeans passes the empty grey levels by (issue 43: a local
 * window's histogram holds some 600 pixels, most of its levels empty):
 * an empty level adds +0.0 to sums that are +0.0 or more, so no bit of a
 * sum moves. Held to the old loops, kept here as the oracle (every level
 * summed), on sparse and dense random histograms, k 1-3, ranges cut at
 * both ends: the same bounds and the same centres, bit for bit. */
#include "rl_test.h"
#include <string.h>
#include "rl_hist.c"

/* the old coarse_bounds and lloyd: every level summed */
static void old_coarse_bounds(const rl_hist *h, int lo, int hi, int k, int *bound)
{
    double cnt[257], sum[257], sq[257];
    int i, m, n = hi - lo, nc, b[4];
    nc = (n + COARSE - 1) / COARSE;
    cnt[0] = sum[0] = sq[0] = 0.0;
    for (i = 0; i < nc; i++) {
        double c = 0, s = 0, q = 0;
        int v;
        for (v = lo + i * COARSE; v < lo + (i + 1) * COARSE && v < hi; v++) {
            c += h->bin[v];
            s += (double)h->bin[v] * v;
            q += (double)h->bin[v] * v * v;
        }
        cnt[i + 1] = cnt[i] + c;
        sum[i + 1] = sum[i] + s;
        sq[i + 1] = sq[i] + q;
    }
    kmeans_dp(cnt, sum, sq, nc, k, b);
    for (m = 0; m <= k; m++)
        bound[m] = lo + b[m] * COARSE < hi ? lo + b[m] * COARSE : hi;
}

static void old_lloyd(const rl_hist *h, int k, int *bound, double *centres)
{
    int i, m, iter;
    for (iter = 0; iter < 64; iter++) {
        int changed = 0;
        for (m = 0; m < k; m++) {
            double c = 0, s = 0;
            for (i = bound[m]; i < bound[m + 1]; i++) {
                c += h->bin[i];
                s += (double)h->bin[i] * i;
            }
            centres[m] = c > 0 ? s / c : 0.5 * (bound[m] + bound[m + 1] - 1);
        }
        for (m = 1; m < k; m++) {
            int nb = (int)floor(0.5 * (centres[m - 1] + centres[m])) + 1;
            if (nb <= bound[m - 1])
                nb = bound[m - 1] + 1;
            if (nb >= bound[m + 1])
                nb = bound[m + 1] - 1;
            if (nb != bound[m]) {
                bound[m] = nb;
                changed = 1;
            }
        }
        if (!changed)
            break;
    }
}

static rl_err old_kmeans(const rl_hist *h, int lo, int hi, int k, double *centres, int *start)
{
    int occupied = 0, i, m, bound[4];
    for (i = lo; i < hi; i++)
        occupied += h->bin[i] != 0;
    if (occupied < k)
        return RL_ERANGE;
    old_coarse_bounds(h, lo, hi, k, bound);
    old_lloyd(h, k, bound, centres);
    polish(h, lo, hi, k, bound, centres);
    for (m = 0; m < k; m++)
        start[m] = bound[m];
    return RL_OK;
}

static unsigned rnd = 88172645u;
static unsigned next(void)
{
    rnd ^= rnd << 13;
    rnd ^= rnd >> 17;
    rnd ^= rnd << 5;
    return rnd;
}

static void kmeans_passes_empty_levels(void **state)
{
    int t, same = 0, differ_centres = 0;
    (void)state;
    for (t = 0; t < 20000; t++) {
        rl_hist h;
        int k = 1 + t % 3, lo = t % 5 == 0 ? (int)(next() % 40) : 0;
        int hi = t % 7 == 0 ? 200 + (int)(next() % 57) : 256;
        int pixels = t % 2 ? 600 : 20 + (int)(next() % 60000), i, m, start[3], ostart[3];
        int modes = 1 + (int)(next() % 3), centre[3], spread[3];
        double c[3], oc[3];
        rl_err e, oe;
        memset(&h, 0, sizeof h);
        for (m = 0; m < modes; m++) {
            centre[m] = (int)(next() % 256);
            spread[m] = 1 + (int)(next() % 40);
        }
        for (i = 0; i < pixels; i++) {
            int v;
            m = (int)(next() % (unsigned)modes);
            v = centre[m] + (int)(next() % (unsigned)(2 * spread[m] + 1)) - spread[m];
            h.bin[v < 0 ? 0 : v > 255 ? 255 : v]++;
        }
        h.total = (uint32_t)pixels;
        e = rl_hist_kmeans(&h, lo, hi, k, c, start);
        oe = old_kmeans(&h, lo, hi, k, oc, ostart);
        assert_int_equal(e, oe);
        if (e != RL_OK)
            continue;
        for (m = 0; m < k; m++) {
            assert_int_equal(start[m], ostart[m]);
            assert_memory_equal(&c[m], &oc[m], sizeof c[m]);
        }
        same++;
        differ_centres += k > 1 && c[0] != c[k - 1];
    }
    printf("%d clusterings, %d of them of distinct centres: the same bounds and centres as every level "
           "summed\n",
           same, differ_centres);
    assert_true(same > 15000 && differ_centres > 5000);
}

int main(void)
{
    const struct CMUnitTest tests[] = {cmocka_unit_test(kmeans_passes_empty_levels)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
