/* The darkness-weighted centroid (rl_refine_centre_rows): on a dark disk
 * drawn here, a start 2 px off lands within 0.05 px of the disk's centre
 * (a hand calculation: the centroid of a symmetric disk is its centre);
 * and on random images, centres, radii, levels and row steps, its four
 * sums a row (a vector where the compiler has one) give the bits of the
 * plain loop written here: pixel x + k's weight and weight * x in sum k,
 * the row's tail in sum 0, the sums added (0 + 1) + (2 + 3). */
#include "rl_test.h"
#include <math.h>
#include "rl_refine.h"

#define W 120
#define H 100
static uint8_t px[W * H];

/* The plain loop: weights min(max(bg - v, 0), span), the disk's chords
 * from every ystep-th row; the new centre into *cx, *cy and the weight
 * seen returned (0: none, the centre kept). */
static double plain(const rl_image *img, const rl_levels *lv, double *cx, double *cy, double r, int ystep)
{
    double sw = 0, sx = 0, sy = 0, span = lv->bg - lv->fg, rr = (r + 1) * (r + 1);
    int x0 = (int)floor(*cx - r - 1), x1 = (int)ceil(*cx + r + 1), y0 = (int)floor(*cy - r - 1),
        y1 = (int)ceil(*cy + r + 1), y;
    if (span < 1 || x0 < 0 || y0 < 0 || x1 >= img->width || y1 >= img->height)
        return 0;
    for (y = y0; y <= y1; y += ystep) {
        const uint8_t *row = img->data + y * img->stride;
        double dy = y - *cy, h2 = rr - dy * dy, h, s[4] = {0, 0, 0, 0}, t[4] = {0, 0, 0, 0}, rw, rx;
        int xa, xb, x;
        if (h2 < 0)
            continue;
        h = sqrt(h2);
        xa = (int)ceil(*cx - h);
        xb = (int)floor(*cx + h);
        if (xa < x0) xa = x0;
        if (xb > x1) xb = x1;
        for (x = xa; x <= xb; x++) {
            double d = lv->bg - row[x], wgt = d <= 0 ? 0.0 : d > span ? span : d;
            /* in fours from xa; past the last whole four, in sum 0 */
            int k = xa + (x - xa) / 4 * 4 + 3 <= xb ? (x - xa) % 4 : 0;
            s[k] += wgt;
            t[k] += wgt * x;
        }
        rw = (s[0] + s[1]) + (s[2] + s[3]);
        rx = (t[0] + t[1]) + (t[2] + t[3]);
        sw += rw;
        sx += rx;
        sy += rw * y;
    }
    if (sw > 0) {
        *cx = sx / sw;
        *cy = sy / sw;
    }
    return sw;
}

static void centroid_of_a_disk(void **state)
{
    rl_image img = rl_image_view(W, H, W, px);
    rl_levels lv;
    double cx = 52.3 + 2.0, cy = 47.6 - 1.0;
    int x, y;
    (void)state;
    memset(&lv, 0, sizeof lv);
    lv.bg = 200;
    lv.fg = 40;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            /* 16 subsamples a pixel: its share of the disk, as grey */
            int in = 0, i, j;
            for (i = 0; i < 4; i++)
                for (j = 0; j < 4; j++) {
                    double u = x - 0.375 + 0.25 * i - 52.3, v = y - 0.375 + 0.25 * j - 47.6;
                    in += u * u + v * v < 12.0 * 12.0;
                }
            px[y * W + x] = (uint8_t)(200 - 160 * in / 16);
        }
    assert_true(rl_refine_centre_rows(&img, &lv, &cx, &cy, 16.0, 1) > 0);
    assert_true(fabs(cx - 52.3) < 0.05 && fabs(cy - 47.6) < 0.05);
}

static void same_bits_as_the_plain_loop(void **state)
{
    rl_image img = rl_image_view(W, H, W, px);
    uint32_t seed = 4242;
    int i, t, read = 0;
    (void)state;
    for (i = 0; i < W * H; i++) {
        seed = seed * 1664525u + 1013904223u;
        px[i] = (uint8_t)(seed >> 24);
    }
    for (t = 0; t < 5000; t++) {
        rl_levels lv;
        double cx, cy, r, ax, ay, bx, by, wa, wb;
        int ystep;
        memset(&lv, 0, sizeof lv);
        seed = seed * 1664525u + 1013904223u;
        cx = 5 + (seed >> 8) % 11000 / 100.0;
        seed = seed * 1664525u + 1013904223u;
        cy = 5 + (seed >> 8) % 9000 / 100.0;
        seed = seed * 1664525u + 1013904223u;
        r = 1 + (seed >> 8) % 4000 / 100.0;
        seed = seed * 1664525u + 1013904223u;
        lv.bg = 60 + (seed >> 8) % 19000 / 100.0;
        lv.fg = lv.bg * ((seed >> 4) % 100) / 100.0;
        ystep = 1 + (int)((seed >> 2) % 3);
        ax = bx = cx;
        ay = by = cy;
        wa = rl_refine_centre_rows(&img, &lv, &ax, &ay, r, ystep);
        wb = plain(&img, &lv, &bx, &by, r, ystep);
        assert_memory_equal(&wa, &wb, sizeof wa);
        assert_memory_equal(&ax, &bx, sizeof ax);
        assert_memory_equal(&ay, &by, sizeof ay);
        read += wa > 0;
    }
    assert_true(read > 1000);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(centroid_of_a_disk),
        cmocka_unit_test(same_bits_as_the_plain_loop),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
