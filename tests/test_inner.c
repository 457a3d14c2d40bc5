/* The code-ring check (rl_inner_enclosed) on drawings made here: a
 * candidate (a dark ring 0.8 r .. r on paper) inside a larger landmark's
 * dark ring (1.6 r .. 1.9 r, paper beyond) is enclosed; without that ring it
 * is not. The same answers where the candidate is near the image's border
 * (the rays of one side leave the image: the others decide), and with the
 * image in a buffer whose rows are longer than the image (its stride), so
 * that a ray sampled without bound checks must still read the pixels a
 * checked one reads. */
#include "rl_test.h"
#include <math.h>
#include "rl_inner.h"

#define W 160
#define H 120
#define PAD 37
static uint8_t buf[(W + PAD) * H];

/* The candidate at (cx, cy), radius r, with or without the enclosing ring,
 * into an image of row stride `stride`. */
static rl_image draw(int stride, double cx, double cy, double r, int ring)
{
    int x, y;
    memset(buf, 255, sizeof buf); /* past the image's rows: would read as paper */
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            double d = hypot(x - cx, y - cy) / r;
            int dark = (d >= 0.8 && d <= 1.0) || (ring && d >= 1.6 && d <= 1.9);
            buf[y * stride + x] = (uint8_t)(dark ? 30 : 200);
        }
    return rl_image_view(W, H, stride, buf);
}

static void enclosed_or_not(void **state)
{
    const double r = 12.0;
    /* in the middle; 10 px from the left border (rays to the left leave
     * the image before 0.9 radii); 8.4 and 8.7 px from the bottom right
     * corner's sides */
    const double at[3][2] = {{80.3, 60.6}, {10.2, 55.4}, {W - 8.4, H - 8.7}};
    int k, stride, ring;
    (void)state;
    for (k = 0; k < 3; k++)
        for (stride = W; stride <= W + PAD; stride += PAD)
            for (ring = 0; ring <= 1; ring++) {
                rl_image img = draw(stride, at[k][0], at[k][1], r, ring);
                int got = rl_inner_enclosed(&img, 256, at[k][0], at[k][1], r, 0.0);
                /* by hand: in the corner the rays towards the image (the
                 * six from 169 to 281 degrees, y down) still meet the ring
                 * and the paper past it, more than a quarter of the 16,
                 * and the others leave the image (unknown) */
                int want = ring;
                if (got != want)
                    fail_msg("at (%.1f, %.1f), stride %d, ring %d: %d", at[k][0], at[k][1], stride, ring, got);
            }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(enclosed_or_not),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
