#include "rl_refine.h"

#include <math.h>
#include "rl_ray.h"

void rl_refine_centre(const rl_image *img, const rl_levels *lv, double *cx, double *cy, double r)
{
    int x, y, x0, x1, y0, y1;
    double sw = 0, sx = 0, sy = 0, bg = lv->bg, span = lv->bg - lv->fg, rr = (r + 1) * (r + 1);
    if (span < 1)
        return;
    x0 = (int)floor(*cx - r - 1);
    x1 = (int)ceil(*cx + r + 1);
    y0 = (int)floor(*cy - r - 1);
    y1 = (int)ceil(*cy + r + 1);
    if (x0 < 0 || y0 < 0 || x1 >= img->width || y1 >= img->height)
        return; /* only for complete landmarks */
    for (y = y0; y <= y1; y++) {
        const uint8_t *row = img->data + (size_t)y * (size_t)img->stride;
        double dy = y - *cy;
        for (x = x0; x <= x1; x++) {
            double dx = x - *cx, w;
            if (dx * dx + dy * dy > rr)
                continue;
            w = bg - row[x];
            if (w <= 0)
                continue;
            if (w > span)
                w = span;
            sw += w;
            sx += w * x;
            sy += w * y;
        }
    }
    if (sw > 0) {
        *cx = sx / sw;
        *cy = sy / sw;
    }
}

#define EDGE_ANGLES 16
#define EDGE_SAMPLES 64

/* The mean profile over the rays inside the image, from lo in steps of
 * step; 0 when too few rays are inside. */
static int mean_profile(const rl_image *img, double cx, double cy, double lo, double step,
                        double *prof)
{
    double ca[EDGE_ANGLES], sa[EDGE_ANGLES], hi = lo + (EDGE_SAMPLES - 1) * step;
    float g[EDGE_SAMPLES];
    int i, a, used = 0;
    rl_ray_dirs(EDGE_ANGLES, ca, sa);
    for (i = 0; i < EDGE_SAMPLES; i++)
        prof[i] = 0;
    for (a = 0; a < EDGE_ANGLES; a++) {
        /* a landmark near the border still gets its radius from the side
         * that is there */
        if (!rl_ray_inside(img, cx + lo * ca[a], cy + lo * sa[a], cx + hi * ca[a], cy + hi * sa[a]))
            continue;
        rl_ray_sample(img, cx + lo * ca[a], cy + lo * sa[a], step * ca[a], step * sa[a],
                      EDGE_SAMPLES, 256, g);
        for (i = 0; i < EDGE_SAMPLES; i++)
            prof[i] += g[i];
        used++;
    }
    if (used < EDGE_ANGLES / 3)
        return 0;
    for (i = 0; i < EDGE_SAMPLES; i++)
        prof[i] /= used;
    return 1;
}

void rl_refine_radius(const rl_image *img, double cx, double cy, double *r)
{
    double prof[EDGE_SAMPLES], lo = 0.75 * *r, hi = 1.3 * *r, step = (hi - lo) / (EDGE_SAMPLES - 1);
    double black = 1e9, white, half;
    int i, imin = 0;
    if (!mean_profile(img, cx, cy, lo, step, prof))
        return;
    for (i = 0; i < EDGE_SAMPLES; i++)
        if (prof[i] < black) {
            black = prof[i];
            imin = i;
        }
    white = prof[imin];
    for (i = imin; i < EDGE_SAMPLES; i++)
        if (prof[i] > white)
            white = prof[i];
    if (white - black < 10.0)
        return;
    half = 0.5 * (black + white);
    for (i = imin; i < EDGE_SAMPLES - 1; i++)
        if (prof[i] <= half && prof[i + 1] > half) {
            *r = lo + (i + (half - prof[i]) / (prof[i + 1] - prof[i])) * step;
            return;
        }
}
